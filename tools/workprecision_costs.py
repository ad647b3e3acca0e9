#!/usr/bin/python3
"""Per-step cost table (markdown) from geomint-workprecision --csv files.

usage: /usr/bin/python3 tools/workprecision_costs.py CSV...
       /usr/bin/python3 tools/workprecision_costs.py --compare BEFORE.csv AFTER.csv
       /usr/bin/python3 tools/workprecision_costs.py --variants SUFFIX CSV...
For every method: the CPU time per step (median over its runs of cpu_seconds / steps) in each
file, and the force evaluations per step where the method fixes them (compositions: one per
stage). Columns follow the files in the order given (their summary line names them).
--compare: two runs of the same problem and regime (e.g. two builds of the tool). Per method,
the median over the runs with the same number of steps in both files of after / before CPU
time, and how many such runs there are: ladders that end at different lengths do not move it,
which they do to the medians of the first form (the cost per step depends on tau).
--variants SUFFIX CSV...: within each file, every method M with a variant M SUFFIX (e.g.
lpf-fixed-point-m10 and lpf-fixed-point-m10-scalar-forces), the median over their runs with the
same number of steps of CPU(M) / CPU(M SUFFIX), and how many runs.
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
        m = re.match(r"# summary \(([\w-]+), (\w+)", ln)
        if m:
            label = f"{m.group(1)} {'double' if m.group(2) == 'double' else '50 digits'}"
    per_step = {}
    for r in csv.DictReader(data):
        steps = int(r["steps"])
        if steps > 0:
            per_step.setdefault(r["method"], []).append(float(r["cpu_seconds"]) / steps)
    return label, {k: statistics.median(v) for k, v in per_step.items()}


def runs(path):
    """(method, steps) -> cpu_seconds of one file."""
    with open(path, newline="") as f:
        data = [ln for ln in f.read().splitlines() if ln and not ln.startswith("#")]
    return {(r["method"], int(r["steps"])): float(r["cpu_seconds"]) for r in csv.DictReader(data) if int(r["steps"]) > 0}


def compare(before_path, after_path):
    before, after = runs(before_path), runs(after_path)
    ratios = {}
    for key, t in after.items():
        if key in before and before[key] > 0:
            ratios.setdefault(key[0], []).append(t / before[key])
    print("| method | after / before, CPU per step (median) | runs compared |")
    print("|---|---|---|")
    for m, r in ratios.items():
        print(f"| {m} | {statistics.median(r):.2f} | {len(r)} |")


def variants(suffix, paths):
    print(f"| problem | method | CPU time / CPU time of the variant {suffix} (median) | runs compared |")
    print("|---|---|---|---|")
    for path in paths:
        label = read(path)[0]
        r = runs(path)
        ratios = {}
        for (m, steps), t in r.items():
            other = r.get((m + suffix, steps))
            if other:
                ratios.setdefault(m, []).append(t / other)
        for m, q in ratios.items():
            print(f"| {label} | {m} | {statistics.median(q):.2f} | {len(q)} |")


def fmt(seconds):
    if seconds is None:
        return "-"
    us = seconds * 1e6
    return f"{us:.3g}"


def main(argv):
    if len(argv) >= 2 and argv[1] == "--compare":
        if len(argv) != 4:
            print(__doc__, file=sys.stderr)
            sys.exit(2)
        compare(argv[2], argv[3])
        return
    if len(argv) >= 2 and argv[1] == "--variants":
        if len(argv) < 4:
            print(__doc__, file=sys.stderr)
            sys.exit(2)
        variants(argv[2], argv[3:])
        return
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
