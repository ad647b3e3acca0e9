# geomint-scheme --analyse|--print-tableau --scheme NAME, --list-methods: the catalogue of methods
# from the literature (include/geomint/methods/catalogue.hpp). Included from CMakeLists.txt.
set(_header "scheme,nodes,m,stages,order,symplectic,symmetric,error_constant,stability_interval,phase_lag_order,kind,stage_order,stability,dissipation_order")
# Published orders and symplecticity: Gauss s = 3 order 6, symplectic (Butcher 1964; Hairer,
# Lubich & Wanner 2006, section VI.4); Radau IIA s = 3 order 5 (Ehle 1969; Hairer & Wanner II,
# section IV.5); Lobatto IIIC s = 3 order 4, not symplectic (Chipman 1971; ibid.); RKN6(4)6FM
# order 6 (Dormand, El-Mikkawy & Prince 1987); Suzuki's method order 4, symplectic (Suzuki 1990;
# 5 Stormer-Verlet steps of 2 stages, 10 stages as one rkn tableau).
# Radau IIA and IA with s = 5 (over their stage algebra): order 9, stage orders 5 and 4,
# A-stable with R(z) the (4,5) Pade approximant, so phase lag order 10 and dissipation order 9.
# Verdicts: Gauss symmetric, Radau and Lobatto IIIC not; stage orders s, s and s - 1; all three
# A-stable (Hairer & Wanner II, section IV.5); their R(z) are the (3,3), (2,3) and (1,3) Pade
# approximants, so on the oscillator |R(iy)| = 1 for Gauss (dissipation inf) and
# 1 - |R(iy)| = O(y^6) for the other two (dissipation order 5), with phase lag order 6 for Gauss
# and Radau (R - e^z = C z^(p+1) with z^6 real on the imaginary axis) and 4 for IIIC. RKN6(4)6FM
# is explicit with det M(tau) > 1 for every tau > 0 (e.g. det M - 1 = 6.7e-10 at tau = 1/2,
# 8.1e-5 at tau = 2, computed exactly from the printed tableau), so its interval of absolute
# stability is empty. Suzuki's composition has coefficients in Q(4^(1/3)) = Q(2^(1/3)): det M = 1,
# interval of periodicity up to tau* = 2.7209745385... (the first tau with |tr M| > 2 of the
# product of its five Stormer-Verlet matrices, computed in 50 digits by
# tests/analysis/test_field_stability.cpp), phase-lag order 4. Error constants: their format here
# (C to 4 digits); their values are checked in tests/analysis/test_bseries_error_constants.cpp.
set(_c "[0-9][.][0-9][0-9][0-9]e-0[0-9]")
foreach(_case "gauss-3,-,-,3,6,yes,yes,${_c},inf,6,rk,3,a-stable,inf" "radau-iia-3,-,-,3,5,no,no,${_c},inf,6,rk,3,a-stable,5"
              "lobatto-iiic-3,-,-,3,4,no,no,${_c},inf,4,rk,2,a-stable,5" "demp-rkn64,-,-,6,6,no,no,${_c},0,6,rkn,2,none,7"
              "suzuki-4,-,-,10,4,yes,yes,${_c},2[.]72097453856014969076597167175,4,rkn,2,periodic,inf"
              "radau-iia-5,-,-,5,9,no,no,${_c},inf,10,rk,5,a-stable,9" "radau-ia-5,-,-,5,9,no,no,${_c},inf,10,rk,4,a-stable,9")
  string(REGEX MATCH "^[^,]+" _name "${_case}")
  geomint_cli_test(geomint_cli_scheme_catalogue_${_name} zero "${_header}.${_case}"
                   $<TARGET_FILE:geomint-scheme> --analyse --scheme ${_name} --csv)
endforeach()
geomint_cli_test(geomint_cli_scheme_catalogue_text zero
                 "catalogue method forest-ruth .Forest-Ruth; Forest & Ruth 1990.: forest-ruth .rkn, 3 stages.*order 4 .*symplectic: yes.*principal error constant C = [0-9.e-]+ .position C_q = [0-9.e-]+, velocity C_p = [0-9.e-]+. at order 5.*interval of periodicity tau. = 1[.]57340194743454005662957944196; phase-lag order 4"
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme forest-ruth)
# Exact symplecticity on the irreducible method, with the first defect where it fails: Radau
# IIA, s = 2 (c = (1/3, 1), a_11 = 5/12, b_1 = 3/4; Hairer & Wanner II, section IV.5):
# 2 b_1 a_11 - b_1^2 = 5/8 - 9/16 = 1/16; Lobatto IIIB, s = 2, is the implicit midpoint rule
# (its two stages are equal); the per-component orders of Nystrom's method (order 4 in both).
geomint_cli_test(geomint_cli_scheme_catalogue_defect zero
                 "symplectic: no .b_i a_ij [+] b_j a_ji = b_i b_j, exact, on the irreducible method of 2 stages.*defect of b_i a_ij [+] b_j a_ji = b_i b_j at .i, j. = .1, 1.: 1/16"
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme radau-iia-2)
geomint_cli_test(geomint_cli_scheme_catalogue_reducible zero
                 "symplectic: yes .b_i a_ij [+] b_j a_ji = b_i b_j, exact, on the irreducible method of 1 stage."
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme lobatto-iiib-2)
geomint_cli_test(geomint_cli_scheme_catalogue_components zero "order of each component: position 4, velocity 4 .local."
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme nystrom-4)
# --print-tableau: a tableau file (Gauss s = 3: c = 1/2 -+ sqrt 15/10, b = (5, 8, 5)/18;
# Hairer & Wanner II, section IV.5), read back with the same analysis.
geomint_cli_test(geomint_cli_scheme_catalogue_print zero
                 "kind rk.stages 3.name gauss-3.field r.2-15.c 1/2-1/10[*]r 1/2 1/2[+]1/10[*]r.a [^\n]*.b 5/18 4/9 5/18"
                 $<TARGET_FILE:geomint-scheme> --print-tableau --scheme gauss-3)
# Radau IIA, s = 5, has no tableau file (its entries lie in a field of degree 24): its operators
# on Q[x]/(N), N = P*_5 - P*_4 made monic, and the 30-digit tableau, whose last row is b
# (c_5 = 1, b_5 = 1/s^2 = 0.04; Hairer & Wanner II, section IV.5).
geomint_cli_test(geomint_cli_scheme_catalogue_print_algebra zero
                 "not a tableau file.kind rk, 5 stages, name radau-iia-5.stages: the roots of N.x. = 1 x.5 [+] .-25/9. x.4.*decimal tableau .30 digits.*c_5 = 1.  a: [-0-9. ]* 0[.]04.  b = 0[.]04"
                 $<TARGET_FILE:geomint-scheme> --print-tableau --scheme radau-iia-5)
# Each also runs by name and from its file in geomint-run, with the same rows.
# (The IIIA-IIIB pairs are left out: their P-series analysis to order 8 takes 15 s in the test
# build; tests/methods/test_catalogue.cpp checks them.)
foreach(_name gauss-3 radau-ia-3 forest-ruth demp-rkn43 nystrom-4)
  add_test(NAME geomint_cli_scheme_catalogue_round_trip_${_name}
           COMMAND ${CMAKE_COMMAND} -DSCHEME=$<TARGET_FILE:geomint-scheme> -DRUN=$<TARGET_FILE:geomint-run> -DNAME=${_name}
                   -DFILE=${CMAKE_CURRENT_BINARY_DIR}/catalogue_${_name}.tableau -P ${CMAKE_CURRENT_SOURCE_DIR}/catalogue_round_trip.cmake)
endforeach()
geomint_cli_test(geomint_cli_scheme_catalogue_list zero "name,kind,stages,order,title,source.gauss-2,rk,2,4,.*nystrom-4,nystrom,4,4,"
                 $<TARGET_FILE:geomint-scheme> --list-methods)
# Usage errors: options of the built-in schemes, no mode, --tableau, an unknown name.
geomint_cli_test(geomint_cli_scheme_catalogue_m 2 "--m and --nodes do not apply to --scheme gauss-3 .a method of the catalogue.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme gauss-3 --m 3)
geomint_cli_test(geomint_cli_scheme_catalogue_no_mode 2 "--scheme gauss-3 .a method of the catalogue. is used with --analyse or --print-tableau.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --scheme gauss-3)
geomint_cli_test(geomint_cli_scheme_catalogue_tableau 2 "--scheme and --tableau FILE exclude each other.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme gauss-3 --tableau ${PROJECT_SOURCE_DIR}/examples/tableaux/gauss2.tableau)
geomint_cli_test(geomint_cli_scheme_catalogue_unknown 2 "--scheme must be one of lpf, midpoint, trapezoidal, galerkin or a method of the catalogue .geomint-scheme --list-methods.; got 'gauss-9'.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --analyse --scheme gauss-9)
geomint_cli_test(geomint_cli_scheme_catalogue_list_alone 2 "--list-methods takes no other option.*usage: geomint-scheme"
                 $<TARGET_FILE:geomint-scheme> --list-methods --scheme gauss-3)
# geomint-run --scheme NAME: Radau IIA, s = 5 (no tableau file: the coefficients in 50 digits from
# its stage algebra) on Kepler (a = 1, e = 1/2, from pericentre) against the exact state at
# t = 100 from Kepler's equation (tests/cli/CMakeLists.txt, the m = 9..16 tests: q =
# (0.0958041308370718831386459947510410149, -0.6955307888642392780075247350316649624),
# p = (1.1438999273507987907512255545384113573, 0.7349138739344099641379528529514756352)),
# to the digits its error at this step allows (order 9).
geomint_cli_test(geomint_cli_run_catalogue_radau_kepler zero
                 "scheme radau-iia-5 .rk, 5 stages.*q = 0[.]0958041[0-9]* -0[.]6955307[0-9]*.p = 1[.]1438999[0-9]* 0[.]7349138"
                 $<TARGET_FILE:geomint-run> --system kepler --scheme radau-iia-5 --tau 0.05 --steps 2000 --digits 50)
# Usage errors: the options of the built-in schemes, --tableau, a constrained system.
geomint_cli_test(geomint_cli_run_catalogue_m 2 "--m, --nodes and --basis apply to the built-in schemes, not to --scheme gauss-3 .a method of the catalogue.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --scheme gauss-3 --m 3)
geomint_cli_test(geomint_cli_run_catalogue_tableau 2 "--scheme and --tableau exclude each other.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --scheme gauss-3 --tableau ${PROJECT_SOURCE_DIR}/examples/tableaux/gauss2.tableau)
geomint_cli_test(geomint_cli_run_catalogue_constrained 2 "--scheme gauss-3 .a method of the catalogue. runs on the free systems only, not on the constrained system circle.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --scheme gauss-3 --system circle)
geomint_cli_test(geomint_cli_run_catalogue_unknown 2 "--scheme must be one of lpf, .* or a method of the catalogue .geomint-scheme --list-methods.; got 'gauss-9'.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --scheme gauss-9)
