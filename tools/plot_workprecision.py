#!/usr/bin/python3
"""Work-precision diagrams from geomint-workprecision --csv (run with /usr/bin/python3, which has
Debian's matplotlib).

usage: /usr/bin/python3 tools/plot_workprecision.py CSV [PNG]
  CSV  output of `geomint-workprecision --system pendulum|kepler|outer-solar [--digits 16|50] --csv` (rows,
       then '#' summary)
  PNG  default docs/figures/workprecision_<system>_<digits>.png, read from the summary line

Left: final phase-space error against CPU seconds; right: max energy error against CPU seconds;
log-log, one line per method (peers -- Odeint, Stormer-Verlet compositions, Taylor series --
dashed with square markers), the summary as a caption.
"""
import csv
import re
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Plotting floor for exact zeros only (a log axis cannot show 0): below the regime's round-off.
FLOOR = {"double": 1e-17, "cpp_bin_float_50": 1e-52}


def read(path):
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    data = [ln for ln in lines if ln and not ln.startswith("#")]
    notes = [ln[2:] for ln in lines if ln.startswith("# ")]
    if not data or data[0] != "method,tau,steps,cpu_seconds,final_error,max_energy_error":
        sys.exit(f"plot_workprecision.py: {path} is not geomint-workprecision --csv output")
    series = OrderedDict()
    for r in csv.DictReader(data):
        s = series.setdefault(r["method"], {"cpu": [], "err": [], "dE": []})
        s["cpu"].append(float(r["cpu_seconds"]))
        s["err"].append(float(r["final_error"]))
        s["dE"].append(float(r["max_energy_error"]))
    system, scalar, reference = "unknown", "double", "closed form"
    for n in notes:
        m = re.match(r"summary \(([\w-]+), (\w+)", n)
        if m:
            system, scalar = m.group(1), m.group(2)
            r = re.search(r"; reference: ([^)]+)\)", n)
            if r:  # older files name none: the closed form
                reference = r.group(1)
    floor = FLOOR.get(scalar, 1e-17)
    for s in series.values():
        for key in ("err", "dE"):
            s[key] = [v if v > 0 else floor for v in s[key]]
    return series, notes, system, scalar, reference


PEERS = ("odeint-", "sv-", "taylor-")


def main(argv):
    if len(argv) not in (2, 3):
        sys.exit(__doc__)
    series, notes, system, scalar, reference = read(argv[1])
    digits = 16 if scalar == "double" else 50
    out = argv[2] if len(argv) == 3 else f"docs/figures/workprecision_{system}_{digits}.png"
    fig, axes = plt.subplots(1, 2, figsize=(13, 6), sharex=True)
    cmap = plt.get_cmap("tab20")
    for i, (name, s) in enumerate(series.items()):
        peer = name.startswith(PEERS)
        style = dict(ls="--", marker="s", color=cmap(i % 20), ms=4, lw=1.6) if peer else dict(
            ls="-", marker="o", color=cmap(i % 20), ms=3, lw=1.2)
        axes[0].loglog(s["cpu"], s["err"], label=name, **style)
        axes[1].loglog(s["cpu"], s["dE"], label=name, **style)
    for target in ((1e-10, 1e-12) if digits == 16 else (1e-20, 1e-30)):
        axes[0].axhline(target, color="0.8", lw=0.8, zorder=0)
    axes[0].set_ylabel("final error |(q, qdot) - (q, qdot)_ref| at T")
    axes[1].set_ylabel("max |H - H0| over [0, T]")
    for ax in axes:
        ax.set_xlabel("CPU seconds")
        ax.grid(True, which="major", alpha=0.3)
    axes[1].legend(fontsize=7, loc="upper right")
    fig.suptitle(f"work-precision, {system} ({scalar}; reference: {reference} in a wider scalar)")
    summary = [n for n in notes if n.startswith("  error")]
    if summary:
        fig.text(0.01, 0.005, "\n".join(s.strip() for s in summary), fontsize=7, va="bottom")
    fig.tight_layout(rect=(0, 0.05, 1, 0.96))
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
