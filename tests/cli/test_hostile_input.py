#!/usr/bin/env python3
"""Hostile input (issue 22): files that are not regular files, absurd command-line numbers,
signals outside the time loop. Each case asserts the exit code, the exact message, a bound on
the wall time (subprocess timeout) and on the memory (RLIMIT_AS in the child), and that no
file outside the output folder changed.

usage: test_hostile_input.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import hashlib
import os
import resource
import shutil
import signal
import subprocess
import sys
import time
import unittest

from cli_support import SEAFLEX, SRC, TempDirCase

# the address space of a child: seaflex checks an example in under 200 MB; 512 MB leaves room
# and stops a read of /dev/zero long before the 2-8 GB the audit saw
MEMORY_LIMIT = 512 << 20
# every refusal below comes before any computation: 10 s is 100 times what they take
TIME_LIMIT = 10

CANTILEVER = """
environment: {gravity: 9.81}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 10, area: 0.01,
         second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
"""

# a floating sphere with a WAMIT database hull.1/.3/.hst next to the model
FLOATING = """
environment:
  gravity: 9.81
  water: {density: 1025, depth: 100}
  waves: {type: airy, height: 2.0, period: 8.0, direction: 0}
bodies:
  buoy: {type: rigid_body, mass: 2.0e5, inertia: [1.0e6, 1.0e6, 5.0e5], position: [0, 0, 0]}
hydrodynamics:
  buoy:
    bem: {wamit: hull, radiation: none}
dynamics: {integrator: rk4, time_step: 0.1, duration: 1}
"""

# a vessel that follows a motion table or RAO table named FILE
MOVING = """
environment:
  gravity: 9.81
  water: {density: 1025, depth: 100}
  waves: {type: airy, height: 2.0, period: 10.0, direction: 0}
bodies:
  vessel:
    type: rigid_body
    mass: 1.0e6
    inertia: [1.0e8, 1.0e8, 1.0e8]
    position: [0, 0, 0]
    motion: {type: TYPE, file: FILE}
dynamics: {integrator: rk4, time_step: 0.1, duration: 1}
"""


def set_memory_limit():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def memory_limit_usable():
    """False for a sanitizer build: AddressSanitizer reserves terabytes of address space for
    its shadow memory and cannot start under RLIMIT_AS (the release build asserts the bound)."""
    try:
        r = subprocess.run([SEAFLEX, "--version"], capture_output=True, timeout=TIME_LIMIT,
                           preexec_fn=set_memory_limit)
        return r.returncode == 0
    except (OSError, subprocess.SubprocessError):
        return False


LIMIT_MEMORY = memory_limit_usable()


def limit_memory():
    if LIMIT_MEMORY:
        set_memory_limit()


def run_bounded(*args, cwd=None, timeout=TIME_LIMIT):
    """seaflex with the memory limit; fails the test (TimeoutExpired) past timeout."""
    return subprocess.run([SEAFLEX, *args], capture_output=True, text=True, timeout=timeout,
                          cwd=cwd, preexec_fn=limit_memory)


def snapshot(root, skip):
    """{relative path: (kind, content hash or link target)} of everything under root but skip."""
    state = {}
    for base, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if os.path.join(base, d) != skip]
        for name in dirs + files:
            path = os.path.join(base, name)
            rel = os.path.relpath(path, root)
            if os.path.islink(path):
                state[rel] = ("link", os.readlink(path))
            elif os.path.isfile(path):
                with open(path, "rb") as f:
                    state[rel] = ("file", hashlib.sha256(f.read()).hexdigest())
            else:
                state[rel] = ("other", "")
    return state


class HostileInput(TempDirCase):

    def setUp(self):
        super().setUp()
        self.out = os.path.join(self.dir, "out")

    def assert_refused(self, args, message, cwd=None):
        """exit 2, message as a whole line of stderr, nothing changed outside self.out."""
        before = snapshot(self.dir, self.out)
        t0 = time.monotonic()
        r = run_bounded(*args, cwd=cwd)
        self.assertLess(time.monotonic() - t0, TIME_LIMIT)
        self.assertEqual(r.returncode, 2, "%s: %s%s" % (args, r.stdout, r.stderr))
        self.assertIn(message, r.stderr.splitlines(), args)
        self.assertEqual(snapshot(self.dir, self.out), before, args)
        self.assertFalse(os.path.exists(os.path.join(self.out, "timeseries.csv")))

    def test_threads_beyond_the_hardware_are_refused(self):
        # 100000 crashed in libgomp, 40000 aborted, 20000 started 20000 threads
        hw = os.cpu_count()
        model = self.model(CANTILEVER)
        for n in (100000, 40000, 20000):
            self.assert_refused(
                ["statics", model, "-o", self.out, "--threads", str(n)],
                "--threads: %d is more than the %d hardware thread%s of this machine "
                "(std::thread::hardware_concurrency); use at most %d"
                % (n, hw, "" if hw == 1 else "s", hw))

    def test_a_model_that_is_not_a_regular_file(self):
        # devices grew to 2-4 GB, a FIFO blocked in open, a directory "was empty"
        os.mkfifo(os.path.join(self.dir, "fifo.yaml"))
        os.mkdir(os.path.join(self.dir, "folder.yaml"))
        os.symlink("/dev/urandom", os.path.join(self.dir, "random.yaml"))
        os.symlink("loop_b.yaml", os.path.join(self.dir, "loop_a.yaml"))
        os.symlink("loop_a.yaml", os.path.join(self.dir, "loop_b.yaml"))
        os.symlink("gone.yaml", os.path.join(self.dir, "dangling.yaml"))
        cases = [
            ("/dev/zero", "/dev/zero: cannot read the model file: it is not a regular file (a "
                          "character device)"),
            ("/dev/urandom", "/dev/urandom: cannot read the model file: it is not a regular file "
                             "(a character device)"),
            ("random.yaml", "random.yaml: cannot read the model file: it is not a regular file (a "
                            "character device, through the symbolic link to '/dev/urandom')"),
            ("fifo.yaml", "fifo.yaml: cannot read the model file: it is not a regular file "
                          "(a FIFO)"),
            ("folder.yaml", "folder.yaml: cannot read the model file: it is a directory"),
            ("loop_a.yaml", "loop_a.yaml: cannot read the model file: it is a symbolic link loop "
                            "(too many levels of symbolic links)"),
            ("dangling.yaml", "dangling.yaml: cannot read the model file: it is a symbolic link "
                              "to 'gone.yaml', which does not exist"),
            ("nowhere.yaml", "nowhere.yaml: cannot read the model file: no such file"),
        ]
        for model, message in cases:
            for command in (["check", model], ["run", model, "-o", self.out]):
                self.assert_refused(command, message, cwd=self.dir)

    def test_a_model_above_the_size_limit(self):
        # 4 MiB + 1 byte of comments: refused before parsing (yaml-cpp needs ~115 bytes of
        # memory per byte of YAML)
        path = os.path.join(self.dir, "huge.yaml")
        with open(path, "w") as f:
            f.write("#" * (4 * 1024 * 1024) + "\n")
        self.assert_refused(["check", "huge.yaml"],
                            "huge.yaml: cannot read the model file: it is 4 MiB, more than 4 MiB "
                            "(the limit for the model file)", cwd=self.dir)

    def wamit_model(self):
        data = os.path.join(SRC, "tests", "data", "wamit", "sphere")
        for ext in ("1", "3", "hst"):
            shutil.copy(os.path.join(data, "sphere." + ext), os.path.join(self.dir, "hull." + ext))
        return self.model(FLOATING)

    def test_wamit_files_that_are_not_regular_files(self):
        # a .1 that is /dev/zero through a symbolic link grew to 8 GB; a directory said "no
        # rows with a finite period"
        model = self.wamit_model()
        prefix = "model.yaml:10:18: hydrodynamics.buoy.bem.wamit: "
        replacements = [
            ("hull.1", lambda p: os.symlink("/dev/zero", p),
             "hull.1: cannot read the WAMIT file: it is not a regular file (a character device, "
             "through the symbolic link to '/dev/zero')"),
            ("hull.1", lambda p: os.symlink("/dev/urandom", p),
             "hull.1: cannot read the WAMIT file: it is not a regular file (a character device, "
             "through the symbolic link to '/dev/urandom')"),
            ("hull.1", os.mkdir, "hull.1: cannot read the WAMIT file: it is a directory"),
            ("hull.3", os.mkfifo, "hull.3: cannot read the WAMIT file: it is not a regular file "
                                  "(a FIFO)"),
            ("hull.hst", lambda p: os.symlink("hull.hst", p),
             "hull.hst: cannot read the WAMIT file: it is a symbolic link loop (too many levels "
             "of symbolic links)"),
        ]
        for name, make, message in replacements:
            path = os.path.join(self.dir, name)
            saved = path + ".saved"
            os.rename(path, saved)
            make(path)
            try:
                self.assert_refused(["check", "model.yaml"], prefix + message, cwd=self.dir)
            finally:
                if os.path.isdir(path) and not os.path.islink(path):
                    os.rmdir(path)
                else:
                    os.remove(path)
                os.rename(saved, path)
        # and the intact database loads
        r = run_bounded("check", "model.yaml", cwd=self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_motion_and_rao_tables_that_are_not_regular_files(self):
        os.mkfifo(os.path.join(self.dir, "motion.csv"))
        os.mkdir(os.path.join(self.dir, "rao.csv"))
        self.model(MOVING.replace("TYPE", "table").replace("FILE", "motion.csv"), "table.yaml")
        self.model(MOVING.replace("TYPE", "rao").replace("FILE", "rao.csv"), "rao.yaml")
        self.assert_refused(["check", "table.yaml"],
                            "table.yaml:12:33: bodies.vessel.motion.file: motion.csv: cannot read "
                            "the motion table: it is not a regular file (a FIFO)", cwd=self.dir)
        self.assert_refused(["check", "rao.yaml"],
                            "rao.yaml:12:31: bodies.vessel.motion.file: rao.csv: file: cannot read "
                            "the RAO file: it is a directory", cwd=self.dir)

    def test_signals_stop_check_and_statics_promptly(self):
        # check of a 3.7 MB model: yaml-cpp parses it for about 3 s; SIGINT stops it at once
        path = os.path.join(self.dir, "big.yaml")
        with open(path, "w") as f:
            f.write("bodies: {}\nextra: [\n")
            f.write(",\n".join("  [%d, 0, 0, 0]" % i for i in range(180000)))
            f.write("]\n")
        p = subprocess.Popen([SEAFLEX, "check", path], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, preexec_fn=limit_memory)
        time.sleep(0.3)
        t0 = time.monotonic()
        p.send_signal(signal.SIGINT)
        _, err = p.communicate(timeout=TIME_LIMIT)
        self.assertLess(time.monotonic() - t0, 1.0)  # parsing to the end takes ~3 s
        self.assertEqual(p.returncode, 130, err)
        self.assertEqual(err, "seaflex: stopped by SIGINT\n")
        # statics of 100000 load increments (minutes): SIGTERM stops it after the current
        # increment, which is kept in statics_partial.csv
        model = self.model(CANTILEVER + "statics: {load_steps: 100000}\n")
        p = subprocess.Popen([SEAFLEX, "statics", model, "-o", self.out, "-q"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             preexec_fn=limit_memory)
        time.sleep(1.0)
        t0 = time.monotonic()
        p.send_signal(signal.SIGTERM)
        _, err = p.communicate(timeout=TIME_LIMIT)
        self.assertLess(time.monotonic() - t0, 1.0)  # an increment takes about 1 ms
        self.assertEqual(p.returncode, 143, err)
        partial = os.path.join(self.out, "statics_partial.csv")
        lines = err.splitlines()
        self.assertEqual(lines[0], "seaflex: the last converged statics increment is in " + partial)
        self.assertRegex(lines[1], r"^seaflex: interrupted by SIGTERM in statics after the "
                                   r"increment to load factor 0\.\d+$")
        with open(partial) as f:
            rows = f.read().splitlines()
        self.assertEqual(len(rows), 2)  # header and the last converged state
        self.assertFalse(os.path.exists(os.path.join(self.out, "statics.csv")))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
