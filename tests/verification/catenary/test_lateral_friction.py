#!/usr/bin/python3
"""A line laid straight on a flat seabed, pulled sideways (issue 18): seaflex run against
Coulomb friction regularized as documented (docs model-format.md 4.5, MoorDyn's law):
f = -F M v / sqrt(|v_t|^2 + v_s^2), F the normal force, M = mu_a a a^T + mu_l b b^T.

The line: 100 m of the 0.1 m wire-like line of test_laid_catenary.py (A = 7.854e-3 m^2,
7850 kg/m^3: m = 61.65 kg/m; buoyancy of its 0.1 m diameter: w = 525.67 N/m; no drag, no
added mass), 20 elements, free (no supports), along x on a flat seabed at 150 m,
k_a = 1e7 N/m/m^2 (k = 1e6 N/m^2 over the 0.1 m width), friction axial 0.3, lateral 0.6,
slip velocity v_s = 0.01 m/s. It starts at rest at its sinkage w/k below the seabed (in
equilibrium), and a uniform distributed load q (N/m) acts from t = 0, across the line (y) or
along it (x). generalized-alpha, 0.01 s steps.

* Above the limit, q = 2 mu w: the line slides; the friction channel is
  mu w L v/sqrt(v^2 + v_s^2) = mu w L (1 - v_s^2/(2 v^2) + ...), so with the velocity v
  measured at the end of the run (10.3 m/s lateral, 5.1 m/s axial) it is mu w L within
  v_s^2/(2 v^2) (5e-7, 1.9e-6) plus 1e-6 (asserted: that sum), and it is the regularized
  law's value at v within 1e-7 (v from the positions: second-order differences of a
  uniformly accelerated motion, exact to round-off); the acceleration is (q - mu w)/m
  (second differences of the position over the last second: 1e-4). The normal force is
  w L (1e-6).
* Below it, q = r mu_l w with r = 0.5: the law cannot stick, the line creeps at the
  velocity where the friction balances the load, v = v_s r/sqrt(1 - r^2) = 5.774 mm/s
  (from rest it gets there within milliseconds: the damper mu w / v_s against m gives a
  time constant of 2 ms). The creep over the last second, from the positions, is asserted
  within 1e-4 (measured 4e-13), the friction channel equal to q L within 1e-6.

    test_lateral_friction.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from catenary_support import G, RHO_W, SeaflexCase, read_rows  # noqa: E402

DEPTH, LENGTH, ELEMENTS = 150.0, 100.0, 20
DIAMETER = 0.1
AREA = math.pi * DIAMETER ** 2 / 4
RHO = 7850.0
MASS = RHO * AREA                      # kg/m
W = (RHO - RHO_W) * AREA * G           # N/m
K = 1.0e7 * DIAMETER
MU_AXIAL, MU_LATERAL, V_SLIP = 0.3, 0.6, 0.01
DT, DURATION = 0.01, 2.0


def model(load):
    z = -DEPTH - W / K
    return """title: laid line pulled sideways (tests/verification/catenary)
environment:
  water: {density: %g, depth: %g}
  seabed: {normal_stiffness: 1.0e7, friction: {axial: %g, lateral: %g}, slip_velocity: %g}
bodies:
  line:
    type: ancf_beam
    start: [0, 0, %.17g]
    end: [%g, 0, %.17g]
    elements: %d
    area: %.17g
    second_moment: 1.0e-8
    youngs_modulus: 1.0e11
    density: %g
hydrodynamics:
  line: {diameter: %g}
loads:
  - {type: distributed_load, body: line, load: [%.17g, %.17g, 0]}
dynamics:
  integrator: generalized_alpha
  time_step: %g
  duration: %g
  output_interval: 0.5
""" % (RHO_W, DEPTH, MU_AXIAL, MU_LATERAL, V_SLIP, z, LENGTH, z, ELEMENTS, AREA, RHO,
       DIAMETER, load[0], load[1], DT, DURATION)


class LateralFriction(SeaflexCase):
    def run_model(self, load, name):
        p, out = self.seaflex("run", model(load), name)
        self.assertEqual(p.returncode, 0, p.stdout[-400:] + p.stderr[-400:])
        rows = read_rows(os.path.join(out, "timeseries.csv"))
        self.assertAlmostEqual(rows[-1]["time"], DURATION, delta=1e-9)
        return rows

    def mean(self, row, axis):
        return sum(row["line.n%d.%s" % (i, axis)] for i in range(ELEMENTS + 1)) / (ELEMENTS + 1)

    def slide(self, mu, axis):
        q = 2 * mu * W
        rows = self.run_model([q, 0] if axis == "x" else [0, q], "slide_" + axis)
        t0, t1, t2 = rows[-3], rows[-2], rows[-1]          # t = 1, 1.5, 2 s
        h = t2["time"] - t1["time"]
        p0, p1, p2 = (self.mean(r, axis) for r in (t0, t1, t2))
        a = (p2 - 2 * p1 + p0) / (h * h)
        v = (p2 - p1) / h + a * h / 2                        # at t = 2 s
        friction = t2["line.seabed.friction"]
        limit = mu * W * LENGTH
        tol = V_SLIP ** 2 / (2 * v * v) + 1e-6
        a_ref = (q - mu * W) / MASS
        print("\nsliding along %s: v = %.4g m/s, friction %.8g N vs mu w L = %.8g N (%+.2e, "
              "tolerance %.1e); acceleration %.6g vs %.6g m/s^2 (%+.2e); normal force %.8g vs "
              "w L %.8g N" % (axis, v, friction, limit, friction / limit - 1, tol, a, a_ref,
                              a / a_ref - 1, t2["line.seabed.force"], W * LENGTH))
        self.assertLess(abs(friction / limit - 1), tol)
        regularized = limit * v / math.sqrt(v * v + V_SLIP ** 2)
        self.assertLess(abs(friction / regularized - 1), 1e-7)
        self.assertLess(abs(a / a_ref - 1), 1e-4)
        self.assertLess(abs(t2["line.seabed.force"] / (W * LENGTH) - 1), 1e-6)
        self.assertAlmostEqual(t2["line.seabed.laid_length"], LENGTH, delta=1e-9 * LENGTH)

    def test_slides_sideways_above_the_limit(self):
        self.slide(MU_LATERAL, "y")

    def test_slides_along_above_the_limit(self):
        self.slide(MU_AXIAL, "x")

    def test_creeps_below_the_limit(self):
        r = 0.5
        q = r * MU_LATERAL * W
        rows = self.run_model([0, q], "creep")
        t1, t2 = rows[-3], rows[-1]                          # t = 1 and 2 s
        v = (self.mean(t2, "y") - self.mean(t1, "y")) / (t2["time"] - t1["time"])
        v_ref = V_SLIP * r / math.sqrt(1 - r * r)
        friction = t2["line.seabed.friction"]
        print("\ncreep at r = %g: %.6g mm/s vs v_s r/sqrt(1 - r^2) = %.6g mm/s (%+.2e); "
              "friction %.8g N vs the load %.8g N (%+.2e); x drift %.2e m"
              % (r, 1e3 * v, 1e3 * v_ref, v / v_ref - 1, friction, q * LENGTH,
                 friction / (q * LENGTH) - 1, self.mean(t2, "x") - LENGTH / 2))
        self.assertLess(abs(v / v_ref - 1), 1e-4)
        self.assertLess(abs(friction / (q * LENGTH) - 1), 1e-6)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
