#!/usr/bin/env python3
"""The command line's own behaviour (issue 16, "rough edges"): --version, the checks of every
numeric option (thread count, NaN, infinity, absurd values: exit 2 and a message naming the
option), -q printing nothing but errors, the statics report naming the criterion it met, the
channel count of `seaflex check`, the summary of a resumed run, the stop of an RK4 run whose
energy grows without bound, and the Newton failure messages.

usage: test_cli_options.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import os
import re
import subprocess
import sys
import unittest

from cli_support import SEAFLEX, SRC, TempDirCase, run

EXAMPLES = os.path.join(SRC, "examples")

CANTILEVER = """
environment: {gravity: 9.81}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 10, area: 0.01,
         second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
"""

# a 1 kg body on a 100 N/m spring along x: omega = 10 rad/s, released 1 micrometre from rest;
# the spring is 100 m long, so that it stays linear even when the motion grows to metres
SPRING = """
environment: {gravity: 0}
bodies:
  box: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [100.000001, 0, 0]}
connections:
  - {name: spring, type: spring, from: {body: ground, position: [0, 0, 0]},
     to: {body: box, position: [0, 0, 0]}, free_length: 100, stiffness: 100}
"""


def project_version():
    with open(os.path.join(SRC, "CMakeLists.txt")) as f:
        return re.search(r"project\(seaflex VERSION ([0-9.]+)", f.read()).group(1)


class Options(TempDirCase):

    def assert_refused(self, args, message):
        r = run(*args)
        self.assertEqual(r.returncode, 2, "%s: %s%s" % (args, r.stdout, r.stderr))
        self.assertIn(message, r.stderr, args)

    def test_version(self):
        r = run("--version")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, "seaflex %s\n" % project_version())

    def test_threads_above_the_hardware_are_refused(self):
        hw = os.cpu_count()
        model = self.model(CANTILEVER)
        out = os.path.join(self.dir, "out")
        self.assert_refused(
            ["statics", model, "-o", out, "--threads", str(hw + 1)],
            "--threads: %d is more than the %d hardware thread%s of this machine "
            "(std::thread::hardware_concurrency); use at most %d" % (hw + 1, hw, "" if hw == 1 else "s", hw))
        self.assert_refused(["statics", model, "-o", out, "--threads", "100000"],
                            "--threads: 100000 is more than the")
        for bad in ("0", "-3", "nan", "1.5", "inf"):
            self.assert_refused(["run", model, "-o", out, "--threads", bad],
                                "--threads: must be a whole number from 1 to %d (the hardware "
                                "threads of this machine), got '%s'" % (hw, bad))
        r = run("statics", model, "-o", out, "-q", "--threads", str(hw))
        self.assertEqual(r.returncode, 0, r.stderr)
        # the same limit on OMP_NUM_THREADS, the default of --threads
        env = dict(os.environ, OMP_NUM_THREADS=str(hw + 1))
        r = subprocess.run([SEAFLEX, "statics", model, "-o", out, "-q"], capture_output=True,
                           text=True, env=env, timeout=300)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("OMP_NUM_THREADS: %d threads are more than the %d hardware threads of this "
                      "machine; set at most %d (or use --threads)" % (hw + 1, hw, hw), r.stderr)
        env["OMP_NUM_THREADS"] = str(hw)
        r = subprocess.run([SEAFLEX, "statics", model, "-o", out, "-q"], capture_output=True,
                           text=True, env=env, timeout=300)
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_numeric_options_are_checked(self):
        model = self.model(CANTILEVER + "dynamics: {time_step: 1e-4, duration: 0.01, output_interval: 1e-3}\n")
        out = os.path.join(self.dir, "out")
        for bad in ("nan", "inf", "-inf", "NaN"):
            self.assert_refused(["run", model, "-o", out, "--checkpoint-every", bad],
                                "--checkpoint-every: must be a finite number in s, got '%s'" % bad)
            self.assert_refused(["bench", model, "--duration", bad],
                                "--duration: must be a finite number in s, got '%s'" % bad)
        for bad in ("-1", "0"):
            self.assert_refused(["run", model, "-o", out, "--checkpoint-every", bad],
                                "--checkpoint-every: must be above 0 and at most 1e+09 s, got %s s" % bad)
        self.assert_refused(["bench", model, "--duration", "1e300"],
                            "--duration: must be above 0 and at most 1e+09 s, got 1e+300 s")
        self.assert_refused(["bench", model, "--duration", "abc"],
                            "--duration: expected a number in s, got 'abc'")
        # within the option's range but beyond the model's limit of 2e9 steps
        self.assert_refused(["bench", model, "--duration", "1e6"],
                            "--duration: 1e+06 s at a time step of 0.0001 s is 1e+10 steps, "
                            "more than the limit of 2e9")
        # a checkpoint interval longer than the run would never write a checkpoint
        self.assert_refused(["run", model, "-o", out, "--checkpoint-every", "1"],
                            "--checkpoint-every: must not exceed the run's duration (0.01 s), got 1 s")
        for bad in ("0", "nan", "1e12", "2.5"):
            self.assert_refused(["modes", model, "-o", out, "-n", bad],
                                "--count: must be a whole number from 1 to 1000000, got '%s'" % bad)

    def test_quiet_prints_only_errors(self):
        model = self.model(CANTILEVER + "dynamics: {time_step: 4e-5, duration: 0.01, output_interval: 1e-3, "
                                        "initial_state: statics}\nstatics: {load_steps: 2}\n")
        out = os.path.join(self.dir, "out")
        for args in (["statics", model], ["run", model], ["modes", model, "-n", "2"],
                     ["run", model, "--checkpoint-every", "0.005"]):
            r = run(*args, "-o", out, "-q")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual((r.stdout, r.stderr), ("", ""), args)
            r = run(*args, "-o", out)  # and without -q, they do print
            self.assertNotEqual(r.stdout, "", args)
        # resume (of a run cut short by hand: checkpoint.txt of the last run is there)
        with open(os.path.join(out, "checkpoint.txt")) as f:
            self.assertIn("seaflex-checkpoint-1", f.read())
        r = run("resume", out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual((r.stdout, r.stderr), ("", ""))
        # errors still go to stderr
        r = run("run", self.model(CANTILEVER), "-o", out, "-q")
        self.assertEqual(r.returncode, 2)
        self.assertIn("needs a dynamics section", r.stderr)

    def test_statics_reports_the_criterion_met(self):
        # a loaded cantilever: the force residual met the tolerance
        r = run("statics", self.model(CANTILEVER), "-o", os.path.join(self.dir, "a"))
        self.assertEqual(r.returncode, 0, r.stderr)
        m = re.search(r"statics converged: 1 load increment\(s\), \d+ Newton iterations; relative "
                      r"residual (\S+) <= tolerance 1.00e-08 \(of the largest force term, (\S+) N\); "
                      r"constraint violation (\S+)\n", r.stdout)
        self.assertIsNotNone(m, r.stdout)
        self.assertLessEqual(float(m.group(1)), 1e-8)
        # the largest force term: the clamp's share of the weight, at least W/2 = 3850 N
        self.assertGreater(float(m.group(2)), 3850)
        # without gravity nothing loads it: every force is round-off, and the criterion met
        # is the update at round-off; the relative residual (1.0 of nothing) is not printed
        r = run("statics", self.model(CANTILEVER.replace("gravity: 9.81", "gravity: 0")), "-o",
                os.path.join(self.dir, "b"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("relative residual", r.stdout)
        self.assertRegex(r.stdout, r"Newton iterations; Newton update \S+ m <= 1e-13 x the model "
                                   r"size \(10 m\): the force residual, \S+ N, is at its round-off floor")
        # the progress lines of the load steps say the same
        r = run("statics", self.model(CANTILEVER + "statics: {load_steps: 2}\n"), "-o",
                os.path.join(self.dir, "c"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stderr, r"\[seaflex\] statics: load factor 0.5 converged in \d+ "
                                   r"iterations: relative residual \S+ <= tolerance 1.00e-08")

    def test_statics_failure_advice_matches_the_cause(self):
        # one Newton iteration per increment and a tolerance that one iteration cannot meet
        # on this nonlinear problem: Newton is converging (quadratically) when it stops, so
        # the advice is more iterations, not a smaller load increment
        path = self.model(CANTILEVER + "statics: {max_iterations: 1, tolerance: 1.0e-14}\n")
        r = run("statics", path, "-o", os.path.join(self.dir, "out"))
        self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
        self.assertRegex(r.stderr, r"statics did not converge at load factor \S+ \(last converged "
                                   r"0\): relative residual \S+ after 2 iterations, largest at "
                                   r"beam.n\d+.\S+; Newton was still converging \(its last iteration "
                                   r"reduced the residual \S+-fold\) when it reached "
                                   r"statics.max_iterations \(1\): raise max_iterations")
        self.assertNotIn("load too large", r.stderr)
        # a line 100 m long pinned at both ends 80 m apart, starting as a V with a kink: at
        # a small load its nearly stress-free shape has no stiffness against buckling, and
        # Newton fails at every increment down to min_increment; the advice names the model,
        # not the increment or the iterations
        path = self.model("""
environment: {gravity: 9.81}
bodies:
  line: {type: ancf_beam, polyline: [[0, 0, 0], [40, 0, -30], [80, 0, 0]], elements: [20, 20],
         area: 0.01, second_moment: 1.0e-8, youngs_modulus: 2.0e11, density: 7850}
supports:
  - {body: line, node: start, type: pinned}
  - {body: line, node: end, type: pinned}
statics: {load_steps: 4}
""")
        r = run("statics", path, "-o", os.path.join(self.dir, "out2"))
        self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
        self.assertRegex(r.stderr, r"statics did not converge at load factor \S+ \(last converged "
                                   r"0\): relative residual \S+ after \d+ iterations, largest at "
                                   r"line.\S+; no convergence even with the load increment halved "
                                   r"to \S+ \(statics.min_increment 0.0001\): the model may have no "
                                   r"equilibrium near this load \(a mechanism: check the supports "
                                   r"and joints; a buckling or snap-through load; a load larger "
                                   r"than the structure can carry\)")
        self.assertNotIn("raise max_iterations", r.stderr)

    def test_check_counts_the_selected_channels(self):
        r = run("check", self.model(CANTILEVER + "output: {channels: ['beam.n10.*', 'beam.n0.x']}\n"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("output channels: 4 (of 33, as the output section selects)\n", r.stdout)
        r = run("check", self.model(CANTILEVER))
        self.assertIn("output channels: 33\n", r.stdout)

    def test_resumed_run_counts_the_whole_run(self):
        # a finished run with checkpoints leaves its last one (at t = 8 s of 10); resuming it
        # runs the last 2 s again, and its summary counts the whole run: the steps and rows
        # of an uninterrupted run, and the wall time before the checkpoint (kept in
        # checkpoint.txt as wall_s, hexadecimal)
        model = os.path.join(EXAMPLES, "double_pendulum.yaml")
        out = os.path.join(self.dir, "out")
        r = run("run", model, "-o", out, "--checkpoint-every", "4")
        self.assertEqual(r.returncode, 0, r.stderr)
        fresh = re.search(r"dynamics: (\d+) steps of 0.001 s to t = 10 s in \S+ s wall time "
                          r"\(1 thread\); (\d+) rows", r.stdout)
        self.assertIsNotNone(fresh, r.stdout)
        self.assertEqual(fresh.groups(), ("10000", "1001"))
        with open(os.path.join(out, "checkpoint.txt")) as f:
            entries = dict(line.split(" ", 1) for line in f.read().splitlines())
        earlier = float.fromhex(entries["wall_s"].strip())
        self.assertEqual(float.fromhex(entries["state.t"].strip()), 8.0)
        r = run("resume", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        resumed = re.search(r"dynamics: (\d+) steps of 0.001 s to t = 10 s in (\S+) s wall time "
                            r"\(1 thread; resumed at t = 8 s, (\S+) s of it since\); (\d+) rows",
                            r.stdout)
        self.assertIsNotNone(resumed, r.stdout)
        self.assertEqual((resumed.group(1), resumed.group(4)), ("10000", "1001"))
        # the whole run's wall time: the part before the checkpoint plus this process's
        # (rounded to 0.01 s in the line)
        self.assertAlmostEqual(float(resumed.group(2)), earlier + float(resumed.group(3)), delta=0.011)

    def test_generalized_alpha_newton_failure_messages(self):
        # A Newton failure
        # never reports "last update 0 m", and its advice matches the cause.
        #
        # 1. Newton limited to one iteration on a nonlinear model (a pendulum swinging
        # through large angles): the updates contract, so the cure is more iterations, not
        # a shorter step
        pendulum = """
environment: {gravity: 9.81}
bodies:
  bob: {type: rigid_body, mass: 1, inertia: [0.01, 0.01, 0.01], position: [1, 0, 0]}
joints:
  - {name: pin, type: revolute, from: {body: ground, position: [0, 0, 0], orientation: [90, 0, 0]},
     to: {body: bob, position: [-1, 0, 0], orientation: [90, 0, 0]}}
"""
        path = self.model(pendulum + "dynamics: {integrator: generalized_alpha, time_step: 0.01, "
                                     "duration: 1, max_iterations: 1}\n")
        r = run("run", path, "-o", os.path.join(self.dir, "a"))
        self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
        self.assertRegex(r.stderr, r"generalized_alpha step failed: Newton did not converge in 1 "
                                   r"iterations?")
        self.assertNotRegex(r.stderr, r"last update 0 m")
        self.assertIn("raise max_iterations", r.stderr)
        self.assertNotIn("shorter time_step", r.stderr)
        # 2. a snap load that Newton cannot follow at this step (test_cli.py's rope): the
        # updates grow, and the cure is a shorter or adaptive step
        path = self.model("""
environment: {gravity: 9.81}
bodies:
  weight: {type: rigid_body, mass: 1000, inertia: [100, 100, 100], position: [0, 0, -9]}
connections:
  - {name: rope, type: spring, from: {body: ground, position: [0, 0, 0]},
     to: {body: weight, position: [0, 0, 0]}, free_length: 10, slack: true, damping: 2.0e4,
     tension_table: [[0, 0], [0.01, 1.0e4], [0.02, 1.0e5], [0.03, 1.0e6], [0.04, 1.0e7], [0.05, 1.0e8]]}
dynamics: {integrator: generalized_alpha, time_step: 0.1, duration: 3, output_interval: 0.1}
""")
        r = run("run", path, "-o", os.path.join(self.dir, "b"))
        self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
        self.assertNotRegex(r.stderr, r"last update 0 m")
        self.assertIn("try step_control: adaptive or a shorter time_step", r.stderr)
        self.assertNotIn("raise max_iterations", r.stderr)

    def test_rk4_growing_without_bound_is_stopped(self):
        # omega h = 10 x 0.3 = 3 > 2.83: RK4 multiplies the amplitude by |R(3i)| = 1.505
        # per step (energy x 2.26). In 35 steps that takes the amplitude from 1e-6 m to 1.6 m
        # and the energy 3e12-fold, far below the divergence test on q (1e6 x the initial
        # size 100 m), so the run used to end normally (exit 0). The growth test fires after its
        # 5 windows of 6 steps, at t = 30 x 0.3 = 9 s, and names omega from the growth per
        # step (omega h from |R(i omega h)|)
        path = self.model(SPRING + "dynamics: {time_step: 0.3, duration: 10.5}\n")
        out = os.path.join(self.dir, "out")
        r = run("run", path, "-o", out)
        self.assertEqual(r.returncode, 3, r.stdout + r.stderr)
        m = re.search(r"t = (\S+) s: the solution grows without bound \(the velocity norm grew by "
                      r"a factor (\S+) per step over the last 24 steps, now \S+, largest at box.x\); "
                      r"the time step 0.3 s is likely above the stability limit of rk4 for this "
                      r"model: rk4 is stable for omega h < 2.83, and this growth is that of a mode "
                      r"of omega = (\S+) rad/s \((\S+) Hz, omega h = (\S+)\); use time_step < (\S+) s "
                      r"or integrator: generalized_alpha", r.stderr)
        self.assertIsNotNone(m, r.stderr)
        self.assertAlmostEqual(float(m.group(1)), 9.0, delta=1e-9)
        # the growth per step of the velocity norm's window maxima: 1.505 to 2 %
        self.assertAlmostEqual(float(m.group(2)) / 1.505, 1.0, delta=0.02)
        self.assertAlmostEqual(float(m.group(3)) / 10.0, 1.0, delta=0.03)
        self.assertAlmostEqual(float(m.group(6)) / 0.283, 1.0, delta=0.03)
        self.assertIn("results up to the failure are in", r.stderr)
        # at omega h = 2.7 (stable) the same spring runs 1000 steps to the end
        r = run("run", self.model(SPRING + "dynamics: {time_step: 0.27, duration: 270}\n"), "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
