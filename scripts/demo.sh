#!/usr/bin/env bash
# The main demonstration: builds the programs it runs (target geomint-demo-programs of the gcc
# preset in build/demo, without the tests), reproduces the papers' results, writes CSV and
# figures under out/, and prints a summary.
# Usage: bash scripts/demo.sh [OUT_DIR]   (default: out)
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h|--help) echo "usage: bash scripts/demo.sh [OUT_DIR]"; exit 0;; -*) echo "usage: bash scripts/demo.sh [OUT_DIR]" >&2; exit 2;; esac
source scripts/deps.sh
geomint_install_deps "${GEOMINT_BUILD_PACKAGES[@]}" python3-matplotlib
out=$(realpath -m "${1:-out}")
build=build/demo
mkdir -p "$out/core"
# Of the tools' stepper units only those of the built-in systems in 16 digits (geomint-symplectic's
# long runs) and 50 digits (geomint-run, geomint-order, geomint-symplectic); the others (100
# digits, m = 9..16, the zoo, the constrained systems of geomint-run) are stubs here. The tool
# units at -O1 but geomint-beam, whose wall time is table 2; the examples as in the gcc preset
# (tools/CMakeLists.txt).
cmake --preset gcc -B "$build" --no-warn-unused-cli -DGEOMINT_BUILD_TESTS=OFF -DGEOMINT_BUILD_DOCS=OFF -DGEOMINT_TOOLS_AT_O1=ON \
  "-DGEOMINT_TOOL_UNITS=geomint_stepper_builtin_16;geomint_stepper_builtin_50" >/dev/null
cmake --build "$build" -j "$(nproc)" --target geomint-demo-programs

echo "=== geomint demonstration: output in $out ==="
"$build/examples/geomint-core-demo" > "$out/core/nodes_bases_weights.txt"
echo "core: nodes, Lagrange bases and D1/D2 weights for m = 2..6, four node families"
echo "      -> $out/core/nodes_bases_weights.txt ($(wc -l < "$out/core/nodes_bases_weights.txt") lines); m = 2 equispaced:"
sed -n '/equispaced, m = 2/,/equispaced, m = 3/p' "$out/core/nodes_bases_weights.txt" | sed '$d' | sed 's/^/      /'

for part in lpf constraints analysis schemes beam; do
  if [ -f "scripts/demo_$part.sh" ]; then
    echo "=== $part ==="
    bash "scripts/demo_$part.sh" "$build" "$out"
  fi
done
echo "=== results: the generated blocks of docs/results refreshed from $out ==="
/usr/bin/python3 scripts/render_results.py "$out" README.md docs/results/lpf.md docs/results/constraints.md docs/results/beam.md
echo "=== geomint demonstration finished: figures and CSV under $out ==="
