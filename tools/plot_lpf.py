#!/usr/bin/python3
"""Figures of the LPF examples (run with /usr/bin/python3, which has Debian's matplotlib).

usage: /usr/bin/python3 tools/plot_lpf.py DIR    (DIR holds the examples' CSV; PNGs go there)
"""
import csv
import sys

import matplotlib

FLOOR = 1e-17  # plotting floor for exact zeros (double data)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0].keys()} if rows else {}


def harmonic(d):
    h = read(f"{d}/harmonic_fig12.csv")
    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(h["t"], h["exact"], "k-", lw=2.5, label="exact cos t + sin t")
    ax.plot(h["t"], h["x16"], "r--", lw=1, label="scheme (16), m = 2")
    ax.set_xlabel("t / s")
    ax.set_ylabel("x / m")
    ax.set_title("Fig. 1: harmonic oscillator, tau = 0.1")
    ax.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(f"{d}/lpf_fig1_harmonic.png", dpi=120)
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(h["t"], h["energy16"], "b-", lw=1, label="consistent start (one step from x0, xdot0)")
    ax.plot(h["t"], h["energy16_paper_start"], "g-", lw=0.8, alpha=0.7, label="paper's x^1 = 1.0948")
    ax.axhline(1.0, color="k", lw=0.5)
    ax.set_xlabel("t / s")
    ax.set_ylabel("energy / J  (p = d2 Ld)")
    ax.set_title("Fig. 2: energy of scheme (16)")
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(f"{d}/lpf_fig2_energy.png", dpi=120)
    plt.close(fig)


def pendulum(d):
    p = read(f"{d}/pendulum.csv")
    q = read(f"{d}/pendulum_large.csv")
    fig, axs = plt.subplots(1, 3, figsize=(13, 3.8))
    for data, lab in ((p, "theta0 = 1"), (q, "theta0 = 2.5")):
        axs[0].plot(data["theta21"], data["p21"], "-", lw=1.5, label=f"(21) Lagrange, {lab}")
        axs[0].plot(data["theta22"], data["p22"], "--", lw=1, label=f"(22) Bernstein, {lab}")
    axs[0].set_xlabel("theta")
    axs[0].set_ylabel("p = thetadot")
    axs[0].set_title("(a) phase portrait")
    axs[0].legend(fontsize=7)
    for data, lab in ((p, "theta0 = 1"), (q, "theta0 = 2.5")):
        e0 = data["energy21"][0]
        axs[1].plot(data["t"], [e - e0 for e in data["energy21"]], lw=0.8, label=f"(21), {lab}")
        axs[1].plot(data["t"], [e - e0 for e in data["energy22"]], "--", lw=0.8, label=f"(22), {lab}")
    axs[1].set_xlabel("t")
    axs[1].set_ylabel("E(t) - E(t_1)")
    axs[1].set_title("(b) energy")
    axs[1].legend(fontsize=7)
    axs[2].semilogy(p["t"], [max(abs(x), FLOOR) for x in p["theta21_minus_theta22"]], lw=0.6, label="theta0 = 1")
    axs[2].semilogy(q["t"], [max(abs(x), FLOOR) for x in q["theta21_minus_theta22"]], lw=0.6, label="theta0 = 2.5")
    axs[2].set_xlabel("t")
    axs[2].set_ylabel("|theta21 - theta22| (double)")
    axs[2].set_title("(c) Lagrange vs Bernstein")
    axs[2].legend(fontsize=7)
    fig.suptitle("Fig. 3: pendulum, schemes (21) and (22), m = 2, tau = 0.1")
    fig.tight_layout()
    fig.savefig(f"{d}/lpf_fig3_pendulum.png", dpi=120)
    plt.close(fig)


def kepler(d):
    k = read(f"{d}/kepler.csv")
    names = sorted({c[: -len("_dE")] for c in k if c.endswith("_dE")})
    fig, axs = plt.subplots(1, 3, figsize=(14, 4))
    axs[0].plot(k["lpf_m2_x"], k["lpf_m2_y"], "b.", ms=1)
    axs[0].set_aspect("equal")
    axs[0].set_title("orbit (lpf m = 2, every 100th step)")
    for n in names:
        axs[1].semilogy(k["t"], [max(abs(x), FLOOR) for x in k[f"{n}_dE"]], lw=0.6, label=n)
        axs[2].semilogy(k["t"], [max(abs(x), FLOOR) for x in k[f"{n}_dJ"]], lw=0.6, label=n)
    axs[1].set_title("|energy error|")
    axs[2].set_title("|angular momentum error|")
    for a in axs[1:]:
        a.set_xlabel("t")
        a.legend(fontsize=7)
    fig.suptitle("Kepler, e = 0.5, tau = 0.01, 10^5 steps")
    fig.tight_layout()
    fig.savefig(f"{d}/lpf_kepler.png", dpi=120)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    d = sys.argv[1]
    harmonic(d)
    pendulum(d)
    kepler(d)
    print(f"wrote {d}/lpf_fig1_harmonic.png lpf_fig2_energy.png lpf_fig3_pendulum.png lpf_kepler.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
