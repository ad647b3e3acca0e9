#!/usr/bin/env bash
# The beam paper's section 4 case with both schemes: table 2 side by side (wall time of 1000
# steps), figures like the paper's figures 1-3 and centreline snapshots.
# Usage: bash scripts/demo_beam.sh BUILD_DIR OUT_DIR
# Needs BUILD_DIR/tools/beam/geomint-beam (built beforehand: this script builds nothing) and
# /usr/bin/python3 with matplotlib (Debian python3-matplotlib). Writes OUT_DIR/beam/.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: bash scripts/demo_beam.sh BUILD_DIR OUT_DIR" >&2
  exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$1"
out="$2/beam"
exe="$build/tools/beam/geomint-beam"
if [ ! -x "$exe" ]; then
  echo "demo_beam.sh: $exe not found; build the project first (target geomint-beam)" >&2
  exit 1
fi
py=/usr/bin/python3
mkdir -p "$out"

echo "=== geomint beam demo: the beam paper's section 4 case (101 nodes, dt = 1e-4 s) ==="
echo "--- table 2: wall time of 1000 steps (best of 3 runs; stepping only, no output) ---"
declare -A best
for scheme in poisson hamel; do
  best[$scheme]=""
  for rep in 1 2 3; do
    ms=$("$exe" --scheme "$scheme" --steps 1000 --every 1000 | sed -n 's/.*wall time: \([0-9.e+-]*\) ms stepping.*/\1/p')
    if [ -z "${best[$scheme]}" ] || awk -v a="$ms" -v b="${best[$scheme]}" 'BEGIN{exit !(a<b)}'; then best[$scheme]=$ms; fi
  done
done
{
  printf '%-34s %16s %16s\n' "method" "Poisson (53)" "Hamel (trapez.)"
  printf '%-34s %16s %16s\n' "paper, MATLAB" "13.5543 s" "14.0054 s"
  printf '%-34s %16s %16s\n' "paper, Python" "15.9470 s" "18.6285 s"
  printf '%-34s %13s ms %13s ms\n' "geomint (C++, double, 1 thread)" "${best[poisson]}" "${best[hamel]}"
} | tee "$out/table2.txt"
{
  echo "method,poisson_s,hamel_s"
  echo "paper MATLAB,13.5543,14.0054"
  echo "paper Python,15.9470,18.6285"
  echo "geomint C++,$(awk -v a="${best[poisson]}" 'BEGIN{print a/1000}'),$(awk -v a="${best[hamel]}" 'BEGIN{print a/1000}')"
} > "$out/table2.csv"

echo "--- 1 s of motion (10000 steps), both schemes, CSV every 10 steps ---"
for scheme in poisson hamel; do
  extra=()
  if [ "$scheme" = poisson ]; then
    extra=(--centreline "$out/centreline.csv" --snapshots 6 --drift "$out/drift_poisson.csv")
  fi
  "$exe" --scheme "$scheme" --steps 10000 --every 10 --csv "$out/$scheme.csv" "${extra[@]}" | tee "$out/$scheme.txt"
done
echo "--- momentum with the midpoint velocity in the Cayley reconstruction (option) ---"
"$exe" --scheme poisson --steps 10000 --every 10 --cayley midpoint --csv "$out/poisson_midpoint.csv" | tee "$out/poisson_midpoint.txt"

echo "--- 0.1 s at dt, dt/2, dt/4: energy and spatial momentum against dt, per velocity in (55) ---"
for v in previous current midpoint; do
  for run in "1000 1e-4" "2000 5e-5" "4000 2.5e-5"; do
    set -- $run
    line=$("$exe" --scheme poisson --steps "$1" --dt "$2" --every 1 --cayley "$v")
    printf 'cayley %-8s dt %-7s %s; %s\n' "$v" "$2" "$(grep 'energy:' <<<"$line" | sed 's/^ *//')" \
      "$(grep 'momentum:' <<<"$line" | sed 's/^ *//')"
  done
done | tee "$out/dt_ladder.txt"

echo "--- figures ---"
"$py" "$root/tools/plot_beam.py" --run "poisson=$out/poisson.csv" --run "hamel=$out/hamel.csv" \
  --centreline "$out/centreline.csv" --outdir "$out"

echo "--- summary ---"
{
for scheme in poisson hamel; do
  f="$out/$scheme.txt"
  echo "$scheme: $(grep 'energy:' "$f" | sed 's/^ *//')"
  echo "$scheme: $(grep 'momentum:' "$f" | sed 's/^ *//')"
done
echo "poisson (midpoint velocity in (55)): $(grep 'momentum:' "$out/poisson_midpoint.txt" | sed 's/^ *//')"
} | tee "$out/summary.txt"
echo "table 2 (1000 steps): poisson ${best[poisson]} ms, hamel ${best[hamel]} ms (paper: 13.55 s / 14.01 s MATLAB, 15.95 s / 18.63 s Python)"
echo "outputs in $out"
