#!/usr/bin/env python3
"""Studies of the dynamic riser benchmarks (issue 21; docs/performance.md "Dynamic riser
benchmarks", docs/verification.md section 29). Writes variants of make_riser_variants to a
temporary folder and runs them.
    /usr/bin/python3 bench/riser/riser_studies.py waves SEAFLEX [--elements 10 100]
            [--steps 0.1 0.05 0.025 0.0125]
        the waves variant at each step and mesh: over the last five wave periods
        (t >= 540 s, output every 0.1 s), max top angle, max bending moment along the
        riser, max top effective tension; errors against the smallest step, their ratios.
    /usr/bin/python3 bench/riser/riser_studies.py transient SEAFLEX [--elements 10 100]
            [--tolerances 1e-3 1e-4 1e-5]
        the transient variant at each error_tolerance: max top angle, max bow, max
        bending moment, the state at 600 s.
    /usr/bin/python3 bench/riser/riser_studies.py bench SEAFLEX MODEL... [--duration D]
        `seaflex bench` (one thread) of each model: the table row of docs/performance.md.
measure_waves() and measure_transient() are used by the tests of
tests/verification/riser_variants/."""
import argparse
import csv
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

here = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(here))
from make_riser_variants import transient_model, waves_model  # noqa: E402

ENV = dict(os.environ, OMP_NUM_THREADS="1")


def _run(seaflex, text, folder, name):
    folder = pathlib.Path(folder)
    path = folder / f"{name}.yaml"
    path.write_text(text)
    out = folder / name
    t0 = time.time()
    res = subprocess.run([seaflex, "run", str(path), "-o", str(out)], capture_output=True,
                         text=True, env=ENV)
    wall = time.time() - t0
    if res.returncode != 0:
        raise RuntimeError(f"seaflex run {path}: exit {res.returncode}\n{res.stderr}")
    return out, wall, res.stdout


def _timeseries(folder):
    with open(pathlib.Path(folder) / "timeseries.csv") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def top_angles(ts, n):
    """The top angle from the vertical (deg) at every output row, from the top node's slope."""
    sx, sy, sz = (ts[f"riser.n{n}.slope_{c}"] for c in "xyz")
    return [math.degrees(math.atan2(math.hypot(a, b), c)) for a, b, c in zip(sx, sy, sz)]


def measure_waves(seaflex, n, dt, folder, duration=600.0, start=540.0):
    """Run the waves variant (n elements, step dt); statistics over t >= start."""
    out, wall, _ = _run(seaflex, waves_model(n, dt=dt, duration=duration, start=start), folder,
                        f"waves_n{n}_dt{dt:g}")
    ts = _timeseries(out)
    ang = [a for t, a in zip(ts["time"], top_angles(ts, n)) if t >= start - 1e-9]
    with open(out / "riser.range.csv") as f:
        rows = list(csv.DictReader(f))
    moment = max(float(r["moment.max"]) for r in rows)
    top_tension = float(rows[-1]["tension_effective.max"])
    return dict(angle=max(ang), moment=moment, top_tension=top_tension, wall=wall)


def measure_transient(seaflex, n, folder, tol=1e-4, duration=600.0, dt=0.1, all_nodes=False):
    """Run the transient variant; maxima over the run (output every 1 s) and the last row."""
    out, wall, stdout = _run(seaflex, transient_model(n, dt=dt, duration=duration, tol=tol,
                                                      all_nodes=all_nodes),
                             folder, f"transient_n{n}_tol{tol:g}")
    ts = _timeseries(out)
    ang = top_angles(ts, n)
    with open(out / "riser.envelope.csv") as f:
        rows = list(csv.DictReader(f))
    return dict(angle_max=max(ang), angle_end=ang[-1], bow=max(float(r["x.max"]) for r in rows),
                moment=max(float(r["moment.max"]) for r in rows), ts=ts, wall=wall,
                summary=next((l for l in stdout.splitlines() if l.startswith("dynamics:")), ""))


def waves(args):
    keys = ("angle", "moment", "top_tension")
    for n in args.elements:
        with tempfile.TemporaryDirectory() as tmp:
            res = {dt: measure_waves(args.seaflex, n, dt, tmp) for dt in args.steps}
        ref = res[min(args.steps)]
        print(f"\nN = {n} (reference: h = {min(args.steps):g} s)")
        print("| h (s) | max top angle (deg) | max bending moment (N m) | max top tension (N) | "
              "error angle | error moment | wall (s) |")
        print("|---|---|---|---|---|---|---|")
        prev = None
        for dt in sorted(args.steps, reverse=True):
            r = res[dt]
            err = {k: r[k] / ref[k] - 1 for k in keys}
            ratio = ""
            if prev is not None and dt != min(args.steps):
                ratio = " (ratio %s)" % ", ".join(
                    f"{prev[k] / err[k]:.2f}" if err[k] else "-" for k in ("angle", "moment"))
            print(f"| {dt:g} | {r['angle']:.6f} | {r['moment']:.6e} | {r['top_tension']:.6e} | "
                  f"{err['angle']:+.2e} | {err['moment']:+.2e}{ratio} | {r['wall']:.1f} |",
                  flush=True)
            prev = err


def transient(args):
    print("| N | error_tolerance | max top angle (deg) | max bow (m) | max bending moment (N m) | "
          "top angle at the end (deg) | wall (s) | run |")
    print("|---|---|---|---|---|---|---|---|")
    for n in args.elements:
        with tempfile.TemporaryDirectory() as tmp:
            for tol in args.tolerances:
                r = measure_transient(args.seaflex, n, tmp, tol=tol)
                print(f"| {n} | {tol:g} | {r['angle_max']:.6f} | {r['bow']:.6f} | "
                      f"{r['moment']:.6e} | {r['angle_end']:.6f} | {r['wall']:.1f} | "
                      f"{r['summary']} |", flush=True)


def bench(args):
    print("| model | simulated | wall (s) | s wall per simulated s | x real time | steps | "
          "Newton it./step | factorizations | assembly / factorization / solve / other |")
    print("|---|---|---|---|---|---|---|---|---|")
    for model in args.models:
        cmd = [args.seaflex, "bench", model]
        if args.duration:
            cmd += ["--duration", str(args.duration)]
        out = subprocess.run(cmd, capture_output=True, text=True, check=True, env=ENV).stdout
        m = re.search(r"([0-9.e+]+) s simulated in ([0-9.]+) s wall: ([0-9.e+-]+) s wall per "
                      r"simulated s, ([0-9.e+]+) x real time", out)
        steps = re.search(r"steps: (\d+) accepted(?:, (\d+) rejected)?", out)
        iters = re.search(r"; ([0-9.]+) iterations per step", out).group(1)
        facs = re.search(r"(\d+) factorizations", out).group(1)
        split = re.findall(r"(assembly|factorization|solve|other) [0-9.]+ s \(([0-9]+) %\)", out)
        rej = f" ({steps.group(2)} rejected)" if steps.group(2) else ""
        print(f"| `{model}` | {m.group(1)} s | {m.group(2)} | {m.group(3)} | {m.group(4)} | "
              f"{steps.group(1)}{rej} | {iters} | {facs} | "
              f"{' / '.join(p for _, p in split)} % |", flush=True)


if __name__ == "__main__":
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="cmd", required=True)
    w = sub.add_parser("waves")
    w.add_argument("seaflex")
    w.add_argument("--elements", type=int, nargs="+", default=[10, 100])
    w.add_argument("--steps", type=float, nargs="+", default=[0.1, 0.05, 0.025, 0.0125])
    t = sub.add_parser("transient")
    t.add_argument("seaflex")
    t.add_argument("--elements", type=int, nargs="+", default=[10, 100])
    t.add_argument("--tolerances", type=float, nargs="+", default=[1e-3, 1e-4, 1e-5])
    b = sub.add_parser("bench")
    b.add_argument("seaflex")
    b.add_argument("models", nargs="+")
    b.add_argument("--duration", type=float)
    a = p.parse_args()
    {"waves": waves, "transient": transient, "bench": bench}[a.cmd](a)
