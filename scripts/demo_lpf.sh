#!/usr/bin/env bash
# Runs the LPF examples and tool (already built) into OUT_DIR/lpf and makes the figures.
# Usage: bash scripts/demo_lpf.sh BUILD_DIR OUT_DIR     (builds nothing)
set -euo pipefail
if [ $# -ne 2 ]; then echo "usage: bash scripts/demo_lpf.sh BUILD_DIR OUT_DIR" >&2; exit 2; fi
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "$1" && pwd)"
out="$2/lpf"
mkdir -p "$out"
for exe in examples/lpf/geomint-lpf-harmonic examples/lpf/geomint-lpf-pendulum examples/lpf/geomint-lpf-kepler \
           tools/lpf/geomint-run; do
  [ -x "$build/$exe" ] || { echo "demo_lpf: missing $build/$exe (build the project first)" >&2; exit 1; }
done
echo "=== LPF example 3.1: harmonic oscillator (tables 1 and 2) ==="
"$build/examples/lpf/geomint-lpf-harmonic" "$out" | tee "$out/harmonic.txt"
echo "=== LPF example 3.2: pendulum, schemes (21) and (22) ==="
"$build/examples/lpf/geomint-lpf-pendulum" "$out" | tee "$out/pendulum.txt"
echo "=== Kepler, e = 0.5, 10^5 steps ==="
"$build/examples/lpf/geomint-lpf-kepler" "$out" | tee "$out/kepler.txt"
echo "=== geomint-run: charged particle, lpf m = 4 on Gauss interior nodes, Bernstein, 50 digits ==="
"$build/tools/lpf/geomint-run" --system charged --scheme lpf --nodes gauss-interior --basis bernstein --m 4 \
  --tau 0.1 --steps 1000 --every 100 --digits 50 --csv | tee "$out/charged_lpf4_50.csv" | cut -c1-150
/usr/bin/python3 "$root/tools/plot_lpf.py" "$out"
echo "=== LPF summary ==="
grep -A7 "Table 2 (solution error" "$out/harmonic.txt" | head -8
grep "max |theta21" "$out/pendulum.txt"
sed -n '2,8p' "$out/kepler.txt"
echo "outputs in $out"
