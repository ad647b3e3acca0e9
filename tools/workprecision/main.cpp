/// geomint-workprecision: work-precision of geomint's variational integrators against strong
/// peers (Boost.Odeint's symplectic RKN steppers, controlled runge_kutta_fehlberg78 and
/// bulirsch_stoer; symmetric compositions of Stormer-Verlet of order 6, 8 and 10; geomint's
/// Taylor-series flow) on the pendulum, the Kepler problem and the outer solar system, in double
/// or in 50 digits.
///
/// Files: problems.hpp (initial data, energy, force, closed-form reference), methods.hpp (one
/// interface over all methods), measurement.hpp (sweeps, timing, summary), regime.cpp (the
/// method lists, one translation unit per problem and regime), main.cpp (command line).
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "regimes.hpp"

namespace {

const char* usage =
    "usage: geomint-workprecision [--system pendulum|kepler|outer-solar] [--digits 16|50] [--csv]\n"
    "                             [--t-end T (0..10^6)] [--max-seconds S (> 0)] [--methods a,b,...]\n"
    "                             [--plain-summation] [--passes N (1..10)]\n"
    "                             [--scalar cpp_bin_float_50|dd_real]\n"
    "Work-precision of geomint's variational integrators (LPF on Gauss interior nodes in its\n"
    "Newton and its fixed-point form, lpf-fixed-point-m*, and Galerkin up to m = 16, and more;\n"
    "in double also lpf-fixed-point-m*-stop-on-rate, whose sweeps stop on their contraction rate,\n"
    "and lpf-fixed-point-m*-scalar-forces, whose stage forces are evaluated one at a time instead\n"
    "of on SIMD packs, the default)\n"
    "against peers: Boost.Odeint's symplectic_rkn_sb3a_mclachlan,\n"
    "symplectic_rkn_sb3a_m4_mclachlan, velocity_verlet, controlled runge_kutta_fehlberg78 and\n"
    "bulirsch_stoer; symmetric compositions of Stormer-Verlet (Yoshida order 6, 7 stages;\n"
    "Kahan-Li order 8, 17 stages; Sofroniou-Spaletta order 10, 35 stages) with coefficients\n"
    "refined to the scalar's precision; geomint's Taylor-series flow (one run).\n"
    "Pendulum: theta0 = 1, thetadot0 = 0. Kepler: e = 0.5, q0 = (0.5, 0), qdot0 = (0, sqrt 3).\n"
    "Outer solar system: Sun, Jupiter, Saturn, Uranus, Neptune, Pluto from 5 September 1994\n"
    "(Hairer, Lubich, Wanner, section I.2.4; days, AU, solar masses); its default T is 100 times\n"
    "the regime's, in days; its geomint side is LPF's fixed-point form m = 6..16 and, in double,\n"
    "Newton's lpf m = 4, 6 and galerkin m = 4 (18 dof); its reference is the Taylor-series flow\n"
    "in the wider scalar.\n"
    "--digits 16: double, T = 1000 (default), errors down to 1e-13, --max-seconds default 1.\n"
    "--digits 50: cpp_bin_float_50, T = 100 (default), errors down to 1e-40, --max-seconds default 4.\n"
    "--scalar dd_real (with --digits 50, where built with libqd): that regime in libqd's\n"
    "double-double (31 digits, round-off near 1e-31): LPF's fixed-point form m = 8, 12, 16 and the\n"
    "peers of that regime but bulirsch_stoer.\n"
    "Fixed-step methods: tau = T/steps shrinks by 2^(1/4); adaptive ones: tolerance by 10^(1/4);\n"
    "a sweep stops below the error floor, when the error stops improving, or when one run takes\n"
    "more than S CPU seconds: such a run is stopped there (checked every 256 steps; the first\n"
    "run of a sweep gets at least 1 s). T is at most 10^6 (a stated bound: beyond it the\n"
    "reference and the Taylor-series flow would take hours); the Taylor-series flow refuses a T\n"
    "beyond 10^8 of its steps. The reference is the closed form in a wider scalar.\n"
    "--csv prints method,tau,steps,cpu_seconds,final_error,max_energy_error (one row per run;\n"
    "the final error is |(q, qdot) - (q, qdot)_ref| at T, the energy error absolute)\n"
    "followed by the summary as '#' lines; otherwise a table and the summary. The summary\n"
    "interpolates (log-log) each method's CPU time at the regime's target errors and compares the\n"
    "best geomint scheme with the best peer (goals: double 1/2 at 1e-10 and 1/3 at 1e-12;\n"
    "50 digits 1/10 at 1e-30).\n"
    "--methods restricts the run to a comma-separated list of method names (see the table).\n"
    "geomint's schemes add the increments of q and p with compensated summation (Brouwer's law\n"
    "for the round-off); --plain-summation turns it off.\n"
    "--passes N: timing passes over every run, the fastest time kept (default 2): a machine that\n"
    "slows down for seconds slows one pass, not all.\n"
    "Exit status: 0, 2 (bad command line), 3 (every run failed: no measurement), 4 (output failed).\n";

}  // namespace

int main(int argc, char** argv) {
  geomint::workprecision::settings o;
  std::optional<std::string> scalar;
  geomint::cli::parser cl("geomint-workprecision", usage);
  cl.toggle("--csv", [&] { o.csv = true; })
      .toggle("--plain-summation", [&] { o.compensated = false; })
      .value("--system", [&](const std::string& v) { o.system = geomint::cli::parse_choice("--system", v, {"pendulum", "kepler", "outer-solar"}); })
      .value("--digits",
             [&](const std::string& v) { o.digits = geomint::cli::parse_choice("--digits", v, {"16", "50"}) == "16" ? 16 : 50; })
      .value("--t-end", [&](const std::string& v) {
        o.t_end = geomint::cli::parse_real("--t-end", v, geomint::cli::real_bound::positive);
        if (*o.t_end > 1e6) throw geomint::cli::usage_error("--t-end is out of range: '" + v + "' (expected T <= 10^6)");
      })
      .value("--max-seconds",
             [&](const std::string& v) { o.max_seconds = geomint::cli::parse_real("--max-seconds", v, geomint::cli::real_bound::positive); })
      .value("--methods", [&](const std::string& v) { o.only = geomint::cli::split_list("--methods", v); })
      .value("--passes", [&](const std::string& v) { o.passes = geomint::cli::parse_integer<int>("--passes", v, 1, 10); })
      .value("--scalar", [&](const std::string& v) { scalar = geomint::cli::parse_choice("--scalar", v, {"double", "cpp_bin_float_50", "dd_real"}); });
  if (const auto done = cl.parse(argc, argv)) return *done;
  // The scalar of the regime: its default, or --scalar where the regime and the build have it.
  const std::string regime_scalar = o.digits == 16 ? "double" : "cpp_bin_float_50";
  o.scalar = scalar.value_or(regime_scalar);
  const bool double_double = o.scalar == "dd_real" && o.digits == 50;
  if (o.scalar != regime_scalar && !double_double) {
    std::cerr << "geomint-workprecision: --scalar " << o.scalar << " does not run --digits " << o.digits
              << " (expected " << regime_scalar << (o.digits == 50 ? " or dd_real" : "") << ")\n"
              << usage;
    return geomint::cli::exit_usage;
  }
#if !GEOMINT_HAVE_QD
  if (double_double) {
    std::cerr << "geomint-workprecision: --scalar dd_real is not compiled into this build (libqd, Debian libqd-dev, was not found)\n";
    return geomint::cli::exit_usage;
  }
#endif
  try {
    using namespace geomint::workprecision;
    int rc = 0;
#if GEOMINT_HAVE_QD
    if (double_double) {
      if (o.system == "kepler") rc = run_regime_double_double<kepler_problem>(o);
      else if (o.system == "outer-solar") rc = run_regime_double_double<outer_solar_problem>(o);
      else rc = run_regime_double_double<pendulum_problem>(o);
    } else
#endif
    if (o.system == "kepler") rc = o.digits == 16 ? run_regime<kepler_problem, 16>(o) : run_regime<kepler_problem, 50>(o);
    else if (o.system == "outer-solar")
      rc = o.digits == 16 ? run_regime<outer_solar_problem, 16>(o) : run_regime<outer_solar_problem, 50>(o);
    else rc = o.digits == 16 ? run_regime<pendulum_problem, 16>(o) : run_regime<pendulum_problem, 50>(o);
    if (rc < 0) {
      std::cout.flush();
      std::cerr << "geomint-workprecision: every run failed (no measurement; see the messages above)\n";
      rc = geomint::cli::exit_run_failure;
    }
    return geomint::cli::finish_stdout("geomint-workprecision", rc);
  } catch (const std::invalid_argument& e) {
    std::cerr << "geomint-workprecision: " << e.what() << "\n" << usage;
    return geomint::cli::finish_stdout("geomint-workprecision", geomint::cli::exit_usage);
  } catch (const std::exception& e) {
    std::cerr << "geomint-workprecision: " << e.what() << "\n";
    return geomint::cli::finish_stdout("geomint-workprecision", 1);
  }
}
