"""A batch whose cases fail (issue 20): a variation of the wrong type (the model loader's
message, per case) and a solver failure are reported with their messages and exit codes,
the other cases finish, `seaflex batch` exits with 3; running again re-runs the failed cases
and a case whose model changed, and only those."""

import json
import subprocess

import h5py
import numpy as np
import pandas as pd

from batch_support import EXE, PENDULUM
from seaflex import batch

CASES = f"""model: {PENDULUM}
table:
  - {{name: light, bodies.upper.mass: 1.0, dynamics.duration: 0.5}}
  - {{name: heavy_text, bodies.upper.mass: heavy, dynamics.duration: 0.5}}
  - {{name: diverging, dynamics.time_step: 0.5, dynamics.output_interval: 0.5,
     dynamics.duration: 20.0}}
  - {{name: heavy, bodies.upper.mass: 3.0, dynamics.duration: 0.5}}
summary: {{channels: [upper.z]}}
"""


def test_failed_cases_are_reported_and_the_others_finish(tmp_path):
    (tmp_path / "cases.yaml").write_text(CASES)
    out = tmp_path / "out"
    proc = subprocess.run([EXE, "batch", str(tmp_path / "cases.yaml"), "-o", str(out),
                           "--workers", "1", "-q"], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 3, proc.stderr  # some case failed
    frame = pd.read_csv(out / "summary.csv")
    assert list(frame["case"]) == ["light", "heavy_text", "diverging", "heavy"]
    assert list(frame["status"]) == ["ok", "input_error", "solver_failure", "ok"]
    assert list(frame["exit_code"]) == [0, 2, 3, 0]
    # the loader's message on the case's own model file (line of `mass: heavy`, column 11)
    lines = (out / "heavy_text" / "model.yaml").read_text().splitlines()
    line = lines.index("    mass: heavy") + 1
    wrong_type = (f"{out}/heavy_text/model.yaml:{line}:11: bodies.upper.mass: expected a number "
                  "in kg, got 'heavy'")
    assert frame["message"][1] == wrong_type
    diverged = frame["message"][2].splitlines()
    assert diverged[0] == f"seaflex: results up to the failure are in {out}/diverging/timeseries.h5"
    assert diverged[1].startswith("seaflex: solver failure: t = 1.5 s: the solution diverged")
    # the results up to the failure stay on disk: rows at 0, 0.5 and 1 s
    with h5py.File(out / "diverging" / "timeseries.h5") as f:
        assert list(f["time"][()]) == [0.0, 0.5, 1.0]
    assert (out / "diverging" / "failed.json").exists()
    assert not (out / "diverging" / "done.json").exists()
    # the cases that finished have their statistics; upper.z starts at -0.4 m
    for i in (0, 3):
        assert frame["upper.z.max"][i] == -0.4 and frame["upper.z.min"][i] < -0.4
    assert np.isnan(frame["upper.z.max"][1]) and np.isnan(frame["upper.z.max"][2])
    assert proc.stderr == (f"seaflex batch: case heavy_text: input_error: {wrong_type}\n"
                           f"seaflex batch: case diverging: solver_failure: {diverged[0]}\n"
                           f"  {diverged[1]}\n")

    # again, with the light case changed: it re-runs, and the failed ones; heavy does not
    (tmp_path / "cases.yaml").write_text(CASES.replace("mass: 1.0,", "mass: 1.25,"))
    marker = (out / "heavy" / "done.json").stat().st_mtime_ns
    again = batch.run(None, str(tmp_path / "cases.yaml"), output=out, workers=1, progress=False,
                      executable=EXE)
    assert list(again["reused"]) == [False, False, False, True]
    assert list(again["status"]) == ["ok", "input_error", "solver_failure", "ok"]
    assert (out / "heavy" / "done.json").stat().st_mtime_ns == marker
    assert "    mass: 1.25\n" in (out / "light" / "model.yaml").read_text()
    assert json.loads((out / "light" / "done.json").read_text())["row"]["status"] == "ok"
    assert again["upper.z.min"][0] != frame["upper.z.min"][0]
