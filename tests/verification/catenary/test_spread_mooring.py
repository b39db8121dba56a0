#!/usr/bin/python3
"""Mooring stiffness of a spread mooring against the analytic elastic catenary (issue 18).

examples/spread_mooring.yaml (the drilling rig's semi-submersible on three 850 m chains in
200 m, each given by anchor, fairlead and length: the catenary first guess) without its
current and waves, pulled along x by a horizontal force F at its centre of gravity:
seaflex statics for F = 0, 0.5, 1 and 2 MN. For each, the fairlead positions seaflex found
give each chain's span X and height h above its anchor; elastic_catenary.solve (Jonkman
2007, written for this verification without seaflex's code) gives the fairlead tension's
horizontal and vertical components H and V for that geometry. Checked:
- each chain's H and V against the fairlead joint's force on the chain (the exact
  reaction), within 1 % (the issue's tolerance for the stiffness; the rigid-seabed catenary
  differs from seaflex's elastic seabed by the sinkage w/k = 7 cm at the laid end, about
  4e-4 of the height, and by the strain law, 4e-7);
- the force-offset curve: F against the analytic sum of the three chains' horizontal pulls
  at seaflex's offsets, within 1 % of the largest F, and the stiffness dF/dx between the
  load levels within 1 %.
Measured (2026-11-26): offsets 0.01, 18.65, 34.26, 52.40 m; the analytic chains balance
F = 0.5, 1 and 2 MN to 0.08 %, 0.09 % and 0.13 %.

usage: test_spread_mooring.py SEAFLEX_EXECUTABLE SOURCE_DIR"""
import math
import os
import sys
import unittest

import elastic_catenary as cat
from catenary_support import G, RHO_W, SRC, SeaflexCase, newton_iterations

# the chains of examples/spread_mooring.yaml
AREA, E, RHO, DIAMETER, LENGTH, N = 0.0147, 3.35e10, 7850.0, 0.137, 850.0, 85
W = G * (RHO * AREA - RHO_W * math.pi / 4 * DIAMETER ** 2)
EA = E * AREA
FORCES = [0.0, 0.5e6, 1.0e6, 2.0e6]


def model_with_pull(force):
    with open(os.path.join(SRC, "examples", "spread_mooring.yaml")) as f:
        lines = f.read().splitlines()
    kept = [ln for ln in lines if not ln.startswith(("  current:", "  waves:"))]
    assert len(kept) == len(lines) - 2, "the example's current and waves lines changed"
    text = "\n".join(kept) + "\n"
    assert "gravity: 9.81\n" in text
    text = text.replace("gravity: 9.81\n", f"gravity: {G!r}\n")
    return text + (f"loads:\n  - {{type: point_force, at: {{body: platform, position: [0, 0, 0]}},"
                   f" force: [{force!r}, 0, 0]}}\n")


class SpreadMooringStiffness(SeaflexCase):
    def test_force_offset_curve(self):
        offsets, analytic = [], []
        for i, force in enumerate(FORCES):
            row, _, stdout = self.statics(model_with_pull(force), name=f"pull{i}")
            # the target, 30, for the mooring from the file (measured 23: most go
            # to the platform's heave and pitch, 6 when it starts at its equilibrium
            # draft); the pulled ones start 15 m and more from their equilibrium (18 to 32)
            self.assertLessEqual(newton_iterations(stdout), 30 if force == 0.0 else 40)
            pull_x = 0.0
            for k in (1, 2, 3):
                anchor = [row[f"chain{k}.n0.{c}"] for c in "xyz"]
                fair = [row[f"chain{k}.n{N}.{c}"] for c in "xyz"]
                dx, dy = fair[0] - anchor[0], fair[1] - anchor[1]
                span = math.hypot(dx, dy)
                ref = cat.solve(span, fair[2] - anchor[2], LENGTH, W, EA)
                fx, fy, fz = (row[f"fairlead{k}.f{c}"] for c in "xyz")
                self.assertLess(abs(math.hypot(fx, fy) - ref.H), 0.01 * ref.H,
                                f"chain {k}, F = {force:g}: H {math.hypot(fx, fy)} vs {ref.H}")
                self.assertLess(abs(fz - ref.V), 0.01 * ref.V,
                                f"chain {k}, F = {force:g}: V {fz} vs {ref.V}")
                # the joint pulls the chain's end towards the platform, away from the anchor
                self.assertGreater(fx * dx + fy * dy, 0.0)
                pull_x += ref.H * dx / span
            offsets.append(row["platform.x"])
            analytic.append(pull_x)
        # the curve: the platform moves downstream, and the analytic chains balance F
        self.assertTrue(all(b > a for a, b in zip(offsets, offsets[1:])), offsets)
        for force, f_ref in zip(FORCES, analytic):
            self.assertLess(abs(f_ref - force), 0.01 * max(FORCES), (force, f_ref))
        for j in range(1, len(FORCES)):
            dxj = offsets[j] - offsets[j - 1]
            k_seaflex = (FORCES[j] - FORCES[j - 1]) / dxj
            k_ref = (analytic[j] - analytic[j - 1]) / dxj
            self.assertLess(abs(k_seaflex - k_ref), 0.01 * k_ref, (j, k_seaflex, k_ref))
        print("offsets (m):", ["%.4f" % x for x in offsets])
        print("analytic F (N):", ["%.1f" % f for f in analytic])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
