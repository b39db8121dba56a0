#!/usr/bin/python3
"""The force-offset curve and the stiffness of a moored body (issue 18).

    PYTHONPATH=build/python /usr/bin/python3 scripts/mooring_stiffness.py MODEL
        [--body NAME] [--direction DEG] [--forces F1,F2,...]

Runs seaflex statics of MODEL with the current and the waves removed and a horizontal force
F on the body's centre of gravity, in the direction DEG (degrees from x towards y; default
0), for each F (N; default 0, 0.25, 0.5, 1 and 2 MN), and prints the body's offset along that
direction, its set-down and the secant stiffness dF/dx between consecutive forces. Uses the
seaflex Python module (docs/python.md). Verified against the analytic elastic catenary on
examples/spread_mooring.yaml by tests/verification/catenary/test_spread_mooring.py."""
import argparse
import math
import sys

import seaflex


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("model")
    p.add_argument("--body", default="platform", help="the moored rigid body (default platform)")
    p.add_argument("--direction", type=float, default=0.0, help="deg from x towards y")
    p.add_argument("--forces", default="0,0.25e6,0.5e6,1e6,2e6", help="N, comma separated")
    a = p.parse_args()
    forces = [float(f) for f in a.forces.split(",")]
    base = seaflex.Model.from_file(a.model)
    d = base.to_dict()
    if a.body not in d.get("bodies", {}):
        sys.exit(f"mooring_stiffness: no body named '{a.body}' in {a.model}")
    env = d.setdefault("environment", {})
    env.pop("current", None)
    env.pop("waves", None)
    c, s = math.cos(math.radians(a.direction)), math.sin(math.radians(a.direction))
    rows = []
    for f in forces:
        m = dict(d)
        m["loads"] = list(d.get("loads", [])) + [{
            "type": "point_force", "name": "mooring_stiffness_pull",
            "at": {"body": a.body, "position": [0, 0, 0]}, "force": [f * c, f * s, 0.0]}]
        r = seaflex.Model.from_dict(m, source_path=base.source_path).statics(beams=False)
        x, y, z = (float(r[f"{a.body}.{k}"][0]) for k in "xyz")
        rows.append((f, x * c + y * s, z))
    z0 = rows[0][2]
    print(f"{'force (N)':>12} {'offset (m)':>11} {'set-down (m)':>13} {'stiffness (N/m)':>16}")
    for i, (f, x, z) in enumerate(rows):
        k = "" if i == 0 else f"{(f - rows[i - 1][0]) / (x - rows[i - 1][1]):16.4g}"
        print(f"{f:12.4g} {x:11.4f} {z0 - z:13.4f} {k}")


if __name__ == "__main__":
    main()
