#!/usr/bin/env python3
"""The bad-input corpus (issue 9): every model in this directory is malformed in one way.

    check_corpus.py SEAFLEX DIR

For each DIR/*.yaml, `seaflex check` and `seaflex run` must exit with code 2 (input error)
within 30 s, print the line that expected.txt gives for the file (file:line:col: key:
message, exactly), write no results, and never crash: no signal, no sanitizer report, no
uncaught exception. expected.txt holds one line per model; a model without a line, or a
line without a model, fails the check.
"""
import os
import subprocess
import sys
import tempfile

CRASH_MARKERS = ("Sanitizer", "runtime error:", "terminate called", "Segmentation fault",
                 "core dumped", "Assertion")


def main(seaflex, corpus):
    seaflex = os.path.abspath(seaflex)
    with open(os.path.join(corpus, "expected.txt")) as f:
        expected = {}
        for line in f:
            line = line.rstrip("\n")
            if line:
                expected[line.split(":", 1)[0]] = line
    models = sorted(n for n in os.listdir(corpus) if n.endswith(".yaml"))
    failures = []
    if len(models) < 40:
        failures.append("the corpus holds %d models, fewer than 40" % len(models))
    for name in sorted(set(expected) - set(models)):
        failures.append("%s: expected.txt names a model that is not there" % name)
    with tempfile.TemporaryDirectory() as tmp:
        for name in models:
            if name not in expected:
                failures.append("%s: no expected message in expected.txt" % name)
                continue
            out = os.path.join(tmp, name)
            for cmd in (["check", name], ["run", name, "-o", out, "-q"]):
                try:
                    r = subprocess.run([seaflex, *cmd], cwd=corpus, capture_output=True, text=True,
                                       timeout=30)
                except subprocess.TimeoutExpired:
                    failures.append("%s: seaflex %s hangs (30 s)" % (name, cmd[0]))
                    continue
                what = "%s (seaflex %s)" % (name, cmd[0])
                if r.returncode != 2:
                    failures.append("%s: exit code %d, expected 2\n%s" % (what, r.returncode, r.stderr))
                if any(m in r.stderr for m in CRASH_MARKERS):
                    failures.append("%s: crashed\n%s" % (what, r.stderr))
                if expected[name] not in r.stderr.splitlines():
                    failures.append("%s: expected the line\n  %s\ngot\n  %s" %
                                    (what, expected[name], r.stderr.strip().replace("\n", "\n  ")))
                if cmd[0] == "run" and os.path.exists(os.path.join(out, "timeseries.csv")):
                    failures.append("%s: wrote results for a rejected model" % what)
    for f in failures:
        print("FAIL " + f)
    print("%d models, %d failures" % (len(models), len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: check_corpus.py SEAFLEX DIR")
    sys.exit(main(sys.argv[1], sys.argv[2]))
