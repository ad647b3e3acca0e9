#!/usr/bin/python3
"""Figures of the geometrically exact beam from geomint-beam output (matplotlib, Agg backend).

Like the beam paper's figures 1-3 (energies, linear and angular momentum against time) plus 3D
snapshots of the centreline:

  /usr/bin/python3 tools/plot_beam.py --run poisson=OUT/poisson.csv --run hamel=OUT/hamel.csv \
      --centreline OUT/centreline.csv --outdir OUT

writes OUTDIR/beam_energy.png, beam_linear_momentum.png, beam_angular_momentum.png and (with
--centreline) beam_centreline.png.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_beam.py: {path} has no data rows")
    return {k: [float(r[k]) for r in rows] for k in rows[0].keys()}


def plot_energy(runs, out):
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    styles = ["-", "--", ":", "-."]
    for i, (label, d) in enumerate(runs):
        ls = styles[i % len(styles)]
        ax.plot(d["t"], d["kinetic"], ls, color="tab:blue", label=f"kinetic ({label})")
        ax.plot(d["t"], d["potential"], ls, color="tab:orange", label=f"potential ({label})")
        ax.plot(d["t"], d["total"], ls, color="tab:green", label=f"total ({label})")
        e0 = d["total"][0]
        ax2.plot(d["t"], [e - e0 for e in d["total"]], ls, label=label)
    ax.set_ylabel("energy [J]")
    ax.set_title("Kinetic, potential and total energy (cf. the beam paper, fig. 1)")
    ax.legend(fontsize=8, ncol=2)
    ax.grid(alpha=0.3)
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel("E(t) - E(0) [J]")
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def plot_momentum(runs, keys, title, unit, out):
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    colors = ["tab:red", "tab:green", "tab:blue"]
    styles = ["-", "--", ":", "-."]
    for i, (label, d) in enumerate(runs):
        ls = styles[i % len(styles)]
        for k, c in zip(keys, colors):
            ax.plot(d["t"], d[k], ls, color=c, label=f"{k} ({label})")
            ax2.plot(d["t"], [x - d[k][0] for x in d[k]], ls, color=c, label=f"{k} ({label})")
    ax.set_ylabel(unit)
    ax.set_title(title)
    ax.legend(fontsize=8, ncol=2)
    ax.grid(alpha=0.3)
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel("deviation from t = 0")
    ax2.legend(fontsize=7, ncol=2)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def plot_centreline(path, out):
    d = read_csv(path)
    steps = sorted(set(int(s) for s in d["step"]))
    fig = plt.figure(figsize=(8, 7))
    ax = fig.add_subplot(projection="3d")
    cmap = plt.get_cmap("viridis")
    allx, ally, allz = [], [], []
    for i, s in enumerate(steps):
        idx = [k for k, v in enumerate(d["step"]) if int(v) == s]
        x = [d["x"][k] for k in idx]
        y = [d["y"][k] for k in idx]
        z = [d["z"][k] for k in idx]
        allx += x
        ally += y
        allz += z
        t = d["t"][idx[0]]
        ax.plot(x, y, z, color=cmap(i / max(1, len(steps) - 1)), lw=2, label=f"t = {t:.4g} s")
        ax.scatter([x[0]], [y[0]], [z[0]], color=cmap(i / max(1, len(steps) - 1)), s=12)
    # Equal aspect ratio.
    spans = [max(v) - min(v) for v in (allx, ally, allz)]
    r = max(spans) / 2 or 1.0
    mids = [(max(v) + min(v)) / 2 for v in (allx, ally, allz)]
    ax.set_xlim(mids[0] - r, mids[0] + r)
    ax.set_ylim(mids[1] - r, mids[1] + r)
    ax.set_zlim(mids[2] - r, mids[2] + r)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.set_title("Centreline snapshots (dot: node 0)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--run", action="append", default=[], metavar="LABEL=CSV", help="a geomint-beam --csv file")
    p.add_argument("--centreline", help="a geomint-beam --centreline file")
    p.add_argument("--outdir", required=True)
    p.add_argument("--prefix", default="beam_")
    a = p.parse_args()
    if not a.run and not a.centreline:
        p.error("give at least one --run or --centreline")
    runs = []
    for spec in a.run:
        if "=" not in spec:
            p.error(f"--run expects LABEL=CSV, got '{spec}'")
        label, path = spec.split("=", 1)
        runs.append((label, read_csv(path)))
    os.makedirs(a.outdir, exist_ok=True)
    written = []
    if runs:
        f = os.path.join(a.outdir, a.prefix + "energy.png")
        plot_energy(runs, f)
        written.append(f)
        f = os.path.join(a.outdir, a.prefix + "linear_momentum.png")
        plot_momentum(runs, ["Px", "Py", "Pz"], "Spatial linear momentum (cf. the beam paper, fig. 2)", "P [kg m/s]", f)
        written.append(f)
        f = os.path.join(a.outdir, a.prefix + "angular_momentum.png")
        plot_momentum(runs, ["Lx", "Ly", "Lz"], "Spatial angular momentum about the origin (cf. fig. 3)", "L [kg m^2/s]", f)
        written.append(f)
    if a.centreline:
        f = os.path.join(a.outdir, a.prefix + "centreline.png")
        plot_centreline(a.centreline, f)
        written.append(f)
    for f in written:
        print(f)


if __name__ == "__main__":
    main()
