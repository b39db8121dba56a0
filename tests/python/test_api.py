"""The Python API (issue 20): seaflex.Model runs the command line's analyses, so its numpy
results equal `seaflex run`'s CSV and HDF5 files bit for bit (no tolerance: the CSV prints
17 significant digits, which round-trip doubles); input and solver errors raise
seaflex.InputError / seaflex.SolverError with the exact message the command line prints.

Run by ctest (python_api) as
    PYTHONPATH=build/python SEAFLEX_EXECUTABLE=build/seaflex SEAFLEX_SOURCE_DIR=. \
        /usr/bin/python3 -m pytest tests/python/test_api.py
"""
import csv
import os
import subprocess

import h5py
import numpy as np
import pytest

import seaflex
from seaflex import _yaml

SEAFLEX = os.environ.get("SEAFLEX_EXECUTABLE", "build/seaflex")
SRC = os.path.abspath(os.environ.get("SEAFLEX_SOURCE_DIR", "."))


def example(name):
    return os.path.join(SRC, "examples", name)


def cli(*args):
    return subprocess.run([SEAFLEX, *args], capture_output=True, text=True, timeout=120)


def read_csv(path):
    """header, columns as float64 arrays (float() of 17 digits is the exact double)"""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, values = rows[0], np.array([[float(v) for v in r] for r in rows[1:]])
    return header, {name: values[:, k] for k, name in enumerate(header)}


def same_bits(a, b):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


# three examples, shortened so that the test stays within a few seconds: a rigid-body
# double pendulum (rk4), the cantilever (ANCF beam, rk4, released from its initial state),
# a riser in current (generalized-alpha from statics, Morison drag)
CASES = [("double_pendulum.yaml", 2.0), ("cantilever.yaml", 0.4),
         ("riser_in_current.yaml", 10.0)]


@pytest.mark.parametrize("name,duration", CASES)
def test_results_equal_the_command_line_bit_for_bit(tmp_path, name, duration):
    d = seaflex.Model.from_file(example(name)).to_dict()
    d["dynamics"]["duration"] = duration
    d.setdefault("output", {})["format"] = "both"
    path = tmp_path / name
    path.write_text(seaflex.Model.from_dict(d).yaml)
    out = tmp_path / "cli"
    r = cli("run", str(path), "-o", str(out), "-q")
    assert r.returncode == 0, r.stderr

    model = seaflex.Model.from_file(path)
    results = model.run()
    header, columns = read_csv(out / "timeseries.csv")
    assert header == ["time"] + results.channels
    assert len(results) == round(duration / d["dynamics"]["output_interval"]) + 1
    for name_ in header:
        assert same_bits(results[name_], columns[name_]), name_
    with h5py.File(out / "timeseries.h5", "r") as f:
        assert same_bits(results.time, f["time"][:])
        table = np.column_stack([results[c] for c in results.channels])
        assert same_bits(table, f["channels"][:])
        assert [n.decode() for n in f["channel_names"][:]] == results.channels
        # beam results along the length: every quantity at every station and row
        for beam in results.beams:
            group = f["beams"][beam]
            b = results.beam(beam)
            assert same_bits(b.s, group["stations"]["s"][:])
            for q in b.quantities:
                assert same_bits(b[q], group["results"][q][:]), (beam, q)
    if d["dynamics"].get("initial_state") == "statics":
        _, statics = read_csv(out / "statics.csv")
        for name_ in header:
            assert same_bits(results.statics[name_], statics[name_]), name_


def test_the_riser_has_beam_results_and_the_channels_are_views(tmp_path):
    model = seaflex.Model.from_file(example("riser_in_current.yaml"))
    results = model.run(duration=2.0)
    assert results.beams == ["riser"]
    tension = results.beam("riser")["tension_effective"]
    assert tension.shape == (len(results), len(results.beam("riser").s))
    # no copies: every channel is a read-only view of the recorded values
    x = results[results.channels[0]]
    assert not x.flags.owndata and not x.flags.writeable
    assert x.base is not None
    assert not tension.flags.owndata
    # beams=False: the channels only, the same numbers
    channels_only = model.run(duration=2.0, beams=False)
    assert channels_only.beams == []
    with pytest.raises(KeyError, match="no beam results for 'riser'"):
        channels_only.beam("riser")
    assert same_bits(channels_only["riser.n10.x"], results["riser.n10.x"])


def test_output_dir_writes_the_command_lines_files_byte_for_byte(tmp_path):
    d = seaflex.Model.from_file(example("double_pendulum.yaml")).to_dict()
    d["dynamics"]["duration"] = 0.5
    path = tmp_path / "model.yaml"
    path.write_text(seaflex.Model.from_dict(d).yaml)
    assert cli("run", str(path), "-o", str(tmp_path / "cli"), "-q").returncode == 0
    seaflex.Model.from_file(path).run(output_dir=tmp_path / "py")
    assert (tmp_path / "py" / "timeseries.csv").read_bytes() == \
        (tmp_path / "cli" / "timeseries.csv").read_bytes()


def test_statics_equal_the_command_line(tmp_path):
    path = example("riser_in_current.yaml")
    r = cli("statics", path, "-o", str(tmp_path), "-q")
    assert r.returncode == 0, r.stderr
    results = seaflex.Model.from_file(path).statics()
    header, columns = read_csv(tmp_path / "statics.csv")
    assert len(results) == 1
    for name in header:
        assert same_bits(results[name], columns[name]), name


def test_an_unstable_equilibrium_warns_as_the_command_line_does(tmp_path):
    """barge_riser's straight riser is compressed far beyond its Euler load (docs/
    verification.md section 32): statics, run and modes issue seaflex.StabilityWarning with
    the text of the command line's warning, keep it in results.warnings, and return the
    results; a stable model (riser_in_current) warns of nothing."""
    path = example("barge_riser.yaml")
    r = cli("statics", path, "-o", str(tmp_path), "-q")
    assert r.returncode == 0, r.stderr
    line = [w for w in r.stderr.splitlines() if "unstable" in w]
    assert len(line) == 1 and line[0].startswith("warning: statics: ")
    model = seaflex.Model.from_file(path)
    with pytest.warns(seaflex.StabilityWarning) as caught:
        results = model.statics()
    assert [str(w.message) for w in caught] == [line[0][len("warning: "):]]
    assert results.warnings == [line[0][len("warning: "):]]
    assert "5 directions of negative stiffness" in results.warnings[0]
    with pytest.warns(seaflex.StabilityWarning) as caught:
        modes = model.modes(6)
    assert modes["unstable"] == 5
    assert any("5 modes with negative stiffness" in str(w.message) for w in caught)
    with pytest.warns(seaflex.StabilityWarning):
        run = model.run(duration=1.0)
    assert run.warnings == results.warnings
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", seaflex.StabilityWarning)
        stable = seaflex.Model.from_file(example("riser_in_current.yaml")).statics()
        assert stable.warnings == []
        # made an error, the warning is raised with the results of the call
        with pytest.raises(seaflex.StabilityWarning) as raised:
            model.statics()
    assert raised.value.results.warnings == results.warnings
    assert len(raised.value.results) == 1


def test_from_yaml_and_to_dict_round_trip():
    model = seaflex.Model.from_file(example("cantilever.yaml"))
    d = model.to_dict()
    again = seaflex.Model.from_dict(d)
    assert again.to_dict() == d
    assert seaflex.Model.from_yaml(model.yaml).to_dict() == d
    assert model.source_path == os.path.abspath(example("cantilever.yaml"))
    assert seaflex.Model.from_dict(d).source_path is None
    assert model.check().endswith("model OK\n")
    assert model.check() == cli("check", example("cantilever.yaml")).stdout


# --- errors: the command line's message, exactly --------------------------------------

BAD = ["current_above_surface.yaml", "code_check_beam_unknown.yaml", "bem_file_missing.yaml"]


@pytest.mark.parametrize("name", BAD)
def test_input_errors_carry_the_command_lines_message(name):
    path = os.path.join(SRC, "tests", "bad-input", name)
    r = cli("check", path)
    assert r.returncode == 2
    with pytest.raises(seaflex.InputError) as e:
        seaflex.Model.from_file(path)
    assert str(e.value) == r.stderr.rstrip("\n")
    assert isinstance(e.value, ValueError)


def test_unreadable_file_and_dict_errors(tmp_path):
    missing = str(tmp_path / "nothing.yaml")
    r = cli("check", missing)
    with pytest.raises(seaflex.InputError) as e:
        seaflex.Model.from_file(missing)
    assert str(e.value) == r.stderr.rstrip("\n")
    d = seaflex.Model.from_file(example("cantilever.yaml")).to_dict()
    d["dynamics"]["time_step"] = -1.0
    with pytest.raises(seaflex.InputError) as e:
        seaflex.Model.from_dict(d)
    line = _yaml.dump(d).splitlines().index("  time_step: -1.0") + 1
    assert str(e.value) == f"<dict>:{line}:14: dynamics.time_step: must be greater than 0 s, got -1.0"


SNAP = """
environment: {gravity: 9.81}
bodies:
  weight: {type: rigid_body, mass: 1000, inertia: [100, 100, 100], position: [0, 0, -5]}
connections:
  - {name: line, type: spring, from: {body: ground, position: [0, 0, 0]},
     to: {body: weight, position: [0, 0, 0]}, free_length: 10, slack: true, stiffness: 1.0e8}
dynamics: {integrator: generalized_alpha, time_step: 0.1, duration: 3, output_interval: 0.1}
"""


def test_solver_errors_carry_the_message_and_the_rows_so_far(tmp_path):
    # tests/cli/test_snap_load.py: fixed steps cannot follow the snap at t = 1.1 s
    path = tmp_path / "snap.yaml"
    path.write_text(SNAP)
    r = cli("run", str(path), "-o", str(tmp_path / "cli"), "-q")
    assert r.returncode == 3
    with pytest.raises(seaflex.SolverError) as e:
        seaflex.Model.from_file(path).run()
    assert "seaflex: solver failure: " + str(e.value) in r.stderr.splitlines()
    assert str(e.value).startswith("t = 1.1 s: the step is far too long for the motion")
    header, columns = read_csv(tmp_path / "cli" / "timeseries.csv")
    results = e.value.results
    assert len(results) == 11 and results.time[-1] == 1.0
    for name in header:
        assert same_bits(results[name], columns[name]), name


@pytest.mark.parametrize("path", sorted(os.listdir(os.path.join(SRC, "examples"))))
def test_every_example_survives_to_dict_and_from_dict(path):
    # the dict written back as YAML is the same model: the same dict, the same summary
    # (all but its first line, which names the model)
    if not path.endswith(".yaml"):
        return
    model = seaflex.Model.from_file(example(path))
    d = model.to_dict()
    again = seaflex.Model.from_dict(d, model.source_path)
    assert again.to_dict() == d
    assert again.check().split("\n", 1)[1] == model.check().split("\n", 1)[1]


def test_relative_file_references_resolve_against_source_path(tmp_path, monkeypatch):
    # hemisphere_in_waves reads ../tests/data/wamit/sphere: after set() the edited model
    # still finds it, from any working directory; a dict without source_path does not
    monkeypatch.chdir(tmp_path)
    model = seaflex.Model.from_file(example("hemisphere_in_waves.yaml"))
    model.set("environment.waves.height", 0.5)
    assert model.name == os.path.abspath(example("hemisphere_in_waves.yaml")) + " (edited)"
    assert "model OK" in model.check()  # read with the WAMIT files
    with pytest.raises(seaflex.InputError, match="cannot read the WAMIT file"):
        seaflex.Model.from_dict(model.to_dict())


def test_a_model_pickles_as_its_text():
    import pickle
    model = seaflex.Model.from_file(example("cantilever.yaml")).set("dynamics.duration", 0.1)
    again = pickle.loads(pickle.dumps(model))
    assert again.yaml == model.yaml and again.name == model.name
    assert again.source_path == model.source_path
    a, b = again.run(), model.run()
    assert a.channels == b.channels
    for name in ["time"] + a.channels:
        assert same_bits(a[name], b[name]), name


def test_yaml_written_from_a_dict_reads_back_the_same():
    # _yaml.dump and the loader's parser (to_dict's reader): strings that look like
    # other things stay strings, floats keep every bit
    import numpy
    value = {
        "strings": ["true", "null", "1.5", "", " padded ", "a: b", "x #y", "[1]", "yes", "~",
                    "-dash", "ünïcode", "line\nbreak", "quote\"s", "riser.n10.x", "a - b"],
        "numbers": [0.1, 1e-300, 1.7976931348623157e308, -0.0, 3, -7, 2 ** 70, float("inf"),
                    -float("inf"), True, False, None],
        "nested": {"empty_map": {}, "empty_list": [], "table": [[1.0, 2.0], [3.0, 0.5]],
                   "items": [{"a": 1, "b": [1, 2]}, {"c": {"d": "e"}}, [{"f": 1}]]},
        "numpy": numpy.array([[0.1, 0.2], [0.3, 0.4]]),
        "key with spaces": 1, "true": "key", "1": "numeric key",
    }
    text = _yaml.dump(value)
    back = seaflex._core.yaml_to_python(text, "<test>")
    expected = dict(value, numpy=[[0.1, 0.2], [0.3, 0.4]])
    assert back == expected
    assert str(back["numbers"][3]) == "-0.0"
    nan = seaflex._core.yaml_to_python(_yaml.dump({"x": float("nan")}), "<test>")
    assert nan["x"] != nan["x"]
    with pytest.raises(TypeError, match="a.b: cannot write a set"):
        _yaml.dump({"a": {"b": {1, 2}}})


def test_an_output_dir_that_is_a_file_is_an_input_error(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    r = cli("run", example("double_pendulum.yaml"), "-o", str(blocker))
    assert r.returncode == 2
    with pytest.raises(seaflex.InputError) as e:
        seaflex.Model.from_file(example("double_pendulum.yaml")).run(output_dir=blocker)
    assert str(e.value) == r.stderr.rstrip("\n")
    assert str(e.value) == f"{blocker}: cannot create the output directory: Not a directory"
