#!/usr/bin/env bash
# Holonomic constraints: the particle on the circle (scheme (23) as printed beside the
# constrained LPF integrator, 10^6 steps), the spherical pendulum and the double pendulum.
# Usage: bash scripts/demo_constraints.sh BUILD_DIR OUT_DIR   (builds nothing)
set -euo pipefail
if [ $# -ne 2 ]; then echo "usage: bash scripts/demo_constraints.sh BUILD_DIR OUT_DIR" >&2; exit 2; fi
root="$(cd "$(dirname "$0")/.." && pwd)"
exe="$1/examples/constraints/geomint-constraints-demo"
out="$2/constraints"
[ -x "$exe" ] || { echo "demo_constraints.sh: $exe not found; build first" >&2; exit 1; }
mkdir -p "$out"
"$exe" "$out" | tee "$out/summary.txt"
/usr/bin/python3 "$root/tools/plot_constraints.py" "$out" "$out"
echo "constraints: CSV and PNG in $out"
