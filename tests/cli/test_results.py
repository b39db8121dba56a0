#!/usr/bin/env python3
"""End-to-end tests of seaflex's result files (docs/results-format.md): HDF5 holds the
same numbers as the CSV files, a run killed with SIGKILL leaves a readable HDF5 file with
every row written before the kill, beam results along the length and their envelopes,
and the model's output section (format, channels, bodies).

Needs h5py and VTK's Python module (Debian: python3-h5py, python3-vtk9).

usage: test_results.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import csv
import math
import os
import shutil
import signal
import subprocess
import sys
import time
import unittest

import xml.etree.ElementTree as ET

import h5py
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from cli_support import SEAFLEX, SRC, TempDirCase, run


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:]])


# a 60 m riser in water with mud, pinned at the top, pulled at the bottom, in a current:
# tension, bending and pressures all non-zero
RISER = """
environment:
  gravity: 9.81
  water: {density: 1025, depth: 500}
  current: {speed: 1.0, direction: 0}
bodies:
  riser:
    type: ancf_beam
    start: [0, 0, -5]
    end: [0, 0, -65]
    elements: 45
    outer_diameter: 0.5
    inner_diameter: 0.45
    youngs_modulus: 2.1e11
    density: 7850
  buoy: {type: rigid_body, mass: 100, inertia: [10, 10, 10], position: [5, 0, 0]}
supports:
  - {body: riser, node: start, type: pinned}
hydrodynamics:
  riser: {cd: 1.0, cm: 2.0, contents_density: 1200}
loads:
  - {type: point_force, body: riser, node: end, force: [0, 0, -1.0e5]}
dynamics:
  integrator: generalized_alpha
  time_step: 0.05
  step_control: adaptive
  duration: DURATION
  output_interval: 0.1
"""


class Results(TempDirCase):

    def test_hdf5_holds_the_csv_numbers(self):
        out = os.path.join(self.dir, "out")
        # the envelopes over the rows (the default takes their extremes over every step:
        # test_envelopes_over_every_step)
        text = RISER.replace("DURATION", "2.0") + "output: {envelope_sampling: rows}\n"
        r = run("run", self.model(text), "-o", out, "-q", "--format", "both")
        self.assertEqual(r.returncode, 0, r.stderr)
        header, rows = read_csv(os.path.join(out, "timeseries.csv"))
        with h5py.File(os.path.join(out, "timeseries.h5"), "r") as f:
            self.assertEqual(f.attrs["format"], "seaflex results 1")
            names = [n.decode() for n in f["channel_names"][:]]
            self.assertEqual(["time"] + names, header)
            # 21 rows: t = 0, 0.1, ..., 2.0
            self.assertEqual(f["time"].shape, (21,))
            self.assertEqual(f["channels"].shape, (21, len(names)))
            # the CSV prints 17 significant digits, which round-trip doubles: equal bits
            np.testing.assert_array_equal(f["time"][:], rows[:, 0])
            np.testing.assert_array_equal(f["channels"][:], rows[:, 1:])
            # positions: time x node x 3, the same numbers as the node channels
            pos = f["beams/riser/positions"][:]
            self.assertEqual(pos.shape, (21, 46, 3))
            for k in range(46):
                for c, axis in enumerate("xyz"):
                    np.testing.assert_array_equal(pos[:, k, c],
                                                  rows[:, header.index(f"riser.n{k}.{axis}")])
            # rows under 16 KiB: uncompressed chunks of several rows (rewritten in place)
            self.assertIsNone(f["beams/riser/positions"].compression)
            self.assertEqual(f["beams/riser/positions"].chunks, (14, 46, 3))
            # beam results: per quantity time x station, against riser.along.csv
            s = f["beams/riser/stations/s"][:]
            self.assertEqual(len(s), 3 * 45 + 1)  # 46 nodes, 2 Gauss points per element
            along_header, along = read_csv(os.path.join(out, "riser.along.csv"))
            self.assertEqual(along_header[:3], ["time", "station", "s"])
            self.assertEqual(along.shape[0], 21 * 136)
            for q in along_header[3:]:
                np.testing.assert_array_equal(f[f"beams/riser/results/{q}"][:].ravel(),
                                              along[:, along_header.index(q)], q)
            self.assertEqual(f["beams/riser/results/tension_effective"].attrs["units"], "N")
            # envelopes: min, max, mean over the 21 rows, as riser.envelope.csv
            env_header, env = read_csv(os.path.join(out, "riser.envelope.csv"))
            self.assertEqual(env.shape[0], 136)
            T = f["beams/riser/results/tension_effective"][:]
            np.testing.assert_array_equal(f["beams/riser/envelope/max/tension_effective"][:],
                                          T.max(axis=0))
            np.testing.assert_array_equal(f["beams/riser/envelope/min/tension_effective"][:],
                                          T.min(axis=0))
            # the mean is summed in another order than numpy's: 1e-12 relative
            np.testing.assert_allclose(f["beams/riser/envelope/mean/tension_effective"][:],
                                       T.mean(axis=0), rtol=1e-12)
            for part in ("min", "max", "mean"):
                np.testing.assert_array_equal(
                    f[f"beams/riser/envelope/{part}/moment"][:],
                    env[:, env_header.index(f"moment.{part}")])

    def test_killed_run_leaves_a_readable_hdf5_file(self):
        # The HDF5 file takes its rows in blocks of Hdf5Recorder::kWorkPerBlock = 524288
        # coordinate-steps (io/hdf5_recorder.hpp): this riser has 45 elements (46 nodes x 6
        # coordinates) and the buoy 7, 283 coordinates, and 5 fixed steps per output row, so
        # a block is written once 524288 / (283 x 5) = 370.5 rows of work have been done since
        # the last: the first write holds rows 0..371 (the first row is recorded before any
        # step), each later one 371 more. A run killed with SIGKILL keeps 1 + 371 j rows.
        block = 371
        self.assertEqual(math.ceil(524288 / (283 * 5)), block)
        fixed = (RISER.replace("step_control: adaptive", "step_control: fixed")
                 .replace("time_step: 0.05", "time_step: 0.002")
                 .replace("output_interval: 0.1", "output_interval: 0.01"))
        out = os.path.join(self.dir, "killed")
        model = self.model(fixed.replace("DURATION", "10000"), "long.yaml")
        proc = subprocess.Popen([SEAFLEX, "run", model, "-o", out, "-q", "--format", "both"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        csv_path = os.path.join(out, "timeseries.csv")
        # three blocks of rows: 1 s in release, a minute or two under the sanitizers; the wait
        # ends as soon as the rows are there
        deadline = time.time() + 300
        try:
            while time.time() < deadline:
                if os.path.exists(csv_path):
                    with open(csv_path) as f:
                        if sum(1 for _ in f) > 3 * block + 2:
                            break
                time.sleep(0.05)
            self.assertIsNone(proc.poll(), "the run ended before it was killed")
            proc.send_signal(signal.SIGKILL)
        finally:
            proc.wait()
        self.assertEqual(proc.returncode, -signal.SIGKILL)
        # the CSV file is written row by row, before the HDF5 recorder takes the row: its
        # whole lines are the rows recorded (its last line may be cut)
        with open(csv_path) as f:
            csv_rows = sum(1 for line in f if line.endswith("\n")) - 1
        with h5py.File(os.path.join(out, "timeseries.h5"), "r") as f:
            t = f["time"][:]
            values = f["channels"][:]
            T = f["beams/riser/results/tension_effective"][:]
        n = len(t)
        self.assertGreaterEqual(n, 2 * block + 1)
        self.assertEqual((n - 1) % block, 0, n)
        # at most one block behind the rows recorded
        self.assertLessEqual(csv_rows - n, block, (csv_rows, n))
        # consecutive output times 0, 0.01, 0.02, ... (the loop counts ticks: exact to
        # round-off of k * 0.01)
        np.testing.assert_allclose(t, 0.01 * np.arange(n), rtol=0, atol=1e-9)
        self.assertEqual(values.shape[0], n)
        self.assertEqual(T.shape[0], n)
        # the same numbers as a complete run of the first rows (runs are deterministic)
        ref = os.path.join(self.dir, "ref")
        r = run("run", self.model(fixed.replace("DURATION", f"{0.01 * (n - 1):.2f}"), "short.yaml"),
                "-o", ref, "-q", "--format", "hdf5")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertFalse(os.path.exists(os.path.join(ref, "timeseries.csv")))
        with h5py.File(os.path.join(ref, "timeseries.h5"), "r") as f:
            np.testing.assert_array_equal(f["channels"][:], values)
            np.testing.assert_array_equal(f["beams/riser/results/tension_effective"][:], T)

    def test_output_section_selects_format_channels_and_bodies(self):
        text = RISER.replace("DURATION", "0.2") + """
output:
  format: hdf5
  channels: ["riser.n45.*", "buoy.z"]
  bodies: [riser, buoy]
  beam_results: envelope
"""
        out = os.path.join(self.dir, "sel")
        os.makedirs(out)
        stale = os.path.join(out, "riser.along.csv")
        with open(stale, "w") as f:
            f.write("from an earlier run\n")
        r = run("run", self.model(text), "-o", out)  # not -q: the "wrote" line is read
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("timeseries.h5", r.stdout)
        self.assertFalse(os.path.exists(os.path.join(out, "timeseries.csv")))
        self.assertFalse(os.path.exists(stale))  # earlier results are removed first
        with h5py.File(os.path.join(out, "timeseries.h5"), "r") as f:
            names = [n.decode() for n in f["channel_names"][:]]
            self.assertEqual(names, ["riser.n45.x", "riser.n45.y", "riser.n45.z", "buoy.z"])
            self.assertNotIn("results", f["beams/riser"])  # envelope only
            self.assertEqual(f["beams/riser/envelope"].attrs["rows"], 3)
        # --format overrides the model
        r = run("run", self.model(text), "-o", out, "-q", "--format", "csv")
        self.assertEqual(r.returncode, 0, r.stderr)
        header, rows = read_csv(os.path.join(out, "timeseries.csv"))
        self.assertEqual(header, ["time", "riser.n45.x", "riser.n45.y", "riser.n45.z", "buoy.z"])
        self.assertFalse(os.path.exists(os.path.join(out, "timeseries.h5")))
        self.assertFalse(os.path.exists(os.path.join(out, "riser.along.csv")))
        self.assertTrue(os.path.exists(os.path.join(out, "riser.envelope.csv")))

    def test_statics_in_hdf5(self):
        out = os.path.join(self.dir, "st")
        # without the free buoy, which has no static equilibrium
        text = "\n".join(l for l in RISER.replace("DURATION", "1").splitlines()
                         if not l.strip().startswith("buoy:"))
        r = run("statics", self.model(text), "-o", out, "-q", "--format", "both")
        self.assertEqual(r.returncode, 0, r.stderr)
        header, rows = read_csv(os.path.join(out, "statics.csv"))
        along_header, along = read_csv(os.path.join(out, "statics.riser.along.csv"))
        with h5py.File(os.path.join(out, "statics.h5"), "r") as f:
            np.testing.assert_array_equal(f["channels"][:], rows[:, 1:])
            np.testing.assert_array_equal(f["beams/riser/results/moment"][0],
                                          along[:, along_header.index("moment")])
            # the effective tension at the top carries the pull (1e5 N) and the submerged
            # weight (steel + mud - buoyancy) of the 60 m below; the current's drag (15 kN
            # sideways) adds 0.2 %: 1 % asked
            w_sub = (7850 * np.pi / 4 * (0.25 - 0.2025) + 1200 * np.pi / 4 * 0.2025
                     - 1025 * np.pi / 4 * 0.25) * 9.81
            T_top = f["beams/riser/results/tension_effective"][0, 0]
            self.assertAlmostEqual(T_top / (1e5 + 60 * w_sub), 1.0, delta=0.01)
        self.assertFalse(os.path.exists(os.path.join(out, "statics.riser.envelope.csv")))

    def test_large_rows_are_compressed(self):
        # a 1000-element beam: rows of 3001 stations (24 KiB) are compressed chunks of one row
        text = """
environment: {gravity: 9.81}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 1000, area: 0.01,
         second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
"""
        out = os.path.join(self.dir, "big")
        r = run("statics", self.model(text), "-o", out, "-q", "--format", "hdf5")
        self.assertEqual(r.returncode, 0, r.stderr)
        with h5py.File(os.path.join(out, "statics.h5"), "r") as f:
            for name, chunks in (("beams/beam/positions", (1, 1001, 3)),
                                 ("beams/beam/results/moment", (1, 3001)),
                                 ("channels", (1, 3003))):
                self.assertEqual(f[name].compression, "gzip", name)
                self.assertEqual(f[name].chunks, chunks, name)
            self.assertIsNone(f["time"].compression)
            # the cantilever under its own weight: moment w L^2 / 2 at the root to 1 % (the
            # tip sags 5 % of L, which shortens the lever arms by about 0.3 %)
            w = 7850 * 0.01 * 9.81
            self.assertAlmostEqual(f["beams/beam/results/moment"][0, 0] / (w * 10**2 / 2), 1.0,
                                   delta=0.01)

    @unittest.skipIf(os.environ.get("SEAFLEX_SANITIZED") == "1",
                     "the snap start takes 2300 adaptive steps: 3 minutes under the sanitizers "
                     "(tests/CMakeLists.txt); run in the release build")
    def test_paraview_time_series(self):
        # the riser and the buoy in an Airy wave, and a plate on simply supported edges
        text = RISER.replace("DURATION", "0.4").replace(
            "  current: {speed: 1.0, direction: 0}",
            "  current: {speed: 1.0, direction: 0}\n  waves: {type: airy, height: 2, period: 8}"
        ).replace("supports:", """  plate: {type: ancf_plate, corner: [20, 0, -1], edge1: [4, 0, 0], edge2: [0, 3, 0],
          elements: [2, 3], thickness: 0.05, youngs_modulus: 210e9, poisson_ratio: 0.3,
          density: 7850}
supports:
  - {body: plate, type: simply_supported, edges: [i0, i_max, j0, j_max]}""")
        out = os.path.join(self.dir, "vtk_out")
        r = run("run", self.model(text), "-o", out, "-q", "--vtk", "--format", "hdf5")
        self.assertEqual(r.returncode, 0, r.stderr)
        pvd = ET.parse(os.path.join(out, "timeseries.pvd")).getroot()
        sets = pvd.find("Collection").findall("DataSet")
        # 5 rows (t = 0 ... 0.4) of 4 parts: beams, plates, rigid bodies, sea surface
        self.assertEqual(len(sets), 5 * 4)
        self.assertEqual([d.get("name") for d in sets[:4]], ["riser", "plate", "buoy", "sea_surface"])
        # the times of the rows (3 * 0.1 s steps: 0.30000000000000004, printed exactly)
        times = sorted({float(d.get("timestep")) for d in sets})
        np.testing.assert_allclose(times, [0.0, 0.1, 0.2, 0.3, 0.4], rtol=0, atol=1e-15)

        def read(entry):
            reader = vtk.vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(out, entry.get("file")))
            reader.Update()
            return reader.GetOutput()

        last = {d.get("name"): read(d) for d in sets[-4:]}
        with h5py.File(os.path.join(out, "timeseries.h5"), "r") as f:
            # the riser: a polyline through its 136 stations with the beam results,
            # printed with 17 digits: the HDF5 numbers exactly
            riser = last["riser"]
            self.assertEqual(riser.GetNumberOfPoints(), 136)
            self.assertEqual(riser.GetNumberOfLines(), 1)
            pd = riser.GetPointData()
            for q in ("tension_effective", "moment", "stress_von_mises"):
                np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray(q)),
                                              f[f"beams/riser/results/{q}"][-1], q)
            np.testing.assert_array_equal(vtk_to_numpy(pd.GetArray("outer_diameter")),
                                          np.full(136, 0.5))
            pts = vtk_to_numpy(riser.GetPoints().GetData())
            np.testing.assert_array_equal(pts[::3], f["beams/riser/positions"][-1])  # the nodes
            # the buoy: the box of its inertia (10 kg m^2 about each axis, 100 kg): a cube of
            # side sqrt(6 * 10 / 100), centred on its centre of gravity (round-off: 1e-12 m)
            buoy = last["buoy"]
            self.assertEqual((buoy.GetNumberOfPoints(), buoy.GetNumberOfPolys()), (8, 6))
            corners = vtk_to_numpy(buoy.GetPoints().GetData())
            names = [n.decode() for n in f["channel_names"][:]]
            cg = [f["channels"][-1, names.index(f"buoy.{a}")] for a in "xyz"]
            np.testing.assert_allclose(corners.mean(axis=0), cg, rtol=0, atol=1e-12)
            np.testing.assert_allclose(np.ptp(corners, axis=0), np.full(3, np.sqrt(0.6)),
                                       rtol=0, atol=1e-12)
            # the plate: (2 + 1) x (3 + 1) nodes, 2 x 3 quads
            plate = last["plate"]
            self.assertEqual((plate.GetNumberOfPoints(), plate.GetNumberOfPolys()), (12, 6))
        # the sea surface: a 41 x 41 grid whose z is the elevation of the 2 m Airy wave:
        # |eta| <= 1 m, and the crest passes x = 0 at t = 0 (eta(0, 0, 0) = 1 m)
        sea = read(sets[3])
        self.assertEqual((sea.GetNumberOfPoints(), sea.GetNumberOfPolys()), (41 * 41, 40 * 40))
        z = vtk_to_numpy(sea.GetPoints().GetData())[:, 2]
        np.testing.assert_array_equal(z, vtk_to_numpy(sea.GetPointData().GetArray("elevation")))
        self.assertLessEqual(np.abs(z).max(), 1.0 + 1e-12)
        self.assertGreater(z.max(), 0.99)
        # asked for only: no vtk files without --vtk or output.vtk
        r = run("run", self.model(text), "-o", out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertFalse(os.path.exists(os.path.join(out, "timeseries.pvd")))
        self.assertFalse(os.path.exists(os.path.join(out, "vtk", "timeseries")))

    def test_envelopes_over_every_step(self):
        # output.envelope_sampling: steps (the default) takes the envelopes' minimum and
        # maximum over every step, not only the output rows: with rows every 10th step they
        # equal those of the same run written at every step, bit for bit (the same states),
        # while the mean stays the mean over the rows; with `rows` the maxima miss the peaks
        # between the rows. From static equilibrium, a regular wave (2 m, 3 s) ramped in over 1 s,
        # fixed 0.01 s steps for 2 s (the riser alone: the free buoy has no statics).
        base = RISER.replace("DURATION", "2.0").replace("  step_control: adaptive\n",
                                                        "  initial_state: statics\n")
        base = base.replace("time_step: 0.05", "time_step: 0.01")
        buoy = "  buoy: {type: rigid_body, mass: 100, inertia: [10, 10, 10], position: [5, 0, 0]}\n"
        self.assertIn(buoy, base)
        base = base.replace(buoy, "")  # free: no statics with it
        base = base.replace("  current: {speed: 1.0, direction: 0}\n",
                            "  current: {speed: 1.0, direction: 0}\n  waves: {type: airy, "
                            "height: 2.0, period: 3.0, ramp: {start: 0, duration: 1.0}}\n")
        self.assertIn("output_interval: 0.1", base)

        def envelope(name, text, fmt):
            out = os.path.join(self.dir, name)
            r = run("run", self.model(text, name + ".yaml"), "-o", out, "-q", "--format", fmt)
            self.assertEqual(r.returncode, 0, r.stderr)
            header, env = read_csv(os.path.join(out, "riser.envelope.csv"))
            return out, header, env

        out_s, header, steps = envelope("steps", base, "both")  # the default
        _, _, explicit = envelope("explicit", base + "output: {envelope_sampling: steps}\n",
                                  "csv")
        np.testing.assert_array_equal(explicit, steps)
        _, _, every = envelope("every", base.replace("output_interval: 0.1",
                                                     "output_interval: 0.01"), "csv")
        _, _, rows = envelope("rows", base + "output: {envelope_sampling: rows}\n", "csv")
        cols = {part: [i for i, h in enumerate(header) if h.endswith("." + part)]
                for part in ("min", "max", "mean")}
        self.assertEqual(len(cols["max"]), 16)
        for part in ("min", "max"):
            np.testing.assert_array_equal(steps[:, cols[part]], every[:, cols[part]], part)
        # the rows alone: lower maxima (and higher minima) somewhere, never beyond the steps'
        ok = np.isfinite(steps[:, cols["max"]])
        self.assertTrue(np.all(rows[:, cols["max"]][ok] <= steps[:, cols["max"]][ok]))
        self.assertTrue(np.all(rows[:, cols["min"]][ok] >= steps[:, cols["min"]][ok]))
        # the maxima the rows miss, against the range each station's moment spans
        hi, lo = steps[:, header.index("moment.max")], steps[:, header.index("moment.min")]
        gap = np.max((hi - rows[:, header.index("moment.max")]) / (hi - lo))
        print("  rows every 0.1 s miss up to %.3g of a station's moment range" % gap)
        # measured 1.15e-2: a sine of the wave's period sampled every 0.1 s loses up to
        # 1 - cos(pi 0.1 / 3) = 5.5e-3 of its amplitude, the start's faster parts more
        self.assertGreater(gap, 2e-3)
        # the mean over the 21 rows, as with `rows`
        np.testing.assert_array_equal(steps[:, cols["mean"]], rows[:, cols["mean"]])
        along_header, along = read_csv(os.path.join(out_s, "riser.along.csv"))
        self.assertEqual(along.shape[0], 21 * 136)
        T = along[:, along_header.index("tension_effective")].reshape(21, 136)
        np.testing.assert_allclose(steps[:, header.index("tension_effective.mean")],
                                   T.mean(axis=0), rtol=1e-12)
        # the HDF5 file's envelopes are the CSV file's
        with h5py.File(os.path.join(out_s, "timeseries.h5"), "r") as f:
            for part in ("min", "max", "mean"):
                np.testing.assert_array_equal(f[f"beams/riser/envelope/{part}/moment"][:],
                                              steps[:, header.index(f"moment.{part}")])
            self.assertEqual(f["beams/riser/envelope"].attrs["rows"], 21)
        # a run resumed from its checkpoint at 1 s writes the same envelopes, byte for byte
        # (the checkpoint holds the extremes of every step before it)
        text = base
        ref = os.path.join(self.dir, "ck")
        r = run("run", self.model(text, "ck.yaml"), "-o", ref, "-q", "--format", "csv",
                "--checkpoint-every", "1.0")
        self.assertEqual(r.returncode, 0, r.stderr)
        resumed = os.path.join(self.dir, "ck_resumed")
        shutil.copytree(ref, resumed)
        r = run("resume", resumed, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        for name in ("riser.envelope.csv", "riser.along.csv", "timeseries.csv"):
            with open(os.path.join(ref, name), "rb") as a, \
                    open(os.path.join(resumed, name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)
        with open(os.path.join(ref, "riser.envelope.csv"), "rb") as a, \
                open(os.path.join(self.dir, "steps", "riser.envelope.csv"), "rb") as b:
            self.assertEqual(a.read(), b.read())
        # bad values: named with file, line and key
        r = run("check", self.model(base + "output: {envelope_sampling: step}\n", "bad1.yaml"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("bad1.yaml:", r.stderr)
        self.assertIn("output.envelope_sampling: unknown value 'step'; did you mean 'steps'?",
                      r.stderr)
        r = run("check", self.model(base + "output: {beam_results: none, envelope_sampling: "
                                    "steps}\n", "bad2.yaml"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("bad2.yaml:", r.stderr)
        self.assertIn("output.envelope_sampling: 'steps' samples the beams' envelopes, which "
                      "beam_results: none leaves out", r.stderr)

    def test_bad_format_option(self):
        r = run("run", self.model(RISER.replace("DURATION", "1")), "-o", self.dir,
                "--format", "xml")
        self.assertEqual(r.returncode, 2)
        self.assertIn("--format", r.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
