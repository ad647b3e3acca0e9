#!/usr/bin/env python3
"""Markdown tables for docs/results/analysis.md from the CSV files of
scripts/demo_analysis.sh (exact_schemes.csv, orders.csv, symplectic.csv, energy.csv).
Usage: python3 tools/studies/tables.py DIR"""
import csv
import os
import sys

def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def row_keys(rows):
    """The (scheme, nodes) pairs in the order the tools print them (their node families and
    schemes, from the library's lists: no list of them here)."""
    keys = []
    for r in rows:
        if (r["scheme"], r["nodes"]) not in keys:
            keys.append((r["scheme"], r["nodes"]))
    return keys


def pivot(rows, value, title):
    """One table: rows (system, scheme, nodes), columns m = 2..8 (midpoint/trapezoidal in column '-')."""
    out = [f"**{title}**", "", "| system | scheme | nodes | m=2 | m=3 | m=4 | m=5 | m=6 | m=7 | m=8 |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    systems = []
    for r in rows:
        if r["system"] not in systems:
            systems.append(r["system"])
    for system in systems:
        for scheme, nodes in row_keys(rows):
            cells = {r["m"]: value(r) for r in rows
                     if r["system"] == system and r["scheme"] == scheme and r["nodes"] == nodes}
            if not cells:
                continue
            if "-" in cells:  # no m: one value for the row
                line = [cells["-"]] + [""] * 6
            else:
                line = [cells.get(str(m), "") for m in range(2, 9)]
            out.append(f"| {system} | {scheme} | {nodes} | " + " | ".join(line) + " |")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: python3 tools/studies/tables.py DIR")
    d = sys.argv[1]
    parts = []
    path = os.path.join(d, "exact_schemes.csv")
    if os.path.exists(path):
        rows = read(path)
        lines = ["**Exact two-step schemes of the harmonic oscillator** (equispaced nodes; "
                 "R = N(s)/D(s), s = tau^2, coefficients in ascending powers of s; "
                 "R - 2 cos tau = c tau^(p+2) + ...)", "",
                 "| m | numerator N(s) | denominator D(s) | order p | c |", "|---|---|---|---|---|"]
        for r in rows:
            lines.append(f"| {r['m']} | {r['numerator']} | {r['denominator']} | {r['order']} | {r['leading_coefficient']} |")
        parts.append("\n".join(lines) + "\n")
    path = os.path.join(d, "orders.csv")
    if os.path.exists(path):
        rows = read(path)
        parts.append(pivot(rows, lambda r: r["global_order"],
                           "Observed global order p (50 digits, T = 1, tau = T/32 -> T/64)"))
        parts.append(pivot(rows, lambda r: r["error_constant"],
                           "Global error constant C (error ~ C tau^p at T = 1)"))
    path = os.path.join(d, "symplectic.csv")
    if os.path.exists(path):
        rows = read(path)
        tau = rows[0]["tau"] if rows else "?"
        parts.append(pivot(rows, lambda r: r["defect"],
                           f"Symplecticity defect max|J^T Omega J - Omega| (50 digits, tau = {tau})"))
    path = os.path.join(d, "energy.csv")
    if os.path.exists(path):
        rows = read(path)
        lines = ["**Long-time energy behaviour** (double, m = 4 where a scheme has an m)", "",
                 "| system | scheme | nodes | m | tau | max abs(H - H0) | drift d(H - H0)/dt |", "|---|---|---|---|---|---|---|"]
        for r in rows:
            lines.append(f"| {r['system']} | {r['scheme']} | {r['nodes']} | {r['m']} | {r['tau']} | "
                         f"{r['max_energy_error']} | {r['energy_drift']} |")
        parts.append("\n".join(lines) + "\n")
    print("\n".join(parts))


if __name__ == "__main__":
    main()
