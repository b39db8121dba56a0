"""Bad input of a batch (issue 20): a key that the model does not have (did you mean), a
malformed cases file, an unreachable or malformed scheduler address, an output folder that is
a file or cannot be written. Each is refused before any case runs, with the exact message
(file:line:col: key: message) and exit code 2 from `seaflex batch`."""

import os
import shutil
import socket
import subprocess
import tempfile
import time
from pathlib import Path

import pytest

from batch_support import EXE, PENDULUM
from seaflex import batch
from seaflex._batch_cases import Marks, parse
from seaflex.batch import BatchError


def refused(tmp_path, text, *options, timeout=60):
    """(stderr, seconds) of `seaflex batch` on a cases file with this text; exit code 2."""
    cases = tmp_path / "cases.yaml"
    cases.write_text(text)
    t0 = time.monotonic()
    proc = subprocess.run([EXE, "batch", str(cases), "-o", str(tmp_path / "out"), *options],
                          capture_output=True, text=True, timeout=timeout)
    assert proc.returncode == 2, proc.stderr
    assert proc.stdout == ""
    return proc.stderr, time.monotonic() - t0


def cases(body):
    return f"model: {PENDULUM}\n{body}"


@pytest.mark.parametrize("body, message", [
    # the last key: the model loader's verdict and its did you mean
    ("product:\n  environment.gravty: [9.8, 9.81]\n",
     "3:3: product.environment.gravty: unknown key 'gravty' in environment of the model "
     f"{PENDULUM}; did you mean 'gravity'?"),
    # a key on the way: the keys the model has
    ("set:\n  dynamics.duration: 1.0\nproduct:\n  bodies.uper.mass: [1, 2]\n",
     f"5:3: product.bodies.uper.mass: unknown key 'uper' in bodies of the model {PENDULUM}; "
     "did you mean 'upper'?"),
    # a list element by name (joints) and a key of it (the loader names it joints[0])
    ("table:\n  - {joints.shouldr.type: ball}\n",
     f"3:6: table[0].joints.shouldr.type: no element 'shouldr' in joints of the model "
     f"{PENDULUM} (an index from 0 or a name); did you mean 'shoulder'?"),
    ("table:\n  - {name: a, bodies.upper.mass: 1}\n  - {joints.shoulder.stifness: 3}\n",
     f"4:6: table[1].joints.shoulder.stifness: unknown key 'stifness' in joints[0] of the model "
     f"{PENDULUM}; did you mean 'stiffness'?"),
    ("product:\n  bodies.upper.mass.kg: [1]\n",
     f"3:3: product.bodies.upper.mass.kg: bodies.upper.mass of the model {PENDULUM} is the value "
     "2.0, not a section with the key 'kg'"),
    # the cases file itself
    ("produkt:\n  bodies.upper.mass: [1]\n",
     "2:1: produkt: unknown key; did you mean 'product'?"),
    ("product:\n  bodies.upper.mass: 3.0\n",
     "3:3: product.bodies.upper.mass: expected a list of values, got 3.0"),
    ("product:\n  bodies.upper.mass: [1]\nsummary:\n  statistics: [max, maximum]\n",
     "5:21: summary.statistics: unknown statistic 'maximum'; did you mean 'max'?"),
    ("product:\n  bodies.upper.mass: [1]\nsummary:\n  statistics: [kurtosis]\n",
     "5:16: summary.statistics: 'kurtosis' comes from statistics.csv, which needs a statistics "
     "section in the model (docs/model-format.md); without it: min, max, mean, std"),
    ("set:\n  bodies.upper.mass: 1\nproduct:\n  bodies.upper.mass: [1, 2]\n",
     "5:3: product.bodies.upper.mass: also given in set: a key is either fixed or varied"),
    ("table:\n  - {name: a/b, bodies.upper.mass: 1}\n",
     "3:6: table[0].name: a case name is up to 120 letters, digits and . _ + = - (not starting "
     "with . _ + = -), got a/b"),
    ("product:\n  bodies.upper.mass: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n"
     "  bodies.lower.mass: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n"
     "  environment.gravity: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n"
     "  dynamics.duration: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n"
     "  dynamics.time_step: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]\n",
     "2:1: product: 110000 cases, more than the limit of 100000 for one batch"),
])
def test_bad_cases_are_refused_up_front(tmp_path, body, message):
    stderr, _ = refused(tmp_path, cases(body))
    assert stderr == f"{tmp_path}/cases.yaml:{message}\n"
    assert not (tmp_path / "out").exists()  # refused before anything is written


def test_a_missing_model_and_a_broken_cases_file(tmp_path):
    stderr, _ = refused(tmp_path, "model: nowhere.yaml\nproduct: {a.b: [1]}\n")
    assert stderr == f"{tmp_path}/cases.yaml:1:1: model: {tmp_path}/nowhere.yaml: no such model file\n"
    stderr, _ = refused(tmp_path, "model: [\n")
    assert stderr.startswith(f"{tmp_path}/cases.yaml:2:1: YAML syntax error: ")


def test_a_key_the_model_leaves_out_but_the_format_knows_is_accepted():
    # environment.water is not in the pendulum's model; the loader knows it
    b = parse({"product": {"environment.water": [{"density": 1000.0}]}}, Marks("cases"),
              *batch._base(str(PENDULUM)), EXE)
    assert [c.name for c in b.cases] == ["case1"]  # a mapping makes no name
    assert "water: {density: 1000.0}" in b.text(b.cases[0])


def test_python_api_messages():
    with pytest.raises(BatchError) as e:
        batch.run(PENDULUM, {"bodies.upper.mas": [1, 2]}, output="unused", executable=EXE)
    assert str(e.value) == (f"cases: product.bodies.upper.mas: unknown key 'mas' in bodies.upper "
                            f"of the model {PENDULUM}; did you mean 'mass'?")
    with pytest.raises(BatchError) as e:
        batch.run({"title": "x"}, {"model": "m.yaml"}, output="unused", executable=EXE)
    assert str(e.value) == ("cases: model: the base model is given twice (as base_model and in "
                            "the cases)")
    with pytest.raises(BatchError) as e:
        batch.run(42, [], output="unused")
    assert str(e.value) == "base_model: expected a model file, a dict or a seaflex.Model, got int"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


GOOD = "set:\n  dynamics.duration: 0.1\nproduct:\n  bodies.upper.mass: [1.0]\n"


def test_an_unreachable_scheduler_is_a_clear_error_not_a_hang(tmp_path):
    port = free_port()  # nothing listens there
    stderr, seconds = refused(tmp_path, cases(GOOD), "--scheduler", f"tcp://127.0.0.1:{port}",
                              timeout=30)
    assert stderr == (f"cannot reach the Dask scheduler at tcp://127.0.0.1:{port}: Connection "
                      "refused; start one with dask-scheduler and dask-worker, or leave out "
                      "--scheduler for a local cluster\n")
    assert seconds < 30  # loosely: a refused connection is reported at once (about 1 s)
    stderr, _ = refused(tmp_path, cases(GOOD), "--scheduler", "tcp://127.0.0.1:99999", timeout=30)
    assert stderr == ("--scheduler: tcp://127.0.0.1:99999: not a scheduler address (port 99999 "
                      "outside 1 to 65535); expected tcp://HOST:PORT\n")
    stderr, _ = refused(tmp_path, cases(GOOD), "--scheduler", "foo://bar", timeout=30)
    assert stderr.startswith("--scheduler: foo://bar: not a scheduler address (unknown address "
                             "scheme 'foo'")


def test_workers_and_scheduler_options(tmp_path):
    cores = os.cpu_count()
    stderr, _ = refused(tmp_path, cases(GOOD), "--workers", "0")
    assert stderr.startswith(f"--workers: must be a whole number from 1 to {cores} (the hardware "
                             "threads of this machine), got '0'\n")
    # more workers than cores: refused (no faster, a Python process each)
    stderr, _ = refused(tmp_path, cases(GOOD), "--workers", str(cores + 1))
    assert stderr.startswith(f"--workers: {cores + 1} is more than the {cores} hardware threads "
                             "of this machine (std::thread::hardware_concurrency); use at most "
                             f"{cores}\n")
    with pytest.raises(BatchError) as e:
        batch.run(PENDULUM, {"set": {"dynamics.duration": 0.1}}, output=tmp_path / "o",
                  workers=cores + 1, executable=EXE)
    assert str(e.value) == (f"workers: {cores + 1} is more than the {cores} cores of this "
                            f"machine; use at most {cores} (or a cluster: --scheduler)")
    stderr, _ = refused(tmp_path, cases(GOOD), "--workers", "2", "--scheduler", "tcp://h:1")
    assert stderr.startswith("--workers excludes --scheduler\n")


def test_an_output_folder_that_is_a_file(tmp_path):
    (tmp_path / "out").write_text("not a folder")
    stderr, _ = refused(tmp_path, cases(GOOD))
    assert stderr == f"{tmp_path}/out: the output folder is a file\n"
    assert (tmp_path / "out").read_text() == "not a folder"


@pytest.fixture
def public_folder():
    """A folder that every user can read (pytest's own are the user's only)."""
    folder = tempfile.mkdtemp(prefix="seaflex-batch-")
    os.chmod(folder, 0o755)
    yield Path(folder)
    shutil.rmtree(folder)


def test_an_output_folder_that_cannot_be_written(public_folder):
    tmp_path = public_folder
    (tmp_path / "cases.yaml").write_text(cases(GOOD))
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    demote = None
    if os.geteuid() == 0:  # root writes anywhere: run as nobody
        def demote():
            os.setgid(65534)
            os.setuid(65534)
    proc = subprocess.run([EXE, "batch", str(tmp_path / "cases.yaml"), "-o", str(locked / "out")],
                          capture_output=True, text=True, timeout=60, preexec_fn=demote)
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr == f"{locked}/out: cannot write into the output folder: Permission denied\n"
