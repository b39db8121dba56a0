#!/usr/bin/env python3
"""Mode shapes of `seaflex modes` (issue 19): DIR/mode_shapes.csv of a cantilever against
the Euler-Bernoulli mode shapes, the dominant coordinate of each mode in modes.csv, and the
ParaView animation per mode.

usage: test_mode_shapes.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import csv
import math
import os
import re
import sys
import unittest

import numpy as np

from cli_support import TempDirCase, run

# a 10 m steel cantilever along x without gravity (the model of test_cli.py's test_modes)
CANTILEVER = """
environment: {gravity: 0}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 10, area: 0.01,
         second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
"""
L = 10.0


def euler_bernoulli(beta_l, x):
    """Clamped-free mode shape (Blevins, Formulas for Natural Frequency and Mode Shape
    (1979), table 8-1): cosh bx - cos bx - s (sinh bx - sin bx)."""
    b = beta_l / L
    s = (math.cosh(beta_l) + math.cos(beta_l)) / (math.sinh(beta_l) + math.sin(beta_l))
    return np.cosh(b * x) - np.cos(b * x) - s * (np.sinh(b * x) - np.sin(b * x))


class ModeShapes(TempDirCase):
    def test_cantilever_mode_shapes_and_dominant_coordinates(self):
        out = os.path.join(self.dir, "out")
        r = run("modes", self.model(CANTILEVER), "-o", out, "-n", "20", "--vtk")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "mode_shapes.csv"), newline="") as f:
            header, *rows = list(csv.reader(f))
        self.assertEqual(header, ["coordinate"] + ["mode%d" % k for k in range(1, 21)])
        shapes = {row[0]: np.array([float(v) for v in row[1:]]) for row in rows}
        x = np.arange(11) * 1.0
        # bending pairs (y and z share a frequency: any combination of the two comes out):
        # the lateral displacement of the nodes is c_y phi(x) in y and c_z phi(x) in z;
        # project on the pair's direction and compare the tip-normalised shape.
        # Tolerance 1e-3 of the tip value: 10 cubic Hermite elements reproduce the first
        # two bending shapes to ~1e-5 and ~1e-4 (errors of order (h beta)^4).
        for mode, beta_l in ((1, 1.8751040687), (2, 1.8751040687), (3, 4.6940911330),
                             (4, 4.6940911330)):
            y = np.array([shapes["beam.n%d.r.y" % k][mode - 1] for k in range(11)])
            z = np.array([shapes["beam.n%d.r.z" % k][mode - 1] for k in range(11)])
            phi = euler_bernoulli(beta_l, x)
            d = np.array([y @ phi, z @ phi])
            d /= np.linalg.norm(d)
            u, v = d[0] * y + d[1] * z, -d[1] * y + d[0] * z
            self.assertLess(np.abs(v).max(), 1e-6 * np.abs(u).max(), "mode %d" % mode)
            np.testing.assert_allclose(u / u[-1], phi / phi[-1], atol=1e-3,
                                       err_msg="mode %d" % mode)
            axial = np.array([shapes["beam.n%d.r.x" % k][mode - 1] for k in range(11)])
            self.assertLess(np.abs(axial).max(), 1e-6 * np.abs(u).max())

        with open(os.path.join(out, "modes.csv"), newline="") as f:
            mh, *modes = list(csv.reader(f))
        self.assertEqual(mh[4:], ["dominant_coordinate", "energy_share"])
        # bending modes: a lateral position near the tip holds the largest kinetic energy
        for row in modes[:2]:
            m = re.fullmatch(r"beam\.n(\d+)\.r\.([yz])", row[4])
            self.assertIsNotNone(m, row[4])
            self.assertGreaterEqual(int(m.group(1)), 7, row[4])
            self.assertTrue(0.0 < float(row[5]) < 1.0)
        # the first axial mode, c / 4L = sqrt(E / rho) / 40 = 129.3 Hz (the 10-element
        # mesh is within 0.5 %): its dominant coordinate is an axial position
        freqs = np.array([float(row[1]) for row in modes])
        c = math.sqrt(210e9 / 7850)
        k = int(np.argmin(abs(freqs - c / (4 * L))))
        self.assertLess(abs(freqs[k] / (c / (4 * L)) - 1), 0.005)
        self.assertRegex(modes[k][4], r"^beam\.n\d+\.r\.x$")
        # the animation of each mode: a collection and 25 frames (one period)
        for mode in (1, 20):
            pvd = os.path.join(out, "mode%d.pvd" % mode)
            self.assertTrue(os.path.isfile(pvd), pvd)
            with open(pvd) as f:
                self.assertEqual(f.read().count("<DataSet"), 25)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
