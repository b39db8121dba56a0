#!/usr/bin/env python3
"""The optional output channels (output: node_slopes, support_reactions, energies,
body_angular_velocity; io/optional_channels.hpp), each checked against a number that does not
come from seaflex: the weight of a hanging chain, the root moment of a cantilever, a
catenary's end forces, the kinetic energy of a rigid body in a known motion, the body-axis
angular velocity of a torque-free spin and R^T w of the world-axis channels.

usage: test_optional_channels.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import csv
import math
import os
import sys
import unittest

from cli_support import SRC, TempDirCase, run

G = 9.81


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def rotation(roll, pitch, yaw):
    """A = Rz(yaw) Ry(pitch) Rx(roll), angles in degrees (docs/model-format.md 5.2)."""
    r, p, y = (math.radians(a) for a in (roll, pitch, yaw))
    rx = [[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]]
    ry = [[math.cos(p), 0, math.sin(p)], [0, 1, 0], [-math.sin(p), 0, math.cos(p)]]
    rz = [[math.cos(y), -math.sin(y), 0], [math.sin(y), math.cos(y), 0], [0, 0, 1]]

    def mul(a, b):
        return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(rz, mul(ry, rx))


class OptionalChannels(TempDirCase):

    def statics_row(self, text):
        path = self.model(text)
        out = os.path.join(self.dir, "out")
        r = run("statics", path, "-o", out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        header, rows = read_csv(os.path.join(out, "statics.csv"))
        return dict(zip(header, rows[0]))

    def test_hanging_chain_reaction_is_its_weight(self):
        # a 50 m steel bar hanging from a pinned top: the support holds its weight
        # W = rho A L g = 7850 * 0.01 * 50 * 9.81 = 38504.25 N. The reaction comes from the
        # multipliers; statics balances the forces to its tolerance 1e-10 of the largest
        # force, so 1e-6 relative is a check with margin
        row = self.statics_row("""
environment: {gravity: 9.81}
bodies:
  chain: {type: ancf_beam, start: [0, 0, 0], end: [0, 0, -50], elements: 20, area: 0.01,
          second_moment: 1.0e-8, youngs_modulus: 2.0e11, density: 7850}
supports:
  - {body: chain, node: start, type: pinned}
statics: {tolerance: 1.0e-10}
output: {support_reactions: true, node_slopes: true, energies: true}
""")
        W = 7850 * 0.01 * 50 * G
        self.assertAlmostEqual(row["chain.n0.reaction.fz"] / W, 1.0, delta=1e-6)
        self.assertAlmostEqual(row["chain.n0.reaction.fx"] / W, 0.0, delta=1e-9)
        self.assertAlmostEqual(row["chain.n0.reaction.fy"] / W, 0.0, delta=1e-9)
        self.assertNotIn("chain.n0.reaction.mx", row)  # pinned: no moment
        # slopes: the hanging bar points down, r' = (0, 0, -(1 + eps)) with the axial
        # strain at the top eps = W / EA = 1.9e-5 (Green-Lagrange: |r'| = sqrt(1 + 2 eps))
        EA = 2.0e11 * 0.01
        self.assertAlmostEqual(row["chain.n0.slope_z"], -math.sqrt(1 + 2 * W / EA), delta=2e-7)
        self.assertAlmostEqual(row["chain.n20.slope_z"], -1.0, delta=1e-9)  # no tension at the foot
        self.assertAlmostEqual(row["chain.n10.slope_x"], 0.0, delta=1e-12)
        # energies in equilibrium: no motion; gravity -m g L/2 (the centre of mass at -L/2,
        # lowered by the stretch, a relative 1e-5); strain energy of a bar under its own
        # weight, U = w^2 L^3 / (6 EA), to 1e-3 (Green-Lagrange versus linear strain, and
        # the cubic elements' axial field: a relative 1e-4 here)
        self.assertEqual(row["chain.energy.kinetic"], 0.0)
        self.assertAlmostEqual(row["chain.energy.gravity"] / (-W * 25.0), 1.0, delta=1e-4)
        w = 7850 * 0.01 * G
        self.assertAlmostEqual(row["chain.energy.strain"] / (w * w * 50 ** 3 / (6 * EA)), 1.0,
                               delta=1e-3)

    def test_catenary_fairlead_tension(self):
        # a 100 m steel line pinned at both ends, 80 m apart at the same height: the elastic
        # catenary (Irvine, Cable Structures, 1981, eq. 2.21 with the ends level) gives the
        # horizontal tension H from  S = H L / EA + (2 H / w) asinh(w L / (2 H)),  solved here
        # by bisection, and each end carries half the weight, V = w L / 2 (symmetry). The
        # pinned end's reaction is the line's tension at the fairlead, sqrt(H^2 + V^2).
        # The line starts on a 16-segment polyline near a catenary (L = its length, 99.94 m;
        # from a straight or V shape statics would start at a buckling problem).
        # H = 26078 N, V = 38482 N. Tolerances: V to 1e-6 (equilibrium, as for the hanging
        # chain); H to 2e-4, three times the share of the bending stiffness that the
        # catenary leaves out, EI / (H a^2) = 2e3 / (26078 x 33.8^2) = 6.7e-5 with the
        # catenary parameter a = H / w = 33.8 m
        E, A, rho, S = 2.0e11, 0.01, 7850.0, 80.0
        w, EA = rho * A * G, E * A
        a = 33.8
        raw = [a * math.asinh((-50 + 100 * k / 16) / a) for k in range(17)]
        pts = [[round(80 * (x - raw[0]) / (raw[-1] - raw[0]), 6), 0,
                round(a * math.cosh(x / a) - a * math.cosh(raw[0] / a), 6)] for x in raw]
        pts[0], pts[-1] = [0, 0, 0], [80, 0, 0]
        L = sum(math.dist(pts[i], pts[i + 1]) for i in range(16))

        def span(H):
            return H * L / EA + 2 * H / w * math.asinh(w * L / (2 * H))
        lo, hi = 1.0, 1e7
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if span(mid) < S else (lo, mid)
        H, V = 0.5 * (lo + hi), w * L / 2
        row = self.statics_row("""
environment: {gravity: 9.81}
bodies:
  line: {type: ancf_beam, polyline: %s, elements: 5,
         area: 0.01, second_moment: 1.0e-8, youngs_modulus: 2.0e11, density: 7850}
supports:
  - {body: line, node: start, type: pinned}
  - {body: line, node: end, type: pinned}
statics: {tolerance: 1.0e-10}
output: {support_reactions: true}
""" % pts)
        self.assertAlmostEqual(row["line.n0.reaction.fz"] / V, 1.0, delta=1e-6)
        self.assertAlmostEqual(row["line.n80.reaction.fz"] / V, 1.0, delta=1e-6)
        self.assertAlmostEqual(-row["line.n0.reaction.fx"] / H, 1.0, delta=2e-4)
        self.assertAlmostEqual(row["line.n80.reaction.fx"] / H, 1.0, delta=2e-4)
        T = math.hypot(row["line.n0.reaction.fx"], row["line.n0.reaction.fz"])
        self.assertAlmostEqual(T / math.hypot(H, V), 1.0, delta=2e-4)

    def test_plate_support_reactions_carry_its_weight(self):
        # the simply supported plate example (10 m x 10 m x 0.1 m steel, 8 x 8 elements): the
        # vertical reactions of the edge nodes add up to the weight rho t a b g = 779895 N;
        # tolerance 1e-6 as for the chain (statics balances forces to its tolerance)
        with open(os.path.join(SRC, "examples", "plate_simply_supported.yaml")) as f:
            text = f.read()
        self.assertNotIn("\noutput:", text)
        row = self.statics_row(text + "\noutput: {support_reactions: true}\n")
        fz = [v for name, v in row.items() if name.endswith(".reaction.fz")]
        self.assertEqual(len(fz), 32)  # the 32 edge nodes of an 8 x 8 mesh
        self.assertAlmostEqual(sum(fz) / (7950 * 0.1 * 100 * G), 1.0, delta=1e-6)
        # held slopes along the edges are generalized forces, named by the slope held
        self.assertIn("plate.n0_1.reaction.r_p2.z", row)

    def test_clamped_root_force_and_moment(self):
        # a very stiff 10 m cantilever along x under its own weight (tip deflection 1e-6 m):
        # the clamp carries the weight W = rho A L g and the root moment W L / 2 about -y
        # (the load's moment about the root is +W L/2 about y: r x F = (x, 0, 0) x (0, 0, -w x)).
        # Linear theory is exact to the rotation of the axis, 1e-7 here: tolerance 1e-6
        row = self.statics_row("""
environment: {gravity: 9.81}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 10, area: 0.01,
         second_moment: 8.33e-6, youngs_modulus: 2.1e16, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
statics: {tolerance: 1.0e-12}
output: {support_reactions: true, channels: ["beam.n0.reaction.*"]}
""")
        W = 7850 * 0.01 * 10 * G
        self.assertEqual(sorted(row), sorted(["time"] + ["beam.n0.reaction." + c for c in
                                                         ("fx", "fy", "fz", "mx", "my", "mz")]))
        self.assertAlmostEqual(row["beam.n0.reaction.fz"] / W, 1.0, delta=1e-6)
        self.assertAlmostEqual(row["beam.n0.reaction.my"] / (-W * 5.0), 1.0, delta=1e-6)
        self.assertAlmostEqual(row["beam.n0.reaction.mx"] / W, 0.0, delta=1e-9)
        self.assertAlmostEqual(row["beam.n0.reaction.mz"] / W, 0.0, delta=1e-9)

    def test_rigid_body_energy_and_body_axis_rates(self):
        # a body thrown with velocity v0 and spinning about its principal axis z (inertia
        # 3 kg m^2) at 90 deg/s, tilted (roll 30, pitch 20, yaw 10): torque-free, so the
        # body-axis rate stays (0, 0, 90) deg/s; in free fall the kinetic energy is
        # 1/2 m |v0 + g t|^2 + 1/2 I3 w^2 and the gravity potential m g z(t). RK4 integrates
        # the translation exactly (a quadratic in t) and the spin to round-off at h = 1e-3
        # (the attitude error is of order (w h)^5 per step): tolerances 1e-9 relative
        m, I3, w = 20.0, 3.0, math.radians(90.0)
        A = rotation(30, 20, 10)
        w_world = [A[i][2] * 90.0 for i in range(3)]  # deg/s: the body z axis in the world
        path = self.model("""
environment: {gravity: 9.81}
bodies:
  box:
    type: rigid_body
    mass: 20
    inertia: [1, 2, 3]
    position: [0, 0, 10]
    orientation: [30, 20, 10]
    velocity: [1, 2, 3]
    angular_velocity: [%.17g, %.17g, %.17g]
dynamics: {time_step: 1.0e-3, duration: 2, output_interval: 0.1}
output: {energies: true, body_angular_velocity: true}
""" % tuple(w_world))
        out = os.path.join(self.dir, "out")
        r = run("run", path, "-o", out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        header, rows = read_csv(os.path.join(out, "timeseries.csv"))
        col = {name: k for k, name in enumerate(header)}
        self.assertEqual(header[-6:], ["box.energy.kinetic", "box.energy.gravity",
                                       "box.energy.strain", "box.body.wx", "box.body.wy",
                                       "box.body.wz"])
        for row in rows:
            t = row[0]
            vz = 3.0 - G * t
            T = 0.5 * m * (1 + 4 + vz * vz) + 0.5 * I3 * w * w
            z = 10 + 3 * t - 0.5 * G * t * t
            self.assertAlmostEqual(row[col["box.energy.kinetic"]] / T, 1.0, delta=1e-9)
            self.assertAlmostEqual(row[col["box.energy.gravity"]] / (m * G * z), 1.0, delta=1e-9)
            self.assertEqual(row[col["box.energy.strain"]], 0.0)
            self.assertAlmostEqual(row[col["box.body.wz"]], 90.0, delta=1e-9)
            self.assertAlmostEqual(row[col["box.body.wx"]], 0.0, delta=1e-9)
            self.assertAlmostEqual(row[col["box.body.wy"]], 0.0, delta=1e-9)
            # R^T w from the world-axis channels and the attitude channels
            R = rotation(row[col["box.roll"]], row[col["box.pitch"]], row[col["box.yaw"]])
            ww = [row[col["box.w" + c]] for c in "xyz"]
            for i, c in enumerate("xyz"):
                expected = sum(R[k][i] * ww[k] for k in range(3))
                self.assertAlmostEqual(row[col["box.body.w" + c]], expected, delta=1e-9)

    def test_channels_are_optional_and_checked(self):
        text = """
bodies:
  chain: {type: ancf_beam, start: [0, 0, 0], end: [0, 0, -5], elements: 2, area: 0.01,
          second_moment: 1.0e-8, youngs_modulus: 2.0e11, density: 7850}
supports:
  - {body: chain, node: start, type: pinned}
"""
        # none by default: the columns of existing files keep their places
        r = run("check", self.model(text))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("output channels: 9\n", r.stdout)
        r = run("check", self.model(text + "output: {node_slopes: true, support_reactions: true, "
                                           "energies: true}\n"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("output channels: 24\n", r.stdout)  # 9 + 9 slopes + 3 reactions + 3 energies
        r = run("check", self.model(text + "output: {energies: yes}\n"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("model.yaml:7:20: output.energies: unknown value 'yes'; expected one of: "
                      "true, false", r.stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
