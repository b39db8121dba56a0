"""Figures of a run's statistics (issue 19), drawn by seaflex_plot.py when the run wrote
them (a model with a statistics section, docs/results-format.md):

  statistics.png           the channels' statistics, one panel per unit: the range min..max
                           (thin), mean -+ std (thick), the mean, and the Rayleigh most
                           probable maximum of extremes.csv
  range_sigma_<beam>.png   range graphs from <beam>.range.csv against arc length: min, max,
                           mean and the band mean -+ k std of effective and wall tension,
                           bending moment, curvature and von Mises stress
"""
import csv
import os
import re

# the unit of a channel from its name's last part (docs/model-format.md, channel names)
UNIT_RULES = [
    (r"\.(x|y|z|stroke|eta|length|elongation)$", "m"),
    (r"\.(vx|vy|vz|speed)$", "m/s"),
    (r"\.(roll|pitch|yaw)$", "deg"),
    (r"\.(wx|wy|wz)$", "deg/s"),
    (r"\.(tension|force|friction|buoyancy|fx|fy|fz)$", "N"),
    (r"\.volume$", "m^3"),
    (r"\.(moment|mx|my|mz)$", "N m"),
    (r"\.pressure$", "Pa"),
]

RANGE_ITEMS = [("tension_effective", "effective tension (kN)", 1e-3),
               ("tension_wall", "wall tension (kN)", 1e-3),
               ("moment", "bending moment (kN m)", 1e-3),
               ("curvature", "curvature (1/m)", 1.0),
               ("stress_von_mises", "von Mises stress (MPa)", 1e-6)]

MAX_CHANNELS_PER_PANEL = 24


def unit_of(name):
    for pattern, unit in UNIT_RULES:
        if re.search(pattern, name):
            return unit
    return None


def read_rows(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        rows = [r for r in reader if header and len(r) == len(header)]
    return header, rows


def plot_channel_statistics(directory, out, written, plt, save):
    path = os.path.join(directory, "statistics.csv")
    if not os.path.isfile(path):
        return
    header, rows = read_rows(path)
    col = {h: i for i, h in enumerate(header)}
    mpm = {}
    ext = os.path.join(directory, "extremes.csv")
    if os.path.isfile(ext):
        eh, erows = read_rows(ext)
        for r in erows:
            if r[1] == "rayleigh" and r[6] not in ("", "nan"):
                mpm[r[0]] = float(r[6])
    groups = {}
    for r in rows:
        name, unit = r[0], unit_of(r[0])
        if ".station" in name or unit is None or int(r[col["count"]]) == 0:
            continue
        groups.setdefault(unit, []).append(r)
    if not groups:
        return
    units = sorted(groups)
    fig, axes = plt.subplots(len(units), 1, figsize=(11, 3.2 * len(units)), squeeze=False)
    for ax, unit in zip(axes[:, 0], units):
        rs = groups[unit][:MAX_CHANNELS_PER_PANEL]
        for i, r in enumerate(rs):
            lo, hi = float(r[col["min"]]), float(r[col["max"]])
            mean, std = float(r[col["mean"]]), float(r[col["std"]])
            ax.plot([i, i], [lo, hi], color="tab:blue", lw=1)
            ax.plot([i, i], [mean - std, mean + std], color="tab:blue", lw=5, alpha=0.5)
            ax.plot([i], [mean], "k_", ms=10)
            if r[0] in mpm:
                ax.plot([i], [mpm[r[0]]], "rv", ms=5)
        ax.set_xticks(range(len(rs)))
        ax.set_xticklabels([r[0] for r in rs], rotation=60, ha="right", fontsize=7)
        ax.set_ylabel("value (%s)" % unit)
        ax.grid(True, alpha=0.3)
    fig.suptitle("statistics of the channels after statistics.start\nmin..max (line), "
                 "mean -+ std (bar), mean (-), Rayleigh most probable maximum (red)", fontsize=10)
    save(fig, os.path.join(out, "statistics.png"), written)


def plot_sigma_ranges(directory, out, written, plt, save):
    for name in sorted(os.listdir(directory)):
        if not name.endswith(".range.csv"):
            continue
        beam = name[: -len(".range.csv")]
        header, rows = read_rows(os.path.join(directory, name))
        if not header or not rows:
            continue
        col = {h: i for i, h in enumerate(header)}
        s = [float(r[col["s"]]) for r in rows]
        k = float(rows[0][col["k"]])
        items = [it for it in RANGE_ITEMS if it[0] + ".upper" in col]
        fig, axes = plt.subplots(len(items), 1, figsize=(10, 2.6 * len(items)), sharex=True,
                                 squeeze=False)
        for ax, (key, label, scale) in zip(axes[:, 0], items):
            get = lambda stat: [float(r[col["%s.%s" % (key, stat)]]) * scale for r in rows]
            ax.fill_between(s, get("lower"), get("upper"), color="tab:orange", alpha=0.3,
                            label="mean -+ %g std" % k)
            ax.plot(s, get("max"), "-", color="tab:red", lw=1, label="max")
            ax.plot(s, get("mean"), "--", color="k", lw=1, label="mean")
            ax.plot(s, get("min"), "-", color="tab:blue", lw=1, label="min")
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
        axes[0, 0].legend(fontsize=8)
        axes[-1, 0].set_xlabel("arc length from the beam's start (m)")
        fig.suptitle("%s: range graph after statistics.start" % beam)
        save(fig, os.path.join(out, "range_sigma_%s.png" % beam), written)


def plot_all(directory, out, written, plt, save):
    """Every statistics figure the run's files allow (none without statistics.csv)."""
    plot_channel_statistics(directory, out, written, plt, save)
    plot_sigma_ranges(directory, out, written, plt, save)
