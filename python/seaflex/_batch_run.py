"""One case of a seaflex batch, as a Dask worker runs it: a pure function of the case.

The case's model is written into a temporary folder next to the case's own folder, run with
the command-line executable in a subprocess (a crash of seaflex cannot take the worker down;
the subprocess dies with the worker), its HDF5 results summarised, and the folder renamed to
OUTPUT/<case> when done: a worker killed mid-case leaves only a temporary folder, and Dask
runs the case again. The marker OUTPUT/<case>/done.json, written last (atomically) holds the
digest of the case's model and its summary row; a case whose marker matches is finished and
is not run again. A failed case keeps its results up to the failure and failed.json.
"""

import fnmatch
import json
import math
import os
import shutil
import socket
import subprocess
import time
import uuid

DONE = "done.json"
FAILED = "failed.json"
LOG = "log.txt"
MODEL = "model.yaml"
STATUS = {0: "ok", 2: "input_error", 3: "solver_failure"}


def write_atomically(path, text):
    """Writes a file whole or not at all (a temporary file renamed over it)."""
    tmp = f"{path}.tmp-{uuid.uuid4().hex[:8]}"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def finished_row(folder, digest):
    """The summary row of a finished case (its marker matches digest), else None."""
    try:
        with open(os.path.join(folder, DONE), encoding="utf-8") as f:
            marker = json.load(f)
    except (OSError, ValueError):
        return None
    if not isinstance(marker, dict) or marker.get("digest") != digest:
        return None
    row = marker.get("row")
    return row if isinstance(row, dict) else None


def _executable(task):
    exe = task.get("executable")
    if exe and os.path.isfile(exe) and os.access(exe, os.X_OK):
        return exe
    exe = os.environ.get("SEAFLEX_EXECUTABLE") or shutil.which("seaflex")
    return exe if exe and os.access(exe, os.X_OK) else None


def _names(dataset):
    return [n.decode() if isinstance(n, bytes) else str(n) for n in dataset[()]]


def _read_csv(path):
    import csv
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def summarize(folder, stem, summary, start):
    """The summary statistics of a case's results (DIR/<stem>.h5): {column: value} and a list
    of notes (patterns that match nothing). Channels: min, max, mean, std (population) over
    the rows with t >= start; beam quantities `<beam>.<quantity>`: min and max over the
    stations and those rows (the envelope when the rows are not written); the statistics
    section's columns from statistics.csv and the most probable maxima from extremes.csv."""
    import h5py
    import numpy as np

    values, notes = {}, []
    stats = summary["statistics"]
    with h5py.File(os.path.join(folder, f"{stem}.h5"), "r") as f:
        names = _names(f["channel_names"])
        time_ = np.asarray(f["time"][()])
        rows = time_ >= start - 1e-9 * max(1.0, abs(start))
        if not rows.any():
            rows = np.ones_like(rows)  # a statics run (one row) or a start past the end
        data = np.asarray(f["channels"][()])[rows] if len(names) else None
        beams = {}
        for beam, group in (f["beams"].items() if "beams" in f else []):
            for q in (group["results"].keys() if "results" in group else []):
                a = np.asarray(group["results"][q][()])[rows]
                beams[f"{beam}.{q}"] = (np.nanmin(a), np.nanmax(a)) if a.size else (math.nan,) * 2
            if "envelope" in group and "results" not in group:
                for q in group["envelope"]["max"].keys():
                    beams[f"{beam}.{q}"] = (np.nanmin(group["envelope"]["min"][q][()]),
                                            np.nanmax(group["envelope"]["max"][q][()]))
    patterns = summary["channels"]
    chosen_channels, chosen_beams = [], []
    if patterns is None:
        chosen_channels = list(range(len(names)))
    else:
        for p in patterns:
            hits = [i for i, n in enumerate(names) if fnmatch.fnmatchcase(n, p)]
            beam_hits = [b for b in beams if fnmatch.fnmatchcase(b, p)]
            if not hits and not beam_hits:
                notes.append(f"summary.channels: '{p}' matches no channel")
            chosen_channels += [i for i in hits if i not in chosen_channels]
            chosen_beams += [b for b in beam_hits if b not in chosen_beams]
    basic = {"min": np.min, "max": np.max, "mean": np.mean, "std": np.std}
    section = {}
    if any(s not in basic for s in stats):
        for line in _read_csv(os.path.join(folder, "statistics.csv")):
            section[line["channel"]] = line
        for line in _read_csv(os.path.join(folder, "extremes.csv")):
            section.setdefault(line["channel"], {})[f"mpm_{line['method']}"] = \
                line["most_probable_maximum"]
    for i in chosen_channels:
        for s in stats:
            if s in basic:
                values[f"{names[i]}.{s}"] = float(basic[s](data[:, i])) if data.size else math.nan
            else:
                text = section.get(names[i], {}).get(s)
                values[f"{names[i]}.{s}"] = float(text) if text not in (None, "") else math.nan
    for b in chosen_beams:
        lo, hi = beams[b]
        if "min" in stats:
            values[f"{b}.min"] = float(lo)
        if "max" in stats:
            values[f"{b}.max"] = float(hi)
    return values, notes


def _command(exe, task, model, folder):
    args = [exe, task["command"], model, "-o", folder, "-q", "--format", "hdf5"]
    # the case dies with the worker that runs it (a killed worker leaves no orphan running)
    setpriv = shutil.which("setpriv")
    return [setpriv, "--pdeathsig", "KILL", "--"] + args if setpriv else args


def _message(code, stderr):
    text = stderr.strip()
    if code < 0:
        return f"seaflex stopped by signal {-code}" + (f": {text}" if text else "")
    return text or f"seaflex exited with code {code}"


def run_case(task):
    """Runs one case (a dict made by seaflex.batch: name, values, text, digest, output,
    command, executable, timeout, summary, start) and returns its summary row."""
    name, output = task["name"], task["output"]
    final = os.path.join(output, name)
    row = finished_row(final, task["digest"])
    if row is not None:  # finished by an earlier attempt (a retry after a lost worker)
        row["reused"] = True
        return row
    row = {"case": name, "status": "error", "exit_code": math.nan, "wall_time": math.nan,
           "message": "", "host": socket.gethostname(), "reused": False}
    exe = _executable(task)
    if exe is None:
        row["message"] = (f"no seaflex executable on {row['host']}: set SEAFLEX_EXECUTABLE or put "
                          "seaflex on PATH")
        return row
    tmp = os.path.join(output, f".{name}.tmp-{uuid.uuid4().hex[:12]}")
    os.makedirs(tmp)
    model = os.path.join(tmp, MODEL)
    write_atomically(model, task["text"])
    t0 = time.monotonic()
    warned = []
    try:
        with open(os.path.join(tmp, LOG), "w", encoding="utf-8") as log:
            proc = subprocess.run(_command(exe, task, model, tmp), stdout=log,
                                  stderr=subprocess.PIPE, text=True, errors="replace",
                                  timeout=task.get("timeout"), stdin=subprocess.DEVNULL)
            log.write(proc.stderr)
        row["exit_code"] = proc.returncode
        row["status"] = STATUS.get(proc.returncode, "error")
        # the command line's warnings (an unstable statics equilibrium, the loader's),
        # naming the case's folder as it will be
        warned = [line[len("warning: "):].replace(tmp, final)
                  for line in proc.stderr.splitlines() if line.startswith("warning: ")]
        if proc.returncode != 0:
            row["message"] = _message(proc.returncode, proc.stderr).replace(tmp, final)
    except subprocess.TimeoutExpired:
        row["status"] = "timeout"
        row["message"] = f"stopped after the case's timeout of {task['timeout']:g} s"
    except OSError as e:
        row["message"] = f"cannot run {exe}: {e.strerror or e}"
    row["wall_time"] = time.monotonic() - t0
    if row["status"] == "ok":
        try:
            stats, notes = summarize(tmp, "timeseries" if task["command"] == "run" else "statics",
                                     task["summary"], task["start"])
            row.update(stats)
            # the warnings first: a case that ran but warned says so in the summary
            row["message"] = "; ".join(warned + notes)
        except Exception as e:  # the results are there; the summary of them is not
            row["message"] = "; ".join(warned + [f"summary: {type(e).__name__}: {e}"])
    marker = {"case": name, "digest": task["digest"], "row": row}
    write_atomically(os.path.join(tmp, DONE if row["status"] == "ok" else FAILED),
                     json.dumps(marker, indent=1))
    _publish(tmp, final, task["digest"])
    return row


def _publish(tmp, final, digest):
    """Renames the finished temporary folder to the case's folder (an older one, a failed or
    outdated case, goes first). When another attempt published the same case meanwhile, the
    first stays."""
    if os.path.isdir(final):
        if finished_row(final, digest) is not None:
            shutil.rmtree(tmp, ignore_errors=True)
            return
        old = f"{os.path.dirname(final)}/.{os.path.basename(final)}.old-{uuid.uuid4().hex[:12]}"
        os.rename(final, old)
        shutil.rmtree(old, ignore_errors=True)
    os.rename(tmp, final)
