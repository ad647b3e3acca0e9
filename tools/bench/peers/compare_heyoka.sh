#!/usr/bin/env bash
# Runs geomint-workprecision and geomint-peer-heyoka one after the other (one sitting) on the
# pendulum and Kepler, double (T = 1000) and 50 digits (T = 100), keeps their CSV output in
# OUT_DIR and prints the comparison table (heyoka_table.py). Without geomint-peer-heyoka in
# BUILD_DIR (it needs -DGEOMINT_PEER_HEYOKA=ON and an installed heyoka) it says so and
# measures geomint's side alone.
# usage: tools/bench/peers/compare_heyoka.sh BUILD_DIR [OUT_DIR]
set -euo pipefail
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: compare_heyoka.sh BUILD_DIR [OUT_DIR (default heyoka-comparison)]" >&2
  exit 2
fi
build=$1
out=${2:-heyoka-comparison}
wp=$build/tools/workprecision/geomint-workprecision
peer=$build/tools/bench/peers/geomint-peer-heyoka
if [ ! -x "$wp" ]; then
  echo "compare_heyoka.sh: $wp is not built" >&2
  exit 2
fi
if [ ! -x "$peer" ]; then
  echo "compare_heyoka.sh: $peer is not built (configure with -DGEOMINT_PEER_HEYOKA=ON and an installed heyoka); geomint's side alone" >&2
  peer=
fi
mkdir -p "$out"
for system in pendulum kepler; do
  for digits in 16 50; do
    "$wp" --system "$system" --digits "$digits" --csv > "$out/geomint-$system-$digits.csv"
    if [ -n "$peer" ]; then "$peer" --system "$system" --digits "$digits" --csv > "$out/heyoka-$system-$digits.csv"; fi
  done
done
python3 "$(dirname "$0")/heyoka_table.py" "$out"
