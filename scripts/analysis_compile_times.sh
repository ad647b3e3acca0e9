#!/usr/bin/env bash
# The compile time of each constexpr exact analysis of include/geomint/analysis, method by method,
# under the compilers' default constant-evaluation limits and under the limit the CMake target
# geomint::geomint sets for its consumers (read from CMakeLists.txt).
#
# For each analysis (order: order_analysis, which includes the error constants; symplecticity;
# symmetry; linear stability: linear_stability and linear_stability_interval) and each method
# (galerkin_tableau<m>, m = 1..8; lpf_tableau<m, gauss_interior> and lpf_tableau<m, equispaced>,
# m = 2..8; the rational catalogue methods stormer_verlet and demp_rkn64) it writes a one-line
# translation unit that evaluates the analysis in a constexpr variable and static_asserts a field
# of it (so the compiler must evaluate it), including only the analysis' header (and
# methods/catalogue.hpp for the catalogue methods), and compiles it with
#   <compiler> -std=gnu++20 -fsyntax-only -I<repo>/include -isystem /usr/include/eigen3 [limit]
# under (a) g++ without a constexpr flag, (b) g++ with the consumer -fconstexpr-ops-limit,
# (c) clang++ without a flag, (d) clang++ with the consumer -fconstexpr-steps (c and d only
# when clang++ is installed). One compile at a time; wall seconds and peak memory by
# /usr/bin/time; each compile capped at the timeout (default 180 s). Once a compile of a
# family (galerkin, lpf gauss_interior, lpf equispaced) times out for an analysis and a
# compiler setting, the larger m of that family are skipped for them.
#
# Prints (stdout) the compilers and flags, a markdown table
#   method | analysis | GCC default | GCC consumer limit | Clang default | Clang consumer limit
# with cells "ok 1.2 s" (compiled), "limit" (the constant-evaluation operation count or step
# limit was reached), "loop limit" / "depth limit" (GCC's -fconstexpr-loop-limit, the
# -fconstexpr-depth limit), "error" (another compile error), "timeout" or "skipped", and a
# second table with the peak memory of each compile. Progress and the first error line of
# every failed compile go to stderr; -l FILE also writes one tab-separated line per compile.
#
# Usage: bash scripts/analysis_compile_times.sh [-t SECONDS] [-m REGEX] [-a REGEX] [-l FILE]
#   -t SECONDS  timeout of one compile (default 180)
#   -m REGEX    only the methods whose name matches (e.g. 'galerkin<[1-3]>')
#   -a REGEX    only the analyses whose name matches (order, symplecticity, symmetry, linear stability)
#   -l FILE     write the raw records (method, analysis, setting, status, seconds, KB, reason)
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
usage="usage: bash scripts/analysis_compile_times.sh [-t SECONDS] [-m REGEX] [-a REGEX] [-l FILE]"

limit_s=180 method_filter="" analysis_filter="" raw_log=""
while getopts ":t:m:a:l:h" opt; do
  case $opt in
    t) [[ "$OPTARG" =~ ^[1-9][0-9]*$ ]] || { echo "analysis_compile_times.sh: -t needs a positive integer" >&2; echo "$usage" >&2; exit 2; }
       limit_s=$OPTARG ;;
    m) method_filter=$OPTARG ;;
    a) analysis_filter=$OPTARG ;;
    l) raw_log=$OPTARG ;;
    h) echo "$usage"; exit 0 ;;
    :) echo "analysis_compile_times.sh: -$OPTARG needs an argument" >&2; echo "$usage" >&2; exit 2 ;;
    *) echo "analysis_compile_times.sh: unknown option -$OPTARG" >&2; echo "$usage" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 0 ] || { echo "analysis_compile_times.sh: unexpected argument '$1'" >&2; echo "$usage" >&2; exit 2; }

command -v g++ >/dev/null || { echo "analysis_compile_times.sh: g++ not found" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "analysis_compile_times.sh: /usr/bin/time not found (Debian: apt-get install time)" >&2; exit 1; }
have_clang=0
command -v clang++ >/dev/null && clang++ --version >/dev/null 2>&1 && have_clang=1

# The consumer limits: the generator expressions of target_compile_options(geomint INTERFACE ...)
# (not the larger budget of the project's own geomint_warnings target).
gcc_flag=$(grep -o 'CXX_COMPILER_ID:GNU>:-fconstexpr-ops-limit=[0-9]*' CMakeLists.txt | head -n 1 | sed 's/.*>://') || true
clang_flag=$(grep -o 'CXX_COMPILER_ID:Clang>:-fconstexpr-steps=[0-9]*' CMakeLists.txt | head -n 1 | sed 's/.*>://') || true
[ -n "$gcc_flag" ] && [ -n "$clang_flag" ] || {
  echo "analysis_compile_times.sh: no consumer constexpr limit found in CMakeLists.txt" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/analysis_compile_times.XXXXXX")
trap 'rm -rf "$work"' EXIT
[ -z "$raw_log" ] || printf 'method\tanalysis\tsetting\tstatus\tseconds\tpeak_kb\treason\n' > "$raw_log"

# Methods: "display name|family|m|C++ expression of the exact_rkn_tableau|extra header".
methods=()
for m in 1 2 3 4 5 6 7 8; do methods+=("galerkin<$m>|galerkin|$m|geomint::galerkin_tableau<$m>()|"); done
for family in gauss_interior equispaced; do
  for m in 2 3 4 5 6 7 8; do methods+=("lpf<$m, $family>|lpf-$family|$m|geomint::lpf_tableau<$m, geomint::$family>()|"); done
done
for name in stormer_verlet demp_rkn64; do
  methods+=("$name|$name|0|[] { const auto t = geomint::methods::$name::tableau(); return geomint::rational_rkn_tableau(t.c, t.a, t.bbar, t.b); }()|geomint/methods/catalogue.hpp")
done
analyses=("order" "symplecticity" "symmetry" "linear stability")
settings=("gcc-default" "gcc-consumer")
[ "$have_clang" = 1 ] && settings+=("clang-default" "clang-consumer")

# The translation unit of analysis $1 on the tableau expression $2 (extra header $3).
translation_unit() {
  local header body
  case $1 in
    order) header=order_conditions.hpp
           body="constexpr geomint::order_summary r = geomint::order_analysis($2); static_assert(r.order >= 0);" ;;
    symplecticity) header=scheme_structure.hpp
           body="constexpr geomint::symplecticity_result r = geomint::symplecticity($2); static_assert(r.symplectic || !r.symplectic);" ;;
    symmetry) header=scheme_structure.hpp
           body="constexpr geomint::symmetry_result r = geomint::symmetry($2); static_assert(r.symmetric || !r.symmetric);" ;;
    "linear stability") header=linear_stability.hpp
           body="constexpr geomint::linear_stability_result r = geomint::linear_stability($2); constexpr geomint::stability_interval i = geomint::linear_stability_interval(r); static_assert(r.order >= 0 && (i.empty || !i.empty));" ;;
  esac
  printf '#include "geomint/analysis/%s"\n' "$header"
  [ -z "$3" ] || printf '#include "%s"\n' "$3"
  printf '%s\n' "$body"
}

# Compiles $1 under setting $2; sets status, seconds, peak_kb, reason.
compile() {
  local cxx flag=()
  case $2 in
    gcc-default) cxx=g++ ;;
    gcc-consumer) cxx=g++ flag=("$gcc_flag") ;;
    clang-default) cxx=clang++ ;;
    clang-consumer) cxx=clang++ flag=("$clang_flag") ;;
  esac
  local rc=0
  /usr/bin/time -f '%e %M' -o "$work/time" timeout -k 10 "$limit_s" \
    "$cxx" -std=gnu++20 -fsyntax-only -I"$repo/include" -isystem /usr/include/eigen3 "${flag[@]}" "$1" \
    > "$work/out" 2>&1 || rc=$?
  read -r seconds peak_kb < <(tail -n 1 "$work/time") || { seconds=0; peak_kb=0; }
  reason=""
  if [ "$rc" = 0 ]; then
    status=ok
  elif [ "$rc" = 124 ] || [ "$rc" = 137 ]; then
    status=timeout reason="no result after ${limit_s} s"
  elif grep -q -e 'operation count exceeds limit' -e 'hit maximum step limit' "$work/out"; then
    status=limit reason=$(grep -m 1 -o -e "[^:]*operation count exceeds limit[^(]*" -e 'constexpr evaluation hit maximum step limit' "$work/out")
  elif grep -q 'loop iteration count exceeds limit' "$work/out"; then
    status="loop limit" reason=$(grep -m 1 -o "[^:]*loop iteration count exceeds limit[^(]*" "$work/out")
  elif grep -q -e 'depth exceeds maximum' -e 'exceeded maximum depth' "$work/out"; then
    status="depth limit" reason=$(grep -m 1 -e 'depth exceeds maximum' -e 'exceeded maximum depth' "$work/out")
  else
    status=error reason=$(grep -m 1 -e 'error' "$work/out" || head -n 1 "$work/out")
  fi
}

declare -A cell memory skip_from
total=0 done_count=0
for entry in "${methods[@]}"; do
  name=${entry%%|*}
  [[ -z "$method_filter" || "$name" =~ $method_filter ]] || continue
  for analysis in "${analyses[@]}"; do
    [[ -z "$analysis_filter" || "$analysis" =~ $analysis_filter ]] || continue
    total=$((total + ${#settings[@]}))
  done
done
for entry in "${methods[@]}"; do
  IFS='|' read -r name family m expression extra <<< "$entry"
  [[ -z "$method_filter" || "$name" =~ $method_filter ]] || continue
  for analysis in "${analyses[@]}"; do
    [[ -z "$analysis_filter" || "$analysis" =~ $analysis_filter ]] || continue
    tu="$work/tu.cpp"
    translation_unit "$analysis" "$expression" "$extra" > "$tu"
    for setting in "${settings[@]}"; do
      key="$name|$analysis|$setting"
      done_count=$((done_count + 1))
      stop=${skip_from["$family|$analysis|$setting"]:-}
      if [ -n "$stop" ]; then
        status=skipped seconds="" peak_kb="" reason="m = $stop timed out"
      else
        compile "$tu" "$setting"
        if [ "$status" = timeout ] && [ "$m" != 0 ]; then skip_from["$family|$analysis|$setting"]=$m; fi
      fi
      case $status in
        ok) cell[$key]=$(printf 'ok %.1f s' "$seconds") ;;
        *) cell[$key]=$status ;;
      esac
      if [ -n "$peak_kb" ] && [ "$status" != timeout ]; then memory[$key]=$(awk -v k="$peak_kb" 'BEGIN { printf "%.0f", k / 1024 }')
      elif [ "$status" = timeout ]; then memory[$key]=">$(awk -v k="$peak_kb" 'BEGIN { printf "%.0f", k / 1024 }')"
      else memory[$key]="-"; fi
      printf '[%d/%d] %-26s %-17s %-15s %-11s %6s s %8s KB %s\n' "$done_count" "$total" "$name" "$analysis" "$setting" \
        "$status" "${seconds:--}" "${peak_kb:--}" "$reason" >&2
      [ -z "$raw_log" ] || printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$analysis" "$setting" "$status" "$seconds" "$peak_kb" "$reason" >> "$raw_log"
    done
  done
done

echo "GCC: $(g++ --version | head -n 1); default limit 2^25 operations; consumer limit $gcc_flag"
if [ "$have_clang" = 1 ]; then
  echo "Clang: $(clang++ --version | head -n 1); default limit 2^20 steps; consumer limit $clang_flag"
else
  echo "Clang: not installed (its columns n/a)"
fi
echo "Each compile: -std=gnu++20 -fsyntax-only, one at a time, wall time, timeout ${limit_s} s."
echo
print_table() {  # $1: the array name (cell or memory), $2: the header suffix
  local -n values=$1
  echo "| method | analysis | GCC default$2 | GCC consumer limit$2 | Clang default$2 | Clang consumer limit$2 |"
  echo "|---|---|---|---|---|---|"
  for entry in "${methods[@]}"; do
    name=${entry%%|*}
    [[ -z "$method_filter" || "$name" =~ $method_filter ]] || continue
    for analysis in "${analyses[@]}"; do
      [[ -z "$analysis_filter" || "$analysis" =~ $analysis_filter ]] || continue
      row="| \`$name\` | $analysis"
      for setting in gcc-default gcc-consumer clang-default clang-consumer; do
        row+=" | ${values["$name|$analysis|$setting"]:-n/a}"
      done
      echo "$row |"
    done
  done
}
print_table cell ""
echo
echo "Peak memory (MB; >N: at the timeout; -: not compiled):"
echo
print_table memory " MB"
