/// geomint-symplectic: the symplecticity defect ||J^T Omega J - Omega|| of the one-step map of
/// each scheme, and (with --long-steps) its long-time energy behaviour.
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "geomint/analysis/symplecticity.hpp"
#include "study_cli.hpp"

namespace {

using namespace geomint;
using boost::multiprecision::cpp_bin_float_100;
using boost::multiprecision::cpp_bin_float_50;

const char* usage =
    "usage: geomint-symplectic [--system S[,S...]|all] [--scheme S[,S...]|all] [--nodes F[,F...]|all]\n"
    "                          [--m M|A..B (2..8)] [--digits 16|50|100] [--tau T] [--q0 a[,b]] [--p0 a[,b]]\n"
    "                          [--long-steps N] [--long-tau T] [--threads K] [--csv]\n"
    "The Jacobian J of the one-step map (q, p) -> (q1, p1) at (q0, p0) with step tau, by central\n"
    "differences with Richardson extrapolation (step eps^(1/5)) in --digits digit arithmetic\n"
    "(default 50, tau 0.25), and the defect max |(J^T Omega J - Omega)_ij|: zero up to about\n"
    "eps^(4/5) for a symplectic map. With --long-steps N (> 0) also N steps of size --long-tau\n"
    "(default tau) in double precision: max |H - H0| and the least-squares drift slope of H - H0.\n"
    "  systems: harmonic, pendulum, kepler, charged (all); default initial data as geomint-run\n"
    "  schemes: lpf, midpoint, trapezoidal, galerkin (all)\n"
    "  nodes (lpf): equispaced, lobatto, chebyshev, gauss-interior (all)\n"
    "CSV header: system,scheme,nodes,m,tau,defect  (plus max_energy_error,energy_drift with\n"
    "--long-steps).\n";

struct extra_options {
  std::string tau = "0.25", long_tau;
  std::vector<std::string> q0, p0;
  long long_steps = 0;
};

template <class T>
T parse_number(const std::string& flag, const std::string& s) {
  std::istringstream in(s);
  T v;
  in >> v;
  if (in.fail() || !in.eof() || !geomint::detail::is_finite(v))
    throw geomint::studies::usage_error(flag + " expects a finite number, got '" + s + "'");
  return v;
}

/// The initial state (q0, p0) of a case in the scalar T: defaults, overridden by --q0/--p0.
template <class T>
analysis::phase_vector<T> initial_state(const std::string& system, const tools::stepper<T>& stepper, const extra_options& x) {
  auto [q, qdot] = tools::default_initial_data<T>(system);
  tools::state_vector<T> p = stepper.momentum(q, qdot);
  const int n = stepper.dof();
  auto read = [&](const std::vector<std::string>& in, tools::state_vector<T>& out, const char* flag) {
    if (in.empty()) return;
    if (static_cast<int>(in.size()) != n)
      throw geomint::studies::usage_error(std::string(flag) + " needs " + std::to_string(n) + " value(s) for " + system);
    for (int i = 0; i < n; ++i) out[i] = parse_number<T>(flag, in[static_cast<std::size_t>(i)]);
  };
  read(x.q0, q, "--q0");
  read(x.p0, p, "--p0");
  analysis::phase_vector<T> z(2 * n);
  z << q, p;
  return z;
}

/// The one-step map of a stepper as a phase_map.
template <class T>
analysis::phase_map<T> as_map(const tools::stepper<T>& stepper, const T& tau) {
  return [&stepper, tau](const analysis::phase_vector<T>& z, analysis::phase_vector<T>& z1) {
    const int n = stepper.dof();
    const tools::state_vector<T> q = z.head(n), p = z.tail(n);
    tools::state_vector<T> q1, p1;
    if (!stepper.step(q, p, tau, q1, p1)) return false;
    z1.resize(2 * n);
    z1 << q1, p1;
    return true;
  };
}

struct row {
  std::string defect = "nan", max_energy = "nan", drift = "nan", failure;
};

template <class T>
std::string sci(const T& v) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(2) << v;
  return out.str();
}

template <class T>
int run(const geomint::studies::selection& sel, const extra_options& x) {
  const auto cases = sel.cases();
  const T tau = parse_number<T>("--tau", x.tau);
  if (!(tau > T(0))) throw geomint::studies::usage_error("--tau must be > 0");
  const double long_tau = x.long_tau.empty() ? static_cast<double>(tau) : parse_number<double>("--long-tau", x.long_tau);
  if (!(long_tau > 0)) throw geomint::studies::usage_error("--long-tau must be > 0");
  // Check --q0 / --p0 here: the workers below report failures per case, not usage errors.
  if (!x.q0.empty() || !x.p0.empty()) {
    const std::string& system = sel.systems.front();
    const std::size_t n = system == "harmonic" || system == "pendulum" ? 1 : 2;
    for (const auto* v : {&x.q0, &x.p0}) {
      if (!v->empty() && v->size() != n)
        throw geomint::studies::usage_error("--q0 / --p0 need " + std::to_string(n) + " value(s) for " + system);
      for (const std::string& s : *v) parse_number<T>("--q0/--p0", s);
    }
  }
  std::vector<row> rows(cases.size());
  const auto start = std::chrono::steady_clock::now();
  geomint::studies::parallel_for(cases.size(), sel.threads, [&](std::size_t i) {
    const auto& c = cases[i];
    try {
      const auto stepper = tools::make_stepper<T>(c.system, c.spec);
      const analysis::phase_vector<T> z0 = initial_state<T>(c.system, *stepper, x);
      const auto J = analysis::one_step_jacobian<T>(as_map<T>(*stepper, tau), z0);
      rows[i].defect = sci(analysis::symplectic_defect<T>(J));
      if (x.long_steps > 0) {
        const auto fast = tools::make_stepper<double>(c.system, c.spec);
        const analysis::phase_vector<double> zd = initial_state<double>(c.system, *fast, x);
        const int n = fast->dof();
        const auto e = analysis::energy_behaviour<double>(
            as_map<double>(*fast, long_tau),
            [&](const analysis::phase_vector<double>& z) {
              return fast->energy(tools::state_vector<double>(z.head(n)), tools::state_vector<double>(z.tail(n)));
            },
            zd, long_tau, x.long_steps);
        if (!e.ok) rows[i].failure = "long run failed after " + std::to_string(e.steps) + " steps";
        rows[i].max_energy = sci(e.max_error);
        rows[i].drift = sci(e.drift);
      }
    } catch (const std::exception& e) {
      rows[i].failure = e.what();
    }
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int status = 0;
  const bool longrun = x.long_steps > 0;
  if (sel.csv)
    std::cout << "system,scheme,nodes,m,tau,defect" << (longrun ? ",max_energy_error,energy_drift" : "") << '\n';
  else
    std::cout << std::left << std::setw(10) << "system" << std::setw(13) << "scheme" << std::setw(16) << "nodes"
              << std::setw(4) << "m" << std::right << std::setw(11) << "defect"
              << (longrun ? "   max|H-H0|   dH/dt" : "") << '\n';
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    const row& r = rows[i];
    if (!r.failure.empty()) {
      std::cerr << "geomint-symplectic: " << c.system << ", " << c.spec.scheme << ": " << r.failure << '\n';
      status = 3;
    }
    if (sel.csv) {
      std::cout << c.system << ',' << c.spec.scheme << ',' << c.spec.nodes_label() << ','
                << geomint::studies::m_label(c.spec) << ',' << x.tau << ',' << r.defect;
      if (longrun) std::cout << ',' << r.max_energy << ',' << r.drift;
    } else {
      std::cout << std::left << std::setw(10) << c.system << std::setw(13) << c.spec.scheme << std::setw(16)
                << c.spec.nodes_label() << std::setw(4) << geomint::studies::m_label(c.spec) << std::right
                << std::setw(11) << r.defect;
      if (longrun) std::cout << std::setw(12) << r.max_energy << std::setw(10) << r.drift;
    }
    std::cout << '\n';
  }
  std::cerr << "geomint-symplectic: " << cases.size() << " case(s), tau = " << x.tau << ", "
            << std::numeric_limits<T>::digits10 << " digits";
  if (longrun) std::cerr << ", " << x.long_steps << " long steps of " << long_tau << " in double";
  std::cerr << "; " << std::fixed << std::setprecision(1) << seconds << " s on " << sel.threads << " thread(s)\n";
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  geomint::studies::selection sel;
  extra_options x;
  try {
    const bool go = geomint::studies::parse_command_line(
        argc, argv, usage, sel, {"16", "50", "100"}, {"--tau", "--long-tau", "--q0", "--p0", "--long-steps"},
        [&](const std::string& flag, const std::string& value) {
          if (flag == "--tau") x.tau = value;
          else if (flag == "--long-tau") x.long_tau = value;
          else if (flag == "--q0") x.q0 = geomint::studies::split_list(value);
          else if (flag == "--p0") x.p0 = geomint::studies::split_list(value);
          else {
            x.long_steps = geomint::studies::parse_integer(flag, value);
            if (x.long_steps < 0) throw geomint::studies::usage_error("--long-steps must be >= 0");
          }
        });
    if (!go) return 0;
    if ((!x.q0.empty() || !x.p0.empty()) && sel.systems.size() != 1)
      throw geomint::studies::usage_error("--q0 / --p0 need a single --system");
    if (sel.digits == 16) return run<double>(sel, x);
    if (sel.digits == 50) return run<cpp_bin_float_50>(sel, x);
    return run<cpp_bin_float_100>(sel, x);
  } catch (const geomint::studies::usage_error& e) {
    std::cerr << "geomint-symplectic: " << e.what() << '\n' << usage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "geomint-symplectic: " << e.what() << '\n';
    return 1;
  }
}
