#!/usr/bin/env python3
"""Storm cost and accuracy, exact against grid wave kinematics (issue 21, docs/performance.md
"The storm benchmark"). Writes the variants of make_storm.storm_model to a temporary folder.
    /usr/bin/python3 bench/storm/sweep.py cost SEAFLEX [--duration 120] [--elements 100]
        `seaflex bench` of the storm for 50, 100, 200, 400 components, exact and grid.
    /usr/bin/python3 bench/storm/sweep.py accuracy SEAFLEX [--duration 630]
        `seaflex run` exact and grid; max top effective tension, max bending moment, max
        riser-top angle and the probe's wave elevation, with their relative differences."""
import argparse
import csv
import os
import pathlib
import re
import subprocess
import sys
import tempfile

here = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(here))
from make_storm import storm_model  # noqa: E402

RAO = str(here.parent.parent / "examples" / "drilling_rig_raos.csv")


def bench(seaflex, text, duration, tmp):
    path = pathlib.Path(tmp) / "storm.yaml"
    path.write_text(text)
    out = subprocess.run([seaflex, "bench", str(path), "--duration", str(duration)],
                         capture_output=True, text=True, check=True,
                         env=dict(os.environ, OMP_NUM_THREADS="1")).stdout
    wall = float(re.search(r"in ([0-9.]+) s wall:", out).group(1))
    per_s = float(re.search(r"([0-9.e+-]+) s wall per simulated s", out).group(1))
    steps = int(re.search(r"steps: (\d+) accepted", out).group(1))
    iters = float(re.search(r"; ([0-9.]+) iterations per step", out).group(1))
    kin = float(re.search(r"wave kinematics ([0-9.]+) s", out).group(1))
    fac = float(re.search(r"factorization ([0-9.]+) s", out).group(1))
    sol = float(re.search(r"solve ([0-9.]+) s", out).group(1))
    asm = float(re.search(r"assembly ([0-9.]+) s", out).group(1))
    return dict(wall=wall, per_s=per_s, steps=steps, iters=iters, kin=kin, other=asm - kin,
                fac=fac, sol=sol)


def cost(args):
    print("| components | kinematics | wall s / simulated s | 3-h storm (extrapolated) | steps | "
          "Newton it./step | kinematics s | other forces+tangents s | factorization s | solve s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for n in (50, 100, 200, 400):
            for kin in ("exact", "grid"):
                r = bench(args.seaflex, storm_model(args.elements, n, kin, 10830.0, "csv", RAO),
                          args.duration, tmp)
                print(f"| {n} | {kin} | {r['per_s']:.4g} | {r['per_s'] * 10830 / 60:.1f} min | "
                      f"{r['steps']} | {r['iters']:.3g} | {r['kin']:.2f} | {r['other']:.2f} | "
                      f"{r['fac']:.3f} | {r['sol']:.3f} |", flush=True)


def statistics(folder):
    with open(pathlib.Path(folder) / "riser.envelope.csv") as f:
        rows = list(csv.DictReader(f))
    top_tension = float(rows[-1]["tension_effective.max"])
    moment = max(max(abs(float(r["moment.max"])), abs(float(r["moment.min"]))) for r in rows)
    with open(pathlib.Path(folder) / "timeseries.csv") as f:
        ts = list(csv.DictReader(f))
    eta = [float(r["wave.eta.riser"]) for r in ts]
    fz = max(abs(float(r["upper_flex_joint.fz"])) for r in ts)
    return dict(top_tension=top_tension, moment=moment, joint_fz=fz,
                eta_max=max(abs(e) for e in eta))


def accuracy(args):
    res = {}
    with tempfile.TemporaryDirectory() as tmp:
        for kin in ("exact", "grid"):
            path = pathlib.Path(tmp) / f"storm_{kin}.yaml"
            path.write_text(storm_model(args.elements, 200, kin, args.duration, "csv", RAO))
            out = pathlib.Path(tmp) / kin
            subprocess.run([args.seaflex, "run", str(path), "-o", str(out), "--quiet"],
                           check=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
            res[kin] = statistics(out)
    print("| statistic | exact | grid | relative difference |")
    print("|---|---|---|---|")
    for key, label in (("top_tension", "max top effective tension (N)"),
                       ("moment", "max bending moment (N m)"),
                       ("joint_fz", "max upper flex joint abs(fz) (N)"),
                       ("eta_max", "max abs(wave elevation) at the riser (m)")):
        a, b = res["exact"][key], res["grid"][key]
        print(f"| {label} | {a:.6g} | {b:.6g} | {(b - a) / a:.2e} |")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("what", choices=["cost", "accuracy"])
    p.add_argument("seaflex")
    p.add_argument("--duration", type=float, default=None)
    p.add_argument("--elements", type=int, default=100)
    args = p.parse_args()
    if args.what == "cost":
        args.duration = args.duration or 120.0
        cost(args)
    else:
        args.duration = args.duration or 630.0
        accuracy(args)


if __name__ == "__main__":
    main()
