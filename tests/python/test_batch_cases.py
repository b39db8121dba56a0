"""The cases of a batch (issue 20): a table combined with a product and the case names it
gives, a base model given as an object with to_dict() and source_path (seaflex.Model) whose
file references are made absolute, so that the case's model runs from its own folder."""

import re

from batch_support import EXE, REPO
from seaflex import batch
from seaflex._batch_cases import Marks, parse

RAOS = REPO / "examples" / "drilling_rig_raos.yaml"


class ModelLike:
    """What seaflex.Model offers the batch: to_dict() and source_path."""
    source_path = str(RAOS)

    def to_dict(self):
        return batch._base(str(RAOS))[0]


def test_a_table_times_a_product():
    cases = {"table": [{"name": "calm", "environment.waves.hs": 1.0},
                       {"name": "rough", "environment.waves.hs": 5.0}],
             "product": {"environment.waves.tp": [8.0, 12.5]}}
    b = parse(cases, Marks("cases"), *batch._base(ModelLike()), EXE)
    assert [c.name for c in b.cases] == ["calm_tp=8", "calm_tp=12.5", "rough_tp=8",
                                         "rough_tp=12.5"]
    assert b.cases[3].values == {"environment.waves.hs": 5.0, "environment.waves.tp": 12.5}
    assert b.paths == ["environment.waves.hs", "environment.waves.tp"]
    # the RAO table, relative to the base model in its file, is absolute in the case's model
    assert re.findall(r"file: (.*)", b.text(b.cases[0])) == [str(REPO / "examples" /
                                                           "drilling_rig_raos.csv")]
    # the same case twice has the same digest; another value another one
    again = parse(cases, Marks("cases"), *batch._base(ModelLike()), EXE)
    assert [c.digest for c in again.cases] == [c.digest for c in b.cases]
    assert len({c.digest for c in b.cases}) == 4


def test_names_fall_back_to_numbers():
    b = parse({"product": {"bodies.platform.position": [[0, 0, -5], [10, 0, -5]]}},
              Marks("cases"), *batch._base(str(REPO / "examples" / "drilling_rig.yaml")), EXE)
    assert [c.name for c in b.cases] == ["case1", "case2"]  # a list makes no folder name
    assert "position: [10, 0, -5]" in b.text(b.cases[1])


def test_the_case_model_runs_from_its_own_folder(tmp_path):
    frame = batch.run(ModelLike(), {"set": {"dynamics.duration": 2.0},
                                    "table": [{"name": "calm", "environment.waves.hs": 1.0}],
                                    "summary": {"channels": ["platform.z"]}},
                      output=tmp_path, workers=1, progress=False, executable=EXE)
    assert list(frame["status"]) == ["ok"], frame["message"][0]
    assert frame["platform.z.min"][0] < frame["platform.z.max"][0]


def test_more_cases_than_in_flight(tmp_path, monkeypatch, capsys):
    # Dask holds at most MAX_IN_FLIGHT cases (with their models) at a time; the rest follow
    monkeypatch.setattr(batch, "MAX_IN_FLIGHT", 2)
    frame = batch.run(str(REPO / "examples" / "double_pendulum.yaml"),
                      {"set": {"dynamics.duration": 0.1},
                       "product": {"bodies.upper.mass": [1.0, 1.5, 2.0, 2.5, 3.0]},
                       "summary": {"channels": ["upper.z"], "statistics": ["min"]}},
                      output=tmp_path, workers=1, progress=True, executable=EXE)
    assert list(frame["status"]) == ["ok"] * 5
    # the progress bar, not on a terminal: a line per finished case, in the order they finish
    lines = capsys.readouterr().err.splitlines()
    bars = [line for line in lines if line.startswith("[")]
    assert len(bars) == 5
    for i, line in enumerate(bars):
        filled = 30 * (i + 1) // 5
        assert re.fullmatch(rf"\[#{{{filled}}}\.{{{30 - filled}}}\] {i + 1}/5 cases, 0 failed, "
                            r"\d+ s: mass=[0-9.]+ ok", line), line
    assert list(frame["case"]) == ["mass=1", "mass=1.5", "mass=2", "mass=2.5", "mass=3"]
    assert list(frame.columns[8:]) == ["upper.z.min"]


def test_a_case_past_its_timeout_is_stopped(tmp_path):
    # 30 s of the pendulum take about 4 s; the timeout stops it at 0.5 s
    frame = batch.run(str(REPO / "examples" / "double_pendulum.yaml"),
                      {"set": {"dynamics.duration": 30.0}, "timeout": 0.5,
                       "table": [{"name": "long"}]},
                      output=tmp_path, workers=1, progress=False, executable=EXE)
    assert list(frame["status"]) == ["timeout"]
    assert frame["message"][0] == "stopped after the case's timeout of 0.5 s"
    assert 0.5 <= frame["wall_time"][0] < 10  # loosely: stopped, not run to the end
    assert (tmp_path / "long" / "failed.json").exists()
    assert not (tmp_path / "long" / "done.json").exists()
