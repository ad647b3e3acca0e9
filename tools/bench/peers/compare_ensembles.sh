#!/usr/bin/env bash
# geomint's ensembles against heyoka's batch mode in one sitting: geomint-ensemble and
# geomint-peer-heyoka --ensemble on the pendulum and Henon-Heiles (1024 trajectories each, the
# same initial data, references and error measure: tools/workprecision/ensemble_data.hpp).
#   bash tools/bench/peers/compare_ensembles.sh BUILD_DIR OUT_DIR
# BUILD_DIR: a build with -DGEOMINT_PEER_HEYOKA=ON (docs/results/ensembles.md uses the native
# preset's). Writes OUT_DIR/{geomint,heyoka}-<system>.csv and OUT_DIR/table.txt.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: bash tools/bench/peers/compare_ensembles.sh BUILD_DIR OUT_DIR" >&2
  exit 2
fi
build=$1 out=$2
G=$build/tools/workprecision/geomint-ensemble
H=$build/tools/bench/peers/geomint-peer-heyoka
for tool in "$G" "$H"; do
  [ -x "$tool" ] || { echo "compare_ensembles.sh: $tool is not built (see docs/results/ensembles.md)" >&2; exit 1; }
done
mkdir -p "$out"
for system in pendulum henon-heiles; do
  "$G" --system "$system" --trajectories 1024 --csv > "$out/geomint-$system.csv"
  "$H" --system "$system" --ensemble 1024 --csv > "$out/heyoka-$system.csv"
done
/usr/bin/python3 "$(dirname "$0")/ensemble_table.py" "$out" > "$out/table.txt"
