"""Issue 22, "wrong physics with exit 0": a 1 t weight released from rest at z = -5 m
falls 5 m onto a slack, tension-only line (1e8 N/m, free length 10 m, anchored at z = 0).
Before, adaptive generalized-alpha from h = 0.1 s took one step through the impact, exited 0
and rebounded to z = +10 m with a peak tension of 0.4-772 MN; fixed 0.1 s steps wrote rows
with the weight at +10 m before failing. By energy (closed form): peak stretch d from
k d^2 / 2 = m g (5 + d), d = 0.031419 m, peak tension k d = 3.1419 MN, and the rebound
to the release height z = -5 m.

Usage: test_snap_load.py SEAFLEX_EXECUTABLE SOURCE_DIR"""
import csv
import math
import os
import re
import sys
import unittest

from cli_support import TempDirCase, run

G, M, K = 9.81, 1000.0, 1.0e8
W = M * G
D = (W + math.sqrt(W * W + 2 * K * W * 5.0)) / K  # peak stretch, closed form
PEAK = K * D

MODEL = """
environment: {{gravity: 9.81}}
bodies:
  weight: {{type: rigid_body, mass: 1000, inertia: [100, 100, 100], position: [0, 0, -5]}}
connections:
  - {{name: line, type: spring, from: {{body: ground, position: [0, 0, 0]}},
     to: {{body: weight, position: [0, 0, 0]}}, free_length: 10, slack: true, stiffness: 1.0e8}}
dynamics: {{integrator: {integrator}, time_step: 0.1, duration: 3, output_interval: 0.1{extra}}}
"""


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [{k: float(v) for k, v in r.items()} for r in rows]


class SnapLoad(TempDirCase):
    def run_model(self, integrator, extra):
        path = self.model(MODEL.format(integrator=integrator, extra=extra))
        out = os.path.join(self.dir, "out_" + integrator)
        return run("run", path, "-o", out), read_rows(os.path.join(out, "timeseries.csv"))

    def test_adaptive_rebound_and_tension(self):
        self.assertAlmostEqual(PEAK, 3.1419e6, delta=1e2)
        for integrator in ("generalized_alpha", "hht", "rk4"):
            r, rows = self.run_model(integrator, ", step_control: adaptive")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertRegex(r.stdout, r"dynamics: \d+ steps \(\d+ rejected and retried")
            # the top of the rebound from any row in free flight after the impact (ballistic:
            # z + vz^2 / 2g is exact): the release height, within 1 % of the 5.03 m rise
            # (issue 22)
            lowest = min(range(len(rows)), key=lambda i: rows[i]["weight.z"])
            flight = [x for x in rows[lowest:] if x["weight.vz"] > 0 and x["weight.z"] > -10]
            self.assertGreater(len(flight), 3, integrator)
            for x in flight:
                apex = x["weight.z"] + x["weight.vz"] ** 2 / (2 * G)
                self.assertAlmostEqual(apex, -5.0, delta=0.01 * (5 + D), msg=integrator)
            self.assertLess(max(x["weight.z"] for x in rows), -4.9, integrator)
            # the output rows (every 0.1 s) never show more than the peak tension
            self.assertLessEqual(max(x["line.tension"] for x in rows), 1.02 * PEAK, integrator)

    def test_fixed_step_stops_at_the_impact(self):
        r, rows = self.run_model("generalized_alpha", "")
        self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
        self.assertIn("solver failure: t = 1.1 s: the step is far too long for the motion: its "
                      "estimated local error is 0.328 at weight.z = -10.0036 (more than 0.01 x "
                      "(1 + |q|)); an impact, a line going taut or slack, or a sudden load within "
                      "one step; try step_control: adaptive or a shorter time_step", r.stderr)
        # every row before the impact, and none after it: the free fall z = -5 - g t^2 / 2
        self.assertAlmostEqual(rows[-1]["time"], 1.0, places=9)
        for x in rows:
            self.assertAlmostEqual(x["weight.z"], -5 - G * x["time"] ** 2 / 2, delta=1e-9)

    def test_inaccurate_at_the_smallest_step_stops(self):
        # no halving allowed: the impact cannot be resolved, the step's error is above the
        # fixed-step limit (1 % of 1 + |q|), and the run says so
        r, rows = self.run_model("generalized_alpha",
                                 ", step_control: adaptive, min_time_step: 0.1")
        self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
        self.assertIn("solver failure: t = 1.1 s: the estimated local error of the step, 0.328 "
                      "at weight.z, exceeds error_tolerance x (1 + |q|) = 1.1e-05 (error_tolerance "
                      "1e-06): the motion changes too fast for the step (an impact, a line going "
                      "taut), and at the smallest step it exceeds 0.01 x (1 + |q|); lower "
                      "min_time_step (at the smallest time step, 0.1 s)", r.stderr)
        self.assertAlmostEqual(rows[-1]["time"], 1.0, places=9)
        self.assertLess(max(x["weight.z"] for x in rows), -4.99)

    def test_steps_above_the_tolerance_at_the_smallest_step_are_reported(self):
        # halving stops at min_time_step 0.0125 s: the impact's steps there keep an error
        # estimate above error_tolerance (but below the 1 % at which a step fails), so the run
        # completes and says how many and how large; the default floor (h / 1024) resolves
        # the impact and prints no warning
        r, _ = self.run_model("generalized_alpha", ", step_control: adaptive, min_time_step: 0.0125")
        self.assertEqual(r.returncode, 0, r.stderr)
        m = re.search(r"warning: (\d+) steps at the smallest time step \(0\.0125 s\) kept an "
                      r"estimated local error above error_tolerance \(up to ([0-9.e+]+) times it",
                      r.stdout)
        self.assertIsNotNone(m, r.stdout)
        self.assertGreater(int(m.group(1)), 0)
        # above the tolerance, below the failure limit 0.01 (1 + |q|) / (1e-6 (1 + |q|))
        self.assertGreater(float(m.group(2)), 1.0)
        self.assertLess(float(m.group(2)), 1e4)
        r, _ = self.run_model("generalized_alpha", ", step_control: adaptive")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("warning:", r.stdout)

    def test_error_tolerance_input(self):
        path = self.model(MODEL.format(integrator="generalized_alpha",
                                       extra=", error_tolerance: 1e-5"))
        r = run("check", path)
        self.assertEqual(r.returncode, 2)
        self.assertIn("dynamics.error_tolerance: applies only with step_control: adaptive",
                      r.stderr)
        path = self.model(MODEL.format(integrator="generalized_alpha",
                                       extra=", step_control: adaptive, error_tolerance: 0.5"))
        r = run("check", path)
        self.assertEqual(r.returncode, 2)
        self.assertRegex(r.stderr, r"model.yaml:\d+:\d+: dynamics.error_tolerance: ")
        path = self.model(MODEL.format(integrator="generalized_alpha",
                                       extra=", step_control: adaptive, error_tolerance: 1e-5"))
        r = run("check", path)
        self.assertEqual(r.returncode, 0, r.stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
