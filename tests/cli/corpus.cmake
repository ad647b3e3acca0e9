# The bad-argument corpus: every tool, fed command lines that are wrong in one flag, must exit
# with status 2 (never crash, hang or take a signal) and print a message naming the flag, then
# its usage text. Included from tests/cli/CMakeLists.txt. The expected status and message are
# the tools' common convention (tools/common/cli.hpp), not output of the tools.
#
# geomint_cli_corpus(<tool target> <message regex> <args...>): one ctest entry per case.
set(_geomint_corpus_index 0)
function(geomint_cli_corpus tool flag_regex)
  math(EXPR _i "${_geomint_corpus_index} + 1")
  set(_geomint_corpus_index ${_i} PARENT_SCOPE)
  string(REPLACE "-" "_" _name "${tool}")
  geomint_cli_test(geomint_cli_corpus_${_name}_${_i} 2 "${flag_regex}.*usage: ${tool}" $<TARGET_FILE:${tool}> ${ARGN})
  set_tests_properties(geomint_cli_corpus_${_name}_${_i} PROPERTIES TIMEOUT 30 LABELS cli_corpus)
endfunction()

# geomint_cli_corpus_empty(<tool target> <flag>): `<tool> <flag> ''`, an empty value as a separate
# argument (CMake drops empty list items, so the command goes through sh).
function(geomint_cli_corpus_empty tool flag)
  string(REPLACE "-" "_" _name "${tool}${flag}")
  add_test(NAME geomint_cli_corpus_${_name}_empty
           COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2 "-DEXPECT_REGEX=${flag} needs a non-empty value.*usage: ${tool}"
                   "-DCOMMAND=/bin/sh;-c;exec \"\$0\" \"\$1\" '';$<TARGET_FILE:${tool}>;${flag}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/expect.cmake)
  set_tests_properties(geomint_cli_corpus_${_name}_empty PROPERTIES TIMEOUT 30 LABELS cli_corpus)
endfunction()

# Cases every tool shares: unknown flags (with and without a value), stray words.
foreach(tool geomint-run geomint-order geomint-symplectic geomint-beam geomint-scheme geomint-workprecision)
  set(_geomint_corpus_index 0)
  geomint_cli_corpus(${tool} "unknown flag --bogus" --bogus)
  geomint_cli_corpus(${tool} "unknown flag --bogus" --bogus=3)
  geomint_cli_corpus(${tool} "unknown flag --bogus" --bogus 3)
  geomint_cli_corpus(${tool} "unexpected argument 'stray'" stray)
  if(NOT tool STREQUAL "geomint-beam")  # geomint-beam's --csv takes a file name
    geomint_cli_corpus(${tool} "--csv takes no value" --csv=1)
  endif()
  set(_geomint_corpus_index_${tool} ${_geomint_corpus_index})
endforeach()

# geomint-run
set(_geomint_corpus_index ${_geomint_corpus_index_geomint-run})
geomint_cli_corpus(geomint-run "--tau is out of range" --tau 1e-320)
geomint_cli_corpus(geomint-run "--tau is out of range" --tau 1e400)
geomint_cli_corpus(geomint-run "--tau expects a finite number > 0" --tau abc)
geomint_cli_corpus(geomint-run "--tau expects a finite number > 0" --tau nan)
geomint_cli_corpus(geomint-run "--tau expects a finite number > 0" --tau inf)
geomint_cli_corpus(geomint-run "--tau must be a finite number > 0" --tau -1)
geomint_cli_corpus(geomint-run "--tau must be a finite number > 0" --tau 0)
geomint_cli_corpus(geomint-run "--tau needs a non-empty value" --tau=)
geomint_cli_corpus(geomint-run "--tau needs a value" --tau)
geomint_cli_corpus(geomint-run "--tau needs a value" --tau --csv)
geomint_cli_corpus(geomint-run "--q0 is out of range" --q0 1e400)
geomint_cli_corpus_empty(geomint-run --q0)
geomint_cli_corpus_empty(geomint-run --tau)
geomint_cli_corpus(geomint-run "--q0 has an empty item" --q0 1,,2)
geomint_cli_corpus(geomint-run "--q0 needs 2 value" --system kepler --q0 1)
geomint_cli_corpus(geomint-run "--p0 expects a finite number" --p0 x)
geomint_cli_corpus(geomint-run "--steps is out of range" --steps 99999999999999999999)
geomint_cli_corpus(geomint-run "--steps is out of range" --steps -1)
geomint_cli_corpus(geomint-run "--steps expects an integer" --steps 1.5)
geomint_cli_corpus(geomint-run "--every is out of range" --every 0)
geomint_cli_corpus(geomint-run "--m is out of range" --m=17)
geomint_cli_corpus(geomint-run "--m expects an integer" --m four)
geomint_cli_corpus(geomint-run "--digits must be one of 16, 50, 100" --digits 15)
geomint_cli_corpus(geomint-run "--system must be one of" --system moon)
geomint_cli_corpus(geomint-run "--scheme must be one of" --scheme rk4)

# geomint-order
set(_geomint_corpus_index ${_geomint_corpus_index_geomint-order})
geomint_cli_corpus(geomint-order "--steps is out of range" --steps 8,99999999999999999999)
geomint_cli_corpus(geomint-order "--steps needs at least 2" --steps 8)
geomint_cli_corpus(geomint-order "--steps must be positive and increasing" --steps 8,4)
geomint_cli_corpus(geomint-order "--steps has an empty item" --steps 8,,16)
geomint_cli_corpus(geomint-order "--t-end must be a finite number > 0" --t-end 0)
geomint_cli_corpus(geomint-order "--t-end expects a finite number > 0" --t-end nan)
geomint_cli_corpus(geomint-order "--m is out of range" --m 2..9)
geomint_cli_corpus(geomint-order "--m range '5..3' is empty" --m 5..3)
geomint_cli_corpus(geomint-order "--threads is out of range" --threads 0)
geomint_cli_corpus(geomint-order "--digits must be one of 16, 50, 100" --digits 15)
geomint_cli_corpus(geomint-order "--scheme must be one of" --scheme rk4)
geomint_cli_corpus(geomint-order "--system must be one of" --system all,moon)

# geomint-symplectic
set(_geomint_corpus_index ${_geomint_corpus_index_geomint-symplectic})
geomint_cli_corpus(geomint-symplectic "--long-steps is out of range" --long-steps 99999999999999999999)
geomint_cli_corpus(geomint-symplectic "--long-steps is out of range" --long-steps -1)
geomint_cli_corpus(geomint-symplectic "--tau is out of range" --tau 1e-320)
geomint_cli_corpus(geomint-symplectic "--tau expects a finite number > 0" --tau abc)
geomint_cli_corpus(geomint-symplectic "--tau must be a finite number > 0" --tau -1)
geomint_cli_corpus(geomint-symplectic "--long-tau must be a finite number > 0" --long-tau 0)
geomint_cli_corpus_empty(geomint-symplectic --q0)
geomint_cli_corpus(geomint-symplectic "--q0 / --p0 need 1 value" --system pendulum --q0 1,2)
geomint_cli_corpus(geomint-symplectic "--m is out of range" --m 99999999999999999999)

# geomint-beam
set(_geomint_corpus_index ${_geomint_corpus_index_geomint-beam})
geomint_cli_corpus(geomint-beam "--steps is out of range" --steps 99999999999999999999)
geomint_cli_corpus(geomint-beam "--steps expects an integer" --steps 1e3)
geomint_cli_corpus(geomint-beam "--dt must be a finite number > 0" --dt 0)
geomint_cli_corpus(geomint-beam "--dt expects a finite number > 0" --dt inf)
geomint_cli_corpus(geomint-beam "--dt is out of range" --dt 1e-400)
geomint_cli_corpus(geomint-beam "--nodes is out of range" --nodes 1)
geomint_cli_corpus(geomint-beam "--nodes is out of range" --nodes 99999999)
geomint_cli_corpus_empty(geomint-beam --csv)
geomint_cli_corpus(geomint-beam "--every is out of range" --every 0)
geomint_cli_corpus(geomint-beam "--scheme must be one of poisson, hamel" --scheme x)
geomint_cli_corpus(geomint-beam "--snapshots is out of range" --snapshots 1)

# geomint-scheme and geomint-workprecision
set(_geomint_corpus_index ${_geomint_corpus_index_geomint-scheme})
geomint_cli_corpus(geomint-scheme "--m is out of range" --m 99999999999999999999)
geomint_cli_corpus(geomint-scheme "--m needs a value" --m)
set(_geomint_corpus_index ${_geomint_corpus_index_geomint-workprecision})
geomint_cli_corpus(geomint-workprecision "--t-end is out of range" --t-end 1e400)
geomint_cli_corpus(geomint-workprecision "--t-end expects a finite number > 0" --t-end abc)
geomint_cli_corpus(geomint-workprecision "--max-seconds must be a finite number > 0" --max-seconds -1)
geomint_cli_corpus(geomint-workprecision "--digits must be one of 16, 50" --digits 100)
geomint_cli_corpus(geomint-workprecision "--passes is out of range" --passes 0)
geomint_cli_corpus(geomint-workprecision "--passes expects an integer in 1..10" --passes x)

# geomint-scheme: options that do not apply to the chosen scheme are usage errors, never ignored
# (--m has no meaning for midpoint and trapezoidal, --nodes for galerkin, midpoint, trapezoidal).
set(_geomint_corpus_index 100)
geomint_cli_corpus(geomint-scheme "--m does not apply to --scheme midpoint" --scheme midpoint --m 3)
geomint_cli_corpus(geomint-scheme "--m does not apply to --scheme trapezoidal" --analyse --scheme trapezoidal --m 2..4)
geomint_cli_corpus(geomint-scheme "--m does not apply to --scheme midpoint" --scheme midpoint --all)
geomint_cli_corpus(geomint-scheme "--nodes does not apply to --scheme galerkin" --scheme galerkin --nodes lobatto --m 2)
geomint_cli_corpus(geomint-scheme "--nodes does not apply to --scheme trapezoidal" --print-tableau --scheme trapezoidal --nodes all)

# Every flag of every tool: a value flag without its value and with an empty value after '=', a
# switch with a value. geomint_cli_corpus_flag(<tool> <flag> <case> <regex> <args...>) names the
# entry after the tool, the flag and the case.
function(geomint_cli_corpus_flag tool flag case flag_regex)
  string(REGEX REPLACE "[^A-Za-z0-9]+" "_" _name "${tool}${flag}_${case}")
  geomint_cli_test(geomint_cli_corpus_${_name} 2 "${flag_regex}.*usage: ${tool}" $<TARGET_FILE:${tool}> ${ARGN})
  set_tests_properties(geomint_cli_corpus_${_name} PROPERTIES TIMEOUT 30 LABELS cli_corpus)
endfunction()
set(_study_values --system --scheme --nodes --m --digits --threads)
set(_values_geomint-run --system --scheme --nodes --basis --m --digits --tau --steps --every --q0 --p0 --tableau)
set(_switches_geomint-run --csv --no-monitor --compensated --growth --estimate)
set(_values_geomint-order ${_study_values} --t-end --steps)
set(_switches_geomint-order --csv --no-monitor)
set(_values_geomint-symplectic ${_study_values} --tau --long-tau --long-steps --q0 --p0)
set(_switches_geomint-symplectic --csv --no-monitor)
set(_values_geomint-brouwer --system --steps --trajectories --tau)
set(_switches_geomint-brouwer --windows)
set(_values_geomint-scheme --scheme --nodes --m --tableau)
set(_switches_geomint-scheme --analyse --analyze --print-tableau --csv --all --list-methods)
set(_values_geomint-beam --steps --dt --nodes --scheme --every --csv --centreline --snapshots --drift --cayley --reconstruction)
set(_switches_geomint-beam)
set(_values_geomint-workprecision --system --digits --t-end --max-seconds --methods --passes)
set(_switches_geomint-workprecision --csv --plain-summation)
foreach(tool geomint-run geomint-order geomint-symplectic geomint-brouwer geomint-scheme geomint-beam geomint-workprecision)
  foreach(flag ${_values_${tool}})
    geomint_cli_corpus_flag(${tool} ${flag} missing "${flag} needs a value" ${flag})
    geomint_cli_corpus_flag(${tool} ${flag} empty "${flag} needs a non-empty value" ${flag}=)
  endforeach()
  foreach(flag ${_switches_${tool}})
    geomint_cli_corpus_flag(${tool} ${flag} valued "${flag} takes no value, got 'x'" ${flag}=x)
  endforeach()
endforeach()

# A bad value for each flag the blocks above leave out.
geomint_cli_corpus_flag(geomint-run --basis bad "--basis must be one of" --basis chebyshev)
geomint_cli_corpus_flag(geomint-run --nodes bad "--nodes must be one of" --nodes moon)
geomint_cli_corpus_flag(geomint-run --p0 range "--p0 is out of range" --p0 1e400)
geomint_cli_corpus_flag(geomint-run --every range "--every is out of range" --every 99999999999999999999)
geomint_cli_corpus_flag(geomint-order --nodes bad "--nodes must be one of" --nodes moon)
geomint_cli_corpus_flag(geomint-order --threads range "--threads is out of range" --threads 65)
geomint_cli_corpus_flag(geomint-order --t-end range "--t-end is out of range" --t-end 1e400)
geomint_cli_corpus_flag(geomint-symplectic --p0 bad "--p0 expects a finite number" --p0 abc)
geomint_cli_corpus_flag(geomint-symplectic --scheme bad "--scheme must be one of" --scheme rk4)
geomint_cli_corpus_flag(geomint-symplectic --nodes bad "--nodes must be one of" --nodes moon)
geomint_cli_corpus_flag(geomint-symplectic --digits bad "--digits must be one of" --digits 15)
geomint_cli_corpus_flag(geomint-symplectic --threads range "--threads is out of range" --threads 0)
geomint_cli_corpus_flag(geomint-symplectic --system bad "--system must be one of" --system moon)
geomint_cli_corpus_flag(geomint-brouwer --steps zero "--steps is out of range" --steps 0)
geomint_cli_corpus_flag(geomint-brouwer --steps range "--steps is out of range" --steps 1000000001)
geomint_cli_corpus_flag(geomint-brouwer --trajectories range "--trajectories is out of range" --trajectories 65)
geomint_cli_corpus_flag(geomint-brouwer --tau zero "--tau must be a finite number > 0" --tau 0)
geomint_cli_corpus_flag(geomint-brouwer --tau range "--tau is out of range" --tau 1e-400)
geomint_cli_corpus_flag(geomint-scheme --scheme bad "--scheme must be one of" --scheme rk4)
geomint_cli_corpus_flag(geomint-scheme --m range "--m range '5..3' is empty" --m 5..3)
geomint_cli_corpus_flag(geomint-beam --cayley bad "--cayley must be one of previous, current, midpoint" --cayley next)
geomint_cli_corpus_flag(geomint-beam --reconstruction bad "--reconstruction must be one of per-node, strain" --reconstruction x)
geomint_cli_corpus_flag(geomint-beam --snapshots range "--snapshots is out of range" --snapshots 10001)
geomint_cli_corpus_flag(geomint-workprecision --methods empty_item "--methods has an empty item" --methods a,,b)
geomint_cli_corpus_flag(geomint-workprecision --passes range "--passes is out of range" --passes 11)
geomint_cli_corpus_flag(geomint-workprecision --max-seconds range "--max-seconds is out of range" --max-seconds 1e400)
geomint_cli_corpus_flag(geomint-workprecision --system bad "--system must be one of" --system moon)

# Two outputs to one file: a usage error naming both flags (the rows would interleave).
geomint_cli_corpus_flag(geomint-beam --csv same_file "--csv and --drift name the same file 'F'" --steps 1 --csv F --drift F)
geomint_cli_corpus_flag(geomint-beam --centreline same_file "--csv and --centreline name the same file" --steps 1 --csv F --centreline ./F)
geomint_cli_corpus_flag(geomint-beam --drift same_stdout "--csv and --drift name the same file '-'" --steps 1 --drift - --csv -)

# Runs that could not finish (they used to hang): refused at parse time, or stopped within
# seconds with a message; the TIMEOUT turns a regression into a failure instead of a hang.
geomint_cli_corpus_flag(geomint-workprecision --t-end taylor_1e300 "--t-end is out of range: '1e300' .expected T <= 10.6"
                        --t-end 1e300 --methods taylor-series)
geomint_cli_test(geomint_cli_bounds_workprecision_budget any
                 "taylor-series at knob 0: stopped after 1.0* CPU seconds .--max-seconds."
                 $<TARGET_FILE:geomint-workprecision> --t-end 1000000 --methods taylor-series --max-seconds 0.1 --passes 1)
set_tests_properties(geomint_cli_bounds_workprecision_budget PROPERTIES TIMEOUT 60 LABELS cli_corpus)
# A sweep in which every run failed is no measurement: exit 3. The Taylor-series flow is one run
# and the only method selected; to T = 10^6 it needs far more than its one CPU second.
geomint_cli_test(geomint_cli_workprecision_all_failed 3
                 "stopped after 1.0* CPU seconds .--max-seconds.*every run failed .no measurement"
                 $<TARGET_FILE:geomint-workprecision> --t-end 1000000 --methods taylor-series --max-seconds 0.1 --passes 1)
set_tests_properties(geomint_cli_workprecision_all_failed PROPERTIES TIMEOUT 60 LABELS cli_corpus)
geomint_cli_corpus_flag(geomint-symplectic --long-steps range "--long-steps is out of range: '1000000001'" --long-steps 1000000001)
# geomint-order's work is bounded up front (10^7 steps per case over the ladder and the zoo
# reference): a ladder to 10^9 steps is refused at parse time, for the built-in and zoo systems.
geomint_cli_corpus_flag(geomint-order --steps builtin_work "--steps: the ladder needs at least 1000000010 steps per case, more than the bound 10000000"
                        --steps 8,1000000000)
geomint_cli_corpus_flag(geomint-order --steps zoo_work "--steps: the ladder and its zoo reference need at least 4000000022 steps per case, more than the bound 10000000"
                        --digits 16 --system henon-heiles --scheme midpoint --steps 8,1000000000)
if(GEOMINT_RUN_MULTIPRECISION)  # geomint-order computes in 50 digits by default
  geomint_cli_test(geomint_cli_bounds_order_t_end nonzero "reference_flow: t_end - t = 1e.300 needs about .* Taylor steps, more than the bound 100000000"
                   $<TARGET_FILE:geomint-order> --t-end 1e300)
  set_tests_properties(geomint_cli_bounds_order_t_end PROPERTIES TIMEOUT 60 LABELS cli_corpus)
endif()

# geomint-modified: the shared cases, every flag without and with an empty value, and its own
# usage errors (one flag wrong in each).
set(_geomint_corpus_index 0)
geomint_cli_corpus(geomint-modified "unknown flag --bogus" --bogus)
geomint_cli_corpus(geomint-modified "unknown flag --bogus" --bogus=3)
geomint_cli_corpus(geomint-modified "unexpected argument 'stray'" stray)
geomint_cli_corpus(geomint-modified "--csv takes no value" --csv=1)
foreach(flag --scheme --nodes --m --tableau --order --system --q0 --p0 --tau --steps --terms --digits)
  geomint_cli_corpus_flag(geomint-modified ${flag} missing "${flag} needs a value" ${flag})
  geomint_cli_corpus_flag(geomint-modified ${flag} empty "${flag} needs a non-empty value" ${flag}=)
endforeach()
geomint_cli_corpus(geomint-modified "give one of --scheme and --tableau" --order 3)
geomint_cli_corpus(geomint-modified "give one of --scheme and --tableau" --scheme midpoint --tableau x.tableau --order 3)
geomint_cli_corpus(geomint-modified "--scheme must be one of" --scheme rk4 --order 3)
geomint_cli_corpus(geomint-modified "--order K is needed without --system" --scheme midpoint)
geomint_cli_corpus(geomint-modified "--order is out of range" --scheme midpoint --order 17)
# With --system the prediction needs the trees to order p + K: at most 16 for a scheme.
geomint_cli_corpus(geomint-modified "--order/--terms: trees of order 17 needed, at most 16 for a scheme .order 2." --scheme midpoint --system pendulum --tau 0.1 --steps 10 --terms 15)
geomint_cli_corpus(geomint-modified "--order/--terms: trees of order 17 needed, at most 16 for a scheme .order 14." --scheme lpf --nodes gauss-interior --m 8 --system pendulum --tau 0.1 --steps 10 --terms 3)
geomint_cli_corpus(geomint-modified "--m applies to --scheme lpf and galerkin only" --scheme midpoint --m 3 --order 3)
geomint_cli_corpus(geomint-modified "--nodes applies to --scheme lpf only" --scheme galerkin --nodes lobatto --order 3)
geomint_cli_corpus(geomint-modified "--m must be in 2..8 for --scheme lpf" --scheme lpf --m 1 --order 3)
geomint_cli_corpus(geomint-modified "--tableau: .*cannot" --tableau no/such.tableau --order 3)
geomint_cli_corpus(geomint-modified "--tau applies with --system only" --scheme midpoint --order 3 --tau 0.1)
geomint_cli_corpus(geomint-modified "--tau is needed with --system" --scheme midpoint --system pendulum --steps 10)
geomint_cli_corpus(geomint-modified "--steps is needed with --system" --scheme midpoint --system pendulum --tau 0.1)
geomint_cli_corpus(geomint-modified "--steps is out of range" --scheme midpoint --system pendulum --tau 0.1 --steps 0)
geomint_cli_corpus(geomint-modified "--tau must be a finite number > 0" --scheme midpoint --system pendulum --tau 0.1,-1 --steps 10)
geomint_cli_corpus(geomint-modified "--terms is out of range" --scheme midpoint --system pendulum --tau 0.1 --steps 10 --terms 0)
# On a Lagrangian that is not natural the trapezoidal variational integrator is outside the
# Galerkin theorem (no Runge-Kutta form in (q, p)) and rkn and prk tableaux do not run
# (geomint/cli/modified.hpp, lagrangian_series_of).
geomint_cli_corpus(geomint-modified "--scheme trapezoidal on --system charged .a Lagrangian that is not natural.: no prediction: its two-point Lobatto quadrature is outside"
                   --scheme trapezoidal --system charged --tau 0.1 --steps 10)
geomint_cli_corpus(geomint-modified "--tableau: rkn tableaux run on natural systems only, not on --system charged"
                   --tableau ${PROJECT_SOURCE_DIR}/examples/tableaux/stormer_verlet.tableau --system charged --tau 0.1 --steps 10)
geomint_cli_corpus(geomint-modified "--q0 needs 1 value" --scheme midpoint --system pendulum --q0 1,2 --tau 0.1 --steps 10)
geomint_cli_corpus(geomint-modified "--digits must be one of 16, 50, 100" --digits 15)
geomint_cli_corpus(geomint-modified "--order with --system --csv"
                   --scheme midpoint --order 3 --system pendulum --tau 0.1 --steps 10 --csv)
