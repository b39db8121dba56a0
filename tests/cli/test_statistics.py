#!/usr/bin/env python3
"""Statistics, extremes and range graphs of `seaflex run` (issue 19, docs/results-format.md):
statistics.csv, extremes.csv and <beam>.range.csv of a real run checked against an
independent computation from timeseries.csv and <beam>.along.csv (numpy, batch formulas:
two-pass moments and a vectorised scan for up-crossings, against seaflex's one-pass
accumulator over turning points); restart files keep the statistics; `seaflex stats`.

usage: test_statistics.py SEAFLEX_EXECUTABLE SOURCE_DIR
"""
import csv
import math
import os
import shutil
import sys
import unittest

import numpy as np

from cli_support import SEAFLEX, SRC, TempDirCase, run

EXAMPLES = os.path.join(SRC, "examples")
START, BLOCKS, STORM, P, K = 20.0, 8, 10800.0, 0.1, 2.5
SECTION = ("\nstatistics:\n  start: %g\n  blocks: %d\n  storm_duration: %g\n"
           "  exceedance_probability: %g\n  k: %g\n" % (START, BLOCKS, STORM, P, K))


def read_table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def close(a, b, rel, absolute=0.0):
    """math.isclose, with NaN equal to NaN (a period without up-crossings)."""
    return (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=rel, abs_tol=absolute)


def batch(t, x):
    """Batch statistics of the record x(t) (docs/results-format.md)."""
    n = len(x)
    mean = x.mean()
    d = x - mean
    m2, m3, m4 = (d ** 2).mean(), (d ** 3).mean(), (d ** 4).mean()
    up = np.nonzero((x[:-1] < mean) & (x[1:] >= mean))[0]  # rows i with x_i < mean <= x_i+1
    peaks = [x[up[j] + 1:up[j + 1] + 1].max() for j in range(len(up) - 1)]
    duration = (t[-1] - t[0]) * n / (n - 1)
    return dict(count=n, duration=duration, min=x.min(), max=x.max(), mean=mean,
                std=math.sqrt(m2), skewness=m3 / m2 ** 1.5 if m2 > 0 else float("nan"),
                kurtosis=m4 / m2 ** 2 if m2 > 0 else float("nan"), up_crossings=len(up),
                period=duration / len(up) if len(up) else float("nan"), peaks=np.array(peaks))


def weibull_ml(y):
    """2-parameter Weibull maximum likelihood by Newton's method on the profile equation
    (seaflex bisects): g(b) = sum y^b ln y / sum y^b - 1/b - mean ln y = 0. g increases
    with b (g' = the weighted variance of ln y + 1/b^2 > 0), so its one root is kept in a
    bracket [lo, hi] that every evaluation narrows; a Newton step that leaves the bracket
    is replaced by its geometric midpoint. (An unguarded Newton from b = 1 overshoots to a
    negative b when the shape is below about 0.5: it once made this reference, not seaflex,
    wrong on two channels of the adaptive-step record.)"""
    ly = np.log(y / y.max())
    lo, hi, b = 1e-6, 1e6, 1.0
    for _ in range(200):
        w = np.exp(b * ly)
        s0, s1, s2 = w.sum(), (w * ly).sum(), (w * ly * ly).sum()
        g = s1 / s0 - 1 / b - ly.mean()
        if g == 0:
            break
        if g > 0:
            hi = b
        else:
            lo = b
        dg = s2 / s0 - (s1 / s0) ** 2 + 1 / b ** 2
        step = b - g / dg
        new = step if lo < step < hi else math.sqrt(lo * hi)
        done = abs(new - b) <= 1e-15 * b
        b = new
        if done:
            break
    return y.max() * np.exp(b * ly).mean() ** (1 / b), b


class StatisticsOfARun(TempDirCase):
    def model_with_statistics(self, example):
        with open(os.path.join(EXAMPLES, example)) as f:
            text = f.read()
        return self.model(text + SECTION, example)

    def test_statistics_match_batch_formulas(self):
        # the example as shipped (adaptive steps: its record has two channels whose Weibull
        # shape is below 0.5, riser.station11.moment_x and riser.station13.stress_von_mises)
        self.check_record("adaptive")

    def test_statistics_match_batch_formulas_with_fixed_steps(self):
        # the record these formulas were first checked on: fixed 0.1 s steps
        self.check_record("fixed")

    def check_record(self, step_control):
        model = self.model_with_statistics("barge_riser.yaml")
        with open(model) as f:
            text = f.read()
        self.assertIn("step_control: adaptive", text)
        with open(model, "w") as f:
            f.write(text.replace("step_control: adaptive", "step_control: " + step_control))
        out = os.path.join(self.dir, "out")
        r = run("run", model, "-o", out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        header, rows = read_table(os.path.join(out, "timeseries.csv"))
        data = np.array(rows, dtype=float)
        keep = data[:, 0] >= START - 1e-9
        t = data[keep, 0]
        records = {name: data[keep, j] for j, name in enumerate(header) if j > 0}
        # the beam stations from riser.along.csv
        ah, arows = read_table(os.path.join(out, "riser.along.csv"))
        along = np.array([[float(v) for v in row] for row in arows])
        along = along[along[:, 0] >= START - 1e-9]
        stations = int(along[:, 1].max()) + 1
        for i in range(stations):
            for q in range(3, len(ah)):
                records["riser.station%d.%s" % (i, ah[q])] = along[along[:, 1] == i, q]
        sh, srows = read_table(os.path.join(out, "statistics.csv"))
        self.assertEqual(sh, ["channel", "count", "duration", "min", "max", "mean", "std",
                              "skewness", "kurtosis", "up_crossings", "period", "peaks"])
        self.assertEqual([row[0] for row in srows], list(records))
        stats = {row[0]: dict(zip(sh[1:], map(float, row[1:]))) for row in srows}
        checked_moments = checked_crossings = 0
        for name, x in records.items():
            s, b = stats[name], batch(t, x)
            if np.isnan(x).all():
                self.assertEqual(s["count"], 0, name)
                continue
            scale = max(abs(b["max"]), abs(b["min"]), 1e-300)
            # 1e-9 relative to the channel's size: one-pass and two-pass sums agree to
            # round-off (~1e-13 for 161 rows)
            for key in ("count", "duration", "min", "max", "mean"):
                self.assertTrue(math.isclose(s[key], b[key], rel_tol=1e-9, abs_tol=1e-9 * scale),
                                "%s %s: %r vs batch %r" % (name, key, s[key], b[key]))
            self.assertTrue(math.isclose(s["std"], b["std"], rel_tol=1e-9, abs_tol=1e-9 * scale),
                            "%s std" % name)
            if b["std"] > 1e-6 * scale:
                # skewness and kurtosis lose digits as std / scale falls; the up-crossing
                # count needs no row within round-off of the mean
                for key in ("skewness", "kurtosis", "period"):
                    self.assertTrue(close(s[key], b[key], 1e-9, 1e-9),
                                    "%s %s: %r vs batch %r" % (name, key, s[key], b[key]))
                self.assertEqual(s["up_crossings"], b["up_crossings"], name)
                self.assertEqual(s["peaks"], len(b["peaks"]), name)
                checked_moments += 1
                checked_crossings += b["up_crossings"] > 0
        self.assertGreater(checked_moments, 100)
        self.assertGreater(checked_crossings, 50)

        # extremes.csv: Rayleigh from the statistics, Gumbel from block maxima and Weibull
        # from peaks recomputed here (Weibull by Newton rather than bisection: 1e-6)
        eh, erows = read_table(os.path.join(out, "extremes.csv"))
        self.assertEqual(eh, ["channel", "method", "input", "parameters", "storm_duration",
                              "storm_count", "most_probable_maximum", "exceedance_probability",
                              "value_at_exceedance"])
        ext = {(row[0], row[1]): row for row in erows}
        n_checked = 0
        for name, x in records.items():
            b = batch(t, x)
            scale = max(abs(b["max"]), abs(b["min"]), 1e-300)
            if not (b["std"] > 1e-6 * scale and len(b["peaks"]) >= 3):
                continue
            ray = ext[(name, "rayleigh")]
            N = STORM / b["period"]
            self.assertAlmostEqual(float(ray[5]), N, delta=1e-9 * N)
            mpm = b["mean"] + b["std"] * math.sqrt(2 * math.log(N))
            self.assertTrue(math.isclose(float(ray[6]), mpm, rel_tol=1e-9, abs_tol=1e-9 * scale))
            y = math.sqrt(-2 * math.log(1 - (1 - P) ** (1 / N)))
            self.assertTrue(math.isclose(float(ray[8]), b["mean"] + b["std"] * y, rel_tol=1e-8,
                                         abs_tol=1e-8 * scale), name)
            # Gumbel: maxima of BLOCKS equal blocks of the analysed duration
            length = b["duration"] / BLOCKS
            idx = np.minimum(np.floor((t - t[0]) / length + 1e-9), BLOCKS - 1).astype(int)
            maxima = np.array([x[idx == k].max() for k in range(BLOCKS)])
            beta = maxima.std(ddof=1) * math.sqrt(6) / math.pi
            mu = maxima.mean() - 0.5772156649015329 * beta + beta * math.log(STORM / length)
            gum = ext[(name, "gumbel")]
            self.assertTrue(math.isclose(float(gum[6]), mu, rel_tol=1e-9, abs_tol=1e-9 * scale),
                            "%s gumbel %s vs %r" % (name, gum[6], mu))
            wei = ext[(name, "weibull")]
            amp = b["peaks"] - b["mean"]
            if (amp > 0).sum() >= 3 and amp.max() > amp.min() * (1 + 1e-6):
                alpha, beta_w = weibull_ml(amp[amp > 0])
                Nw = STORM * len(amp) / b["duration"]
                mpm_w = b["mean"] + alpha * math.log(Nw) ** (1 / beta_w)
                self.assertTrue(math.isclose(float(wei[6]), mpm_w, rel_tol=1e-6,
                                             abs_tol=1e-6 * scale),
                                "%s weibull %s vs %r" % (name, wei[6], mpm_w))
            n_checked += 1
        self.assertGreater(n_checked, 50)

        # range graph: min, max, mean, std of the stations, and mean -+ k std
        rh, rrows = read_table(os.path.join(out, "riser.range.csv"))
        self.assertEqual(rh[:3], ["station", "s", "k"])
        self.assertEqual(len(rrows), stations)
        for row in rrows:
            i = int(row[0])
            self.assertEqual(float(row[2]), K)
            for q in ("tension_effective", "moment", "stress_von_mises", "curvature"):
                s = stats["riser.station%d.%s" % (i, q)]
                c = {key: float(row[rh.index("%s.%s" % (q, key))])
                     for key in ("min", "max", "mean", "std", "lower", "upper")}
                for key in ("min", "max", "mean", "std"):
                    self.assertEqual(c[key], s[key])
                self.assertTrue(math.isclose(c["upper"], s["mean"] + K * s["std"], rel_tol=1e-12))
                self.assertTrue(math.isclose(c["lower"], s["mean"] - K * s["std"], rel_tol=1e-12,
                                             abs_tol=1e-12 * abs(s["mean"])))

        # seaflex stats: selected channels, with their most probable maxima
        r = run("stats", out, "barge.x", "riser.station0.tension_*")
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.splitlines()
        self.assertTrue(lines[0].startswith("channel"))
        names = [line.split()[0] for line in lines[1:-1]]
        self.assertEqual(names, ["barge.x", "riser.station0.tension_wall",
                                 "riser.station0.tension_effective"])
        fields = lines[1].split()
        self.assertAlmostEqual(float(fields[3]), stats["barge.x"]["mean"],
                               delta=1e-5 * abs(stats["barge.x"]["mean"]))
        r = run("stats", out, "barge.xx")
        self.assertEqual(r.returncode, 2)
        self.assertIn("CHANNEL: 'barge.xx' matches no channel; did you mean 'barge.x'?", r.stderr)
        # seaflex plot draws the statistics and the range graph with its mean -+ k std band
        r = run("plot", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        for name in ("statistics.png", "range_sigma_riser.png"):
            path = os.path.join(out, "plots", name)
            self.assertIn("wrote %s" % path, r.stdout)
            with open(path, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        r = run("stats", os.path.join(self.dir, "nowhere"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("statistics.csv: cannot read the result file: no such file; run a model with a "
                      "statistics section (docs/model-format.md)", r.stderr)

    def test_statistics_in_the_hdf5_file(self):
        import h5py
        model = self.model_with_statistics("barge_riser.yaml")
        out = os.path.join(self.dir, "both")
        r = run("run", model, "-o", out, "-q", "--format", "both")
        self.assertEqual(r.returncode, 0, r.stderr)
        sh, srows = read_table(os.path.join(out, "statistics.csv"))
        with h5py.File(os.path.join(out, "timeseries.h5"), "r") as f:
            g = f["statistics"]
            self.assertEqual(list(g["channel"].asstr()[:]), [row[0] for row in srows])
            for j, column in enumerate(sh[1:], start=1):
                np.testing.assert_array_equal(g[column][:], [float(row[j]) for row in srows],
                                              err_msg=column)

    def test_resumed_statistics_equal_an_uninterrupted_run(self):
        # checkpoints every 30 s of a 100 s run: the last one is at t = 90 s; resuming it
        # cuts the files back to t = 90 s, restores the accumulators and runs to the end:
        # the statistics, extremes and range graphs are those of the run never stopped
        model = self.model_with_statistics("barge_riser.yaml")
        ref = os.path.join(self.dir, "ref")
        r = run("run", model, "-o", ref, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        out = os.path.join(self.dir, "ckpt")
        r = run("run", model, "-o", out, "-q", "--checkpoint-every", "30")
        self.assertEqual(r.returncode, 0, r.stderr)
        for name in ("statistics.csv", "extremes.csv", "riser.range.csv"):
            os.remove(os.path.join(out, name))
        r = run("resume", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("at t = 90 s", r.stdout)
        for name in ("statistics.csv", "extremes.csv", "riser.range.csv", "timeseries.csv"):
            with open(os.path.join(ref, name), "rb") as a, open(os.path.join(out, name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
