/// geomint-workprecision: work-precision of geomint's variational integrators against strong
/// peers (Boost.Odeint's symplectic RKN steppers, controlled runge_kutta_fehlberg78 and
/// bulirsch_stoer; symmetric compositions of Stormer-Verlet of order 6, 8 and 10; geomint's
/// Taylor-series flow) on the pendulum and the Kepler problem, in double or in 50 digits.
///
/// Files: problems.hpp (initial data, energy, force, closed-form reference), methods.hpp (one
/// interface over all methods), measurement.hpp (sweeps, timing, summary), regime.cpp (the
/// method lists, one translation unit per problem and regime), main.cpp (command line).
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "regimes.hpp"

namespace {

const char* usage =
    "usage: geomint-workprecision [--system pendulum|kepler] [--digits 16|50] [--csv]\n"
    "                             [--t-end T (> 0)] [--max-seconds S (> 0)] [--methods a,b,...]\n"
    "Work-precision of geomint's variational integrators (LPF on Gauss interior nodes and\n"
    "Galerkin up to m = 16, and more) against peers: Boost.Odeint's symplectic_rkn_sb3a_mclachlan,\n"
    "symplectic_rkn_sb3a_m4_mclachlan, velocity_verlet, controlled runge_kutta_fehlberg78 and\n"
    "bulirsch_stoer; symmetric compositions of Stormer-Verlet (Yoshida order 6, 7 stages;\n"
    "Kahan-Li order 8, 17 stages; Sofroniou-Spaletta order 10, 35 stages) with coefficients\n"
    "refined to the scalar's precision; geomint's Taylor-series flow (one run).\n"
    "Pendulum: theta0 = 1, thetadot0 = 0. Kepler: e = 0.5, q0 = (0.5, 0), qdot0 = (0, sqrt 3).\n"
    "--digits 16: double, T = 1000 (default), errors down to 1e-13, --max-seconds default 1.\n"
    "--digits 50: cpp_bin_float_50, T = 100 (default), errors down to 1e-40, --max-seconds default 4.\n"
    "Fixed-step methods: tau = T/steps shrinks by sqrt(2); adaptive ones: tolerance by 10^(1/2);\n"
    "a sweep stops below the error floor, when the error stops improving, or when one run takes\n"
    "more than S CPU seconds. The reference is the closed form in a wider scalar.\n"
    "--csv prints method,tau,steps,cpu_seconds,final_error,max_energy_error (one row per run)\n"
    "followed by the summary as '#' lines; otherwise a table and the summary. The summary\n"
    "interpolates (log-log) each method's CPU time at the regime's target errors and compares the\n"
    "best geomint scheme with the best peer (goals: double 1/2 at 1e-10 and 1/3 at 1e-12;\n"
    "50 digits 1/10 at 1e-30).\n"
    "--methods restricts the run to a comma-separated list of method names (see the table).\n";

int fail(const std::string& why) {
  std::cerr << "geomint-workprecision: " << why << "\n" << usage;
  return 2;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

bool parse_positive(const std::string& s, double& out) {
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0' && std::isfinite(out) && out > 0;
}

}  // namespace

int main(int argc, char** argv) {
  geomint::workprecision::settings o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i], v;
    bool has_inline = false;
    if (const auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      v = a.substr(eq + 1);
      a = a.substr(0, eq);
      has_inline = true;
    }
    auto value = [&](std::string& out) {
      if (has_inline) return true;
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    if (a == "--csv" && !has_inline) {
      o.csv = true;
    } else if ((a == "--help" || a == "-h") && !has_inline) {
      std::cout << usage;
      return 0;
    } else if (a == "--system") {
      if (!value(v) || (v != "pendulum" && v != "kepler")) return fail("--system must be pendulum or kepler");
      o.system = v;
    } else if (a == "--digits") {
      if (!value(v) || (v != "16" && v != "50")) return fail("--digits must be 16 or 50");
      o.digits = v == "16" ? 16 : 50;
    } else if (a == "--t-end") {
      double x = 0;
      if (!value(v) || !parse_positive(v, x)) return fail("--t-end must be a number > 0");
      o.t_end = x;
    } else if (a == "--max-seconds") {
      double x = 0;
      if (!value(v) || !parse_positive(v, x)) return fail("--max-seconds must be a number > 0");
      o.max_seconds = x;
    } else if (a == "--methods") {
      if (!value(v) || split(v).empty()) return fail("--methods needs a comma-separated list of method names");
      o.only = split(v);
    } else {
      return fail("unknown argument '" + std::string(argv[i]) + "'");
    }
  }
  try {
    using namespace geomint::workprecision;
    int rc = 0;
    if (o.system == "kepler") rc = o.digits == 16 ? run_kepler_16(o) : run_kepler_50(o);
    else rc = o.digits == 16 ? run_pendulum_16(o) : run_pendulum_50(o);
    std::cout.flush();
    if (!std::cout) {
      std::cerr << "geomint-workprecision: writing the output failed\n";
      return 1;
    }
    return rc;
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  } catch (const std::exception& e) {
    std::cerr << "geomint-workprecision: " << e.what() << "\n";
    return 1;
  }
}
