#!/usr/bin/env bash
# The modified Hamiltonian of a dozen methods against their measured energy errors: writes
# docs/results/modified_methods.md, its data docs/results/data/modified_methods.csv and the figure
# docs/figures/modified_methods.png, every number from geomint-modified (the commands are printed
# on the page). Catalogue methods go through their exact tableau files (geomint-scheme
# --print-tableau --scheme NAME); RK4 from tests/cli/rk4.tableau.
# Usage: bash scripts/demo_modified_methods.sh BUILD_DIR   (builds nothing; about 5 min at -Og)
set -euo pipefail
if [ $# -ne 1 ]; then echo "usage: bash scripts/demo_modified_methods.sh BUILD_DIR" >&2; exit 2; fi
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$1"
modified="$build/tools/studies/geomint-modified"
scheme="$build/tools/analysis/geomint-scheme"
for exe in "$modified" "$scheme"; do
  [ -x "$exe" ] || { echo "demo_modified_methods.sh: $exe not found; build it first" >&2; exit 1; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
page="$root/docs/results/modified_methods.md"
data="$root/docs/results/data/modified_methods.csv"
terms="$work/terms.md"
steps=400
# The ladder of tau by order: the errors stay well above double round-off (1e-16).
taus_for() { if [ "$1" -ge 8 ]; then echo 0.8,0.4,0.2; elif [ "$1" -ge 6 ]; then echo 0.4,0.2,0.1; else echo 0.2,0.1,0.05; fi; }
# The terms predicted: the leading one; RK4 (not symplectic) two, its h^4 term averaging to zero;
# order 8 three (h^(p+1) vanishes for these symmetric methods, h^(p+2) is the first correction),
# since at its longest steps the leading term alone is 10% off.
terms_for() { if [ "$2" != yes ]; then echo 2; elif [ "$1" -ge 8 ]; then echo 3; else echo 1; fi; }

# label|arguments (a catalogue name is written to a tableau file first)
methods=(
  "Stormer-Verlet|catalogue:stormer-verlet"
  "midpoint|--scheme midpoint"
  "Gauss s=2|catalogue:gauss-2"
  "Gauss s=3|catalogue:gauss-3"
  "Lobatto IIIA-IIIB s=3|catalogue:lobatto-iiia-iiib-3"
  "Ruth-3|catalogue:ruth-3"
  "Forest-Ruth|catalogue:forest-ruth"
  "Yoshida triple jump|catalogue:yoshida-triple-jump"
  "Suzuki-4|catalogue:suzuki-4"
  "lpf gauss-interior m=3|--scheme lpf --nodes gauss-interior --m 3"
  "lpf gauss-interior m=4|--scheme lpf --nodes gauss-interior --m 4"
  "lpf gauss-interior m=5|--scheme lpf --nodes gauss-interior --m 5"
  "galerkin m=2|--scheme galerkin --m 2"
  "galerkin m=3|--scheme galerkin --m 3"
  "RK4 (not symplectic)|--tableau tests/cli/rk4.tableau"
)

echo "method,kind,order,tau,steps,predicted,measured" > "$data"
: > "$terms"
: > "$work/failures.txt"
for entry in "${methods[@]}"; do
  label="${entry%%|*}"
  spec="${entry#*|}"
  if [[ "$spec" == catalogue:* ]]; then
    name="${spec#catalogue:}"
    "$scheme" --print-tableau --scheme "$name" > "$work/$name.tableau"
    args=(--tableau "$work/$name.tableau")
    shown="--tableau NAME.tableau  # geomint-scheme --print-tableau --scheme $name > NAME.tableau"
  else
    read -r -a args <<< "$spec"
    shown="$spec"
  fi
  # The order and the leading terms of the modified Hamiltonian (or field) from --order.
  first="$(cd "$root" && "$modified" "${args[@]}" --order 2 | head -n 1)"
  order="$(sed -n 's/.*: order \([0-9]*\),.*/\1/p' <<< "$first")"
  symplectic=yes; [[ "$first" == *"not symplectic"* ]] && symplectic=no
  (cd "$root" && "$modified" "${args[@]}" --order $((order + 1))) > "$work/series.txt"
  if [ "$symplectic" = yes ]; then
    # The first two terms of order p + 1 and the count of the others.
    leading="$(awk -v p="h^$order" '/^modified Hamiltonian/ {on = 1; next}
      on && $1 == p {n++; if (n <= 2) {printf "%s%s %s", sep, $5, $2; sep = "; "}}
      END {if (n > 2) printf " (+ %d more)", n - 2}' "$work/series.txt")"
  else
    leading="(no modified Hamiltonian; modified field at h^$order: $(awk -v k="$((order + 1))" '$3 == k {n++} END {print n + 0}' "$work/series.txt") trees)"
  fi
  echo "| $label | $order | $leading |" >> "$terms"
  kind=symplectic; [ "$symplectic" = no ] && kind=drift
  taus="$(taus_for "$order")"
  (cd "$root" && "$modified" "${args[@]}" --system pendulum --tau "$taus" --steps $steps --no-monitor --terms "$(terms_for "$order" "$symplectic")" --csv) \
    > "$work/run.csv" 2> "$work/run.log" || status=$?
  # Exit 3: a run the step monitor refused prints nan; the page says which and why.
  if [ "${status:-0}" -ne 0 ]; then
    [ "$status" -eq 3 ] || { cat "$work/run.log" >&2; exit 1; }
    grep "failed" "$work/run.log" | sed "s/^geomint-modified: /- $label, /" >> "$work/failures.txt"
  fi
  unset status
  tail -n +2 "$work/run.csv" | while IFS=, read -r tau n predicted measured; do
    echo "$label,$kind,$order,$tau,$n,$predicted,$measured" >> "$data"
  done
  echo "$label|$shown" >> "$work/commands.txt"
  echo "modified_methods: $label (order $order) done" >&2
done

/usr/bin/python3 "$root/tools/plot_modified.py" "$data" "$root/docs/figures/modified_methods.png"

{
  echo "# The modified Hamiltonian of a dozen methods, predicted against measured"
  echo
  echo "Generated by \`bash scripts/demo_modified_methods.sh BUILD_DIR\` from \`geomint-modified\`"
  echo "(docs/results/modified.md says what is predicted and how). Pendulum H = p^2/2 - cos q from q = 1"
  echo "at rest, $steps steps at each tau, double precision; for each method"
  echo
  echo "    geomint-modified METHOD --order P+1"
  echo "    geomint-modified METHOD --system pendulum --tau TAUS --steps $steps --no-monitor --csv"
  echo
  echo "with TAUS = 0.2,0.1,0.05 for order p <= 4, 0.4,0.2,0.1 for p = 6 and 0.8,0.4,0.2 for p = 8 (the"
  echo "errors stay above double round-off), --terms 2 for RK4, --terms 3 for p = 8 (the h^(p+2) term"
  echo "too), and METHOD one of the list below."
  echo "Without the step monitor (\`--no-monitor\`): the page measures the energy error itself."
  echo
  while IFS='|' read -r label shown; do echo "    $shown"; done < "$work/commands.txt"
  echo
  echo "## The leading term of the modified Hamiltonian"
  echo
  echo "H~ = H + h^p sum c H(t) + ...: the terms of order p + 1 as \`geomint-modified --order P+1\`"
  echo "prints them (the first two, and how many more), each c H(t) with t a tree: y[...] for rk (every"
  echo "H: H(y[t1..tm]) = H^(m+1)(F(t1),..,F(tm))), q/p trees for the others (two colours, H differentiated"
  echo "in q or p by the colours of the subtrees' roots; on H = |p|^2/2 + V(q) for a library scheme and rkn,"
  echo "on H = T(p) + V(q) for prk, whose colour 0, printed q, is p there). On H = |p|^2/2 + V(q),"
  echo "H(q[p[q]]) = -V''(p, p) and H(p[q[p]]) = -|V'|^2: Stormer-Verlet's -1/12 and 1/24 are"
  echo "H~ = H + h^2 (V''(p, p)/12 - |V'|^2/24) + O(h^4), the kick-drift-kick form of the symmetric BCH"
  echo "formula (Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd ed. 2006, section III.4.2)."
  echo
  echo "| method | order p | leading terms c H(t) at h^p |"
  echo "|---|---|---|"
  cat "$terms"
  echo
  echo "## Predicted against measured energy error"
  echo
  echo "Symplectic methods: max_n |h^p (H_{p+1}(y_n) - H_{p+1}(y_0)) + ...| (the terms taken) against"
  echo "max_n |H(y_n) - H(y_0)|."
  echo "RK4: the drift rate dH/dt from the modified field (terms h^4 and h^5) against the fitted slope."
  echo
  echo "| method | kind | p | tau | predicted | measured | ratio |"
  echo "|---|---|---|---|---|---|---|"
  tail -n +2 "$data" | awk -F, '{r = ($7 != 0 && $6 != "nan" && $7 != "nan") ? sprintf("%.4f", $6 / $7) : "-"; printf "| %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $6, $7, r}'
  if [ -s "$work/failures.txt" ]; then
    echo
    echo "nan: runs the step monitor refused (docs/guide/robustness.md), each with the monitor's reason (its"
    echo "energy criterion compares a step's energy change with the energy the step exchanges):"
    echo
    cat "$work/failures.txt"
  fi
  echo
  echo "![predicted against measured energy error](../figures/modified_methods.png)"
  echo
  echo "Figure: docs/figures/modified_methods.png (tools/plot_modified.py): measured max |H(y_n) - H(y_0)|"
  echo "(markers) and the prediction (lines) against tau, one colour per method; RK4 as |drift rate|."
} > "$page"
echo "modified_methods: $page, $data, docs/figures/modified_methods.png"
