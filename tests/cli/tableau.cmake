# geomint-run --tableau FILE (include/geomint/methods/tableau_file.hpp, docs/guide/tableau_files.md):
# the example files run, in 16, 50 and 100 digits; --scheme and --tableau exclude each other;
# every malformed file exits 2 naming the file and the line. Included from CMakeLists.txt.
set(_tableaux ${PROJECT_SOURCE_DIR}/examples/tableaux)
# Expected values from exact mathematics: the harmonic oscillator from the tool's default data
# q0 = 1, qdot0 = 1 has q(t) = cos t + sin t, p(t) = cos t - sin t; at t = 1 (mpmath):
# q = 1.38177329067603622405, p = -0.30116867893975678925. The order-4 methods' error at tau = 0.01
# is about 1e-10, so 8 digits are checked; Stormer-Verlet (order 2, error about 1e-5) to 4.
geomint_cli_test(geomint_cli_run_tableau_gauss2 zero "scheme gauss-2 .rkn, 2 stages.*q = 1[.]3817732[0-9]*.p = -0[.]3011686[0-9]*"
                 $<TARGET_FILE:geomint-run> --tableau ${_tableaux}/gauss2.tableau --tau 0.01 --steps 100)
geomint_cli_test(geomint_cli_run_tableau_forest_ruth_50 zero "forest-ruth .rkn, 4 stages.*digits 50.*q = 1[.]3817732[0-9]*.p = -0[.]3011686[0-9]*"
                 $<TARGET_FILE:geomint-run> --tableau ${_tableaux}/forest_ruth.tableau --tau 0.01 --steps 100 --digits 50)
geomint_cli_test(geomint_cli_run_tableau_gauss2_100 zero "digits 100.*q = 1[.]3817732[0-9]*.p = -0[.]3011686[0-9]*"
                 $<TARGET_FILE:geomint-run> --tableau ${_tableaux}/gauss2.tableau --tau 0.01 --steps 100 --digits 100)
geomint_cli_test(geomint_cli_run_tableau_verlet zero "stormer-verlet .rkn, 2 stages.*q = 1[.]381[0-9]*.p = -0[.]301[0-9]*"
                 $<TARGET_FILE:geomint-run> --tableau ${_tableaux}/stormer_verlet.tableau --tau 0.01 --steps 100)
# Usage errors: exclusive flags, an rkn tableau on a Lagrangian that is not natural, no file.
geomint_cli_test(geomint_cli_run_tableau_and_scheme 2 "--scheme and --tableau exclude each other.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --scheme midpoint --tableau ${_tableaux}/gauss2.tableau)
geomint_cli_test(geomint_cli_run_tableau_not_natural 2 "rkn tableau runs on natural systems only.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --system charged --tableau ${_tableaux}/gauss2.tableau --steps 1)
geomint_cli_test(geomint_cli_run_tableau_no_file 2 "no_such[.]tableau:0: cannot open the file.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --tableau ${CMAKE_CURRENT_BINARY_DIR}/no_such.tableau)
# Malformed files, written here: each exits 2 naming the file and the line.
set(_head "kind rkn\nstages 2\n")
set(_rest "a 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n")
foreach(_case
    "missing_entries|${_head}c 0\n${_rest}|bad_missing_entries[.]tableau:3: c needs 2 entries .S, S = 2., found 1"
    "extra_entries|${_head}c 0 1\na 0 0 1/2 0 1\nbbar 1/2 0\nb 1/2 1/2\n|bad_extra_entries[.]tableau:4: a needs 4 entries .S[*]S, S = 2., found 5"
    "unknown_key|${_head}c 0 1\n${_rest}bhatt 1 2\n|bad_unknown_key[.]tableau:7: unknown key 'bhatt'"
    "no_real_root|${_head}field r^4 + r^2 + 1\nc 0 1\n${_rest}|bad_no_real_root[.]tableau:3: field: the field polynomial has no real root"
    "division_by_zero|${_head}field r^2 - 2\nc 0 1\na 0 0 1/(r^2-2) 0\nbbar 1/2 0\nb 1/2 1/2\n|bad_division_by_zero[.]tableau:5: a entry 3: entry '1/.r.2-2.': division by zero"
    "missing_array|${_head}c 0 1\na 0 0 1/2 0\nb 1/2 1/2\n|bad_missing_array[.]tableau:5: no 'bbar' line")
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _name)
  list(GET _parts 1 _text)
  list(GET _parts 2 _regex)
  string(REPLACE "\\n" "\n" _text "${_text}")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bad_${_name}.tableau "${_text}")
  geomint_cli_test(geomint_cli_run_tableau_bad_${_name} 2 "${_regex}.*usage: geomint-run"
                   $<TARGET_FILE:geomint-run> --tableau ${CMAKE_CURRENT_BINARY_DIR}/bad_${_name}.tableau)
endforeach()
geomint_cli_test(geomint_cli_run_tableau_and_m 2 "--m, --nodes and --basis apply to the built-in schemes, not to --tableau.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --m 3 --tableau ${_tableaux}/gauss2.tableau)
