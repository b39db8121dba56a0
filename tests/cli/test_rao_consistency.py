#!/usr/bin/python3
"""Consistency of displacement RAOs (issue 17): the RAOs of the free-floating semi of the
drilling rig, computed by seaflex from its own regular-wave run (scripts/semi_raos.py: the
fit of the last six periods, phases leading the crest at the RAO origin), imposed on the
same body in the same wave through `motion: {type: rao}`, give the same wave-frequency
motion: the first harmonic (complex amplitude, fitted the same way) of the imposed surge,
heave and pitch equals the free one within 1 %. This checks the RAO convention end to end
(a lag read as a lead, or the crest at the wrong origin, would fail by far more).
The whole time series are not compared: the free semi also carries the slowly decaying
transients of its lightly damped natural modes (surge about 90 s on the moorings, heave
about 17 s, damped by Morison drag only), 17 % of the heave amplitude at 10 s after 15
periods, which RAOs do not describe.

    test_rao_consistency.py SEAFLEX SOURCE_DIR
"""
import importlib.util
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

PERIOD = 10.0


def main(seaflex, source):
    spec = importlib.util.spec_from_file_location("semi_raos",
                                                  os.path.join(source, "scripts", "semi_raos.py"))
    semi = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(semi)
    with tempfile.TemporaryDirectory() as work:
        surge, heave, pitch = semi.run(seaflex, work, PERIOD)
        table = os.path.join(work, "raos.csv")
        with open(table, "w") as f:
            for T in (PERIOD - 1, PERIOD + 1):  # equal rows: no interpolation error at PERIOD
                f.write("%r, 0, %r, %r, 0, 0, %r, %r, 0, 0, %r, %r, 0, 0\n" %
                        (T, abs(surge), math.degrees(np.angle(surge)), abs(heave),
                         math.degrees(np.angle(heave)), abs(pitch), math.degrees(np.angle(pitch))))
        ramp, duration, dt = 3 * PERIOD, 15 * PERIOD, PERIOD / 100
        model = os.path.join(work, "imposed.yaml")
        with open(model, "w") as f:
            f.write("""environment:
  gravity: 9.81
  water: {density: 1025, depth: 340}
  waves: {type: airy, height: 2, period: %r, direction: 0, ramp: {start: 0, duration: %r}}
bodies:
  platform:
    type: rigid_body
    mass: 5.453e7
    inertia: [4.908e10, 5.584e10, 7.067e10]
    position: [0, 0, -5]
    motion: {type: rao, file: raos.csv, origin: [0, 0, -5], ramp: %r}
dynamics: {integrator: rk4, time_step: %r, duration: %r, output_interval: %r}
output: {channels: [platform.x, platform.z, platform.pitch]}
""" % (PERIOD, ramp, ramp, dt, duration, dt))
        subprocess.run([seaflex, "run", model, "-o", os.path.join(work, "imposed"), "-q"],
                       check=True)
        imposed = np.genfromtxt(os.path.join(work, "imposed", "timeseries.csv"), delimiter=",",
                                names=True)
    failures = 0
    w = 2 * math.pi / PERIOD
    for name, h_free in (("platformx", surge), ("platformz", heave), ("platformpitch", pitch)):
        t = imposed["time"]
        keep = t >= duration - 6 * PERIOD - 1e-9
        h_imposed = semi.fit(t[keep], imposed[name][keep], w)
        err = abs(h_imposed - h_free) / abs(h_free)
        ok = err <= 0.01
        failures += not ok
        print("%s %s: free RAO %.5g at %.2f deg, imposed %.5g at %.2f deg: difference %.3g "
              "(tolerance 1 %%)" % ("ok  " if ok else "FAIL", name, abs(h_free),
                                   math.degrees(np.angle(h_free)), abs(h_imposed),
                                   math.degrees(np.angle(h_imposed)), err))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
