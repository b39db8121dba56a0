#!/usr/bin/python3
"""Draws PNG figures of a seaflex run: `seaflex plot DIR [CHANNEL ...]` calls this script.

    seaflex_plot.py DIR [CHANNEL ...] [--out PLOTDIR] [--snapshots N]

DIR holds timeseries.csv or timeseries.h5 (seaflex run). Without channels it writes a
report into
DIR/plots/:
  motion_<body>.png     surge, sway, heave, roll, pitch, yaw of each rigid body
  beam_<beam>.png       horizontal deflection (x and y) against height at N moments,
                        with the envelope (min and max over the run) of each node
  tensions.png          every <name>.tension channel (ropes and springs)
  cylinders.png         stroke, pressure and force of every pneumatic cylinder
  tensioners.png        stroke and tension of every constant-tension tensioner
                        (connections type: tensioner)
  joint_forces.png      the resultant force of every joint (at a riser's end joint: the
                        riser's effective tension there)
  range_<beam>.png      range graphs from <beam>.envelope.csv: min, max and mean over the
                        run of effective tension, bending moment, von Mises stress and the
                        horizontal position, against arc length
  statistics.png, range_sigma_<beam>.png   with a statistics section: see
                        plot_statistics.py
  fatigue_<beam>.png, code_check_<beam>.png: fatigue damage and life, and the code-check
                        utilisation along each beam (scripts/plot_design.py); a seaflex
                        fatigue directory gets fatigue_total_<beam>.png
With channels (names, or shell patterns such as 'platform.*'), one figure per channel,
<channel>.png. Uses Debian's python3-matplotlib (Agg backend, no display needed).
Exit codes: 0 done, 2 bad input (no such directory, file or channel).
"""
import argparse
import csv
import fnmatch
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_statistics  # noqa: E402  (the statistics figures, issue 19)

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:  # pragma: no cover - depends on the machine
    sys.stderr.write("seaflex plot: needs matplotlib (Debian: apt-get install python3-matplotlib)\n")
    sys.exit(2)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_design  # noqa: E402  (fatigue and code-check figures)

DPI = 110


def fail(message):
    sys.stderr.write("seaflex plot: %s\n" % message)
    sys.exit(2)


def read_csv(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if not header or header[0] != "time":
            fail("%s: expected a seaflex CSV file whose first column is 'time'" % path)
        cols = {name: [] for name in header}
        for row in reader:
            if len(row) != len(header):
                break  # a run cut short may leave a partial last line
            for name, value in zip(header, row):
                cols[name].append(float(value))
    return header, cols


def read_h5(path):
    """The channels of a timeseries.h5 (docs/results-format.md), as read_csv gives them."""
    try:
        import h5py
    except ImportError:
        fail("%s: reading HDF5 results needs h5py (Debian: apt-get install python3-h5py)" % path)
    with h5py.File(path, "r") as f:
        names = list(f["channel_names"].asstr()[:])
        values = f["channels"][:]
        cols = {"time": list(f["time"][:])}
    for k, name in enumerate(names):
        cols[name] = list(values[:, k])
    return ["time"] + names, cols


def steady_axis(ax, values):
    """A signal constant to round-off gets a +-1 axis instead of one magnifying 1e-13."""
    lo, hi = min(values), max(values)
    if hi - lo <= 1e-9 * max(1.0, abs(lo), abs(hi)):
        mid = 0.5 * (lo + hi)
        ax.set_ylim(mid - 1.0, mid + 1.0)


def save(fig, path, written):
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    written.append(path)


def rigid_bodies(header):
    names = set(h[: -len(".roll")] for h in header if h.endswith(".roll"))
    return sorted(n for n in names if n + ".pitch" in header and n + ".x" in header)


def beams(header):
    found = {}
    for h in header:
        m = re.fullmatch(r"(.+)\.n(\d+)\.x", h)
        if m:
            found.setdefault(m.group(1), set()).add(int(m.group(2)))
    return {b: sorted(n) for b, n in found.items() if b + ".n0.z" in header}


def plot_motion(body, t, cols, out, written):
    fig, axes = plt.subplots(3, 2, figsize=(10, 8), sharex=True)
    items = [("x", "surge x (m)"), ("roll", "roll (deg)"), ("y", "sway y (m)"),
             ("pitch", "pitch (deg)"), ("z", "heave z (m)"), ("yaw", "yaw (deg)")]
    for ax, (key, label) in zip(axes.flat, items):
        ax.plot(t, cols["%s.%s" % (body, key)], lw=1)
        steady_axis(ax, cols["%s.%s" % (body, key)])
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("time (s)")
    fig.suptitle("%s: motion of the centre of gravity" % body)
    save(fig, os.path.join(out, "motion_%s.png" % body), written)


def plot_beam(beam, nodes, t, cols, snapshots, out, written):
    fig, axes = plt.subplots(1, 2, figsize=(10, 8), sharey=True)
    n = len(t)
    picks = sorted(set(int(round(k * (n - 1) / max(1, snapshots - 1))) for k in range(snapshots)))
    for comp, ax in zip(("x", "y"), axes):
        for i in picks:
            xs = [cols["%s.n%d.%s" % (beam, k, comp)][i] for k in nodes]
            zs = [cols["%s.n%d.z" % (beam, k)][i] for k in nodes]
            ax.plot(xs, zs, lw=1, label="t = %g s" % t[i])
        lo = [min(cols["%s.n%d.%s" % (beam, k, comp)]) for k in nodes]
        hi = [max(cols["%s.n%d.%s" % (beam, k, comp)]) for k in nodes]
        zs0 = [cols["%s.n%d.z" % (beam, k)][0] for k in nodes]
        ax.fill_betweenx(zs0, lo, hi, color="grey", alpha=0.2, label="envelope")
        if max(hi) - min(lo) <= 1e-9 * max(1.0, abs(max(hi)), abs(min(lo))):
            ax.set_xlim(min(lo) - 1.0, max(hi) + 1.0)  # constant to round-off
        ax.set_xlabel("%s (m)" % comp)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("z (m)")
    axes[1].legend(fontsize=7, loc="best")
    fig.suptitle("%s: horizontal position against height" % beam)
    save(fig, os.path.join(out, "beam_%s.png" % beam), written)


def plot_panels(title, t, cols, names, panels, height, path, written):
    """One panel per (channel suffix, scale, ylabel), each with a line per name over time;
    nothing when there are no names."""
    if not names:
        return
    fig, axes = plt.subplots(len(panels), 1, figsize=(10, height), sharex=True)
    for ax, (suffix, scale, label) in zip(axes, panels):
        for name in names:
            ax.plot(t, [v * scale for v in cols[name + suffix]], lw=1, label=name)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    axes[-1].set_xlabel("time (s)")
    fig.suptitle(title)
    save(fig, path, written)


def plot_group(title, t, series, ylabel, path, written):
    if not series:
        return
    fig, ax = plt.subplots(figsize=(10, 5))
    for name, values in series:
        ax.plot(t, values, lw=1, label=name)
    ax.set_xlabel("time (s)")
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title)
    save(fig, path, written)


def report(header, cols, out, snapshots, written):
    t = cols["time"]
    for body in rigid_bodies(header):
        plot_motion(body, t, cols, out, written)
    for beam, nodes in sorted(beams(header).items()):
        plot_beam(beam, nodes, t, cols, snapshots, out, written)
    tensions = [(h[: -len(".tension")], cols[h]) for h in header if h.endswith(".tension")]
    plot_group("tension of ropes and springs", t, tensions, "tension (N)",
               os.path.join(out, "tensions.png"), written)
    cyl = sorted(h[: -len(".stroke")] for h in header
                 if h.endswith(".stroke") and h[: -len(".stroke")] + ".pressure" in header)
    plot_panels("pneumatic cylinders", t, cols, cyl,
                [(".stroke", 1.0, "stroke (m)"), (".pressure", 1e-6, "pressure (MPa)"),
                 (".force", 1.0, "force (N)")], 9, os.path.join(out, "cylinders.png"), written)
    # constant-tension tensioners: a stroke and a tension, no gas pressure
    tens = sorted(h[: -len(".stroke")] for h in header
                  if h.endswith(".stroke") and h[: -len(".stroke")] + ".tension" in header
                  and h[: -len(".stroke")] + ".pressure" not in header)
    plot_panels("tensioners (stroke from the length at the start; tension along the line)", t,
                cols, tens, [(".stroke", 1.0, "stroke (m)"), (".tension", 1e-6, "tension (MN)")],
                7, os.path.join(out, "tensioners.png"), written)
    joints = sorted(h[: -len(".fx")] for h in header
                    if h.endswith(".fx") and h[: -len(".fx")] + ".fz" in header)
    series = []
    for j in joints:
        fx, fy, fz = cols[j + ".fx"], cols[j + ".fy"], cols[j + ".fz"]
        series.append((j, [(a * a + b * b + c * c) ** 0.5 for a, b, c in zip(fx, fy, fz)]))
    plot_group("joint forces (resultant)", t, series, "force (N)",
               os.path.join(out, "joint_forces.png"), written)


RANGE_ITEMS = [("tension_effective", "effective tension (N)", 1.0),
               ("moment", "bending moment (N m)", 1.0),
               ("stress_von_mises", "von Mises stress (MPa)", 1e-6),
               ("x", "x (m)", 1.0)]


def plot_ranges(directory, out, written):
    """Range graphs (envelopes against arc length) of every <beam>.envelope.csv."""
    for name in sorted(os.listdir(directory)):
        if not name.endswith(".envelope.csv"):
            continue
        beam = name[: -len(".envelope.csv")]
        with open(os.path.join(directory, name), newline="") as f:
            reader = csv.reader(f)
            header = next(reader, None)
            rows = [r for r in reader if header and len(r) == len(header)]
        if not header or "s" not in header or not rows:
            continue
        col = {h: i for i, h in enumerate(header)}
        s = [float(r[col["s"]]) for r in rows]
        items = [it for it in RANGE_ITEMS if it[0] + ".max" in col]
        if not items:
            continue
        fig, axes = plt.subplots(len(items), 1, figsize=(10, 2.6 * len(items)), sharex=True)
        axes = axes if len(items) > 1 else [axes]
        for ax, (key, label, scale) in zip(axes, items):
            for stat, style in (("max", "-"), ("mean", "--"), ("min", "-")):
                values = [float(r[col["%s.%s" % (key, stat)]]) * scale for r in rows]
                ax.plot(s, values, style, lw=1, label=stat)
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
        axes[0].legend(fontsize=8)
        axes[-1].set_xlabel("arc length from the beam's start (m)")
        fig.suptitle("%s: range over the run" % beam)
        save(fig, os.path.join(out, "range_%s.png" % beam), written)


def channels(header, cols, patterns, out, written):
    t = cols["time"]
    for pattern in patterns:
        match = [h for h in header[1:] if fnmatch.fnmatchcase(h, pattern)]
        if not match:
            fail("no channel matches '%s' (channels are the columns of timeseries.csv)" % pattern)
        for name in match:
            plot_group(name, t, [(name, cols[name])], name,
                       os.path.join(out, "%s.png" % name), written)


def main(argv):
    parser = argparse.ArgumentParser(prog="seaflex plot", description=__doc__.split("\n")[0])
    parser.add_argument("dir", help="the output directory of seaflex run")
    parser.add_argument("channels", nargs="*", help="channel names or shell patterns")
    parser.add_argument("--out", help="where to write the PNG files (default DIR/plots)")
    parser.add_argument("--snapshots", type=int, default=8, help="moments in the beam figures")
    parser.add_argument("--dpi", type=int, default=110, help="resolution of the PNG files")
    args = parser.parse_intermixed_args(argv)
    global DPI
    DPI = max(30, args.dpi)
    path = os.path.join(args.dir, "timeseries.csv")
    h5 = os.path.join(args.dir, "timeseries.h5")
    if os.path.isfile(path):
        header, cols = read_csv(path)
    elif os.path.isfile(h5):
        header, cols = read_h5(h5)
    elif os.path.isdir(args.dir) and any(n.endswith(".fatigue_total.csv") for n in os.listdir(args.dir)):
        out = args.out or os.path.join(args.dir, "plots")  # a seaflex fatigue directory
        os.makedirs(out, exist_ok=True)
        written = []
        plot_design.plot_design(plt, save, args.dir, out, written)
        for w in written:
            print("wrote %s" % w)
        return 0
    else:
        fail("%s: no timeseries.csv or timeseries.h5 here (write one with seaflex run MODEL -o %s)"
             % (args.dir, args.dir))
    if len(cols["time"]) < 2:
        fail("%s: fewer than two rows" % path)
    out = args.out or os.path.join(args.dir, "plots")
    os.makedirs(out, exist_ok=True)
    written = []
    if args.channels:
        channels(header, cols, args.channels, out, written)
    else:
        report(header, cols, out, max(2, args.snapshots), written)
        plot_ranges(args.dir, out, written)
        plot_statistics.plot_all(args.dir, out, written, plt, save)
        plot_design.plot_design(plt, save, args.dir, out, written)
    for w in written:
        print("wrote %s" % w)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
