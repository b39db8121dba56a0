#!/usr/bin/env python3
"""The largest step that keeps the storm's statistics within 1 % (issue 21 item 4;
docs/performance.md, "Time step of the storm" and "The storm files' time step and refresh
rate"). Runs bench/storm/storm_n<N>.yaml (or, with --short-crested, storm_sc_n<N>.yaml;
make_storm.storm_model with dynamics.duration changed, 30 s ramp included, and with --seed
another realization of the sea) at several time steps and a reference at a smaller step, and
tabulates
    max top effective tension, max bending moment along the riser, max von Mises stress
    along the riser (riser.envelope.csv), RMS of the riser's top angle from the vertical
    over t >= 30 s (from the top node's slope, output channel riser.n<N>.slope_*)
against the reference, with the wall time of each run (one thread).
    /usr/bin/python3 bench/storm/step_study.py SEAFLEX [--duration 630]
        [--steps 0.4 0.2 0.1 0.05] [--reference 0.025] [--kinematics grid]
        [--reference-kinematics exact] [--elements 100] [--work DIR]
        [--envelope-sampling rows|steps] [--seed 1] [--short-crested] [--tolerance 1e-9]
The reference runs at the default Newton tolerance, 1e-10; the runs at --steps at the storm
file's (storm_n100: 1e-8 since the twelfth session, 1e-9 before; the others 1e-9) or at
--tolerance.
--kinematics (and --reference-kinematics) is `exact`, `grid` (the storm files' spacings,
ds 0.5 m, dt 0.2 s and dz_growth 0.2), or e.g. `grid:ds=0.25,dt=0.1` for other spacings
(the other keys of environment.waves.grid keep their defaults). With --work DIR the runs are kept in
DIR and a run of the same model text whose results are already there is not made again
(e.g. the exact reference; a different binary is not noticed: use a fresh DIR then).
The maxima are over every step of each run (output.envelope_sampling: steps, seaflex's
default); with --envelope-sampling rows over its rows, written at the same times in every
run, every --output s (default 0.4 s, a multiple of every step), so that they are taken
over the same samples whatever the step (the tables of docs/performance.md before the
tenth session). Every step must divide --output (the loader asks for a whole number of
steps): e.g. --output 0.5 for 0.25, 0.16666666666666667 (0.5/3), 0.125 and 0.1."""
import argparse
import csv
import hashlib
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
from make_storm import storm_model  # noqa: E402

RAO = str(here.parent.parent / "examples" / "drilling_rig_raos.csv")
SC_RAO = str(here / "storm_sc_raos.csv")
RAMP = 30.0


def variant(n, kinematics, duration, step, output, rho_inf=None, tolerance=None,
            envelope_steps=True, seed=None, short_crested=False):
    kind, _, spacing = kinematics.partition(":")
    if short_crested:  # storm_sc_n<n>.yaml: 22 components in each of 9 directions, exact sum
        if kind != "exact":
            raise ValueError("the short-crested sea needs the exact sum (the grid needs a "
                             "long-crested sea): give --kinematics exact")
        text = storm_model(n, 22, kind, duration, "csv", SC_RAO, spread=True)
    else:
        text = storm_model(n, 200, kind, duration, "csv", RAO)
    if seed is not None:  # another realization of the same sea
        text, k = re.subn(r"\n    seed: [0-9]+\n", f"\n    seed: {seed}\n", text)
        assert k == 1
    if tolerance is not None:
        text, k = re.subn(r"\n  tolerance: [0-9.e+-]+\n", f"\n  tolerance: {tolerance:g}\n", text)
        assert k == 1
    if rho_inf is not None:
        text, k = re.subn(r"\n  rho_inf: [0-9.]+\n", f"\n  rho_inf: {rho_inf:g}\n", text)
        assert k == 1
    if spacing:
        grid = ", ".join(f"{k}: {v}" for k, v in (kv.split("=") for kv in spacing.split(",")))
        text = re.sub(r"\n    grid: \{[^\n]*", "", text)  # the storm file's own spacings
        text, k = re.subn(r"\n    kinematics: grid[^\n]*\n",
                          f"\n    kinematics: grid\n    grid: {{{grid}}}\n", text)
        assert k == 1
    # every digit of the step (0.5/3 s as the files write it)
    text, k = re.subn(r"\n  time_step: [0-9.]+\n", f"\n  time_step: {step!r}\n", text)
    assert k == 1
    text, k = re.subn(r"\n  output_interval: [0-9.]+\n", f"\n  output_interval: {output:g}\n",
                      text)
    assert k == 1
    text = text.replace("  beam_results: envelope\n",
                        f"  beam_results: envelope\n  node_slopes: true\n"
                        f"  channels: [\"riser.n{n}.*\", \"wave.eta.riser\"]\n")
    # the envelopes' extremes over every step (seaflex's default) or over the rows only
    text = text.replace("  beam_results: envelope\n", "  beam_results: envelope\n"
                        f"  envelope_sampling: {'steps' if envelope_steps else 'rows'}\n")
    return text


def run(seaflex, text, folder, name):
    path = pathlib.Path(folder) / f"{name}.yaml"
    path.write_text(text)
    out = pathlib.Path(folder) / name
    # written after a run that finished, with the model's digest: kept only for the same model
    done = out / "step_study.done"
    digest = hashlib.sha256(text.encode()).hexdigest()
    if done.exists() and done.read_text().split("\n")[0] == digest:
        return dict(statistics(out), wall=float("nan"), summary="(kept from an earlier run)")
    t0 = time.time()
    res = subprocess.run([seaflex, "run", str(path), "-o", str(out)], capture_output=True,
                         text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    wall = time.time() - t0
    summary = next((l for l in res.stdout.splitlines() if l.startswith("dynamics:")), "")
    if res.returncode != 0:
        return dict(failed=f"exit {res.returncode}: {res.stderr.strip()[-300:]}", wall=wall)
    done.write_text(digest + "\n" + summary + "\n")
    return dict(statistics(out), wall=wall, summary=summary)


def statistics(folder):
    with open(folder / "riser.envelope.csv") as f:
        rows = list(csv.DictReader(f))
    top_tension = float(rows[-1]["tension_effective.max"])
    moment = max(float(r["moment.max"]) for r in rows)
    mises = max(float(r["stress_von_mises.max"]) for r in rows)
    with open(folder / "timeseries.csv") as f:
        ts = list(csv.DictReader(f))
    top = [k[: -len(".slope_x")] for k in ts[0] if k.endswith(".slope_x")][0]
    ang = [math.atan2(math.hypot(float(r[top + ".slope_x"]), float(r[top + ".slope_y"])),
                      float(r[top + ".slope_z"])) for r in ts if float(r["time"]) >= RAMP - 1e-9]
    rms = math.degrees(math.sqrt(sum(a * a for a in ang) / len(ang)))
    return dict(top_tension=top_tension, moment=moment, mises=mises, angle_rms=rms)


KEYS = (("top_tension", "max top tension (N)"), ("moment", "max bending moment (N m)"),
        ("mises", "max von Mises (Pa)"), ("angle_rms", "RMS top angle (deg)"))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("seaflex")
    p.add_argument("--duration", type=float, default=630.0)
    p.add_argument("--elements", type=int, default=100)
    p.add_argument("--steps", type=float, nargs="+", default=[0.4, 0.2, 0.1, 0.05])
    p.add_argument("--reference", type=float, default=0.025)
    p.add_argument("--kinematics", default="grid")
    p.add_argument("--reference-kinematics", default="exact")
    p.add_argument("--output", type=float, default=0.4)
    p.add_argument("--work", help="keep the runs in this folder and reuse them")
    p.add_argument("--envelope-sampling", choices=["rows", "steps"], default="steps",
                   help="output.envelope_sampling of every run: the maxima over every step "
                        "(the default) or over the output rows only")
    p.add_argument("--short-crested", action="store_true",
                   help="the short-crested sea of storm_sc_n<N>.yaml (with --kinematics exact "
                        "and --reference-kinematics exact)")
    p.add_argument("--seed", type=int,
                   help="the sea's random seed for every run (the storm files': 1)")
    p.add_argument("--tolerance", type=float,
                   help="the Newton tolerance of the runs at --steps (the reference keeps "
                        "1e-10; default: the storm file's)")
    p.add_argument("--rho-inf", type=float,
                   help="generalized-alpha's rho_inf for the runs at --steps (the reference "
                        "keeps the storm file's)")
    a = p.parse_args()
    if a.short_crested and (a.kinematics != "exact" or a.reference_kinematics != "exact"):
        p.error("--short-crested needs --kinematics exact and --reference-kinematics exact "
                "(the grid needs a long-crested sea)")
    res = {}
    if a.work:
        os.makedirs(a.work, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = a.work or tmp
        runs = [(h, a.kinematics, a.rho_inf) for h in a.steps] + [(a.reference, a.kinematics, None)]
        if a.reference_kinematics != a.kinematics:
            runs.append((a.reference, a.reference_kinematics, None))
        for h, kin, rho in runs:
            # the reference at the default Newton tolerance, 1e-10
            tol = 1e-10 if h == a.reference else a.tolerance
            steps = a.envelope_sampling == "steps"
            res[(h, kin)] = r = run(
                a.seaflex,
                variant(a.elements, kin, a.duration, h, a.output, rho, tol, steps, a.seed,
                        a.short_crested), tmp,
                f"storm{'_sc' if a.short_crested else ''}_{kin.replace(':', '_').replace(',', '_').replace('=', '')}"
                f"_{h:g}_{a.duration:g}_{a.elements}_{a.output:g}"
                + (f"_rho{rho:g}" if rho is not None else "") + ("" if steps else "_rows")
                + (f"_tol{tol:g}" if tol is not None and h != a.reference else "")
                + (f"_seed{a.seed}" if a.seed is not None else ""))
            print(f"# h = {h:g} s, {kin}: {r.get('failed') or r['summary']} "
                  f"({r['wall']:.1f} s wall)", flush=True)
    ref = res[(a.reference, a.reference_kinematics)]
    print(f"\nReference: h = {a.reference:g} s, kinematics {a.reference_kinematics}")
    print("| h (s) | kinematics | " + " | ".join(f"{t} (error)" for _, t in KEYS) +
          " | wall (s) |")
    print("|---|---|" + "---|" * len(KEYS) + "---|")
    for (h, kin), r in sorted(res.items(), key=lambda kv: (-kv[0][0], kv[0][1])):
        if "failed" in r:
            print(f"| {h:g} | {kin} | failed: {r['failed']} |" + " |" * len(KEYS))
            continue
        cells = " | ".join(f"{r[k]:.6g} ({r[k] / ref[k] - 1:+.2e})" for k, _ in KEYS)
        print(f"| {h:g} | {kin} | {cells} | {r['wall']:.1f} |")


if __name__ == "__main__":
    main()
