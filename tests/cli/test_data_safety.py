#!/usr/bin/env python3
"""Data loss and corruption (issue 22): a link planted under a temporary or result file
name is never followed; resume refuses missing or cut result files, changed input files
and damaged checkpoints with a located message (exit 2) and changes nothing; a full disk
(RLIMIT_FSIZE) leaves every CSV complete up to its last whole row, names the file and
exits 3. Every test also asserts that no file outside the output folder changed.

usage: test_data_safety.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import csv
import hashlib
import os
import resource
import shutil
import signal
import subprocess
import sys
import unittest

from cli_support import SANITIZER_BUILD, SEAFLEX, SRC, TempDirCase, run


EXAMPLES = os.path.join(SRC, "examples")


def snapshot(top, skip):
    """sha256 of every file under top (links as their target text), except under skip"""
    out = {}
    for root, dirs, files in os.walk(top):
        if os.path.abspath(root).startswith(os.path.abspath(skip)):
            continue
        for name in files:
            p = os.path.join(root, name)
            if os.path.islink(p):
                out[p] = "link:" + os.readlink(p)
            else:
                with open(p, "rb") as f:
                    out[p] = hashlib.sha256(f.read()).hexdigest()
    return out


def line_of(path, key):
    with open(path) as f:
        for k, line in enumerate(f, 1):
            if line.split(" ", 1)[0] == key:
                return k
    raise KeyError(key)


def set_entry(path, key, value):
    with open(path) as f:
        lines = f.read().split("\n")
    lines = [key + " " + value if l.split(" ", 1)[0] == key else l for l in lines]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def entry(path, key):
    with open(path) as f:
        for line in f:
            if line.split(" ", 1)[0] == key:
                return line.rstrip("\n").split(" ", 1)[1]
    raise KeyError(key)


def check_csv(test, path):
    """a complete CSV: ends with a newline, every row as many fields as the header"""
    with open(path, "rb") as f:
        data = f.read()
    test.assertTrue(data.endswith(b"\n"), "%s ends in a partial line" % path)
    test.assertNotIn(b"\0", data, path)
    rows = list(csv.reader(data.decode().splitlines()))
    test.assertGreater(len(rows), 1, path)
    test.assertTrue(all(len(r) == len(rows[0]) for r in rows), "%s: uneven rows" % path)
    return rows


class DataSafety(TempDirCase):
    def setUp(self):
        super().setUp()
        # the drilling rig with RAO motion from a table (an input file), 6 s instead of 200
        with open(os.path.join(EXAMPLES, "drilling_rig_raos.yaml")) as f:
            text = f.read()
        self.assertIn("\n  duration: 200\n", text)
        self.src = os.path.join(self.dir, "model")
        os.mkdir(self.src)
        self.model_path = os.path.join(self.src, "rig.yaml")
        with open(self.model_path, "w") as f:
            f.write(text.replace("\n  duration: 200\n", "\n  duration: 6\n"))
        self.table = os.path.join(self.src, "drilling_rig_raos.csv")
        shutil.copy(os.path.join(EXAMPLES, "drilling_rig_raos.csv"), self.table)
        self.out = os.path.join(self.dir, "out")
        self.ckpt = os.path.join(self.out, "checkpoint.txt")
        self.victim = os.path.join(self.dir, "victim.txt")  # outside the output folder
        with open(self.victim, "w") as f:
            f.write("precious\n" * 10000)

    def checkpointed(self):
        """a finished run with checkpoints every 2 s: its last is at t = 4 s"""
        r = run("run", self.model_path, "-o", self.out, "-q", "--checkpoint-every", "2")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(entry(self.ckpt, "state.t"), "0x1p+2")

    def refused(self, message, memory=None):
        """resume exits 2 with exactly this message and changes no file anywhere"""
        before = snapshot(self.dir, os.path.join(self.dir, "none"))

        def limits():
            if memory and not SANITIZER_BUILD:
                resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        r = subprocess.run([SEAFLEX, "resume", self.out, "-q"], capture_output=True, text=True,
                           timeout=60, preexec_fn=limits)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertEqual(r.stderr, message + "\n")
        self.assertEqual(snapshot(self.dir, os.path.join(self.dir, "none")), before)

    def test_planted_links_are_never_followed(self):
        # the old fixed temporary name, a link to a file outside: the checkpoint is written
        # through an exclusive temporary file instead, and the link and its target stay
        os.mkdir(self.out)
        os.symlink(self.victim, os.path.join(self.out, "checkpoint.txt.tmp"))
        outside = snapshot(self.dir, self.out)
        self.checkpointed()
        self.assertEqual(snapshot(self.dir, self.out), outside)
        self.assertEqual(os.readlink(os.path.join(self.out, "checkpoint.txt.tmp")), self.victim)
        self.assertEqual([n for n in os.listdir(self.out) if ".tmp." in n], [])  # none left
        # a result file replaced by a link before resume: refused, nothing written through it
        along = os.path.join(self.out, "riser.along.csv")
        os.remove(along)
        os.symlink(self.victim, along)
        self.refused("%s:%d:1: recorder1.beam0.bytes: %s is a symbolic link (results are never "
                     "written through a link): resume needs the files of the run before the "
                     "checkpoint; start the run again"
                     % (self.ckpt, line_of(self.ckpt, "recorder1.beam0.bytes"), along))
        # an envelope planted as a link is replaced (rename), its target untouched
        os.remove(along)
        r = run("run", self.model_path, "-o", self.out, "-q", "--checkpoint-every", "2")
        self.assertEqual(r.returncode, 0, r.stderr)
        envelope = os.path.join(self.out, "riser.envelope.csv")
        os.remove(envelope)
        os.symlink(self.victim, envelope)
        r = run("resume", self.out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertFalse(os.path.islink(envelope))
        self.assertEqual(snapshot(self.dir, self.out), outside)

    def test_resume_refuses_missing_or_cut_result_files(self):
        self.checkpointed()
        along = os.path.join(self.out, "riser.along.csv")
        key = "recorder1.beam0.bytes"
        where = "%s:%d:1: %s: " % (self.ckpt, line_of(self.ckpt, key), key)
        again = "resume needs the files of the run before the checkpoint; start the run again"
        bytes_ = int(entry(self.ckpt, key))
        # deleted: used to be padded with 4 MB of NUL bytes, exit 0
        with open(along, "rb") as f:
            kept = f.read()
        os.remove(along)
        self.refused(where + "%s is missing: %s" % (along, again))
        self.assertFalse(os.path.exists(along))
        # cut short
        with open(along, "wb") as f:
            f.write(kept[:1000])
        self.refused(where + "%s has 1000 bytes, fewer than the %d it had at the checkpoint: it "
                     "was cut or replaced; %s" % (along, bytes_, again))
        with open(along, "wb") as f:
            f.write(kept)
        # a damaged byte count: beyond the file, negative, not a number ("cannot resize
        # file" and std::stoi leaked before)
        set_entry(self.ckpt, key, "4000000000")
        self.refused(where + "%s has %d bytes, fewer than the 4000000000 it had at the "
                     "checkpoint: it was cut or replaced; %s" % (along, len(kept), again))
        set_entry(self.ckpt, key, "-5")
        self.refused(where + "must be from 0 to 9223372036854775807, got -5")
        set_entry(self.ckpt, key, "1e3")
        self.refused(where + "not a whole number: '1e3'")
        set_entry(self.ckpt, key, str(bytes_))
        r = run("resume", self.out, "-q")  # repaired: resumes
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = check_csv(self, along)
        self.assertEqual(float(rows[-1][0]), 6.0)

    def test_resume_refuses_changed_inputs(self):
        self.checkpointed()
        key = "input0.file"
        self.assertEqual(bytes.fromhex(entry(self.ckpt, key)).decode(), self.table)
        where = "%s:%d:1: %s: " % (self.ckpt, line_of(self.ckpt, key), key)
        with open(self.table, "rb") as f:
            kept = f.read()
        with open(self.table, "ab") as f:  # one more (valid) line
            f.write(b"\n")
        self.refused(where + "the input file %s changed since the checkpoint: a restart needs the "
                     "same inputs" % self.table)
        os.remove(self.table)
        self.refused(where + "the input file %s is gone since the checkpoint: a restart needs the "
                     "same inputs" % self.table)
        with open(self.table, "wb") as f:
            f.write(kept)
        r = run("resume", self.out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_checkpoint_reader_validates_every_field(self):
        self.checkpointed()
        with open(self.ckpt) as f:
            good = f.read()

        def damaged(key, value, message, memory=None):
            with open(self.ckpt, "w") as f:
                f.write(good)
            set_entry(self.ckpt, key, value)
            self.refused("%s:%d:1: %s: %s" % (self.ckpt, line_of(self.ckpt, key), key, message),
                         memory)

        q = entry(self.ckpt, "state.v").split(" ")
        self.assertEqual(q[0], "115")
        # state.v of the wrong length: read out of bounds before (valgrind)
        damaged("state.v", " ".join(["114"] + q[1:-1]),
                "has 114 entries where the model has 115: the checkpoint is for another model or "
                "damaged")
        damaged("state.v", " ".join(q[:-1]), "a size of 115 does not match the 114 numbers on the line")
        damaged("state.q", " ".join(["115", "0x1p+0z"] + q[2:]), "not a number: '0x1p+0z'")
        damaged("recorder1.beam0.envelope.min", "3 16 " + " ".join(["0"] * 48),
                "is 3 x 16 where the model needs 31 x 16: the checkpoint is for another model or "
                "damaged")
        damaged("sim.ticks", "-1", "must be from 0 to 62914560, got -1")
        damaged("sim.level", "99", "must be from 0 to 20, got 99")
        damaged("state.t", "inf", "must be finite, got inf")
        damaged("checkpoint_rows", "0", "must be from 1 to 60, got 0")
        # the model entry: not hex (std::stoi leaked), /dev/zero (2 GB were allocated; the
        # resume runs with 1 GB of address space here)
        damaged("model", "2f7", "not a file name written by seaflex (pairs of lowercase hex digits)")
        damaged("model", "zz", "not a file name written by seaflex (pairs of lowercase hex digits)")
        damaged("model", b"/dev/zero".hex(),
                "/dev/zero is not a regular file (a directory, device or pipe is not a model)",
                memory=1 << 30)
        damaged("model", self.src.encode().hex(),
                "%s is not a regular file (a directory, device or pipe is not a model)" % self.src)
        # a line twice
        with open(self.ckpt, "w") as f:
            f.write(good + "state.t 0x1p+1\n")
        self.refused("%s:%d:1: state.t: appears twice (first on line %d)"
                     % (self.ckpt, good.count("\n") + 1, line_of(self.ckpt, "state.t")))
        # not a checkpoint at all: a directory, a device
        os.remove(self.ckpt)
        os.mkdir(self.ckpt)
        self.refused("%s: not a regular file (a directory, device or pipe is not a checkpoint)"
                     % self.ckpt)
        os.rmdir(self.ckpt)
        os.symlink("/dev/zero", self.ckpt)
        self.refused("%s: not a regular file (a directory, device or pipe is not a checkpoint)"
                     % self.ckpt, memory=1 << 30)

    def test_full_disk_keeps_whole_rows_and_names_the_file(self):
        # RLIMIT_FSIZE stands for a full disk: a write beyond it fails with EFBIG (SIGXFSZ
        # ignored). riser.along.csv (10 kB a row) reaches 60 kB first, at its 6th row;
        # timeseries.csv (4 kB a row), the checkpoint and the envelope stay below
        outside = snapshot(self.dir, self.out)

        def limited(size):
            def pre():
                signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
                resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))
            return subprocess.run([SEAFLEX, "run", self.model_path, "-o", self.out, "-q",
                                   "--checkpoint-every", "2"],
                                  capture_output=True, text=True, timeout=60, preexec_fn=pre)
        r = limited(60000)
        self.assertEqual(r.returncode, 3, r.stderr)
        along = os.path.join(self.out, "riser.along.csv")
        self.assertEqual(r.stderr,
                         "seaflex: results up to the failure are in %s\n"
                         "seaflex: cannot write %s: File too large (the file size limit, ulimit -f)\n"
                         % (os.path.join(self.out, "timeseries.csv"), along))
        rows = check_csv(self, along)
        series = check_csv(self, os.path.join(self.out, "timeseries.csv"))
        envelope = check_csv(self, os.path.join(self.out, "riser.envelope.csv"))
        self.assertLessEqual(os.path.getsize(along), 60000)
        # whole rows of 31 stations, the last time also in timeseries.csv
        self.assertEqual((len(rows) - 1) % 31, 0)
        self.assertEqual(rows[-1][1], "30")
        self.assertIn(rows[-1][0], [row[0] for row in series])
        self.assertEqual(len(envelope), 32)
        # 20 kB: the envelope (30 kB) cannot be written either: it is absent (no temporary
        # file left), and both files are named
        r = limited(20000)
        self.assertEqual(r.returncode, 3, r.stderr)
        envelope = os.path.join(self.out, "riser.envelope.csv")
        self.assertEqual(r.stderr,
                         "seaflex: cannot write %s: File too large (the file size limit, ulimit -f)\n"
                         "seaflex: results up to the failure are in %s\n"
                         "seaflex: cannot write %s: File too large (the file size limit, ulimit -f)\n"
                         % (envelope, os.path.join(self.out, "timeseries.csv"), along))
        self.assertFalse(os.path.exists(envelope))
        self.assertEqual([n for n in os.listdir(self.out) if ".tmp." in n], [])
        for name in os.listdir(self.out):
            if name.endswith(".csv"):
                check_csv(self, os.path.join(self.out, name))
        self.assertEqual(snapshot(self.dir, self.out), outside)

    def test_hdf5_write_failure_exits_3_once_without_a_crash(self):
        # the same limit on HDF5 output: statics.h5 (370 kB) or timeseries.h5 cannot be
        # written. Was: the error escaped as a generic one (exit 2), was printed twice, and
        # HDF5's exit handler then crashed on the file it could not close (SIGSEGV). Now:
        # exit 3, the file named once. (A file cut by the limit may not open: HDF5 records
        # its end of file ahead of the data; CSV output keeps whole rows.)
        for size, name in ((200000, "statics.h5"), (390000, "timeseries.h5")):
            out = os.path.join(self.dir, "h5_%d" % size)

            def pre():
                signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
                resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))
            r = subprocess.run([SEAFLEX, "run", os.path.join(EXAMPLES, "barge_riser.yaml"),
                                "-o", out, "-q", "--format", "hdf5"],
                               capture_output=True, text=True, timeout=120, preexec_fn=pre)
            self.assertEqual(r.returncode, 3, r.stderr)
            message = "seaflex: cannot write %s: HDF5 H5Fflush failed\n" % os.path.join(out, name)
            self.assertEqual(r.stderr.count(message), 1, r.stderr)
            self.assertNotIn("error:", r.stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
