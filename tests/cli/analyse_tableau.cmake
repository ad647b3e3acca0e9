# geomint-scheme --analyse --tableau FILE (include/geomint/analysis/bseries/method_analysis.hpp,
# analysis/method_verdicts.hpp, analysis/rk_stability.hpp): the exact order, symplecticity,
# symmetry, stage order, principal error constant (analysis/bseries/error_constants.hpp) and
# linear stability (over Q and Q(r): analysis/field_stability.hpp) of a tableau file in the
# --analyse CSV columns;
# --print-tableau prints a built-in scheme's tableau; --tableau without a file, or with the
# built-in scheme's flags, and a bad file exit 2. Included from CMakeLists.txt.
set(_tableaux ${PROJECT_SOURCE_DIR}/examples/tableaux)
set(_header "scheme,nodes,m,stages,order,symplectic,symmetric,error_constant,stability_interval,phase_lag_order,kind,stage_order,stability,dissipation_order")
set(_test_tableaux ${PROJECT_SOURCE_DIR}/tests/analysis/tableaux)
# Published orders and symplecticity: Stormer-Verlet order 2 (Hairer, Lubich & Wanner,
# Geometric Numerical Integration, 2006, section I.1.4), Gauss s = 2 order 4 (ibid. section
# II.1.4), Forest-Ruth order 4 (Forest & Ruth, Physica D 43 (1990) 105-117); all symplectic
# (ibid. Theorem VI.4.10) and symmetric (ibid. section V.2; Forest-Ruth a symmetric composition).
# Stormer-Verlet on y'' = -y: tr M = 2 - tau^2, det M = 1: periodic for tau <= 2; R - 2 cos tau =
# tau^4 / 12 + ...: phase-lag order 2; stage order 2 (a 1 = c^2 / 2, a c = 0 != c^3 / 6). Gauss
# s = 2 as an rkn tableau (the collocation RKN method): tr M = 2 (7 z^2 - 192 z + 432) / (z^2 +
# 24 z + 432), z = tau^2, det M = 1, so 2 + tr M = 16 (z - 9)(z - 12) / (...) >= 0 up to tau = 3
# (the stage equations solved exactly by hand or any computer algebra system, and the built-in
# lpf gauss-interior m = 3, the same map, prints the same); stage order 3 = s + 1 (collocation).
# Forest-Ruth: stage order 2 (exact for constant forces, as each Stormer-Verlet step); its step
# matrix has coefficients in Q(2^(1/3)): interval of periodicity up to tau* = 1.5734019474...
# (the first tau with |tr M| > 2 of the product of its Stormer-Verlet matrices, computed in 50
# digits by tests/analysis/test_field_stability.cpp), phase-lag order 4 (order 4, det M = 1).
# Error constants (C = sqrt(C_q^2 + C_p^2) to 4 digits): Stormer-Verlet C^2 = 1/36 + 1/72 = 1/24
# from its Taylor expansion (tests/analysis/test_bseries_error_constants.cpp), C = 2.041e-01;
# Gauss s = 2 as the collocation RKN method: the library's lpf gauss-interior m = 3 (the same
# map, above) has C = 4.076e-03 (geomint-scheme --analyse --nodes gauss-interior --m 3); the
# others are checked in that test file, here only their format.
set(_tableau_cases "${_tableaux}/stormer_verlet|stormer-verlet,-,-,2,2,yes,yes,2[.]041e-01,2,2,rkn,2,periodic,inf"
                  "${_tableaux}/gauss2|gauss-2,-,-,2,4,yes,yes,4[.]076e-03,3,4,rkn,3,periodic,inf"
                  "${_tableaux}/forest_ruth|forest-ruth,-,-,4,4,yes,yes,[0-9][.][0-9][0-9][0-9]e-0[0-9],1[.]57340194743454005662957944196,4,rkn,2,periodic,inf")
# Classical RK4: order 4 (Hairer, Norsett & Wanner, Solving ODEs I, section II.1), not
# symplectic (b_1 a_11 + b_1 a_11 = 0 != b_1^2; HLW Theorem VI.4.3), not symmetric; stage order
# 1 (a_21 c_1 = 0 != c_2^2 / 2). R(iy) = 1 - y^2/2 + y^4/24 + i (y - y^3/6), |R(iy)|^2 = 1 - y^6/72
# + y^8/576: |R(iy)| <= 1 for y <= 2 sqrt 2 = 2.8284271247461900976033774484194 (Hairer & Wanner,
# Solving ODEs II, section IV.2), absolute; 1 - |R| = y^6/144 + ...: dissipation order 5;
# arg R(iy) = y - y^5/120 + ...: phase-lag order 4 (van der Houwen & Sommeijer 1987).
# Nystrom's method (Nystrom 1925; HNW I, section II.14): order 4, not symplectic (b_1 (bbar_2 -
# a_12) = 1/36 != b_2 (bbar_1 - a_21) = 1/72; HLW Theorem VI.4.10). On y'' = -y, from the stage
# equations: tr M = (z^2 - 12 z + 24) / 12 and det M = 1 - z^3 / 288 (z = tau^2), so absolute
# stability (Jury: det M <= 1, 1 + det M -+ tr M >= 0) ends at the root z = 6.690079991706694...
# of z^3 - 24 z^2 + 288 z - 1152: tau* = 2.58651889451956154854055275834; 1 - sqrt(det M) =
# tau^6 / 576 + ...: dissipation order 5; phase lag tau^5 / 320 + ...: order 4; stage order 2
# (a 1 = c^2 / 2; a c = (0, 0, 0, 1/4) != c^3 / 6).
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/rk4.tableau
     "kind rk\nstages 4\nname rk4\nc 0 1/2 1/2 1\na 0 0 0 0  1/2 0 0 0  0 1/2 0 0  0 0 1 0\nb 1/6 1/3 1/3 1/6\n")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/nystrom4.tableau
     "kind rkn\nstages 4\nname nystrom-4\nc 0 1/2 1/2 1\na 0 0 0 0  1/8 0 0 0  1/8 0 0 0  0 0 1/2 0\nbbar 1/6 1/6 1/6 0\nb 1/6 1/3 1/3 1/6\n")
geomint_cli_test(geomint_cli_scheme_analyse_tableau_rk4 zero "${_header}.rk4,-,-,4,4,no,no,[0-9][.][0-9][0-9][0-9]e-0[0-9],2[.]82842712474619009760337744842,4,rk,1,absolute,5"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${CMAKE_CURRENT_BINARY_DIR}/rk4.tableau --csv)
geomint_cli_test(geomint_cli_scheme_analyse_tableau_nystrom4 zero
                 "${_header}.nystrom-4,-,-,4,4,no,no,[0-9][.][0-9][0-9][0-9]e-0[0-9],2[.]58651889451956154854055275834,4,rkn,2,absolute,5"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${CMAKE_CURRENT_BINARY_DIR}/nystrom4.tableau --csv)
# Every kind over Q(r) (tests/analysis/tableaux): Gauss s = 3 (Q(sqrt 15)) order 6, symplectic,
# symmetric, stage order 3, R the Pade approximant R_33: A-stable, |R(iy)| = 1 (det M = 1),
# R(iy) = exp(i (y - C y^7 + ...)): phase-lag order 6. Radau IIA s = 3 (Q(sqrt 6)) order 5, not
# symplectic or symmetric, stage order 3, R = R_23 (L-stable; the CSV says a-stable), R(z) - e^z =
# C z^6 + ...: |R(iy)| = 1 - C' y^6: dissipation order 5, phase-lag order 6 (Hairer & Wanner,
# Solving ODEs II, sections IV.3 and IV.5). Lobatto IIIA-IIIB s = 3 (prk): order 4, symplectic,
# symmetric (HLW sections II.2, V.2, VI.4), stage order min(3, s - 2 = 1); from its stage
# equations on q' = p, p' = -q: tr M = (tau^4 - 22 tau^2 + 48) / (tau^2 + 24), det M = 1, so
# |tr M| <= 2 up to tau^2 = 8 (2 + tr M = (tau^2 - 8)(tau^2 - 12) / (tau^2 + 24)), phase lag
# -tau^5 / 2880: order 4. The implicit midpoint rule as a nystrom tableau: order 2, symplectic,
# symmetric, stage order 1, tr M = 2 (4 - tau^2) / (4 + tau^2), |tr M| <= 2 for every tau.
list(APPEND _tableau_cases "${_test_tableaux}/gauss3_rk|gauss-3-rk,-,-,3,6,yes,yes,[0-9][.][0-9][0-9][0-9]e-0[0-9],inf,6,rk,3,a-stable,inf"
     "${_test_tableaux}/radau_iia3|radau-iia-3,-,-,3,5,no,no,[0-9][.][0-9][0-9][0-9]e-0[0-9],inf,6,rk,3,a-stable,5"
     "${_test_tableaux}/lobatto_iiia_iiib3|lobatto-iiia-iiib-3,-,-,3,4,yes,yes,[0-9][.][0-9][0-9][0-9]e-0[0-9],2[.]82842712474619009760337744842,4,prk,1,periodic,inf"
     "${_test_tableaux}/midpoint_nystrom|midpoint-nystrom,-,-,1,2,yes,yes,[0-9][.][0-9][0-9][0-9]e-0[0-9],inf,2,nystrom,1,periodic,inf")
foreach(_case IN LISTS _tableau_cases)
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _file)
  list(GET _parts 1 _row)
  get_filename_component(_stem "${_file}" NAME)
  geomint_cli_test(geomint_cli_scheme_analyse_tableau_${_stem} zero "${_header}.${_row}"
                   $<TARGET_FILE:geomint-scheme> --analyse --tableau ${_file}.tableau --csv)
endforeach()
geomint_cli_test(geomint_cli_scheme_analyse_tableau_rk_text zero
                 "radau-iia-3 .rk, 3 stages.*stage order 3.*symmetric: no.*R.z. = .60 [+] 24 z [+] 3 z.2./.60 - 36 z [+] 9 z.2 - z.3.. A-stable: yes, L-stable: yes"
                 $<TARGET_FILE:geomint-scheme> --analyse --tableau ${_test_tableaux}/radau_iia3.tableau)
geomint_cli_test(geomint_cli_scheme_analyse_tableau_text zero "gauss-2 .rkn, 2 stages.*order 4 .Nystrom trees up to order 8.*symplectic: yes"
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
