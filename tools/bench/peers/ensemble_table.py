#!/usr/bin/env python3
"""The comparison table of compare_ensembles.sh: from the '#' summary lines of geomint-ensemble
--csv (geomint-<system>.csv) and geomint-peer-heyoka --ensemble --csv (heyoka-<system>.csv) in
DIR, one markdown row per system and final error: geomint's best ensemble method, its best
one-by-one method (the scalar integrator), heyoka's best batch variant, and the ratios.
usage: ensemble_table.py DIR"""
import os
import re
import sys

from heyoka_table import ms, summary

ENTRY = re.compile(r"(\S+) (\S+) s;")


def fastest(text, prefix):
    """(name, seconds) of the fastest entry whose name starts with prefix, or None."""
    found = [(name, float(t)) for name, t in ENTRY.findall(text) if name.startswith(prefix)]
    return min(found, key=lambda e: e[1]) if found else None


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.stderr.write("usage: ensemble_table.py DIR (the output folder of compare_ensembles.sh)\n")
        return 2
    d = sys.argv[1]
    print("| system | largest final error | geomint ensemble | geomint one by one | heyoka batch | ensemble / one by one | ensemble / heyoka |")
    print("|---|---|---|---|---|---|---|")
    for system in ("pendulum", "henon-heiles"):
        g = summary(os.path.join(d, "geomint-%s.csv" % system))
        h = summary(os.path.join(d, "heyoka-%s.csv" % system))
        for error in sorted(g, key=float, reverse=True):
            e = fastest(g[error], "ensemble-")
            o = fastest(g[error], "one-by-one-")
            b = fastest(h.get(error, ""), "heyoka-")
            cell = lambda x: "%s (%s)" % (ms(x[1]), x[0]) if x else "not reached"
            cells = [system, error, cell(e), cell(o), cell(b) if h else "not measured",
                     "%.2f" % (e[1] / o[1]) if e and o else "-", "%.2f" % (e[1] / b[1]) if e and b else "-"]
            print("| " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
