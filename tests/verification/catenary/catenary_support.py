"""What the catenary verification tests share: the seaflex executable from the command line
(SEAFLEX_EXECUTABLE SOURCE_DIR), running it in a temporary directory, reading its CSV
results, and the YAML of a line on a flat seabed."""
import csv
import math
import os
import subprocess
import sys
import tempfile
import unittest

SEAFLEX = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else "/work/main/build/seaflex"
SRC = sys.argv[2] if len(sys.argv) > 2 else "."

G = 9.80665            # seaflex's default gravity
RHO_W = 1025.0


def read_rows(path):
    """The rows of a seaflex CSV file as dicts of floats."""
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def yaml_points(points):
    return "[" + ", ".join("[%.17g, %.17g, %.17g]" % tuple(p) for p in points) + "]"


def polyline_length(points):
    return sum(math.dist(points[i], points[i + 1]) for i in range(len(points) - 1))


class SeaflexCase(unittest.TestCase):
    """A test case with a fresh temporary directory and a way to run seaflex in it."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def seaflex(self, command, text, name="model", timeout=600):
        """Writes the model, runs `seaflex COMMAND model.yaml -o out_NAME` and returns
        (completed process, output directory)."""
        path = os.path.join(self.dir, name + ".yaml")
        with open(path, "w") as f:
            f.write(text)
        out = os.path.join(self.dir, "out_" + name)
        p = subprocess.run([SEAFLEX, command, path, "-o", out], capture_output=True, text=True,
                           timeout=timeout)
        return p, out

    def statics(self, text, name="model"):
        p, out = self.seaflex("statics", text, name)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        return read_rows(os.path.join(out, "statics.csv"))[0], out, p.stdout


def newton_iterations(stdout):
    """The Newton iteration count of seaflex statics' summary line."""
    for line in stdout.splitlines():
        if line.startswith("statics converged"):
            return int(line.split("increment(s), ")[1].split(" Newton")[0])
    return None
