#!/usr/bin/python3
"""Predicted against measured energy errors of the methods of docs/results/modified_methods.md
(run with /usr/bin/python3, which has Debian's matplotlib).

usage: /usr/bin/python3 tools/plot_modified.py CSV PNG
  CSV  docs/results/data/modified_methods.csv (scripts/demo_modified_methods.sh):
       method,kind,order,tau,steps,predicted,measured
"""
import csv
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    series = OrderedDict()
    with open(argv[0], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or "predicted" not in rows[0]:
        sys.exit(f"plot_modified.py: {argv[0]} has no method,...,predicted,measured rows")
    for r in rows:
        s = series.setdefault((r["method"], r["kind"], r["order"]), {"tau": [], "pred": [], "meas": []})
        s["tau"].append(float(r["tau"]))
        s["pred"].append(abs(float(r["predicted"])))
        s["meas"].append(abs(float(r["measured"])))
    fig, ax = plt.subplots(figsize=(12, 6))
    cmap = plt.get_cmap("tab20")
    for i, ((method, kind, order), s) in enumerate(series.items()):
        colour = cmap(i % 20)
        label = f"{method} (p = {order}{', dH/dt' if kind == 'drift' else ''})"
        ax.loglog(s["tau"], s["pred"], "-", color=colour, lw=1.2)
        ax.loglog(s["tau"], s["meas"], "o", color=colour, ms=5, label=label)
    ax.set_xlabel("tau")
    ax.set_ylabel("max |H(y_n) - H(y_0)|  (RK4: |dH/dt|)")
    ax.set_title("Pendulum, 400 steps: measured (markers), predicted from the modified equation (lines)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))  # same methods overlap: Gauss = galerkin
    fig.tight_layout()
    fig.savefig(argv[1], dpi=110)


if __name__ == "__main__":
    main(sys.argv[1:])
