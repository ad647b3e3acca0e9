#!/usr/bin/env python3
"""The comparison table of compare_heyoka.sh: from the '#' summary lines of
geomint-workprecision --csv (geomint-<system>-<digits>.csv) and geomint-peer-heyoka --csv
(heyoka-<system>-<digits>.csv) in DIR, one markdown row per problem, regime and final error:
geomint's best scheme, heyoka's best variant and its default (heyoka-double in double), and
the ratio of the two bests; geomint's 50-digit regime also in dd_real where
geomint-<system>-50-dd.csv exists (geomint-workprecision --scalar dd_real).
usage: heyoka_table.py DIR"""
import os
import re
import sys

ERROR = re.compile(r"^#\s+error (\S+):(.*)$")


def summary(path):
    """{error: text after the colon} of a CSV file's summary lines ({} if the file is absent)."""
    if not os.path.exists(path):
        return {}
    rows = {}
    with open(path) as f:
        for line in f:
            m = ERROR.match(line.rstrip("\n"))
            if m:
                rows[m.group(1)] = m.group(2)
    return rows


def best(text, who):
    """(name, seconds) of 'best <who> NAME X s' in a summary line, or None."""
    m = re.search(r"best %s (\S+) (\S+) s" % who, text)
    return (m.group(1), float(m.group(2))) if m else None


def variant(text, name):
    """Seconds of one heyoka variant ('NAME X s;') in a summary line, or None."""
    m = re.search(r"\b%s (\S+) s;" % re.escape(name), text)
    return float(m.group(1)) if m else None


def ms(x):
    return "%.3g ms" % (1e3 * x)


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.stderr.write("usage: heyoka_table.py DIR (the output folder of compare_heyoka.sh)\n")
        return 2
    d = sys.argv[1]
    print("| problem, regime | final error | geomint best | heyoka best | heyoka default | geomint / heyoka best |")
    print("|---|---|---|---|---|---|")
    for system in ("pendulum", "kepler", "outer-solar"):
        days = system == "outer-solar"
        for digits, scalar, regime in (("16", "", "double, T = 10^5 days" if days else "double, T = 1000"),
                                       ("50", "", "cpp_bin_float_50, T = 10^4 days" if days else "cpp_bin_float_50, T = 100"),
                                       ("50", "-dd", "dd_real, T = 100")):
            g = summary(os.path.join(d, "geomint-%s-%s%s.csv" % (system, digits, scalar)))
            h = summary(os.path.join(d, "heyoka-%s-%s.csv" % (system, digits)))
            default = "heyoka-double" if digits == "16" else "heyoka-real128"
            for error in sorted(g, key=float, reverse=True):
                gb = best(g[error], "geomint")
                hb = best(h.get(error, ""), "heyoka")
                hd = variant(h.get(error, ""), default)
                cells = [
                    "%s, %s" % (system, regime),
                    error,
                    "%s (%s)" % (ms(gb[1]), gb[0]) if gb else "not reached",
                    "%s (%s)" % (ms(hb[1]), hb[0]) if hb else ("not reached" if h else "not measured"),
                    ms(hd) if hd else "-",
                    "%.2f" % (gb[1] / hb[1]) if gb and hb else "-",
                ]
                print("| " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
