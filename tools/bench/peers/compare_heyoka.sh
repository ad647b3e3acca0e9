#!/usr/bin/env bash
# Runs geomint-workprecision and geomint-peer-heyoka one after the other (one sitting) on the
# pendulum, Kepler and the outer solar system, double (T = 1000; 10^5 days) and 50 digits (T = 100;
# 10^4 days; geomint also in dd_real where built with libqd), keeps their CSV output in
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
for system in pendulum kepler outer-solar; do
  for digits in 16 50; do
    "$wp" --system "$system" --digits "$digits" --csv > "$out/geomint-$system-$digits.csv"
    if [ -n "$peer" ]; then "$peer" --system "$system" --digits "$digits" --csv > "$out/heyoka-$system-$digits.csv"; fi
  done
  if [ "$system" != outer-solar ]; then
    "$wp" --system "$system" --digits 50 --scalar dd_real --csv > "$out/geomint-$system-50-dd.csv" 2>/dev/null \
      || rm -f "$out/geomint-$system-50-dd.csv"  # a build without libqd
  fi
done
python3 "$(dirname "$0")/heyoka_table.py" "$out"
