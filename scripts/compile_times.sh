#!/usr/bin/env bash
# Compile-time profile of one CMake preset: configures it into build/<preset>-times with a
# compiler launcher that records the CPU time (user + system) and the peak memory of every compile
# and link, builds the given targets (default: all) and prints the units by CPU time, the total
# and the largest memory of one unit. CPU time, not
# wall time, so that the figures hold on a loaded machine. Arguments -DNAME=VALUE are cache
# settings on top of the preset's (e.g. -DGEOMINT_TEST_SUITE_OPTIONS=-O1).
# Usage: bash scripts/compile_times.sh <preset> [-DNAME=VALUE...] [target...]
set -euo pipefail
cd "$(dirname "$0")/.."
usage="usage: bash scripts/compile_times.sh <preset> [-DNAME=VALUE...] [target...]"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
preset=$1; shift
settings=()
while [ $# -gt 0 ] && [[ "$1" == -D* ]]; do
  [[ "$1" == -D?*=* ]] || { echo "compile_times.sh: '$1' is not -DNAME=VALUE" >&2; echo "$usage" >&2; exit 2; }
  settings+=("$1"); shift
done
build="build/${preset}-times"
log="$PWD/$build/compile_times.log"
mkdir -p "$build"
launcher="$PWD/$build/time_launcher.sh"
cat > "$launcher" <<'LAUNCHER'
#!/usr/bin/env bash
# Runs a compile or link command under /usr/bin/time: "user system wall maxrss_kb output" per line.
out=""; prev=""
for arg in "$@"; do [ "$prev" = "-o" ] && out="$arg"; prev="$arg"; done
exec /usr/bin/time -f "%U %S %e %M $out" -a -o "$GEOMINT_TIMES_LOG" "$@"
LAUNCHER
chmod +x "$launcher"
rm -f "$log"
cmake --preset "$preset" -B "$build" -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" \
      -DCMAKE_CXX_LINKER_LAUNCHER="$launcher" "${settings[@]}" > /dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
GEOMINT_TIMES_LOG="$log" cmake --build "$build" -j2 "${targets[@]}"
echo "=== CPU seconds (user + system) per unit, largest first ($log) ==="
awk '{printf "%8.1f  %s\n", $1 + $2, $5}' "$log" | sort -rn
awk '{cpu += $1 + $2; if ($4 > rss) {rss = $4; unit = $5}} END {
  printf "=== total: %.0f s of CPU time in %d compiles and links; largest memory %.1f GB (%s) ===\n", cpu, NR, rss / 1048576, unit}' "$log"
