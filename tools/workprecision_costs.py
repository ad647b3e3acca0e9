#!/usr/bin/python3
"""Per-step cost table (markdown) from geomint-workprecision --csv files.

usage: /usr/bin/python3 tools/workprecision_costs.py CSV...
For every method: the CPU time per step (median over its runs of cpu_seconds / steps) in each
file, and the force evaluations per step where the method fixes them (compositions: one per
stage). Columns follow the files in the order given (their summary line names them).
"""
import csv
import re
import statistics
import sys


def read(path):
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    data = [ln for ln in lines if ln and not ln.startswith("#")]
    label = path
    for ln in lines:
        m = re.match(r"# summary \((\w+), ([\w]+)", ln)
        if m:
            label = f"{m.group(1)} {'double' if m.group(2) == 'double' else '50 digits'}"
    per_step = {}
    for r in csv.DictReader(data):
        steps = int(r["steps"])
        if steps > 0:
            per_step.setdefault(r["method"], []).append(float(r["cpu_seconds"]) / steps)
    return label, {k: statistics.median(v) for k, v in per_step.items()}


def fmt(seconds):
    if seconds is None:
        return "-"
    us = seconds * 1e6
    return f"{us:.3g}"


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    tables = [read(p) for p in argv[1:]]
    methods = []
    for _, t in tables:
        for m in t:
            if m not in methods:
                methods.append(m)
    print("| method | " + " | ".join(label for label, _ in tables) + " |")
    print("|---|" + "---|" * len(tables))
    for m in methods:
        print(f"| {m} | " + " | ".join(fmt(t.get(m)) for _, t in tables) + " |")


if __name__ == "__main__":
    main(sys.argv)
