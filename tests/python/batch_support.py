"""Helpers of the batch tests (tests/python/test_batch*.py): the seaflex executable, the
double pendulum with other masses written by text substitution (independent of the batch's
own YAML writer), serial runs of the command line, processes below a worker."""

import os
import re
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
EXE = os.environ.get("SEAFLEX_EXECUTABLE") or str(REPO / "build" / "seaflex")
PENDULUM = REPO / "examples" / "double_pendulum.yaml"
# 6 x 4 = 24 cases; 2 s of motion (2000 RK4 steps, about 0.3 s of wall time each)
UPPER = [1.0, 1.5, 2.0, 2.5, 3.0, 3.5]
LOWER = [1.0, 1.5, 2.0, 2.5]
DURATION = 2.0


def pendulum_text(upper, lower, duration=DURATION):
    """examples/double_pendulum.yaml with the rods' masses and the duration replaced."""
    text = PENDULUM.read_text()
    for old, new in ((r"\n    mass: 2\.0 ", f"\n    mass: {upper!r} "),
                     (r"\n    mass: 1\.5\n", f"\n    mass: {lower!r}\n"),
                     (r"\n  duration: 10\.0 ", f"\n  duration: {duration!r} ")):
        text, n = re.subn(old, new, text, count=1)
        assert n == 1, old
    return text


def cases_yaml(duration=DURATION):
    """The 24-case batch as a CASES.yaml text."""
    return (f"model: {PENDULUM}\n"
            f"set:\n  dynamics.duration: {duration!r}\n"
            f"product:\n  bodies.upper.mass: {UPPER!r}\n  bodies.lower.mass: {LOWER!r}\n"
            "summary:\n  channels: [lower.z, shoulder.fz]\n")


def serial_runs(folder, duration=DURATION):
    """{(upper, lower): bytes of timeseries.h5} of 24 serial runs of `seaflex run`."""
    results = {}
    for upper in UPPER:
        for lower in LOWER:
            case = folder / f"serial_{upper}_{lower}"
            case.mkdir(parents=True)
            (case / "model.yaml").write_text(pendulum_text(upper, lower, duration))
            subprocess.run([EXE, "run", str(case / "model.yaml"), "-o", str(case), "-q",
                            "--format", "hdf5"], check=True, timeout=60)
            results[(upper, lower)] = (case / "timeseries.h5").read_bytes()
    return results


def children(pid):
    """{pid: command line} of the processes whose parent is pid."""
    found = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                stat = f.read()
            ppid = int(stat.rsplit(")", 1)[1].split()[1])
            if ppid == pid:
                with open(f"/proc/{entry}/cmdline", "rb") as f:
                    found[int(entry)] = f.read().split(b"\0")
        except (OSError, ValueError, IndexError):
            continue
    return found


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False
