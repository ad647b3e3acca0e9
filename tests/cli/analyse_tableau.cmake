# geomint-scheme --analyse --tableau FILE (include/geomint/analysis/bseries/method_analysis.hpp):
# the exact order and symplecticity of a tableau file, in the --analyse CSV columns ('-' where a
# column is not computed for a file); --print-tableau prints a built-in scheme's tableau;
# --tableau without a file, or with the built-in scheme's flags, and a bad file exit 2.
# Included from CMakeLists.txt.
set(_tableaux ${PROJECT_SOURCE_DIR}/examples/tableaux)
set(_header "scheme,nodes,m,stages,order,symplectic,symmetric,error_constant,stability_interval,phase_lag_order,kind,stage_order,stability,dissipation_order")
# Published orders and symplecticity: Stormer-Verlet order 2 (Hairer, Lubich & Wanner,
# Geometric Numerical Integration, 2006, section I.1.4), Gauss s = 2 order 4 (ibid. section
# II.1.4), Forest-Ruth order 4 (Forest & Ruth, Physica D 43 (1990) 105-117); all symplectic
# (ibid. Theorem VI.4.10).
foreach(_case "stormer_verlet|stormer-verlet,-,-,2,2,yes" "gauss2|gauss-2,-,-,2,4,yes" "forest_ruth|forest-ruth,-,-,4,4,yes")
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _file)
  list(GET _parts 1 _row)
  geomint_cli_test(geomint_cli_scheme_analyse_tableau_${_file} zero "${_header}.${_row},-,-,-,-,rkn,-,-,-"
                   $<TARGET_FILE:geomint-scheme> --analyse --tableau ${_tableaux}/${_file}.tableau --csv)
endforeach()
# Classical RK4: order 4 (Hairer, Norsett & Wanner, Solving ODEs I, section II.1), not
# symplectic (b_1 a_11 + b_1 a_11 = 0 != b_1^2; HLW Theorem VI.4.3). Nystrom's method (Nystrom
# 1925; HNW I, section II.14): order 4, not symplectic (b_1 (bbar_2 - a_12) = 1/36 !=
# b_2 (bbar_1 - a_21) = 1/72; HLW Theorem VI.4.10).
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/rk4.tableau
     "kind rk\nstages 4\nname rk4\nc 0 1/2 1/2 1\na 0 0 0 0  1/2 0 0 0  0 1/2 0 0  0 0 1 0\nb 1/6 1/3 1/3 1/6\n")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/nystrom4.tableau
     "kind rkn\nstages 4\nname nystrom-4\nc 0 1/2 1/2 1\na 0 0 0 0  1/8 0 0 0  1/8 0 0 0  0 0 1/2 0\nbbar 1/6 1/6 1/6 0\nb 1/6 1/3 1/3 1/6\n")
geomint_cli_test(geomint_cli_scheme_analyse_tableau_rk4 zero "${_header}.rk4,-,-,4,4,no,-,-,-,-,rk,-,-,-"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${CMAKE_CURRENT_BINARY_DIR}/rk4.tableau --csv)
geomint_cli_test(geomint_cli_scheme_analyse_tableau_nystrom4 zero "${_header}.nystrom-4,-,-,4,4,no,-,-,-,-,rkn,-,-,-"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${CMAKE_CURRENT_BINARY_DIR}/nystrom4.tableau --csv)
geomint_cli_test(geomint_cli_scheme_analyse_tableau_text zero "gauss-2 .rkn, 2 stages.*order 4 .P-series.*up to order 8.*symplectic: yes"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${_tableaux}/gauss2.tableau)
# Usage errors: --tableau needs a file (and names --print-tableau), is analysed with --analyse,
# excludes the built-in scheme's flags; a bad or missing file names the file and the line.
geomint_cli_test(geomint_cli_scheme_tableau_no_file 2 "--tableau needs a value: a tableau FILE .to print a built-in scheme's tableau use --print-tableau.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --tableau --nodes gauss-interior --m 3)
geomint_cli_test(geomint_cli_scheme_tableau_last 2 "--tableau needs a value.*--print-tableau.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau)
geomint_cli_test(geomint_cli_scheme_tableau_without_analyse 2 "--tableau FILE is analysed with --analyse.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --tableau ${_tableaux}/gauss2.tableau)
geomint_cli_test(geomint_cli_scheme_tableau_and_scheme 2 "--scheme, --nodes and --m choose a built-in scheme.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme midpoint --tableau ${_tableaux}/gauss2.tableau)
geomint_cli_test(geomint_cli_scheme_tableau_missing 2 "no_such[.]tableau:0: cannot open the file.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${CMAKE_CURRENT_BINARY_DIR}/no_such.tableau)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bad_short_a.tableau "kind rkn\nstages 2\nc 0 1\na 0 0 1/2\nbbar 1/2 0\nb 1/2 1/2\n")
geomint_cli_test(geomint_cli_scheme_tableau_bad 2 "bad_short_a[.]tableau:4: a needs 4 entries .S[*]S, S = 2., found 3.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${CMAKE_CURRENT_BINARY_DIR}/bad_short_a.tableau)
# --print-tableau: the cases of corpus.cmake that used --tableau, and its flag checks.
geomint_cli_test(geomint_cli_scheme_print_tableau_nodes 2 "--nodes does not apply to --scheme trapezoidal.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --print-tableau --scheme trapezoidal --nodes all)
geomint_cli_test(geomint_cli_scheme_print_tableau_valued 2 "--print-tableau takes no value, got 'x'.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --print-tableau=x)
geomint_cli_test(geomint_cli_scheme_tableau_empty 2 "--tableau needs a non-empty value.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau=)
