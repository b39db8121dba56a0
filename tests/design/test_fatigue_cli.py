#!/usr/bin/env python3
"""Fatigue and code checks from the command line (issue 19 part B).

    test_fatigue_cli.py SEAFLEX SOURCE_DIR

1. A riser in current and waves with a `fatigue` section that also writes every hot-spot
   stress (riser.fatigue_stress.csv): an independent rainflow (the four-point method of
   ASTM E1049-85 / Amzallag et al. 1994 on the reversals, residue as half cycles), written
   here with numpy and no code of seaflex, and Miner's sum over the DNV-RP-C203 (2016) D
   curve in seawater with cathodic protection give the damage of every point of
   riser.fatigue.csv to 1e-9 relative (the same sums in another order). The stresses
   themselves are checked against riser.along.csv: their mean over the 8 points is SCF
   T_wall / A and their spread lies between 2 SCF |M| r/I cos(pi/8) and 2 SCF |M| r/I.
2. Code checks of a pipe cantilever at statics, against hand calculations to 1e-6: a
   clamped pipe under a transverse tip load P (root moment P L, no tension) and a pinned
   one under an axial tip load (tension F, no moment), for DNV-ST-F201 combined loading
   and API RP 2RD.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "cli"))
import cli_support  # noqa: E402
from cli_support import TempDirCase, run  # noqa: E402
import unittest  # noqa: E402

RISER = """
title: riser for fatigue
environment:
  gravity: 9.81
  water: {density: 1025, depth: 300}
  current: {speed: 1.0, direction: 0}
  waves: {type: airy, height: 6.0, period: 9.0, direction: 0, ramp: {start: 0, duration: 10}}
bodies:
  riser:
    type: ancf_beam
    start: [0, 0, -300]
    end: [0, 0, 10]
    elements: 10
    outer_diameter: 0.7
    inner_diameter: 0.4
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  riser: {cd: 0.65, cm: 1.6}
supports:
  - {body: riser, node: start, type: pinned}
  - {body: riser, node: end, type: fixed, fix: [x, y]}
loads:
  - {type: point_force, body: riser, node: end, force: [0, 0, 6.0e6]}
statics:
  load_steps: 4
dynamics:
  integrator: generalized_alpha
  time_step: 0.05
  duration: 60
  output_interval: 0.1
  initial_state: statics
fatigue:
  curve: D
  environment: seawater_cp
  scf: 1.2
  start: 10
  write_stresses: true
code_check:
  smys: 448e6
  smts: 531e6
"""

YEAR = 365.25 * 86400.0


def reversals(x):
    """Peaks and valleys of x, with its first and last samples (plateaus count once)."""
    x = np.asarray(x, dtype=float)
    keep = np.concatenate(([True], np.diff(x) != 0.0))
    x = x[keep]
    if len(x) < 3:
        return x
    d = np.sign(np.diff(x))
    turn = np.nonzero(d[1:] != d[:-1])[0] + 1
    return np.concatenate(([x[0]], x[turn], [x[-1]]))


def rainflow_four_point(rev):
    """Ranges and counts: four consecutive reversals a b c d close the cycle b-c when
    |c - b| <= |b - a| and |c - b| <= |d - c|; what stays counts as half cycles."""
    ranges, counts, stack = [], [], []
    for r in rev:
        stack.append(r)
        while len(stack) >= 4:
            a, b, c, d = stack[-4:]
            inner = abs(c - b)
            if inner <= abs(b - a) and inner <= abs(d - c):
                ranges.append(inner)
                counts.append(1.0)
                del stack[-3:-1]
            else:
                break
    res = np.abs(np.diff(np.array(stack)))
    return np.concatenate((ranges, res)), np.concatenate((counts, 0.5 * np.ones(len(res))))


def miner_d_curve_cp(ranges_pa, counts):
    """DNV-RP-C203 (2016) Table 2-2, D: log N = 11.764 - 3 log S for N <= 1e6, else
    15.606 - 5 log S (S in MPa)."""
    s = np.asarray(ranges_pa) / 1e6
    pos = s > 0
    s, c = s[pos], np.asarray(counts)[pos]
    logs = np.log10(s)
    n1 = 10.0 ** (11.764 - 3.0 * logs)
    n = np.where(n1 <= 1e6, n1, 10.0 ** (15.606 - 5.0 * logs))
    return float(np.sum(c / n))


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {h: data[:, i] for i, h in enumerate(header)}


class FatigueRun(TempDirCase):
    def test_damage_equals_independent_rainflow(self):
        out = os.path.join(self.dir, "out")
        r = run("run", self.model(RISER), "-o", out)  # not -q: it silences the summary
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("fatigue: damage", r.stdout)
        self.assertIn("code check DNV-ST-F201: governing utilisation", r.stdout)
        stress = read_csv(os.path.join(out, "riser.fatigue_stress.csv"))
        fat = read_csv(os.path.join(out, "riser.fatigue.csv"))
        along = read_csv(os.path.join(out, "riser.along.csv"))
        points = 8
        stations = int(stress["station"].max()) + 1
        times = np.unique(stress["time"])
        self.assertGreater(len(times), 400)
        self.assertGreaterEqual(times[0], 10.0 - 1e-9)  # fatigue.start skips the build-up
        # thickness effect: wall 0.15 m, D curve k = 0.2, t_ref = 25 mm
        factor = (0.15 / 0.025) ** 0.2
        exposure = times[-1] - times[0]
        checked = 0
        for i in range(stations):
            rows = stress["station"] == i
            order = np.argsort(stress["time"][rows], kind="stable")
            worst = 0.0
            for j in range(points):
                x = stress["p%d" % j][rows][order]
                rng, cnt = rainflow_four_point(reversals(x))
                d = miner_d_curve_cp(factor * rng, cnt)
                got = fat["damage_p%d" % j][i]
                self.assertGreater(d, 0.0)
                self.assertLess(abs(got - d), 1e-9 * d, "station %d point %d: %g vs %g" % (i, j, got, d))
                worst = max(worst, d)
                checked += 1
            self.assertLess(abs(fat["damage"][i] - worst), 1e-9 * worst)
            per_year = worst * YEAR / exposure
            self.assertLess(abs(fat["damage_per_year"][i] - per_year), 1e-9 * per_year)
            self.assertLess(abs(fat["life_years"][i] - 1.0 / per_year), 1e-9 / per_year)
        self.assertEqual(checked, stations * points)
        # the stresses against the beam results of the same rows (SCF 1.2; A, I, r of the pipe)
        A = math.pi / 4 * (0.7**2 - 0.4**2)
        I = math.pi / 64 * (0.7**4 - 0.4**4)
        ro = 0.35
        t_along = along["time"]
        for k in (len(times) // 3, len(times) - 1):
            t = times[k]
            srows = np.nonzero(np.abs(stress["time"] - t) < 1e-9)[0]
            arows = np.nonzero(np.abs(t_along - t) < 1e-9)[0]
            self.assertEqual(len(srows), stations)
            self.assertEqual(len(arows), stations)
            for sr, ar in zip(srows, arows):
                p = np.array([stress["p%d" % j][sr] for j in range(points)])
                axial = 1.2 * along["tension_wall"][ar] / A
                self.assertLess(abs(p.mean() - axial), 1e-9 * max(abs(axial), 1.0) + 1e-6)
                amp = 1.2 * along["moment"][ar] * ro / I
                spread = p.max() - p.min()
                self.assertLessEqual(spread, 2 * amp * (1 + 1e-9) + 1e-6)
                self.assertGreaterEqual(spread, 2 * amp * math.cos(math.pi / 8) * (1 - 1e-9) - 1e-6)


CANTILEVER = """
title: pipe cantilever for code checks
environment: {{gravity: 0}}
bodies:
  pipe:
    type: ancf_beam
    start: [0, 0, 0]
    end: [10, 0, 0]
    elements: 8
    outer_diameter: 0.3
    inner_diameter: 0.25
    youngs_modulus: 207e9
    density: 7850
supports:
  - {{body: pipe, node: start, type: {support}}}
loads:
  - {{type: point_force, body: pipe, node: end, force: [{fx}, 0, {fz}]}}
statics:
  load_steps: 1
  tolerance: 1e-12
code_check:
  smys: 448e6
  smts: 531e6
  gamma_F: 1.2
  gamma_SC: 1.26
  design_factor: 1.2
"""


class CodeCheckCantilever(TempDirCase):
    D, Di, L = 0.3, 0.25, 10.0
    fy, fu = 448e6, 531e6
    g = 1.26 * 1.15  # gamma_SC gamma_m

    def capacities(self):
        t = (self.D - self.Di) / 2  # 0.025 m: D/t = 12 < 15, beta = 0.4 (no pressure)
        ac = 0.6 + 0.4 * self.fu / self.fy
        Mk = self.fy * ac * (self.D - t) ** 2 * t
        Tk = self.fy * ac * math.pi * (self.D - t) * t
        return Mk, Tk

    def root(self, fx, fz, support):
        out = os.path.join(self.dir, "out")
        path = self.model(CANTILEVER.format(fx=fx, fz=fz, support=support))
        r = run("statics", path, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("code check API RP 2RD: governing utilisation", r.stdout)
        cc = read_csv(os.path.join(out, "statics.pipe.code_check.csv"))
        self.assertEqual(cc["s"][0], 0.0)
        return cc["dnv_utilisation"][0], cc["api_utilisation"][0]

    def test_transverse_tip_load(self):
        # P = 10 N: tip slope P L^2 / (2 E I) ~ 3e-6, so the root moment is P L to ~1e-11
        P = 10.0
        dnv, api = self.root(0, -P, "clamped")
        Mk, _ = self.capacities()
        M = P * self.L
        I = math.pi / 64 * (self.D**4 - self.Di**4)
        self.assertLess(abs(dnv - self.g * 1.2 * M / Mk), 1e-6 * dnv)
        sigma = M * (self.D / 2) / I
        self.assertLess(abs(api - sigma / (1.2 * 2 / 3 * self.fy)), 1e-6 * api)

    def test_axial_tip_load(self):
        # pinned: a clamped end also fixes the length of the slope r' at the root node,
        # where the strain (and so the tension) of an ANCF beam is then held at zero
        F = 2.0e6
        dnv, api = self.root(F, 0, "pinned")
        _, Tk = self.capacities()
        self.assertLess(abs(dnv - self.g * (1.2 * F / Tk) ** 2), 1e-6 * dnv)
        A = math.pi / 4 * (self.D**2 - self.Di**2)
        self.assertLess(abs(api - F / A / (1.2 * 2 / 3 * self.fy)), 1e-6 * api)


SCATTER = """
normalise: {normalise}
cases:
  - {{name: a, result: A, probability: {pa}, hs: 6.0, tp: 9.0, heading: 0}}
  - {{name: b, model: riser_b.yaml, probability: 0.75, hs: 3.0, tp: 9.0, heading: 0}}
"""


class ScatterDiagram(TempDirCase):
    """seaflex fatigue: the damage per year of every point is sum_i p_i D_i / T_i * 1 year
    (here recomputed from the cases' riser.fatigue.csv), the life its inverse."""

    def setUp(self):
        super().setUp()
        short = RISER.replace("duration: 60", "duration: 30").replace("  write_stresses: true\n", "")
        self.model(short, "riser_a.yaml")
        self.model(short.replace("height: 6.0", "height: 3.0"), "riser_b.yaml")
        r = run("run", os.path.join(self.dir, "riser_a.yaml"), "-o", os.path.join(self.dir, "A"), "-q")
        self.assertEqual(r.returncode, 0, r.stderr)

    def expected(self, folders, probabilities):
        total = 0.0
        for folder, p in zip(folders, probabilities):
            f = read_csv(os.path.join(folder, "riser.fatigue.csv"))
            d = np.stack([f["damage_p%d" % j] for j in range(8)], axis=1)
            total = total + p * d * YEAR / f["exposure_s"][:, None]
        return total

    def test_combined_damage(self):
        path = self.model(SCATTER.format(normalise="false", pa=0.25), "scatter.yaml")
        out = os.path.join(self.dir, "total")
        r = run("fatigue", path, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("shortest life", r.stdout)
        tot = read_csv(os.path.join(out, "riser.fatigue_total.csv"))
        d = self.expected([os.path.join(self.dir, "A"), os.path.join(out, "b")], [0.25, 0.75])
        worst = d.max(axis=1)
        self.assertTrue(np.all(worst > 0))
        np.testing.assert_allclose(tot["damage_per_year"], worst, rtol=1e-12)
        np.testing.assert_allclose(tot["life_years"], 1 / worst, rtol=1e-12)
        np.testing.assert_array_equal(tot["worst_point"], d.argmax(axis=1))
        with open(os.path.join(out, "fatigue_cases.csv")) as f:
            cases = f.read().splitlines()
        self.assertEqual(cases[0], "name,hs,tp,heading,probability,folder")
        self.assertTrue(cases[1].startswith("a,6,9,0,0.25,"))

    def test_probabilities_must_sum_to_one(self):
        path = self.model(SCATTER.format(normalise="false", pa=0.2), "scatter.yaml")
        out = os.path.join(self.dir, "total")
        r = run("fatigue", path, "-o", out)
        self.assertEqual(r.returncode, 2)
        self.assertIn("scatter.yaml:4:3: cases: the probabilities sum to 0.95, not 1: correct them, "
                      "or give normalise: true to scale them to 1", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(out, "riser.fatigue_total.csv")))
        # normalise: true scales them by 1/0.95, with a warning
        path = self.model(SCATTER.format(normalise="true", pa=0.2), "scatter.yaml")
        r = run("fatigue", path, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("the probabilities sum to 0.95; normalised to 1", r.stderr)
        tot = read_csv(os.path.join(out, "riser.fatigue_total.csv"))
        d = self.expected([os.path.join(self.dir, "A"), os.path.join(out, "b")],
                          [0.2 / 0.95, 0.75 / 0.95])
        np.testing.assert_allclose(tot["damage_per_year"], d.max(axis=1), rtol=1e-12)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
