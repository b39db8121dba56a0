"""A batch on a cluster started as docs/python-batch.md shows (issue 20): dask-scheduler and
a dask-worker as separate processes, `seaflex batch --scheduler ADDRESS`; the results equal
a serial run of the command line byte for byte."""

import json
import os
import signal
import subprocess
import sys
import time

from batch_support import EXE, pendulum_text

DASK_SCHEDULER = os.path.join(os.path.dirname(sys.executable), "dask-scheduler")
DASK_WORKER = os.path.join(os.path.dirname(sys.executable), "dask-worker")


def stop(proc):
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def test_a_batch_on_dask_scheduler_and_dask_worker(tmp_path):
    info = tmp_path / "scheduler.json"
    log = open(tmp_path / "dask.log", "w")
    scheduler = subprocess.Popen([DASK_SCHEDULER, "--host", "127.0.0.1", "--port", "0",
                                  "--no-dashboard", "--scheduler-file", str(info)],
                                 stdout=log, stderr=log)
    worker = None
    try:
        deadline = time.monotonic() + 30
        while not info.exists() or not info.read_text().strip():
            assert time.monotonic() < deadline and scheduler.poll() is None
            time.sleep(0.1)
        time.sleep(0.2)  # the file is written whole, but give it a moment
        address = json.loads(info.read_text())["address"]
        worker = subprocess.Popen([DASK_WORKER, "--scheduler-file", str(info), "--nworkers", "1",
                                   "--nthreads", "1", "--no-dashboard"], stdout=log, stderr=log)
        (tmp_path / "cases.yaml").write_text(
            f"model: {tmp_path / 'base.yaml'}\ntable:\n  - {{name: a, bodies.lower.mass: 1.25}}\n"
            "  - {name: b, bodies.lower.mass: 2.25}\n")
        (tmp_path / "base.yaml").write_text(pendulum_text(2.0, 1.5, 0.5))
        proc = subprocess.run([EXE, "batch", str(tmp_path / "cases.yaml"), "-o",
                               str(tmp_path / "out"), "--scheduler", address, "-q"],
                              capture_output=True, text=True, timeout=120)
        assert proc.returncode == 0, proc.stderr
    finally:
        if worker:
            stop(worker)
        stop(scheduler)
        log.close()
    for name, lower in (("a", 1.25), ("b", 2.25)):
        serial = tmp_path / f"serial_{name}"
        serial.mkdir()
        (serial / "model.yaml").write_text(pendulum_text(2.0, lower, 0.5))
        subprocess.run([EXE, "run", str(serial / "model.yaml"), "-o", str(serial), "-q",
                        "--format", "hdf5"], check=True, timeout=60)
        assert (tmp_path / "out" / name / "timeseries.h5").read_bytes() == \
            (serial / "timeseries.h5").read_bytes()
