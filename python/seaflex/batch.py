"""Load-case batches of seaflex on dask.distributed (docs/python-batch.md).

    seaflex.batch.run(base_model, cases, client=None, output="batch", workers=None,
                      scheduler=None, progress=True)
    python3 -m seaflex.batch CASES.yaml -o DIR [--workers N | --scheduler ADDRESS]
    seaflex batch CASES.yaml -o DIR [--workers N | --scheduler ADDRESS]

A base model plus variations (any key path; a product of lists and/or an explicit table, see
_batch_cases.py). Every case is the base model with its variation, written as YAML into its
own folder OUTPUT/<case>/ and run there by the command-line executable (HDF5 results); its
row of the summary table (OUTPUT/summary.csv, also returned as a pandas DataFrame) holds
the varied values, the status, the wall time, the message of a failure and statistics of
the chosen channels. A failed case does not stop the others; a finished case (a marker that
matches its model) is not run again; a worker killed mid-case loses nothing (the case runs
again elsewhere). Dask: a LocalCluster of `workers` processes with one thread each by
default, the scheduler at `scheduler`, or the given `client`. Exit codes of the command
line: 0 every case ok, 2 bad input (nothing run), 3 some case failed (see the summary).
"""

import argparse
import math
import os
import sys
import time
import uuid

from seaflex._batch_cases import BatchError, Marks, find_executable, parse, read_yaml, value_text
from seaflex._batch_run import finished_row, run_case, write_atomically

__all__ = ["run", "main", "BatchError"]

SUMMARY = "summary.csv"
# connecting to a scheduler gives up after this long (Dask's own default is 30 s)
CONNECT_TIMEOUT_S = 5
# cases handed to Dask at a time (each with its model's text); the others wait their turn
MAX_IN_FLIGHT = 512


def _base(base_model):
    """(model dict, its file or None) from a path, a dict, or an object with to_dict() and
    source_path (seaflex.Model)."""
    if base_model is None:
        return None, None
    if isinstance(base_model, (str, os.PathLike)):
        path = os.fspath(base_model)
        if not os.path.isfile(path):
            raise BatchError(f"{path}: no such model file")
        data, _ = read_yaml(path, "model file")
        return data, path
    if isinstance(base_model, dict):
        return base_model, None
    if hasattr(base_model, "to_dict"):
        source = getattr(base_model, "source_path", None)
        return base_model.to_dict(), os.fspath(source) if source else None
    raise BatchError(f"base_model: expected a model file, a dict or a seaflex.Model, got "
                     f"{type(base_model).__name__}")


def _output_folder(output):
    """Creates the output folder; BatchError when it is a file or cannot be written."""
    output = os.path.abspath(os.fspath(output))
    if os.path.exists(output) and not os.path.isdir(output):
        raise BatchError(f"{output}: the output folder is a file")
    try:
        os.makedirs(output, exist_ok=True)
        probe = os.path.join(output, f".seaflex-batch-probe-{uuid.uuid4().hex[:8]}")
        with open(probe, "w", encoding="utf-8"):
            pass
        os.remove(probe)
    except OSError as e:
        raise BatchError(f"{output}: cannot write into the output folder: "
                         f"{e.strerror or e}") from None
    return output


def _clean_temporaries(output, names):
    """Removes what killed attempts left (OUTPUT/.<case>.tmp-*, .old-*)."""
    import shutil
    prefixes = tuple(f".{n}." for n in names)
    for entry in os.listdir(output):
        if entry.startswith(prefixes) and (".tmp-" in entry or ".old-" in entry):
            shutil.rmtree(os.path.join(output, entry), ignore_errors=True)


class _Progress:
    """A text progress bar on stderr: redrawn in place on a terminal, one line per finished
    case otherwise (logs)."""

    def __init__(self, total, enabled, stream=None):
        self.total, self.enabled = total, enabled
        self.stream = stream or sys.stderr
        self.tty = self.stream.isatty()
        self.done = self.failed = 0
        self.t0 = time.monotonic()

    def update(self, row):
        self.done += 1
        self.failed += row.get("status") != "ok"
        self.show(row)

    def show(self, row=None):
        """Draws the bar (on a terminal; a log gets a line per finished case)."""
        if not self.enabled or (row is None and not self.tty):
            return
        width = 30
        filled = int(width * self.done / max(1, self.total))
        text = (f"[{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} cases, "
                f"{self.failed} failed, {time.monotonic() - self.t0:.0f} s")
        if self.tty:
            self.stream.write("\r" + text + ("\n" if self.done == self.total else ""))
        else:
            self.stream.write(f"{text}: {row.get('case')} {row.get('status')}\n")
        self.stream.flush()


START_HINT = ("start one with dask-scheduler and dask-worker, or leave out --scheduler for a "
              "local cluster")


def _reachable(scheduler):
    """Refuses a scheduler address that is malformed, or (TCP) where nothing answers within
    CONNECT_TIMEOUT_S: a refused connection is reported at once, not after Dask's
    retries."""
    import socket
    from distributed.comm.addressing import parse_address, parse_host_port
    from distributed.comm.registry import get_backend
    try:
        scheme, location = parse_address(scheduler)
        get_backend(scheme)
        if scheme not in ("tcp", "tls"):
            return
        host, port = parse_host_port(location)
        if not 1 <= int(port) <= 65535:
            raise ValueError(f"port {port} outside 1 to 65535")
    except (ValueError, TypeError) as e:
        raise BatchError(f"--scheduler: {scheduler}: not a scheduler address ({e}); expected "
                         "tcp://HOST:PORT") from None
    try:
        socket.create_connection((host, port), timeout=CONNECT_TIMEOUT_S).close()
    except OSError as e:
        reason = e.strerror or (f"no answer within {CONNECT_TIMEOUT_S} s"
                                if isinstance(e, TimeoutError) else str(e))
        raise BatchError(f"cannot reach the Dask scheduler at {scheduler}: {reason}; "
                         f"{START_HINT}") from None


def _connect(client, workers, scheduler):
    """(client, things to close): the given client, a client of the scheduler, or a new
    LocalCluster of `workers` processes with one thread each."""
    if client is not None:
        if workers is not None or scheduler is not None:
            raise BatchError("give a client, or workers, or a scheduler address, not several")
        return client, []
    if workers is not None and scheduler is not None:
        raise BatchError("--workers and --scheduler: give one (the scheduler's workers run the "
                         "cases)")
    import dask
    from distributed import Client, LocalCluster
    if scheduler is not None:
        _reachable(scheduler)
        try:
            with dask.config.set({"distributed.comm.timeouts.connect":
                                  f"{CONNECT_TIMEOUT_S}s"}):
                c = Client(scheduler, timeout=CONNECT_TIMEOUT_S, set_as_default=False)
        except (OSError, TimeoutError) as e:
            raise BatchError(f"cannot reach the Dask scheduler at {scheduler} within "
                             f"{CONNECT_TIMEOUT_S} s ({type(e).__name__}: {e}); {START_HINT}") \
                from None
        return c, [c]
    n = workers if workers is not None else (os.cpu_count() or 1)
    problem = _worker_count(n)
    if problem:
        raise BatchError(f"workers: {problem}")
    # dashboard on a free port: with None distributed 2022.12 still serves HTTP on 8787 and
    # warns on stderr when another cluster (a second batch) holds that port
    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=40)
    c = Client(cluster, set_as_default=False)
    return c, [c, cluster]


def _frame(rows, batch):
    import pandas as pd
    frame = pd.DataFrame(rows)
    fixed = ["case"] + batch.paths + ["status", "exit_code", "wall_time", "message", "reused",
                                      "host"]
    for column in fixed:
        if column not in frame:
            frame[column] = math.nan
    for path in batch.paths:  # lists and mappings as YAML text, numbers stay numbers
        frame[path] = [v if v is None or isinstance(v, (int, float, str)) else value_text(v)
                       for v in frame[path]]
    rest = [c for c in frame.columns if c not in fixed]
    return frame[fixed + rest]


def run(base_model, cases, client=None, output="batch", workers=None, scheduler=None,
        progress=True, executable=None):
    """Runs a batch and returns its summary (a pandas DataFrame, also OUTPUT/summary.csv).

    base_model: a model file, a dict, a seaflex.Model (to_dict() and source_path), or None
    when cases names it (`model:`). cases: the contents of a CASES.yaml as a dict (product,
    table, set, summary, command, timeout), a list of table rows, or a file name. client: a
    dask.distributed Client; else scheduler (an address, tcp://HOST:PORT); else a LocalCluster
    of `workers` processes (default: the machine's cores). executable: the seaflex executable
    (default $SEAFLEX_EXECUTABLE, else seaflex on PATH). Raises BatchError for bad input
    before any case runs; failed cases are rows with their status and message."""
    base, base_path = _base(base_model)
    if isinstance(cases, (str, os.PathLike)):
        data, marks = read_yaml(os.fspath(cases), "cases file")
    else:
        data, marks = cases, Marks("cases")
    batch = parse(data, marks, base, base_path, executable)
    output = _output_folder(output)
    exe = find_executable(executable)
    if exe and os.path.isfile(exe):
        exe = os.path.abspath(exe)
    names = [c.name for c in batch.cases]
    _clean_temporaries(output, names)

    rows, todo = {}, []
    for case in batch.cases:
        row = finished_row(os.path.join(output, case.name), case.digest)
        if row is not None:
            row["reused"] = True
            rows[case.name] = row
        else:
            todo.append(case)
    bar = _Progress(len(batch.cases), progress)
    for case in batch.cases:
        if case.name in rows:
            bar.update(rows[case.name])
    summary = {"channels": batch.summary.channels, "statistics": batch.summary.statistics}
    if todo:
        bar.show()  # before the cluster starts (a second or two)
        client, closing = _connect(client, workers, scheduler)
        try:
            from distributed import as_completed
            token = uuid.uuid4().hex[:8]
            futures, pending = {}, iter(todo)
            running = as_completed([], loop=client.loop)

            def submit_next():
                case = next(pending, None)
                if case is None:
                    return
                model = batch.model(case)
                task = {"name": case.name, "values": case.values,
                        "text": batch.text(case, model), "digest": case.digest,
                        "output": output, "command": batch.command, "executable": exe,
                        "timeout": batch.timeout, "summary": summary,
                        "start": batch.start(model)}
                future = client.submit(run_case, task, key=f"seaflex-case-{case.name}-{token}",
                                       retries=1)
                futures[future] = case
                running.add(future)

            for _ in range(MAX_IN_FLIGHT):  # the rest as these finish
                submit_next()
            for future in running:
                case = futures.pop(future)
                try:
                    row = future.result()
                except Exception as e:  # lost workers (KilledWorker) or a broken environment
                    row = {"case": case.name, "status": "error",
                           "message": f"{type(e).__name__}: {e}", "reused": False}
                rows[case.name] = row
                bar.update(row)
                submit_next()
        finally:
            for thing in closing:
                thing.close()
        _clean_temporaries(output, names)
    ordered = []
    for case in batch.cases:
        row = dict(rows[case.name])
        row.update(case.values)
        ordered.append(row)
    frame = _frame(ordered, batch)
    write_atomically(os.path.join(output, SUMMARY), frame.to_csv(index=False))
    return frame


def _worker_count(n):
    """A worker count: a whole number from 1 to the machine's cores (more workers than cores
    run no faster, and each is a Python process of its own); else the message."""
    cores = os.cpu_count() or 1
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        return f"must be a whole number from 1 to {cores} (the cores of this machine), got '{n}'"
    if n > cores:
        return (f"{n} is more than the {cores} core{'s' if cores != 1 else ''} of this machine; "
                f"use at most {cores} (or a cluster: --scheduler)")
    return None


def _whole_number(text):
    try:
        n = int(text)
    except ValueError:
        n = text
    problem = _worker_count(n)
    if problem:
        raise argparse.ArgumentTypeError(problem)
    return n


def main(argv=None):
    """python3 -m seaflex.batch CASES.yaml -o DIR [--workers N | --scheduler ADDRESS]."""
    parser = argparse.ArgumentParser(
        prog=os.environ.get("SEAFLEX_BATCH_PROG", "python3 -m seaflex.batch"),
        description="run a seaflex load-case batch on dask.distributed (docs/python-batch.md)")
    parser.add_argument("cases", metavar="CASES", help="the cases file (YAML)")
    parser.add_argument("-o", "--output", default="batch",
                        help="output folder: a folder per case and summary.csv (default: batch)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", type=_whole_number,
                       help="worker processes of a local cluster (default and most: the "
                            "machine's cores)")
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="a running Dask scheduler (tcp://HOST:PORT) whose workers run the "
                            "cases")
    parser.add_argument("-q", "--quiet", action="store_true",
                        help="no progress bar; print only errors and failed cases")
    args = parser.parse_args(argv)
    try:
        frame = run(None, args.cases, output=args.output, workers=args.workers,
                    scheduler=args.scheduler, progress=not args.quiet)
    except BatchError as e:
        print(e, file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("seaflex batch: interrupted; finished cases are kept (run again to continue)",
              file=sys.stderr)
        return 130
    failed = frame[frame["status"] != "ok"]
    for _, row in failed.iterrows():
        message = str(row["message"]).replace("\n", "\n  ")
        print(f"seaflex batch: case {row['case']}: {row['status']}: {message}",
              file=sys.stderr)
    if not args.quiet:
        reused = int(frame["reused"].fillna(False).astype(bool).sum())
        print(f"{len(frame)} cases: {len(frame) - len(failed)} ok ({reused} finished before), "
              f"{len(failed)} failed; summary: "
              f"{os.path.join(os.path.abspath(args.output), SUMMARY)}")
    return 3 if len(failed) else 0


if __name__ == "__main__":
    sys.exit(main())
