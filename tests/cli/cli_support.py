"""What the command-line tests share: the seaflex executable and source tree from the
command line (SEAFLEX_EXECUTABLE SOURCE_DIR), running seaflex, and a test case with its own
temporary directory."""
import os
import subprocess
import sys
import tempfile
import unittest

SEAFLEX = sys.argv[1] if len(sys.argv) > 1 else "build/seaflex"
SRC = sys.argv[2] if len(sys.argv) > 2 else "."


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
