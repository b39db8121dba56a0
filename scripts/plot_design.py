"""Design-result figures for `seaflex plot` (imported by seaflex_plot.py): fatigue damage and
life along each beam (<beam>.fatigue.csv of seaflex run, <beam>.fatigue_total.csv of
seaflex fatigue) and the code-check utilisation along it (<beam>.code_check.csv and
statics.<beam>.code_check.csv), with units on every axis.

  fatigue_<beam>.png          damage per year (log) and life (years, log) against arc length
  fatigue_total_<beam>.png    the same combined over the load cases of seaflex fatigue
  code_check_<beam>.png       DNV-ST-F201 and API RP 2RD utilisation (-) against arc length,
                              with the limit 1
"""
import csv
import math
import os


def _read(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        rows = [r for r in reader if header and len(r) == len(header)]
    if not header or not rows:
        return None
    return {h: [float(r[i]) for r in rows] for i, h in enumerate(header)}


def _positive(values):
    return [v if v > 0 and math.isfinite(v) else float("nan") for v in values]


def _fatigue(plt, save, path, title, out, written):
    cols = _read(path)
    if not cols or "damage_per_year" not in cols:
        return
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    s = cols["s"]
    ax1.semilogy(s, _positive(cols["damage_per_year"]), "-", lw=1)
    ax1.set_ylabel("damage per year (1/year)")
    ax1.grid(True, which="both", alpha=0.3)
    ax2.semilogy(s, _positive(cols["life_years"]), "-", lw=1, color="tab:red")
    ax2.set_ylabel("fatigue life (years)")
    ax2.set_xlabel("arc length from the beam's start (m)")
    ax2.grid(True, which="both", alpha=0.3)
    fig.suptitle(title)
    save(fig, out, written)


def plot_design(plt, save, directory, out, written):
    """Every fatigue and code-check file of directory, into out."""
    for name in sorted(os.listdir(directory)):
        path = os.path.join(directory, name)
        if name.endswith(".fatigue_total.csv"):
            beam = name[: -len(".fatigue_total.csv")]
            _fatigue(plt, save, path, "%s: fatigue over the load cases" % beam,
                     os.path.join(out, "fatigue_total_%s.png" % beam), written)
        elif name.endswith(".fatigue.csv"):
            beam = name[: -len(".fatigue.csv")]
            _fatigue(plt, save, path, "%s: fatigue damage and life of the run" % beam,
                     os.path.join(out, "fatigue_%s.png" % beam), written)
        elif name.endswith(".code_check.csv"):
            beam = name[: -len(".code_check.csv")]
            cols = _read(path)
            if not cols or "dnv_utilisation" not in cols:
                continue
            fig, ax = plt.subplots(figsize=(10, 4))
            ax.plot(cols["s"], cols["dnv_utilisation"], "-", lw=1, label="DNV-ST-F201 combined loading")
            ax.plot(cols["s"], cols["api_utilisation"], "--", lw=1, label="API RP 2RD von Mises")
            ax.axhline(1.0, color="k", lw=0.8, ls=":", label="limit")
            ax.set_xlabel("arc length from the beam's start (m)")
            ax.set_ylabel("utilisation (-)")
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=8)
            ax.set_title("%s: largest code-check utilisation" % beam)
            save(fig, os.path.join(out, "code_check_%s.png" % beam), written)
