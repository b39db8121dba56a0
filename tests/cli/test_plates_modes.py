#!/usr/bin/env python3
"""Plate section results and mode shapes (issue 19): <plate>.nodes.csv and the plate's VTK
point data of the simply supported plate example; DIR/mode_shapes.csv of a cantilever
against the Euler-Bernoulli mode shapes, the dominant coordinate of each mode in modes.csv,
and the ParaView animation per mode.

usage: test_plates_modes.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import csv
import math
import os
import re
import sys
import unittest

import numpy as np

from cli_support import SRC, TempDirCase, run

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


def navier_moment(q, a, nu, x, y, terms=401):
    """Navier's M_x of a simply supported square plate (Timoshenko & Woinowsky-Krieger
    (1959) eq. (133)), vectorised over the odd m, n."""
    m = np.arange(1, terms + 1, 2)[:, None] * 1.0
    n = np.arange(1, terms + 1, 2)[None, :] * 1.0
    k = (m ** 2 + n ** 2) / a ** 2
    terms_ = (m ** 2 / a ** 2 + nu * n ** 2 / a ** 2) / (m * n * k ** 2)
    return 16 * q / np.pi ** 4 * (terms_ * np.sin(m * np.pi * x / a) * np.sin(n * np.pi * y / a)).sum()


class PlateResults(TempDirCase):
    def test_plate_nodes_csv_and_vtk(self):
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        out = os.path.join(self.dir, "out")
        model = os.path.join(SRC, "examples", "plate_simply_supported.yaml")
        r = run("statics", model, "-o", out, "--vtk")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "statics.plate.nodes.csv"), newline="") as f:
            header, *rows = list(csv.reader(f))
        self.assertEqual(header[:7], ["time", "node", "i", "j", "x", "y", "z"])
        data = np.array(rows, dtype=float)
        self.assertEqual(len(data), 81)
        col = {h: k for k, h in enumerate(header)}
        h, nu, q = 0.1, 0.3, 7950 * 0.1 * 9.81
        centre = data[(data[:, 2] == 4) & (data[:, 3] == 4)][0]
        m11, m22 = centre[col["moment_11"]], centre[col["moment_22"]]
        # symmetry of the square plate; the twisting moment vanishes at the centre
        self.assertAlmostEqual(m11, m22, delta=1e-6 * m11)
        self.assertLess(abs(centre[col["moment_12"]]), 1e-6 * m11)
        # Navier (linear; at self-weight w/h = 0.16 with edges free in the plane the plate
        # is within 1 % of linear, test_plate.cpp): 8 x 8 elements within 3 %
        ref = navier_moment(q, 10.0, nu, 5.0, 5.0)
        self.assertAlmostEqual(m11, ref, delta=0.03 * ref)
        # the surface stresses are the membrane force and moment through the thickness
        for row in data:
            for side, sign in (("top", -1), ("bottom", 1)):
                s = {c: row[col["membrane_%s" % c]] / h + sign * 6 * row[col["moment_%s" % c]] / h ** 2
                     for c in ("11", "22", "12")}
                for c in ("11", "22", "12"):
                    self.assertAlmostEqual(row[col["stress_%s_%s" % (c, side)]], s[c],
                                           delta=1e-9 * max(1.0, abs(s[c])))
                vm = math.sqrt(s["11"] ** 2 - s["11"] * s["22"] + s["22"] ** 2 + 3 * s["12"] ** 2)
                self.assertAlmostEqual(row[col["stress_von_mises_%s" % side]], vm,
                                       delta=1e-9 * max(1.0, vm))
        # the same values as point data of the plate in the ParaView files
        vtp = [os.path.join(dp, f) for dp, _, fs in os.walk(os.path.join(out, "vtk"))
               for f in fs if f.startswith("plate")]
        self.assertEqual(len(vtp), 1, vtp)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(vtp[0])
        reader.Update()
        pd = reader.GetOutput().GetPointData()
        for name in ("moment_11", "membrane_22", "stress_von_mises_bottom"):
            np.testing.assert_allclose(vtk_to_numpy(pd.GetArray(name)), data[:, col[name]],
                                       rtol=1e-6, atol=1e-6 * np.abs(data[:, col[name]]).max())


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
        # the first axial mode, c / 4L = sqrt(E / rho) / 40 = 129.3 Hz: its dominant
        # coordinate is an axial position. The frequency is 1.2 % high (tolerance 2 %): the
        # clamp holds the whole slope r' = (1, 0, 0) at the root, so also the axial strain
        # there, where the exact mode has its largest strain
        freqs = np.array([float(row[1]) for row in modes])
        c = math.sqrt(210e9 / 7850)
        k = int(np.argmin(abs(freqs - c / (4 * L))))
        self.assertLess(abs(freqs[k] / (c / (4 * L)) - 1), 0.02)
        self.assertRegex(modes[k][4], r"^beam\.n\d+\.r\.x$")
        # the animation of each mode: a collection and 25 frames (one period)
        for mode in (1, 20):
            pvd = os.path.join(out, "mode%d.pvd" % mode)
            self.assertTrue(os.path.isfile(pvd), pvd)
            with open(pvd) as f:
                self.assertEqual(f.read().count("<DataSet"), 25)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
