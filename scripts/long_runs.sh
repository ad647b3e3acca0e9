#!/usr/bin/env bash
# Long runs (not a test): N steps (default 10^7) of each integrator family through the tools,
# reporting the energy error at the end, the maximum energy error over the run, the time per
# step and the peak resident memory (max RSS). Constant memory is checked by running each case
# twice, with N/100 and N steps: the two peaks must agree (no growth with the number of steps).
#
#   scripts/long_runs.sh [build-dir] [steps]      (default build/gcc, 10000000)
#
# The build needs, of the tools' units, the built-in systems and the circle in double; the
# smallest such build:
#   cmake --preset gcc -B build/long -DGEOMINT_BUILD_TESTS=OFF -DGEOMINT_BUILD_DOCS=OFF \
#     "-DGEOMINT_TOOL_UNITS=geomint_stepper_builtin_16;geomint_run_circle_16"
#   cmake --build build/long --target geomint-run geomint-beam
#
# Families: the free LPF integrator, the classical variational integrators (midpoint,
# Galerkin), the constrained LPF integrator (circle), and the beam (per node-step: N / 100
# steps of the 101-node beam, i.e. about N node-steps).
set -euo pipefail
build=${1:-build/gcc}
steps=${2:-10000000}
run=$build/tools/lpf/geomint-run
beam=$build/tools/beam/geomint-beam
for tool in "$run" "$beam"; do
  [[ -x $tool ]] || { echo "long_runs.sh: $tool not built (cmake --build $build --target geomint-run geomint-beam)" >&2; exit 1; }
done

# Progress on stderr when it is a terminal (nothing otherwise; stdout, the table, is unchanged):
# cases done, elapsed and remaining time, estimated in proportion to the steps (a beam step
# counts as `weight` = 100 free steps: its 101 nodes).
small=$((steps / 100))
cases=12 done_cases=0 weight=1 done_work=0 total_work=$((5 * (small + steps) + 100 * (small / 100 + small)))
mmss() { printf '%d:%02d' $(($1 / 60)) $(($1 % 60)); }
progress() {
  [ -t 2 ] || return 0
  local elapsed=$SECONDS line
  line="long_runs.sh: $done_cases/$cases cases, $(mmss "$elapsed") elapsed"
  if [ "$done_work" -gt 0 ] && [ "$done_cases" -lt "$cases" ]; then
    line+=", about $(mmss $((elapsed * (total_work - done_work) / done_work))) left"
  fi
  if [ "$done_cases" -lt "$cases" ]; then printf '\r\033[K%s' "$line" >&2; fi
}

# measure <label> <steps> <command...>: prints label, steps, seconds, ns/step, max RSS (kB)
# and the last lines of the tool's summary.
measure() {
  local label=$1 n=$2
  shift 2
  local out
  if ! out=$( { /usr/bin/time -f 'TIME %e %M' "$@" > /tmp/long_runs_out.$$ ; } 2>&1 ); then
    if [ -t 2 ]; then printf '\r\033[K' >&2; fi
    echo "long_runs.sh: '$label' failed: $*" >&2
    grep -v '^TIME\|^Command exited' <<<"$out" | head -n 3 >&2
    rm -f /tmp/long_runs_out.$$
    exit 1
  fi
  local seconds rss
  seconds=$(grep '^TIME' <<<"$out" | awk '{print $2}')
  rss=$(grep '^TIME' <<<"$out" | awk '{print $3}')
  local ns
  ns=$(awk -v s="$seconds" -v n="$n" 'BEGIN { printf "%.1f", 1e9 * s / n }')
  local energy
  energy=$(grep -E 'max \|energy - energy0\||energy:' /tmp/long_runs_out.$$ | tr '\n' ' ' | sed 's/|/!/g')
  if [ -t 2 ]; then printf '\r\033[K' >&2; fi  # the row on a clean line
  printf '| %s | %s | %s | %s | %s | %s |\n' "$label" "$n" "$seconds" "$ns" "$rss" "$energy"
  rm -f /tmp/long_runs_out.$$
  done_cases=$((done_cases + 1)) done_work=$((done_work + weight * n))
  progress
}

echo "| case | steps | seconds | ns/step | max RSS (kB) | energy |"
echo "|---|---|---|---|---|---|"
progress
for n in "$small" "$steps"; do
  measure "LPF m=4 gauss-interior, pendulum, tau=0.1" "$n" "$run" --system pendulum --m 4 --nodes gauss-interior --tau 0.1 --steps "$n"
  measure "LPF m=2 equispaced, Kepler e=0.5, tau=0.01" "$n" "$run" --system kepler --m 2 --tau 0.01 --steps "$n"
  measure "midpoint VI, pendulum, tau=0.1" "$n" "$run" --system pendulum --scheme midpoint --tau 0.1 --steps "$n"
  measure "Galerkin m=3, Kepler e=0.5, tau=0.01" "$n" "$run" --system kepler --scheme galerkin --m 3 --tau 0.01 --steps "$n"
  measure "constrained LPF m=2, circle, tau=0.1" "$n" "$run" --system circle --m 2 --tau 0.1 --steps "$n"
done
# The beam: 101 nodes, dt = 1e-4 (the paper's case); steps/100 steps = about `steps` node-steps.
weight=100
for n in $((small / 100)) "$small"; do
  measure "beam (Poisson, 101 nodes, dt=1e-4), per beam step" "$n" "$beam" --steps "$n" --dt 0.0001
done
