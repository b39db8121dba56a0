"""Scale (issue 22): model checks whose cost used to grow quadratically answer within a
memory limit and a generous time limit. The limits are bounds against a blow-up, not timings:
each case takes well under a tenth of its time limit on the 2-core development machine
(docs/performance.md, "Model check at scale").

usage: test_scale.py SEAFLEX_EXECUTABLE SOURCE_DIR"""
import csv
import math
import os
import resource
import subprocess
import sys
import unittest

from cli_support import SANITIZER_BUILD, SEAFLEX, SRC, TempDirCase

GIB = 1 << 30


# The time and memory bounds are properties of the release build (the one users run); a
# sanitizer build (.ci/run's second stage) checks the messages without them and skips the
# largest models, which it would run tens of times slower.
RELEASE = not SANITIZER_BUILD
release_only = unittest.skipUnless(RELEASE, "time and memory bounds: release build only")


def run_limited(args, memory_bytes, timeout):
    """seaflex with its address space limited to memory_bytes (RLIMIT_AS) and a wall-clock
    timeout in seconds (subprocess.TimeoutExpired fails the test); a sanitizer build runs
    without the memory limit and with 20 times the time."""

    def limit():
        if RELEASE:
            resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))

    return subprocess.run([SEAFLEX, *args], capture_output=True, text=True,
                          timeout=timeout if RELEASE else 20 * timeout, preexec_fn=limit)


def chain_model(n, redundant_at=None):
    """n rigid links of 1 m hanging on ball joints j0 .. j{n-1} from ground; with
    redundant_at = i, a joint 'extra' that repeats joint j{i}."""
    lines = ["title: chain", "environment: {gravity: 9.81}", "bodies:"]
    for i in range(n):
        lines.append(f"  b{i}: {{type: rigid_body, mass: 10, inertia: [1, 1, 0.1], "
                     f"position: [0, 0, {-(i + 0.5)}]}}")
    lines.append("joints:")
    lines.append("  - {name: j0, type: ball, from: {body: ground, position: [0, 0, 0]}, "
                 "to: {body: b0, position: [0, 0, 0.5]}}")
    for i in range(1, n):
        lines.append(f"  - {{name: j{i}, type: ball, from: {{body: b{i - 1}, position: [0, 0, "
                     f"-0.5]}}, to: {{body: b{i}, position: [0, 0, 0.5]}}}}")
    if redundant_at is not None:
        i = redundant_at
        lines.append(f"  - {{name: extra, type: ball, from: {{body: b{i - 1}, position: [0, 0, "
                     f"-0.5]}}, to: {{body: b{i}, position: [0, 0, 0.5]}}}}")
    lines.append("dynamics: {integrator: rk4, time_step: 1e-3, duration: 0.01}")
    return "\n".join(lines) + "\n"


class ModelCheckAtScale(TempDirCase):
    def test_redundant_joint_in_a_2000_body_chain(self):
        # before: 69 s and 838 MB (Eigen's SparseQR without row ordering); now about 0.3 s
        # and 90 MB. The chain has 14,000 coordinates and 8,001 constraint rows.
        path = self.model(chain_model(2000, redundant_at=1000))
        r = run_limited(["check", path], GIB, timeout=20)
        self.assertEqual(r.returncode, 2, r.stderr[-2000:])
        self.assertEqual(
            r.stderr.strip().splitlines(),
            [f"{path}:4005:5: joints[2000]: 'extra' over-constrains the assembly: its condition "
             "'x' repeats what 'j1000' already imposes; remove it or use a joint with fewer "
             "conditions (a closed loop of parallel revolute joints, such as a four-bar, needs a "
             "ball and a universal joint in place of two of its revolutes)"])

    def test_2000_body_chain_without_the_extra_joint_passes(self):
        path = self.model(chain_model(2000))
        r = run_limited(["check", path], GIB, timeout=20)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        self.assertIn("model OK", r.stdout)

    @release_only
    def test_20000_free_bodies(self):
        # before: 25 s (yaml-cpp's linear key search and a linear body search per body);
        # now about 1.3 s and 260 MB
        lines = ["title: free", "environment: {gravity: 9.81}", "bodies:"]
        for i in range(20000):
            lines.append(f"  b{i}: {{type: rigid_body, mass: 10, inertia: [1, 1, 0.1], "
                         f"position: [{i}, 0, 0]}}")
        lines.append("dynamics: {integrator: rk4, time_step: 1e-3, duration: 0.01}")
        path = self.model("\n".join(lines) + "\n")
        r = run_limited(["check", path], GIB, timeout=20)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        self.assertIn("model OK", r.stdout)


BENCH_RISER = os.path.join(SRC, "bench/riser/riser_n1000.yaml")


def riser_model(case, replacements):
    """bench/riser/riser_n1000.yaml with each (old, new) text replaced; every old text must
    be there."""
    with open(BENCH_RISER) as f:
        text = f.read()
    for old, new in replacements:
        case.assertIn(old, text)
        text = text.replace(old, new)
    return text


class RiserStaticsAtScale(TempDirCase):
    @release_only
    def test_10000_element_riser(self):
        # bench/riser/riser_n1000.yaml with 10,000 elements of 3 cm and no current: statics
        # stopped at load factor 1.2e-4 before ("a mode that the loads drive": a
        # regularization of 1e-14 x the largest diagonal, 12 EI / l^3 ~ 2e15, outweighed the
        # riser's string stiffness); now about 3 s and 130 MB
        text = riser_model(self, [("elements: 1000\n", "elements: 10000\n"),
                                  ("  current: {speed: 3.0, direction: 0}\n", "")])
        self.assertNotIn("current:", text)
        path = self.model(text)
        out = os.path.join(self.dir, "out")
        r = run_limited(["statics", path, "-o", out], GIB, timeout=60)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        with open(os.path.join(out, "statics.riser.along.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 30001)  # 3 stations per element and the end
        bottom, top = rows[0], rows[-1]
        # the top node carries the applied 6.826837e6 N alone (its x and y are held; no
        # current): the effective tension there equals it. Tolerance 1e-5 of it (68 N):
        # Newton stops at its round-off floor, a force residual of about 10 N with 3 cm
        # elements (1e-16 x 300 m x 12 EI / l^3); measured 4.8 N off
        force = 6.826837e6
        self.assertLess(abs(float(top["tension_effective"]) - force), 1e-5 * force)
        # bottom: the applied force less the weight, plus the buoyancy of the submerged
        # length: the stretched riser's top, z_top = 0.024 m, is above the water, and
        # buoyancy acts per unstretched length, so the 300 m riser is submerged over
        # 300 - z_top (docs/verification.md). Tolerance 1e-5 of 2e6 N (20 N)
        area = math.pi / 4 * (0.7 ** 2 - 0.4 ** 2)
        outer = math.pi / 4 * 0.7 ** 2
        z_top = float(top["z"])
        self.assertGreater(z_top, 0.02)  # it stretched: about 8e-5 x 300 m
        self.assertLess(z_top, 0.03)
        expected = force - 7850 * area * 9.81 * 300 + 1025 * outer * 9.81 * (300 - z_top)
        self.assertLess(abs(float(bottom["tension_effective"]) - expected), 1e-5 * 2e6)


class RiserDynamicsAtScale(TempDirCase):
    @release_only
    def test_10000_element_riser_in_current_from_statics(self):
        # bench/riser/riser_n1000.yaml with 10,000 elements of 3 cm in its 3 m/s current:
        # dynamics from statics stopped at t = 0.2 s before ("Newton diverges ... largest
        # update at riser.n691.r'.z"): the initial accelerations M^-1 (Q - C_q^T lambda)
        # turned the statics residual's round-off (about 10 N) over the slope mass of a
        # 3 cm element (5e-7 kg m^2) into 1e7 rad/s^2. The statics solution is an
        # equilibrium of the dynamic equations at rest (steady current, no waves), so the
        # exact motion is none: every node must stay where statics put it.
        text = riser_model(self, [("elements: 1000\n", "elements: 10000\n"),
                                  ("duration: 600\n", "duration: 3\n")])
        self.assertIn("current: {speed: 3.0", text)
        path = self.model(text)
        out = os.path.join(self.dir, "out")
        r = run_limited(["run", path, "-o", out, "--quiet"], GIB, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        with open(os.path.join(out, "timeseries.csv")) as f:
            reader = csv.reader(f)
            header = next(reader)
            rows = [[float(x) for x in row] for row in reader]
        self.assertEqual([row[0] for row in rows], [0.0, 1.0, 2.0, 3.0])
        columns = [i for i, name in enumerate(header) if name.startswith("riser.n")]
        self.assertEqual(len(columns), 3 * 10001)
        # at rest to 1e-9 m over 3 s (round-off of positions of 300 m is 6e-14 m; a
        # slope excited by 1e7 rad/s^2 moves its node by metres in one step)
        drift = max(abs(rows[-1][i] - rows[0][i]) for i in columns)
        self.assertLess(drift, 1e-9)
        # the bow is the mesh-converged one: the middle node's offset in the current
        # (5.32 m) equals that of 1,000 elements (bench/riser as shipped) within 1e-8
        # relative (the cubic elements are converged at 1,000: measured 7e-12; an error of
        # the start would move the nodes by metres)
        mid = header.index("riser.n5000.x")
        coarse = os.path.join(self.dir, "coarse")
        r = run_limited(["statics", BENCH_RISER, "-o", coarse], GIB, timeout=60)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        with open(os.path.join(coarse, "statics.riser.along.csv")) as f:
            along = list(csv.DictReader(f))
        middle = [row for row in along if abs(float(row["s"]) - 150.0) < 1e-9]
        self.assertTrue(middle, "no station at s = 150 m in the 1,000-element statics")
        x_coarse = float(middle[0]["x"])
        self.assertGreater(x_coarse, 5.0)  # the current bows the riser by metres
        self.assertLess(abs(rows[0][mid] - x_coarse), 1e-8 * abs(x_coarse))


class RadiationFitAtScale(TempDirCase):
    @release_only
    def test_state_space_fit_of_a_2000_s_memory_at_1_ms(self):
        # before: over 30 s and 565 MB (2,000,001 kernel samples of 6 x 6); now the kernel is
        # sampled at most 2 x 4096 times: about 0.8 s and 20 MB
        wamit = os.path.abspath(os.path.join(SRC, "tests/data/wamit/sphere/sphere"))
        path = self.model(
            "environment: {gravity: 9.81, water: {density: 1025, depth: 50}}\n"
            "bodies:\n"
            "  sphere: {type: rigid_body, mass: 268349.5, inertia: [1.0e6, 1.0e6, 1.0e6], "
            "position: [0, 0, -2]}\n"
            "hydrodynamics:\n"
            "  sphere:\n"
            f"    bem: {{wamit: {wamit}, radiation: state_space, memory: 2000, "
            "kernel_time_step: 0.001, displaced_volume: 261.799, "
            "still_water_position: [0, 0, -2]}\n"
            "dynamics: {integrator: rk4, time_step: 0.02, duration: 0.1}\n")
        r = run_limited(["check", path], GIB, timeout=30)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        self.assertIn("model OK", r.stdout)


    def test_convolution_with_a_2000_s_memory_at_1_ms_is_refused(self):
        # the convolution keeps every kernel sample: 2,000,001 of them would take 576 MB and
        # minutes to compute; the loader refuses more than 100,000 (exit 2, the key named)
        wamit = os.path.abspath(os.path.join(SRC, "tests/data/wamit/sphere/sphere"))
        path = self.model(
            "environment: {gravity: 9.81, water: {density: 1025, depth: 50}}\n"
            "bodies:\n"
            "  sphere: {type: rigid_body, mass: 268349.5, inertia: [1.0e6, 1.0e6, 1.0e6], "
            "position: [0, 0, -2]}\n"
            "hydrodynamics:\n"
            "  sphere:\n"
            "    bem:\n"
            f"      wamit: {wamit}\n"
            "      radiation: convolution\n"
            "      memory: 2000\n"
            "      kernel_time_step: 0.001\n"
            "dynamics: {integrator: rk4, time_step: 0.02, duration: 0.1}\n")
        r = run_limited(["check", path], GIB, timeout=30)
        self.assertEqual(r.returncode, 2, r.stderr[-2000:])
        self.assertEqual(r.stderr.strip().splitlines(),
                         [f"{path}:10:25: hydrodynamics.sphere.bem.kernel_time_step: memory / "
                          "kernel_time_step = 2e+06 kernel samples, more than the limit of "
                          "100000 for radiation: convolution; use a kernel_time_step of at "
                          "least 0.02 s, a shorter memory, or radiation: state_space"])


class DidYouMeanAtScale(TempDirCase):
    def test_long_misspelt_body_name(self):
        # the issue's reproducer: two 100,000-letter names took 53 s in the edit distance.
        # A body name is now at most 64 letters, and a reference over 256 letters is not
        # searched for a suggestion
        name = "r" * 100000
        bad = "r" * 99999 + "s"
        path = self.model(
            "bodies:\n"
            f"  ? {name}\n"
            "  : {type: rigid_body, mass: 10, inertia: [1, 1, 1], position: [0, 0, 0]}\n"
            "supports:\n"
            f"  - {{body: {bad}, type: fixed, fix: [x]}}\n"
            "dynamics: {integrator: rk4, time_step: 1e-3, duration: 0.01}\n")
        r = run_limited(["check", path], GIB, timeout=5)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr.strip().splitlines(),
                         [f"{path}:2:5: bodies: body names may have at most 64 characters (they "
                          "become output channel and file names, such as <body>.n0.x), got "
                          "100000 characters",
                          f"{path}:5:12: supports[0].body: no body named '{bad}': the model "
                          "has no valid bodies"])
        # a valid 64-letter name and a 100,000-letter reference to it
        name = "r" * 64
        path = self.model(
            "bodies:\n"
            f"  {name}: {{type: rigid_body, mass: 10, inertia: [1, 1, 1], position: [0, 0, 0]}}\n"
            "supports:\n"
            f"  - {{body: {bad}, type: fixed, fix: [x]}}\n"
            "dynamics: {integrator: rk4, time_step: 1e-3, duration: 0.01}\n")
        r = run_limited(["check", path], GIB, timeout=5)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr.strip().splitlines(),
                         [f"{path}:4:12: supports[0].body: no body named '{bad}'; "
                          f"expected one of: {name}"])

    def test_normal_misspelt_name_keeps_its_suggestion(self):
        path = self.model(
            "bodies:\n"
            "  buoy: {type: rigid_body, mass: 10, inertia: [1, 1, 1], position: [0, 0, 0]}\n"
            "supports:\n"
            "  - {body: buoi, type: fixed, fix: [x]}\n"
            "dynamics: {integrator: rk4, time_step: 1e-3, duration: 0.01}\n")
        r = run_limited(["check", path], GIB, timeout=5)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr.strip().splitlines(),
                         [f"{path}:4:12: supports[0].body: no body named 'buoi'; "
                          "did you mean 'buoy'?"])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
