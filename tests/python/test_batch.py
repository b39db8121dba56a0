"""seaflex.batch on a LocalCluster (issue 20, verification): a 24-case batch on 2 workers
gives the same bytes as 24 serial runs of the command line; running it again runs nothing;
a worker killed in the middle of a case loses nothing. Label slow (about 30 s)."""

import os
import signal
import threading
import time

import pytest

from batch_support import (EXE, LOWER, UPPER, alive, cases_yaml, children,
                           serial_runs)
from seaflex import batch


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    return serial_runs(tmp_path_factory.mktemp("serial"))


@pytest.fixture(scope="module")
def first(tmp_path_factory):
    folder = tmp_path_factory.mktemp("batch")
    (folder / "cases.yaml").write_text(cases_yaml())
    frame = batch.run(None, str(folder / "cases.yaml"), output=folder / "out", workers=2,
                      progress=False, executable=EXE)
    return folder, frame


def assert_same_as_serial(out, frame, serial):
    assert len(frame) == 24
    assert list(frame["status"]) == ["ok"] * 24, frame[["case", "status", "message"]]
    seen = set()
    for _, row in frame.iterrows():
        key = (row["bodies.upper.mass"], row["bodies.lower.mass"])
        seen.add(key)
        # bit for bit: the case's HDF5 file against the serial run's
        assert (out / row["case"] / "timeseries.h5").read_bytes() == serial[key], row["case"]
    assert seen == {(u, l) for u in UPPER for l in LOWER}
    assert not [p for p in out.iterdir() if ".tmp-" in p.name or ".old-" in p.name]


def test_24_cases_on_2_workers_equal_24_serial_runs(first, serial):
    folder, frame = first
    out = folder / "out"
    assert_same_as_serial(out, frame, serial)
    assert not frame["reused"].any()
    assert frame["host"].nunique() == 1
    # the summary: the frame as CSV, and statistics over every row (t >= 0)
    import numpy as np
    import pandas as pd
    csv = pd.read_csv(out / "summary.csv")
    assert list(csv["case"]) == list(frame["case"])
    assert list(csv.columns[:9]) == ["case", "bodies.upper.mass", "bodies.lower.mass", "status",
                                     "exit_code", "wall_time", "message", "reused", "host"]
    assert list(csv.columns[9:]) == [f"{c}.{s}" for c in ("lower.z", "shoulder.fz")
                                     for s in ("min", "max", "mean", "std")]
    import h5py
    row = frame.iloc[5]
    with h5py.File(out / row["case"] / "timeseries.h5") as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["channel_names"][()]]
        z = f["channels"][()][:, names.index("lower.z")]
    # the same numbers as numpy on the file (exactly: the same operations on the same data)
    assert row["lower.z.max"] == np.max(z) and row["lower.z.min"] == np.min(z)
    assert row["lower.z.mean"] == np.mean(z) and row["lower.z.std"] == np.std(z)
    assert row["lower.z.min"] < -1.12 < row["lower.z.max"]  # it starts at z = -1.12 m and swings
    # case names from the varied values; the summary's values are the model's
    assert frame.iloc[0]["case"] == "upper.mass=1_lower.mass=1"
    assert frame.iloc[23]["case"] == "upper.mass=3.5_lower.mass=2.5"
    model = (out / frame.iloc[23]["case"] / "model.yaml").read_text()
    assert "duration: 2.0," in model and "    mass: 3.5\n" in model


class NoClient:
    """Any use of the client fails the test: nothing may be submitted."""

    def __getattr__(self, name):
        raise AssertionError(f"the batch used its client ({name}) although every case was done")


def test_running_again_skips_all_24(first):
    folder, _ = first
    out = folder / "out"
    before = {p: (p.stat().st_mtime_ns, p.stat().st_ino) for p in out.rglob("*")
              if p.name != "summary.csv"}
    frame = batch.run(None, str(folder / "cases.yaml"), output=out, client=NoClient(),
                      progress=False, executable=EXE)
    assert list(frame["status"]) == ["ok"] * 24
    assert frame["reused"].all()
    after = {p: (p.stat().st_mtime_ns, p.stat().st_ino) for p in out.rglob("*")
             if p.name != "summary.csv"}
    assert after == before  # no file rewritten, none added or removed


def test_a_worker_killed_mid_case_loses_nothing(tmp_path, serial):
    from distributed import Client, LocalCluster
    (tmp_path / "cases.yaml").write_text(cases_yaml())
    out = tmp_path / "out"
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=50)
    client = Client(cluster, set_as_default=False)
    result = {}
    try:
        pids = client.run(os.getpid)
        victim = pids[sorted(pids)[0]]

        def work():
            result["frame"] = batch.run(None, str(tmp_path / "cases.yaml"), output=out,
                                        client=client, progress=False, executable=EXE)

        thread = threading.Thread(target=work)
        thread.start()
        # wait until 3 cases are done and the victim runs seaflex on a case
        deadline = time.monotonic() + 60
        while True:
            done = [p for p in out.glob("*/done.json")] if out.exists() else []
            running = {pid: cmd for pid, cmd in children(victim).items()
                       if cmd and cmd[0].decode().endswith("seaflex") and b"run" in cmd}
            if len(done) >= 3 and running:
                break
            assert time.monotonic() < deadline, "the batch did not get going"
            time.sleep(0.01)
        case_pid, cmd = next(iter(running.items()))
        model = cmd[cmd.index(b"run") + 1].decode()
        tmp_folder = os.path.basename(os.path.dirname(model))  # .<case>.tmp-<id>
        case = tmp_folder[1:tmp_folder.index(".tmp-")]
        os.kill(victim, signal.SIGKILL)
        # the case's seaflex dies with its worker (setpriv --pdeathsig)
        t0 = time.monotonic()
        while alive(case_pid) and time.monotonic() - t0 < 5:
            time.sleep(0.01)
        assert not alive(case_pid)
        thread.join(120)
        assert not thread.is_alive()
    finally:
        client.close()
        cluster.close()
    frame = result["frame"]
    assert case in list(frame["case"])
    assert not (out / case / "done.json").read_text() == ""
    assert_same_as_serial(out, frame, serial)
