"""What the command-line tests share: the seaflex executable and source tree from the
command line (SEAFLEX_EXECUTABLE SOURCE_DIR), running seaflex, and a test case with its own
temporary directory."""
import os
import resource
import subprocess
import sys
import tempfile
import unittest

SEAFLEX = sys.argv[1] if len(sys.argv) > 1 else "build/seaflex"
SRC = sys.argv[2] if len(sys.argv) > 2 else "."


def _sanitizer_build():
    """True for an AddressSanitizer build (.ci/run's second stage): it reserves terabytes of
    address space for its shadow memory, so it cannot start under a 1 GiB RLIMIT_AS."""
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))
    try:
        return subprocess.run([SEAFLEX, "--version"], capture_output=True, timeout=60,
                              preexec_fn=limit).returncode != 0
    except (OSError, subprocess.SubprocessError):
        return True


SANITIZER_BUILD = _sanitizer_build()
# long runs of whole examples: checked in the release build; under the sanitizers (15 to 20
# times slower) they would take most of .ci/run's time, and their code paths are run
# there by the verification tests
release_only = unittest.skipIf(SANITIZER_BUILD, "a long run: release build only")


def run(*args, timeout=300):
    return subprocess.run([SEAFLEX, *args], capture_output=True, text=True, timeout=timeout)


class TempDirCase(unittest.TestCase):
    """A test case whose files live in a fresh temporary directory, self.dir."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def model(self, text, name="model.yaml"):
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            f.write(text)
        return path
