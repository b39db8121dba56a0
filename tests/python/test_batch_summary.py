"""The statistics in a batch's summary (issue 20): for the drilling rig with a statistics
section, min/max/mean/std of a channel equal statistics.csv (same rows, t >= start), the
most probable maximum equals extremes.csv, a beam quantity's max and min are those of the
HDF5 beam results over the stations and the rows t >= start."""

import csv
import math

import h5py
import numpy as np

from batch_support import EXE, REPO
from seaflex import batch

RIG = REPO / "examples" / "drilling_rig.yaml"


def test_summary_statistics_equal_the_results(tmp_path):
    cases = {"set": {"dynamics.duration": 30.0, "statistics": {"start": 10.0}},
             "table": [{"name": "h4", "environment.waves.height": 4.0}],
             "summary": {"channels": ["platform.pitch", "wire_1.tension", "riser.tension_*"],
                         "statistics": ["min", "max", "mean", "std", "mpm_rayleigh", "period"]}}
    frame = batch.run(RIG, cases, output=tmp_path / "out", workers=1, progress=False,
                      executable=EXE)
    row = frame.iloc[0]
    assert row["status"] == "ok" and row["message"] == ""
    folder = tmp_path / "out" / "h4"
    with open(folder / "statistics.csv") as f:
        stats = {line["channel"]: line for line in csv.DictReader(f)}
    with open(folder / "extremes.csv") as f:
        mpm = {line["channel"]: float(line["most_probable_maximum"]) for line in csv.DictReader(f)
               if line["method"] == "rayleigh"}
    for channel in ("platform.pitch", "wire_1.tension"):
        for s in ("min", "max", "mean", "std", "period"):
            # statistics.csv accumulates row by row (Welford), the summary uses numpy's two
            # passes: equal to 1e-12 relative (both are 1e-16 accurate on 41 rows)
            assert math.isclose(row[f"{channel}.{s}"], float(stats[channel][s]), rel_tol=1e-12,
                                abs_tol=1e-300), (channel, s)
        assert row[f"{channel}.mpm_rayleigh"] == mpm[channel]
    with h5py.File(folder / "timeseries.h5") as f:
        t = f["time"][()]
        tension = f["beams/riser/results/tension_effective"][()]
    kept = tension[t >= 10.0]
    assert len(kept) == 41 and len(t) == 61  # rows every 0.5 s from 10 s to 30 s
    assert row["riser.tension_effective.max"] == np.nanmax(kept)
    assert row["riser.tension_effective.min"] == np.nanmin(kept)
    assert "riser.tension_effective.mean" not in frame  # along a beam: min and max only
    assert "riser.tension_wall.max" in frame


def test_a_warning_reaches_the_summary(tmp_path):
    """barge_riser's statics is unstable (docs/verification.md section 32): the case runs
    (status ok) and its summary message is the command line's warning. The stable drilling
    rig of the test above keeps an empty message."""
    base = REPO / "examples" / "barge_riser.yaml"
    cases = {"command": "statics", "table": [{"name": "as_is", "statics.load_steps": 1}]}
    frame = batch.run(base, cases, output=tmp_path / "out", workers=1, progress=False,
                      executable=EXE)
    row = frame.iloc[0]
    assert row["status"] == "ok"
    assert row["message"].startswith("statics: the equilibrium found is unstable: 5 directions")
