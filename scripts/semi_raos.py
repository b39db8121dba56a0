#!/usr/bin/python3
"""Computes the displacement RAOs of the drilling rig's semi-submersible with seaflex itself,
for examples/drilling_rig_raos.csv (the table examples/drilling_rig_raos.yaml imposes).

    semi_raos.py SEAFLEX [--out examples/drilling_rig_raos.csv] [--work DIR]

The semi of examples/drilling_rig.yaml (hull hydrostatics, Morison strips, four mooring
springs; without the riser and tensioner) floats freely in regular waves of height 2 m
travelling towards +x (heading 0 deg), one run per period. After the wave ramp the last
six periods of surge, heave and pitch are fitted by least squares with
x = P cos(w t) + Q sin(w t) + C; with the wave at the RAO origin (the centre of gravity,
x = y = 0) eta = a cos(w t), x = Re{H a e^{i w t}} gives H = (P - i Q) / a: amplitude |H|
(m/m, deg/m) and phase arg H (deg, a lead relative to the crest at the RAO origin: the
seaflex convention, docs/model-format.md 5.4). Sway, roll and yaw are zero in head seas.
The RAOs are those of this linearized-by-fit, drag-damped model at a = 1 m: drag and the
mooring make the response amplitude-dependent, so they are an example, not a design RAO.
"""
import argparse
import math
import os
import subprocess
import sys

import numpy as np

PERIODS = [5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 18, 20, 22, 25, 30]
AMPLITUDE = 1.0

MODEL = """title: semi-submersible of the drilling rig, free floating in a regular wave
environment:
  gravity: 9.81
  water: {{density: 1025, depth: 340}}
  waves: {{type: airy, height: {height}, period: {period}, direction: 0, ramp: {{start: 0, duration: {ramp}}}}}
bodies:
  platform:
    type: rigid_body
    mass: 5.453e7
    inertia: [4.908e10, 5.584e10, 7.067e10]
    position: [0, 0, -5]
hydrodynamics:
  platform:
    hull:
      - box: {{center: [0, -29.535, -13.5], size: [108, 18.5, 9]}}
      - box: {{center: [0, 29.535, -13.5], size: [108, 18.5, 9]}}
      - box: {{center: [-45.05, -29.535, 3.7], size: [17.9, 17.9, 25.4]}}
      - box: {{center: [45.05, -29.535, 3.7], size: [17.9, 17.9, 25.4]}}
      - box: {{center: [-45.05, 29.535, 3.7], size: [17.9, 17.9, 25.4]}}
      - box: {{center: [45.05, 29.535, 3.7], size: [17.9, 17.9, 25.4]}}
    morison:
      - {{end_a: [-54, -29.535, -13.5], end_b: [54, -29.535, -13.5], diameter: 14.56, cd: 1.0, cm: 2.0, strips: 16, end_effects: true}}
      - {{end_a: [-54, 29.535, -13.5], end_b: [54, 29.535, -13.5], diameter: 14.56, cd: 1.0, cm: 2.0, strips: 16, end_effects: true}}
      - {{end_a: [-45.05, -29.535, -9], end_b: [-45.05, -29.535, 16.4], diameter: 20.2, cd: 1.0, cm: 2.0, end_effects: true}}
      - {{end_a: [45.05, -29.535, -9], end_b: [45.05, -29.535, 16.4], diameter: 20.2, cd: 1.0, cm: 2.0, end_effects: true}}
      - {{end_a: [-45.05, 29.535, -9], end_b: [-45.05, 29.535, 16.4], diameter: 20.2, cd: 1.0, cm: 2.0, end_effects: true}}
      - {{end_a: [45.05, 29.535, -9], end_b: [45.05, 29.535, 16.4], diameter: 20.2, cd: 1.0, cm: 2.0, end_effects: true}}
connections:
  - {{name: mooring_1, type: spring, from: {{body: platform, position: [54, 38.785, 5]}},
     to: {{body: ground, position: [761.1, 745.9, 0]}}, stiffness: 1.25e5, free_length: 992}}
  - {{name: mooring_2, type: spring, from: {{body: platform, position: [-54, 38.785, 5]}},
     to: {{body: ground, position: [-761.1, 745.9, 0]}}, stiffness: 1.25e5, free_length: 992}}
  - {{name: mooring_3, type: spring, from: {{body: platform, position: [-54, -38.785, 5]}},
     to: {{body: ground, position: [-761.1, -745.9, 0]}}, stiffness: 1.25e5, free_length: 992}}
  - {{name: mooring_4, type: spring, from: {{body: platform, position: [54, -38.785, 5]}},
     to: {{body: ground, position: [761.1, -745.9, 0]}}, stiffness: 1.25e5, free_length: 992}}
statics: {{load_steps: 1}}
dynamics:
  integrator: generalized_alpha
  rho_inf: 0.9
  time_step: {dt}
  duration: {duration}
  output_interval: {dt}
  initial_state: statics
output: {{channels: [platform.x, platform.z, platform.pitch]}}
"""


def fit(t, x, w):
    A = np.column_stack([np.cos(w * t), np.sin(w * t), np.ones_like(t)])
    (p, q, _), *_ = np.linalg.lstsq(A, x, rcond=None)
    return complex(p, -q) / AMPLITUDE


def run(seaflex, work, period):
    ramp = 3 * period
    duration = ramp + 12 * period
    dt = period / 100.0
    name = os.path.join(work, "semi_T%g" % period)
    with open(name + ".yaml", "w") as f:
        f.write(MODEL.format(height=2 * AMPLITUDE, period=period, ramp=ramp, dt=dt,
                             duration=duration))
    subprocess.run([seaflex, "run", name + ".yaml", "-o", name, "-q"], check=True)
    data = np.genfromtxt(os.path.join(name, "timeseries.csv"), delimiter=",", names=True)
    t = data["time"]
    keep = t >= duration - 6 * period
    w = 2 * math.pi / period
    return [fit(t[keep], data[c][keep], w) for c in ("platformx", "platformz", "platformpitch")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("seaflex")
    ap.add_argument("--out", default="examples/drilling_rig_raos.csv")
    ap.add_argument("--work", default="/tmp/seaflex_semi_raos")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    rows = []
    for T in PERIODS:
        surge, heave, pitch = run(a.seaflex, a.work, T)
        rows.append((T, surge, heave, pitch))
        print("T = %5.1f s: surge %.4f m/m %7.1f deg, heave %.4f m/m %7.1f deg, pitch %.4f "
              "deg/m %7.1f deg" % (T, abs(surge), math.degrees(np.angle(surge)), abs(heave),
                                   math.degrees(np.angle(heave)), abs(pitch),
                                   math.degrees(np.angle(pitch))), file=sys.stderr)
    with open(a.out, "w") as f:
        f.write("# Displacement RAOs of the drilling rig's semi-submersible (examples/drilling_rig.yaml)\n"
                "# computed by seaflex itself: scripts/semi_raos.py (free floating, regular waves\n"
                "# H = 2 m, heading 0 deg = waves travelling towards +x, Morison drag included).\n"
                "# RAO origin: the centre of gravity at rest, (0, 0, -5) m. Phases: lead, relative\n"
                "# to the wave crest at the RAO origin (seaflex's convention). Amplitudes m/m and\n"
                "# deg/m. One heading: the table serves long-crested seas travelling towards +x.\n")
        f.write("period_s, heading_deg, surge_amp, surge_phase, sway_amp, sway_phase, heave_amp, "
                "heave_phase, roll_amp, roll_phase, pitch_amp, pitch_phase, yaw_amp, yaw_phase\n")
        for T, s, h, p in rows:
            f.write("%g, 0, %.6g, %.3f, 0, 0, %.6g, %.3f, 0, 0, %.6g, %.3f, 0, 0\n" %
                    (T, abs(s), math.degrees(np.angle(s)), abs(h), math.degrees(np.angle(h)),
                     abs(p), math.degrees(np.angle(p))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
