#!/usr/bin/env python3
"""Figures of the constrained studies (geomint-constraints-demo CSV) as PNG.

usage: /usr/bin/python3 tools/plot_constraints.py CSV_DIR PNG_DIR
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return {key: [float(row[key]) for row in rows] for key in rows[0]}


FLOOR = 1e-18


def floor(values):
    """Zero cannot be drawn on a log axis: exact zeros are drawn at FLOOR (below double eps)."""
    return [max(v, FLOOR) for v in values]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    src, dst = sys.argv[1], sys.argv[2]

    circle = read(f"{src}/circle.csv")
    paper23 = read(f"{src}/circle_paper23.csv")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    axes[0].semilogy(circle["t"], floor(circle["lpf_constraint"]), ".", ms=1, label="| |q|^2 - 1 |")
    axes[0].semilogy(circle["t"], floor(circle["lpf_energy_error"]), label="|H - H0|")
    axes[0].set_xlabel("t")
    axes[0].set_title("constrained LPF (m = 2), tau = 0.1 (zeros drawn at 1e-18)")
    axes[0].legend()
    axes[1].semilogy(paper23["step"], floor(paper23["paper23_constraint"]), "o-", ms=3, label="| |x^k|^2 - 1 |")
    axes[1].semilogy(paper23["step"], floor(paper23["paper23_energy_error"]), "s-", ms=3, label="|H - H0|")
    axes[1].set_xlabel("step k")
    axes[1].axhline(1e-3, color="gray", lw=0.5)
    axes[1].set_title("scheme (23) as printed: defect x 5.83 per step")
    axes[1].legend()
    fig.tight_layout()
    fig.savefig(f"{dst}/constraints_circle.png", dpi=110)

    sph = read(f"{src}/spherical.csv")
    fig = plt.figure(figsize=(11, 4))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    count = min(len(sph["x"]), 400)
    ax.plot(sph["x"][:count], sph["y"][:count], sph["z"][:count], lw=0.8)
    ax.set_title("spherical pendulum path (t <= 1000)")
    ax2 = fig.add_subplot(1, 2, 2)
    ax2.semilogy(sph["t"], floor(sph["energy_error"]), label="|H - H0|")
    ax2.semilogy(sph["t"], floor(sph["momentum_error"]), label="|L_z - L_z0|")
    ax2.semilogy(sph["t"], floor(sph["constraint"]), label="| |q|^2 - 1 |")
    ax2.set_xlabel("t")
    ax2.set_title("constrained LPF m = 3 Gauss interior, tau = 0.05")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(f"{dst}/constraints_spherical.png", dpi=110)

    dbl = read(f"{src}/double.csv")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    axes[0].plot(dbl["t"], dbl["x2_cartesian"], label="x2, Cartesian + 2 rods")
    axes[0].plot(dbl["t"], dbl["x2_angles"], "--", label="x2, angles")
    axes[0].set_xlabel("t")
    axes[0].set_title("double pendulum, lower bob")
    axes[0].legend()
    axes[1].semilogy(dbl["t"], floor(dbl["difference"]), label="distance between the two lower bobs")
    axes[1].semilogy(dbl["t"], floor(dbl["energy_error"]), label="Cartesian |H - H0|")
    axes[1].set_xlabel("t")
    axes[1].legend()
    fig.tight_layout()
    fig.savefig(f"{dst}/constraints_double.png", dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
