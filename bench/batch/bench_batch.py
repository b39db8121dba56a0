#!/usr/bin/env python3
"""Throughput of seaflex batches (docs/performance.md, "Batches"): the same batch on a
LocalCluster of 1 and of 2 worker processes (one thread each), wall times printed.

    PYTHONPATH=build/python:python SEAFLEX_EXECUTABLE=build/seaflex \
        /usr/bin/python3 bench/batch/bench_batch.py [--cases 16] [--duration 10] [--repeat 2]

The batch: examples/double_pendulum.yaml (RK4, 1 ms steps) with `--cases` upper-rod masses
and `--duration` s of motion each: cases of equal cost. Each measurement starts a fresh
cluster (its start-up is timed apart), runs the batch into a new folder (nothing skipped)
and closes the cluster. "ideal" is the sum of the cases' own wall times (seaflex in its
subprocess) divided by the workers. "plain" runs the same 16 case models with the command
line from a pool of 1 or 2 threads (no Dask): what the machine gives two processes at once.
"""

import argparse
import os
import platform
import shutil
import subprocess
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from distributed import Client, LocalCluster

from seaflex import batch

REPO = Path(__file__).resolve().parents[2]


def measure(workers, cases, folder):
    t0 = time.monotonic()
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=50)
    client = Client(cluster, set_as_default=False)
    client.wait_for_workers(workers)
    startup = time.monotonic() - t0
    try:
        t0 = time.monotonic()
        frame = batch.run(None, cases, client=client, output=folder, progress=False)
        wall = time.monotonic() - t0
    finally:
        client.close()
        cluster.close()
    assert (frame["status"] == "ok").all(), frame[["case", "status", "message"]]
    return startup, wall, float(frame["wall_time"].sum())


def plain(workers, models, exe, folder):
    """Wall time of the case models run by `seaflex run` from `workers` threads."""
    def one(i):
        out = folder / f"plain_{i}"
        subprocess.run([exe, "run", str(models[i]), "-o", str(out), "-q", "--format", "hdf5"],
                       check=True)
    t0 = time.monotonic()
    with ThreadPoolExecutor(workers) as pool:
        list(pool.map(one, range(len(models))))
    return time.monotonic() - t0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=16)
    parser.add_argument("--duration", type=float, default=10.0, help="s of motion per case")
    parser.add_argument("--repeat", type=int, default=2, help="measurements per worker count")
    args = parser.parse_args()
    exe = os.environ.get("SEAFLEX_EXECUTABLE") or shutil.which("seaflex") or str(
        REPO / "build" / "seaflex")
    os.environ["SEAFLEX_EXECUTABLE"] = exe
    version = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout.strip()
    masses = [round(1.0 + 0.125 * i, 3) for i in range(args.cases)]
    with tempfile.TemporaryDirectory(prefix="seaflex-bench-batch-") as tmp:
        cases = Path(tmp) / "cases.yaml"
        cases.write_text(f"model: {REPO / 'examples' / 'double_pendulum.yaml'}\n"
                         f"set:\n  dynamics.duration: {args.duration!r}\n"
                         f"product:\n  bodies.upper.mass: {masses!r}\n"
                         "summary:\n  channels: [lower.z]\n")
        print(f"{version} ({exe}); {platform.node()}, {os.cpu_count()} cores, "
              f"load average {os.getloadavg()[0]:.2f} at the start")
        print(f"batch: {args.cases} cases of examples/double_pendulum.yaml, {args.duration:g} s "
              "of motion each (RK4, h = 1 ms)")
        print(f"{'workers':>7} {'run':>3} {'start-up (s)':>12} {'batch wall (s)':>14} "
              f"{'cases/s':>8} {'sum of cases (s)':>16} {'ideal (s)':>9} {'plain (s)':>9}")
        walls = {}
        for run in range(args.repeat):
            for workers in (1, 2):
                folder = Path(tmp) / f"out_{workers}_{run}"
                startup, wall, busy = measure(workers, str(cases), folder)
                walls.setdefault(workers, []).append(wall)
                models = sorted(folder.glob("*/model.yaml"))
                control = plain(workers, models, exe, Path(tmp))
                print(f"{workers:>7} {run + 1:>3} {startup:>12.2f} {wall:>14.2f} "
                      f"{args.cases / wall:>8.2f} {busy:>16.2f} {busy / workers:>9.2f} "
                      f"{control:>9.2f}")
                shutil.rmtree(folder)
                for old in Path(tmp).glob("plain_*"):
                    shutil.rmtree(old)
        best1, best2 = min(walls[1]), min(walls[2])
        print(f"speed-up of 2 workers over 1 (best walls): {best1 / best2:.2f}")


if __name__ == "__main__":
    main()
