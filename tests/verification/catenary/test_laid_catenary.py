#!/usr/bin/python3
"""Static catenary with a laid length (issue 18): seaflex statics of a mooring line from an
anchor pinned on a flat seabed to a pinned fairlead, against the analytic elastic catenary
of elastic_catenary.py (Jonkman 2007, cross-checked by shooting).

The line: a 0.1 m wire-like line, A = pi 0.1^2/4, E = 1e11 Pa (EA = 7.854e8 N), density
7850 kg/m^3, buoyancy of a 0.1 m diameter in 1025 kg/m^3 water: submerged weight w =
525.67 N/m; bending stiffness EI = 1e3 N m^2 (second_moment 1e-8 m^4: a wire rope has almost
none; the catenary has none). Water depth 150 m, fairlead 10 m below the surface (h = 140 m
above the seabed), horizontal span X = 440 m, unstretched length L of about 500 m: the
analytic solution has H = 67.6 kN, V = 124.0 kN and a laid length of 264.2 m (236 m
suspended). Seabed: flat, k_a = 1e7 N/m/m^2, i.e. k = 1e6 N/m per metre of line over the
0.1 m contact width: sinkage w/k = 0.53 mm.

First guess. The beam's unstretched length is the length of its polyline (docs
model-format.md 5.1). The polyline's points are those of the inextensible catenary of the
same span and height (EA -> infinity), one element per segment; the unstretched length L is
the polyline's length (the chords are 6 mm shorter than the curve's 500 m for 200
elements), and the analytic solution is computed for that L. From the documented first guess
of a slack line, a polyline along the seabed and straight up to the fairlead, this line does
not converge (test_documented_first_guess: expected failure, issue 18 item 3).

What the analytic catenary leaves out, and the tolerances:
* a rigid seabed: seaflex's line sinks w/k and its contact ends beyond the rigid catenary's
  touchdown point. elastic_catenary.touchdown_boundary_layer gives both (a tensioned beam on
  an elastic foundation): the contact extends 0.24 m beyond the touchdown point of the
  catenary on a seabed 0.2 mm lower. The reference laid length is that catenary's plus the
  0.24 m (0.09 % of the laid length: inside the 0.2 % either way);
* bending stiffness: its boundary layer sqrt(EI/H) = 0.12 m is in the above; its effect on
  the tensions, of order EI/(H l^2) over the suspended length l, is 3e-7;
* the strain law: seaflex's Green-Lagrange law against Hooke's changes H by 4e-7
  (elastic_catenary's test);
* the discretization: 2.5 m cubic elements resolve the catenary; the laid length is
  resolved only as well as the elements resolve the 0.2 m boundary layer at the touchdown
  point (-0.005 % at 1.25 m elements, -0.04 % at 2.5 m, -0.21 % at 5 m, -0.69 % at 10 m:
  below).
The tolerance is the issue's 0.2 %, on the fairlead tension, the anchor tension and the
laid length; the measured errors are printed.

    test_laid_catenary.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import elastic_catenary as ec  # noqa: E402
from catenary_support import (G, RHO_W, SeaflexCase, newton_iterations, polyline_length,  # noqa: E402
                              read_rows, yaml_points)

DEPTH, Z_FAIRLEAD, SPAN, LENGTH = 150.0, -10.0, 440.0, 500.0
HEIGHT = DEPTH + Z_FAIRLEAD
DIAMETER = 0.1
AREA = math.pi * DIAMETER ** 2 / 4
E, I, RHO = 1.0e11, 1.0e-8, 7850.0
EA, EI = E * AREA, E * I
W = (RHO - RHO_W) * AREA * G
K_AREA = 1.0e7
K = K_AREA * DIAMETER             # per metre of line: the contact width is the diameter
TOLERANCE = 2e-3                  # the issue's 0.2 %


def catenary_polyline(elements):
    """Points of the inextensible catenary (same span, height and nominal length), in the
    model's axes. The anchor, and the points on the seabed, are placed at the laid line's
    sinkage w/k below the seabed (0.53 mm): an anchor held on the seabed's surface would lift
    the line's end out of its sinkage, a bend of the line that the catenary has not."""
    c = ec.solve(SPAN, HEIGHT, LENGTH, W, 1e15)
    pts = [c.position(LENGTH * i / elements) for i in range(elements + 1)]
    pts[-1] = (SPAN, HEIGHT)
    return [(x, 0.0, z - DEPTH - (W / K if z == 0.0 else 0.0)) for x, z in pts]


def two_segment_polyline():
    """The documented first guess of a slack line: along the seabed, then straight up to the
    fairlead, of total length LENGTH."""
    c = LENGTH - SPAN
    u = (HEIGHT ** 2 - c ** 2) / (2 * c)
    return [(0.0, 0.0, -DEPTH), (SPAN - u, 0.0, -DEPTH), (SPAN, 0.0, Z_FAIRLEAD)]


def model(points, elements=1, friction="", load_steps=1):
    return """title: catenary with a laid length (tests/verification/catenary)
environment:
  water: {density: %g, depth: %g}
  seabed: {normal_stiffness: %g%s}
bodies:
  line:
    type: ancf_beam
    polyline: %s
    elements: %s
    area: %.17g
    second_moment: %g
    youngs_modulus: %g
    density: %g
hydrodynamics:
  line: {diameter: %g}
supports:
  - {body: line, node: start, type: pinned}
  - {body: line, node: end, type: pinned}
statics: {load_steps: %d}
output: {support_reactions: true}
""" % (RHO_W, DEPTH, K_AREA, friction, yaml_points(points), elements, AREA, I, E, RHO,
       DIAMETER, load_steps)


def reference(length):
    """The analytic references for a line of unstretched length `length`: the rigid-seabed
    catenary, and the one corrected for the elastic seabed (its seabed lowered to z_v, the
    contact extended by the boundary layer)."""
    rigid = ec.solve(SPAN, HEIGHT, length, W, EA)
    extra, zv = ec.touchdown_boundary_layer(W, rigid.H, EI, K)
    corrected = ec.solve(SPAN, HEIGHT - zv, length, W, EA)
    return rigid, corrected, corrected.LB + extra


def measured(row, elements):
    fair = [row["line.n%d.reaction.f%s" % (elements, c)] for c in "xyz"]
    anchor = [row["line.n0.reaction.f%s" % c] for c in "xyz"]
    return math.hypot(*fair), math.hypot(*anchor), row["line.seabed.laid_length"]


class LaidCatenary(SeaflexCase):
    def compare(self, elements, check_laid=True):
        pts = catenary_polyline(elements)
        length = polyline_length(pts)
        row, out, stdout = self.statics(model(pts))
        t_fair, t_anchor, laid = measured(row, elements)
        rigid, corrected, laid_ref = reference(length)
        suspended = elements * (length - rigid.LB) / length
        print("\n%d elements (%.1f per suspended length), L = %.6f m, %s Newton iterations"
              % (elements, suspended, length, newton_iterations(stdout)))
        print("  analytic (rigid seabed) %r" % rigid)
        print("  fairlead tension %.6g N vs %.6g: %+.2e" % (
            t_fair, corrected.fairlead_tension, t_fair / corrected.fairlead_tension - 1))
        print("  anchor tension   %.6g N vs %.6g: %+.2e" % (
            t_anchor, corrected.anchor_tension, t_anchor / corrected.anchor_tension - 1))
        print("  laid length      %.6g m vs %.6g (rigid %.6g, + boundary layer %.4f m): %+.2e"
              % (laid, laid_ref, rigid.LB, laid_ref - corrected.LB, laid / laid_ref - 1))
        self.assertGreaterEqual(suspended, 20.0)
        self.assertLess(abs(t_fair / corrected.fairlead_tension - 1), TOLERANCE)
        self.assertLess(abs(t_anchor / corrected.anchor_tension - 1), TOLERANCE)
        if check_laid:
            self.assertLess(abs(laid / laid_ref - 1), TOLERANCE)
        return row, out, laid / laid_ref - 1

    def along(self, elements):
        """Statics: the largest relative difference of the effective tension from the
        catenary's at the stations within four elements of the touchdown point and at the
        others, and the largest distance of a node from the catenary."""
        row, out, _ = self.compare(elements)
        length = polyline_length(catenary_polyline(elements))
        _, corrected, _ = reference(length)
        along = read_rows(os.path.join(out, "statics.line.along.csv"))
        near = 4 * length / elements
        dev = [(abs(r["tension_effective"] / corrected.tension(r["s"]) - 1), r["s"]) for r in along]
        at_td = max(d for d in dev if abs(d[1] - corrected.LB) <= near)
        away = max(d for d in dev if abs(d[1] - corrected.LB) > near)
        s = [i * length / elements for i in range(elements + 1)]   # node i at i L / N
        pos = max(math.hypot(row["line.n%d.x" % i] - corrected.position(s[i])[0],
                             row["line.n%d.z" % i] + DEPTH - corrected.position(s[i])[1])
                  for i in range(elements + 1))
        print("  effective tension along the line: largest relative difference %.2e (at s = "
              "%.2f m) more than four elements from the touchdown point, %.2e (at s = %.2f m) "
              "within them\n  node positions: largest distance from the catenary %.3g m"
              % (away[0], away[1], at_td[0], at_td[1], pos))
        return at_td[0], away[0], pos

    def test_fine_mesh(self):
        """2.5 m elements, 94 per suspended length: tensions and laid length; the effective
        tension along the line, more than four elements (10 m) from the touchdown point,
        within 0.2 % (see test_tension_at_the_touchdown_point for the four); every node
        within 1 cm of the catenary (its sag at mid-span is metres: the catenary's shape,
        not just its end forces)."""
        _, away, pos = self.along(200)
        self.assertLess(away, TOLERANCE)
        self.assertLess(pos, 0.01)

    # The effective tension (statics.line.along.csv) oscillates about the touchdown point,
    # over about four elements either side: +3.5 %, -2.4 % of H at 2.5 m elements (0.2 % four
    # elements away), +6.7 %, -5.5 % at 5 m, +1.5 % at 1.25 m, while the support reactions
    # agree with the catenary to 1e-6 (test_fine_mesh). The
    # cubic element must bend from the seabed's zero curvature to the catenary's w/H over
    # a 0.2 m boundary layer, and its Green-Lagrange strain, the derivative of the positions,
    # takes up the misfit: a stress-recovery error that converges with the mesh, but one
    # that the touchdown zone's fatigue and code checks would see.
    @unittest.expectedFailure
    def test_tension_at_the_touchdown_point(self):
        at_td, _, _ = self.along(200)
        self.assertLess(at_td, TOLERANCE)

    def test_issue_mesh_tensions(self):
        """10 m elements, 24 per suspended length (the issue's >= 20): the tensions."""
        self.compare(50, check_laid=False)

    # The laid length at the issue's mesh (>= 20 elements per suspended length) is outside
    # 0.2 %: -0.69 % at 10 m elements (-0.21 % at 5 m, -0.04 % at 2.5 m): the cubic element
    # holding the touchdown point cannot follow the jump of the curvature there (0 on the
    # seabed, w/H above it, over the 0.2 m boundary layer) and its contact ends early. A
    # discretization error, converging with the mesh (test_fine_mesh), not a wrong model.
    @unittest.expectedFailure
    def test_issue_mesh_laid_length(self):
        _, _, err = self.compare(50)

    def test_friction_is_not_felt_in_statics(self):
        """docs 4.5: static equilibrium feels no friction (the regularized law needs a
        velocity). With friction the static solution is the frictionless one, the friction
        channel is zero, and the anchor tension is H: one of the equilibria Coulomb friction
        allows (any anchor tension in [max(0, H - C_B w L_B), H] is one after some history),
        not the limit state of the analytic catenary with friction (Jonkman's, C_B = 0.5:
        H_A = 0 here)."""
        pts = catenary_polyline(100)
        plain, _, _ = self.statics(model(pts), "plain")
        rough, _, _ = self.statics(model(pts, friction=", friction: {axial: 0.5, lateral: 1.0}"),
                                   "rough")
        self.assertEqual(rough["line.seabed.friction"], 0.0)
        for name, value in plain.items():
            self.assertAlmostEqual(rough[name], value, delta=1e-12 * max(1.0, abs(value)),
                                   msg=name)
        length = polyline_length(pts)
        jonkman = ec.solve(SPAN, HEIGHT, length, W, EA, CB=0.5)
        _, t_anchor, laid = measured(plain, 100)
        print("\nwith friction 0.5: anchor tension %.6g N (frictionless); the analytic limit "
              "state with C_B = 0.5 has %.6g N, the admissible range is [%.6g, %.6g] N"
              % (t_anchor, jonkman.anchor_tension, max(0, jonkman.H - 0.5 * W * jonkman.LB),
                 jonkman.H))

    # The documented first guess of a slack line (docs model-format.md 5.1 and 12: a
    # polyline along the seabed then straight to the fairlead, load steps) does not converge
    # for this line: statics stops at load factor 2e-4 with the residual not reduced after
    # 100 iterations (seaflex 0.1.0, 2026-11-26), whatever the seabed stiffness (1e7, 1e9)
    # and for EI up to 1e5 N m^2; it converges (194 iterations, 10 load steps) only with the
    # 0.1 m solid bar's EI = 4.9e5 N m^2. A first guess from the catenary is issue 18 item 3.
    @unittest.expectedFailure
    def test_documented_first_guess(self):
        pts = two_segment_polyline()
        n1 = round(100 * (pts[1][0]) / LENGTH)
        p, out = self.seaflex("statics", model(pts, "[%d, %d]" % (n1, 100 - n1), load_steps=10))
        self.assertEqual(p.returncode, 0, p.stderr[-400:])
        row = read_rows(os.path.join(out, "statics.csv"))[0]
        t_fair, _, _ = measured(row, 100)
        _, corrected, _ = reference(LENGTH)
        self.assertLess(abs(t_fair / corrected.fairlead_tension - 1), TOLERANCE)


CHAIN_AREA, CHAIN_EA, CHAIN_DEPTH, CHAIN_SPAN, CHAIN_LENGTH = 0.01465, 1.0e10, 200.0, 950.0, 1000.0
CHAIN_HEIGHT = CHAIN_DEPTH - 15.0
CHAIN_W = (RHO - RHO_W) * CHAIN_AREA * G                     # 981 N/m
CHAIN_DIAMETER = math.sqrt(4 * CHAIN_AREA / math.pi)         # volume-equivalent, 0.137 m


def chain_model(load_steps):
    """The issue's hard case: a 1000 m chain (115 kg/m, w = 981 N/m) with EA = 1e10 N in
    200 m of water, fairlead 15 m below the surface and 950 m from the anchor, 200 elements,
    from the documented first guess (along the seabed, then straight to the fairlead)."""
    c = CHAIN_LENGTH - CHAIN_SPAN
    u = (CHAIN_HEIGHT ** 2 - c ** 2) / (2 * c)
    pts = [(0.0, 0.0, -CHAIN_DEPTH), (CHAIN_SPAN - u, 0.0, -CHAIN_DEPTH),
           (CHAIN_SPAN, 0.0, CHAIN_HEIGHT - CHAIN_DEPTH)]
    n1 = round(200 * pts[1][0] / CHAIN_LENGTH)
    return """title: 1000 m chain, EA 1e10 N (tests/verification/catenary)
environment:
  water: {density: %g, depth: %g}
  seabed: {normal_stiffness: 1.0e6}
bodies:
  chain:
    type: ancf_beam
    polyline: %s
    elements: [%d, %d]
    area: %g
    second_moment: 1.0e-8
    youngs_modulus: %.17g
    density: %g
hydrodynamics:
  chain: {diameter: %.17g}
supports:
  - {body: chain, node: start, type: pinned}
  - {body: chain, node: end, type: pinned}
statics: {load_steps: %d, max_iterations: 100}
output: {support_reactions: true}
""" % (RHO_W, CHAIN_DEPTH, yaml_points(pts), n1, 200 - n1, CHAIN_AREA, CHAIN_EA / CHAIN_AREA,
       RHO, CHAIN_DIAMETER, load_steps)


class ChainHardCase(SeaflexCase):
    """The issue's hard case, reported: does statics converge from the documented first
    guess, in how many Newton iterations, to the catenary? (Issue 18 item 3 targets <= 30
    iterations for a three-line mooring with a first guess from the catenary; not built.)"""

    def solve(self, load_steps):
        p, out = self.seaflex("statics", chain_model(load_steps), "chain%d" % load_steps)
        self.assertEqual(p.returncode, 0, p.stderr[-400:])
        row = read_rows(os.path.join(out, "statics.csv"))[0]
        fair = math.hypot(*[row["chain.n200.reaction.f%s" % c] for c in "xyz"])
        k = 1.0e6 * CHAIN_DIAMETER
        rigid = ec.solve(CHAIN_SPAN, CHAIN_HEIGHT, CHAIN_LENGTH, CHAIN_W, CHAIN_EA)
        extra, zv = ec.touchdown_boundary_layer(CHAIN_W, rigid.H, CHAIN_EA / CHAIN_AREA * 1e-8, k)
        ref = ec.solve(CHAIN_SPAN, CHAIN_HEIGHT - zv, CHAIN_LENGTH, CHAIN_W, CHAIN_EA)
        print("\nchain, %d load step(s): %s Newton iterations; fairlead tension %.6g N vs "
              "%.6g N (%+.2e), laid length %.5g m vs %.5g m (rigid %.5g m + boundary layer)"
              % (load_steps, newton_iterations(p.stdout), fair, ref.fairlead_tension,
                 fair / ref.fairlead_tension - 1, row["chain.seabed.laid_length"],
                 ref.LB + extra, ref.LB))
        self.stderr = p.stderr
        return fair / ref.fairlead_tension - 1

    def test_one_load_step(self):
        """Converges (45 Newton iterations, 2026-11-26) to the catenary within 0.2 %, a
        stable equilibrium: no warning."""
        self.assertLess(abs(self.solve(1)), TOLERANCE)
        self.assertNotIn("unstable", self.stderr)

    def test_a_fold_is_flagged(self):
        """The folded equilibria of test_more_load_steps (below) are unstable: statics
        warns, naming the directions of negative stiffness (8 with 2 steps on 2026-11-29,
        as many as seaflex modes finds by its dense eigen-solution); a run that finds the
        catenary does not. Which step counts fold depends on the round-off, so the test
        asks for the warning exactly when the fairlead tension is off by more than 10 %,
        over 2, 3 and 50 steps, two of which fold in both builds (the note below): at least
        one fold must be seen, or the test would check nothing."""
        folds = 0
        for steps in (2, 3, 50):
            error = self.solve(steps)
            folded = abs(error) > 0.1
            folds += folded
            self.assertEqual("the equilibrium found is unstable" in self.stderr, folded,
                             "%d steps, fairlead tension %+.2e: %s"
                             % (steps, error, self.stderr[-400:]))
        self.assertGreater(folds, 0)

    # With 2 load steps (and others, below; 1, 5 and 10 are right) statics reports convergence
    # (relative residual 1e-10) on a spurious equilibrium: the line folds into two Z-shaped
    # kinks near s = 800 and 860 m (strain 3.4 %, curvature 0.5 1/m there), lifts its whole
    # laid length off the seabed and carries a fairlead tension of 3.6 MN (2 steps; 6.8 MN
    # with 20) instead of the catenary's 0.68 MN (seaflex 0.1.0, 2026-11-26). With EI =
    # 6.8e3 N m^2 the fold costs almost nothing, and the first load increment (87 iterations
    # from the slack guess) drives the line into it. Which step counts fold depends on the
    # round-off: on 2026-11-28 the portable build folded with 2, 3, 50 and 100 steps (fairlead
    # tension +170 %, +362 %, +445 %, +445 %) and found the catenary with 4 and 20, and the
    # SEAFLEX_NATIVE build (fused multiply-adds) folded with 3, 50 and 100 (+110 %, +3128 %,
    # +3128 %) and found it with 2, 4 and 20. 2, 3 and 50 steps: two of them fold in both
    # builds, so that a build whose round-off avoids one fold still shows the failure.
    @unittest.expectedFailure
    def test_more_load_steps(self):
        errors = [self.solve(n) for n in (2, 3, 50)]
        self.assertLess(max(abs(e) for e in errors), TOLERANCE)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
