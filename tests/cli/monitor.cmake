# Command-line cases of the step monitor (geomint/solvers/step_monitor.hpp), --estimate, the
# studies' asymptotic-regime verdicts and the tools' initial data and option checks
# (docs/guide/robustness.md). Included from CMakeLists.txt; uses geomint_cli_test. Every expected
# outcome comes from exact mathematics, stated above each case.

# Parabolic Kepler orbit, q0 = (1, 0), p0 = (0, sqrt 2): E = 0 exactly, conserved by the flow; a
# resolved run (tau omega_max = tau sqrt(2 / r^3) <= 1.5e-2) must pass every monitored step.
foreach(tau 0.01 0.000001)
  geomint_cli_test(geomint_cli_monitor_parabolic_kepler_${tau} zero "max .energy - energy0. = "
                   $<TARGET_FILE:geomint-run> --system kepler --q0 1,0 --p0 0,1.4142135623730951 --scheme galerkin
                   --m 4 --tau ${tau})
endforeach()
# Spring pendulum released at rest at the pivot's height (r = 1, phi = pi/2): E = 0.
geomint_cli_test(geomint_cli_monitor_spring_pendulum_pivot_height zero "max .energy - energy0. = "
                 $<TARGET_FILE:geomint-run> --system spring-pendulum --q0 1,1.5707963267948966 --p0 0,0 --scheme galerkin
                 --m 3 --tau 0.01)
# The midpoint rule on the harmonic oscillator (omega = 1) at tau = 100: unconditionally stable and
# energy-conserving, but it advances the phase by 2 atan 50 = 3.1 per step instead of 100:
# q(1000) = 0.532 against cos 1000 + sin 1000 = 1.389. tau omega = 100 > 3 (its bound).
geomint_cli_test(geomint_cli_monitor_midpoint_tau100 3 "step 0: .*tau . omega_max = 100[.]0+ > 3[.]0+"
                 $<TARGET_FILE:geomint-run> --scheme midpoint --tau 100 --steps 10)
# Ruth's order-3 method (Ruth 1983; tests/cli/ruth3.tableau) on the pendulum from rest at
# tau = 0.1: resolved (tau omega_max <= 0.1 against 3) and accurate (its energy error stays near
# 1e-5, Ruth's h^3 term), but its step 33 straddles the turning point at t = 3.3, where the step
# exchanges no kinetic and potential energy to first order: the monitor must accept it.
geomint_cli_test(geomint_cli_monitor_turning_point zero "max .energy - energy0. = 1[.][0-9]+e-05"
                 $<TARGET_FILE:geomint-run> --system pendulum --tableau ${CMAKE_CURRENT_SOURCE_DIR}/ruth3.tableau
                 --tau 0.1 --steps 400)
# Default initial data are (q0, qdot0): with --q0 only, the default velocity (0, 1) gives
# E = |qdot|^2 / 2 = 1/2 at any position (the momentum p = qdot + A(q) follows q).
geomint_cli_test(geomint_cli_run_q0_keeps_default_velocity zero "energy = 0[.]5(0000|\n)|energy = 0[.]49999"
                 $<TARGET_FILE:geomint-run> --system charged --q0 10,0 --steps 0)
# Options that do not apply to the scheme are usage errors.
geomint_cli_test(geomint_cli_run_m_midpoint 2 "--m applies to --scheme lpf, lpf-fixed-point and galerkin only.*usage: geomint-run"
                 $<TARGET_FILE:geomint-run> --scheme midpoint --m 5)
foreach(tool geomint-order geomint-symplectic)
  geomint_cli_test(geomint_cli_${tool}_m_midpoint 2 "--m applies to --scheme lpf, lpf-fixed-point and galerkin only.*usage: ${tool}"
                   $<TARGET_FILE:${tool}> --scheme midpoint --m 5)
  geomint_cli_test(geomint_cli_${tool}_nodes_galerkin 2 "--nodes applies to --scheme lpf only.*usage: ${tool}"
                   $<TARGET_FILE:${tool}> --scheme galerkin --nodes lobatto)
endforeach()
# --estimate: the midpoint rule on the harmonic oscillator from (1, 1) is the rotation by
# theta = 2 atan(tau/2) per step, so its global error at t = 10 with tau = 0.1 is, in closed form,
# max |(cos 100 theta + sin 100 theta, cos 100 theta - sin 100 theta) - (cos 10 + sin 10,
# cos 10 - sin 10)| = 0.011498; Richardson's estimate must find it (0.0115, under 1/100 of the
# solution's size 1.38: not coarse). At tau = 1 over t = 100 the error is 1.30 (closed form),
# as large as the solution: the run must say it is coarse.
geomint_cli_test(geomint_cli_run_estimate_midpoint zero "estimated global error at t = 10: 0[.]011[45]"
                 $<TARGET_FILE:geomint-run> --scheme midpoint --tau 0.1 --steps 100 --estimate)
geomint_cli_test(geomint_cli_run_estimate_coarse zero "coarse run: the estimated error is"
                 $<TARGET_FILE:geomint-run> --scheme midpoint --tau 1 --steps 100 --estimate)
geomint_cli_test(geomint_cli_run_estimate_csv zero "step,t,q1,p1,energy,error_estimate.0,0,1,1,1,0"
                 $<TARGET_FILE:geomint-run> --scheme midpoint --tau 0.1 --steps 2 --estimate --csv)
if(GEOMINT_RUN_MULTIPRECISION)  # geomint-order studies the built-in systems in 50 or 100 digits
  # The midpoint rule on the harmonic oscillator over T = 7: at N = 2, 4, 8 its phase errors are
  # 2.8, 1.2 and 0.4 rad (closed form above), errors as large as the solution: no order. With
  # the monitor, tau = 3.5 > 3 (its resolution bound, omega = 1) fails the case; without it, the
  # verdict flags the row.
  geomint_cli_test(geomint_cli_order_unresolved 3 "tau . omega_max = 3[.]50+ > 3[.]0+"
                   $<TARGET_FILE:geomint-order> --system harmonic --scheme midpoint --t-end 7 --steps 2,4)
  geomint_cli_test(geomint_cli_order_short_ladder 3 "outside: a ladder of 2 step counts"
                   $<TARGET_FILE:geomint-order> --system harmonic --scheme midpoint --t-end 7 --steps 2,4 --no-monitor)
  geomint_cli_test(geomint_cli_order_large_errors 3 "outside: global error not well below the solution's size"
                   $<TARGET_FILE:geomint-order> --system harmonic --scheme midpoint --t-end 7 --steps 2,4,8 --no-monitor)
endif()
# geomint-symplectic on the parabolic Kepler orbit (E = 0): the monitor no longer refuses the
# perturbed states of the difference Jacobian; Galerkin is symplectic, so in double its defect is
# at round-off level (1e-1x).
geomint_cli_test(geomint_cli_symplectic_parabolic_kepler zero "kepler,galerkin,-,4,0.25,[0-9.]+e-1[0-9],ok"
                 $<TARGET_FILE:geomint-symplectic> --digits 16 --system kepler --q0 1,0 --p0 0,1.4142135623730951
                 --scheme galerkin --m 4 --csv)
# geomint-symplectic keeps the monitor's reason when the map fails at a perturbed state: from the
# pendulum's q0 = 1, tau omega_max = 5 sqrt(cos q) >= 5 sqrt(cos 1) = 3.67, above the midpoint
# rule's bound 3.
geomint_cli_test(geomint_cli_symplectic_monitor_reason 3 "the map failed at a perturbed state: .*tau . omega_max = [0-9.]+ > 3"
                 $<TARGET_FILE:geomint-symplectic> --digits 16 --system pendulum --scheme midpoint --tau 5)
# geomint-symplectic's long runs carry an error estimate (the same run at tau/2): for the midpoint
# rule on the harmonic oscillator from (1, 1) (the rotation by 2 atan(tau/2) per step, closed form
# above) 2 |z_200(0.05) - z_400(0.025)|_inf = 0.0043189 at t = 10 (true error 0.0028797, below
# it), under 1/100 of the solution's size 1.38; at tau = 1 over t = 100 it is 2.6178 (true error
# 1.30, the solution's size 1.39): the run must say it is coarse. The defect's own estimate is
# printed beside it.
geomint_cli_test(geomint_cli_symplectic_long_estimate zero
                 "max_energy_error,energy_drift,regime,defect_estimate,state_error_estimate.harmonic,midpoint,-,-,0.25,[^,]+,[^,]+,[^,]+,ok,[^,]+,4[.]32e-03"
                 $<TARGET_FILE:geomint-symplectic> --digits 16 --system harmonic --scheme midpoint --long-steps 200
                 --long-tau 0.05 --csv)
geomint_cli_test(geomint_cli_symplectic_long_coarse zero
                 "2[.]62e[+]00  COARSE.*coarse long run: the estimated error at t = N tau is 2[.]62e[+]00"
                 $<TARGET_FILE:geomint-symplectic> --digits 16 --system harmonic --scheme midpoint --long-steps 100
                 --long-tau 1)
