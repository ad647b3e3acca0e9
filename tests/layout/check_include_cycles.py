#!/usr/bin/env python3
"""The library's headers include each other without a cycle: reads every #include "geomint/..."
line under include/geomint (conditional ones too: a cycle through an #if is still one), finds
the strongly connected components of that graph (Tarjan) and fails, naming every header of each
component with more than one header or a self-include.
Usage: check_include_cycles.py SOURCE_DIR"""
import pathlib
import re
import sys


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.splitlines()[-1], file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1]) / "include"
    headers = sorted(p.relative_to(root).as_posix() for p in (root / "geomint").rglob("*.hpp"))
    if not headers:
        print(f"check_include_cycles: no headers under {root / 'geomint'}", file=sys.stderr)
        return 2
    pattern = re.compile(r'^\s*#\s*include\s*[<"](geomint/[^">]+)[">]', re.M)
    edges = {h: sorted(set(pattern.findall((root / h).read_text(encoding="utf-8"))) & set(headers)) for h in headers}
    index, low, on_stack, stack, cycles = {}, {}, set(), [], []

    def visit(v: str) -> None:  # recursive Tarjan; the graph has a few hundred nodes
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1 or v in edges[v]:
                cycles.append(sorted(component))

    sys.setrecursionlimit(10000)
    for h in headers:
        if h not in index:
            visit(h)
    for c in cycles:
        print("include cycle: " + " <-> ".join(c))
    print(f"{len(headers)} headers, {sum(len(e) for e in edges.values())} includes, {len(cycles)} cycles")
    return 1 if cycles else 0


if __name__ == "__main__":
    sys.exit(main())
