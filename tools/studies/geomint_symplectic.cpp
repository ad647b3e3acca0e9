/// geomint-symplectic: the symplecticity defect ||J^T Omega J - Omega|| of the one-step map of
/// each scheme, and (with --long-steps) its long-time energy behaviour.
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tuple>

#include "geomint/analysis/symplecticity.hpp"
#include "study_cli.hpp"

namespace {

using namespace geomint;
using boost::multiprecision::cpp_bin_float_100;
using boost::multiprecision::cpp_bin_float_50;

const char* usage =
    "usage: geomint-symplectic [--system S[,S...]|all] [--scheme S[,S...]|all] [--nodes F[,F...]|all]\n"
    "                          [--m M|A..B (2..8)] [--digits 16|50|100] [--tau T] [--q0 a[,b]] [--p0 a[,b]]\n"
    "                          [--long-steps N (0..10^9)] [--long-tau T] [--threads K (1..64)] [--csv]\n"
    "                          [--no-monitor]\n"
    "The Jacobian J of the one-step map (q, p) -> (q1, p1) at (q0, p0) with step tau, by central\n"
    "differences with Richardson extrapolation (step eps^(1/5)) in --digits digit arithmetic\n"
    "(default 50, tau 0.25), and the defect max |(J^T Omega J - Omega)_ij|: zero up to about\n"
    "eps^(4/5) for a symplectic map. With --long-steps N (> 0) also N steps of size --long-tau\n"
    "(default tau) in double precision: max |H - H0| and the least-squares drift slope of H - H0.\n"
    "  systems: harmonic, pendulum, kepler, charged (all); default initial data as geomint-run\n"
    "  schemes: lpf, midpoint, trapezoidal, galerkin (all); lpf-fixed-point (natural systems)\n"
    "  nodes (lpf): equispaced, lobatto, chebyshev, gauss-interior (all)\n"
    "  zoo systems: henon-heiles, spring-pendulum, double-pendulum, toda, outer-solar, arenstorf\n"
    "  (zoo) with the restricted scheme set: midpoint; lpf --nodes gauss-interior --m 2..4;\n"
    "  galerkin --m 2..3; --digits 16|50 (outer-solar in 50 digits: m = 2); others exit with 2.\n"
    "Error estimates (a posteriori, always printed): defect_estimate, the change of the defect when\n"
    "the difference step is doubled (the size of the defect's own numerical error); with\n"
    "--long-steps, the same long run at tau/2 (2N steps) and state_error_estimate = 2 |z_N(tau) -\n"
    "z_2N(tau/2)|_inf, Richardson's estimate of the global error at t = N tau for any order >= 1;\n"
    "above 1/100 of the solution's size max(|q|, |p|) the run is called coarse (stderr, table).\n"
    "Work: the defect 4 maps per phase coordinate at each of its two difference steps; the long\n"
    "run 3N steps per case (--long-steps N at most 10^9).\n"
    "CSV header: system,scheme,nodes,m,tau,defect  (plus max_energy_error,energy_drift with\n"
    "--long-steps), regime, defect_estimate (plus state_error_estimate with --long-steps).\n"
    "regime is 'ok', 'failed', or 'outside: ...' for a result that is no\n"
    "measurement (a defect above 1: tau far outside the scheme's regime); any case not 'ok' makes\n"
    "the exit status 3. The step monitor (geomint/solvers/step_monitor.hpp: resolution tau omega_max\n"
    "and energy change) is on; a step that leaves the scheme's regime fails the case with the\n"
    "monitor's reason; --no-monitor turns it off. Initial data as geomint-run: --p0 is the\n"
    "momentum, else the default velocity's momentum at --q0. --m applies to lpf,\n"
    "lpf-fixed-point and galerkin, --nodes to lpf (an error if no selected scheme uses it).\n";

struct extra_options {
  std::string tau = "0.25", long_tau;
  std::vector<std::string> q0, p0;
  long long_steps = 0;
  bool monitor = true;
};

/// A number already checked by the parser (cli.hpp), read in the scalar T at full precision.
template <class T>
T parse_number(const std::string& flag, const std::string& s) {
  std::istringstream in(s);
  T v;
  in >> v;
  if (in.fail() || !in.eof() || !geomint::is_finite(v))
    throw geomint::cli::usage_error(flag + " expects a finite number, got '" + s + "'");
  return v;
}

/// The initial state (q0, p0) of a case in the scalar T (tools::default_initial_state: --p0 or
/// the default velocity's momentum at q0).
template <class T>
analysis::phase_vector<T> initial_state(const std::string& system, const any_stepper<T>& stepper, const extra_options& x) {
  dynamic_vector<T> q, p;
  try {
    std::tie(q, p) = tools::default_initial_state<T>(system, stepper, x.q0, x.p0,
                                                     [](const std::string& s) { return parse_number<T>("--q0/--p0", s); });
  } catch (const std::invalid_argument& e) {  // a wrong count of values: a usage error
    throw geomint::cli::usage_error(e.what());
  }
  analysis::phase_vector<T> z(2 * stepper.dof());
  z << q, p;
  return z;
}

/// The one-step map of a stepper as a phase_map; the status of its last failed step goes to
/// *failure (if given), so that a failure keeps its reason (e.g. the step monitor's criterion).
template <class T>
analysis::phase_map<T> as_map(const any_stepper<T>& stepper, const T& tau, step_status* failure = nullptr) {
  return [&stepper, tau, failure](const analysis::phase_vector<T>& z, analysis::phase_vector<T>& z1) {
    const int n = stepper.dof();
    const dynamic_vector<T> q = z.head(n), p = z.tail(n);
    dynamic_vector<T> q1, p1;
    const step_status st = stepper.try_step(q, p, tau, q1, p1);
    if (!st) {
      if (failure) *failure = st;
      return false;
    }
    z1.resize(2 * n);
    z1 << q1, p1;
    return true;
  };
}

struct row {
  std::string defect = "nan", max_energy = "nan", drift = "nan", failure, regime = "ok";
  std::string defect_estimate = "nan", state_estimate = "nan";
  bool coarse = false;  ///< the long run's estimated error above 1/100 of the solution's size
};

/// The map, recording the last state it produced (the end of a run through energy_behaviour).
template <class T>
analysis::phase_map<T> recording(analysis::phase_map<T> map, analysis::phase_vector<T>& last) {
  return [map = std::move(map), &last](const analysis::phase_vector<T>& z, analysis::phase_vector<T>& z1) {
    if (!map(z, z1)) return false;
    last = z1;
    return true;
  };
}

template <class T>
std::string sci(const T& v) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(2) << v;
  return out.str();
}

template <class T>
int run(const geomint::studies::selection& sel, const extra_options& x) {
  const auto cases = sel.cases();
  const T tau = parse_number<T>("--tau", x.tau);  // checked finite > 0 by the parser
  const double long_tau = x.long_tau.empty() ? static_cast<double>(tau) : parse_number<double>("--long-tau", x.long_tau);
  // Check --q0 / --p0 here: the workers below report failures per case, not usage errors.
  if (!x.q0.empty() || !x.p0.empty()) {
    const std::string& system = sel.systems.front();
    const auto n = static_cast<std::size_t>(tools::with_free_system(system, []<class Sys>() { return Sys::dof; }));
    for (const auto* v : {&x.q0, &x.p0}) {
      if (!v->empty() && v->size() != n)
        throw geomint::cli::usage_error("--q0 / --p0 need " + std::to_string(n) + " value(s) for " + system);
      for (const std::string& s : *v) parse_number<T>("--q0/--p0", s);
    }
  }
  std::vector<row> rows(cases.size());
  const auto start = std::chrono::steady_clock::now();
  geomint::studies::parallel_for(cases.size(), sel.threads, [&](std::size_t i) {
    const auto& c = cases[i];
    try {
      const auto stepper = tools::make_stepper<T>(c.system, c.spec);
      if (x.monitor) stepper->set_monitor(step_monitor<T>::on());
      const analysis::phase_vector<T> z0 = initial_state<T>(c.system, *stepper, x);
      step_status failed;
      analysis::phase_matrix<T> J;
      analysis::phase_matrix<T> J2;  // with the difference step doubled: the defect's estimate
      try {
        J = analysis::one_step_jacobian<T>(as_map<T>(*stepper, tau, &failed), z0);
        J2 = analysis::one_step_jacobian<T>(as_map<T>(*stepper, tau, &failed), z0,
                                            T(2) * analysis::default_difference_step<T>());
      } catch (const std::runtime_error& e) {
        throw std::runtime_error(failed ? std::string(e.what()) : std::string(e.what()) + ": " + failed.message());
      }
      const T defect = analysis::symplectic_defect<T>(J);
      rows[i].defect = sci(defect);
      {
        using std::abs;
        rows[i].defect_estimate = sci(T(abs(T(analysis::symplectic_defect<T>(J2) - defect))));
      }
      // A defect of order one is no measurement of symplecticity: the map is outside the
      // regime where the finite-difference Jacobian means anything (tau far too large).
      if (!(defect <= T(1))) rows[i].regime = "outside: defect above 1";
      if (x.long_steps > 0) {
        const auto fast = tools::make_stepper<double>(c.system, c.spec);
        if (x.monitor) fast->set_monitor(step_monitor<double>::on());
        const analysis::phase_vector<double> zd = initial_state<double>(c.system, *fast, x);
        const int n = fast->dof();
        step_status long_failure;
        const std::function<double(const analysis::phase_vector<double>&)> energy =
            [&](const analysis::phase_vector<double>& z) {
              return fast->energy(dynamic_vector<double>(z.head(n)), dynamic_vector<double>(z.tail(n)));
            };
        analysis::phase_vector<double> end = zd, end_half = zd;
        const auto e = analysis::energy_behaviour<double>(recording(as_map<double>(*fast, long_tau, &long_failure), end),
                                                          energy, zd, long_tau, x.long_steps);
        if (!e.ok)
          rows[i].failure = "long run failed after " + std::to_string(e.steps) + " steps: " + long_failure.message();
        rows[i].max_energy = sci(e.max_error);
        rows[i].drift = sci(e.drift);
        if (e.ok) {
          // The same run at tau/2: Richardson's estimate of the global error at t = N tau,
          // |z(tau) - z(tau/2)| 2^p / (2^p - 1) <= 2 |z(tau) - z(tau/2)| for every order p >= 1.
          const auto half = analysis::energy_behaviour<double>(
              recording(as_map<double>(*fast, long_tau / 2, &long_failure), end_half), energy, zd, long_tau / 2,
              2 * x.long_steps);
          if (!half.ok) {
            rows[i].failure = "the run at tau/2 (error estimate) failed after " + std::to_string(half.steps) +
                              " steps: " + long_failure.message();
          } else {
            const double estimate = 2 * (end - end_half).lpNorm<Eigen::Infinity>();
            rows[i].state_estimate = sci(estimate);
            rows[i].coarse = !(estimate <= end_half.lpNorm<Eigen::Infinity>() / 100);
          }
        }
      }
    } catch (const std::exception& e) {
      rows[i].failure = e.what();
    }
  }, "geomint-symplectic");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int status = 0;
  const int scheme_w = geomint::studies::scheme_column_width(cases);
  const bool longrun = x.long_steps > 0;
  if (sel.csv)
    std::cout << "system,scheme,nodes,m,tau,defect" << (longrun ? ",max_energy_error,energy_drift" : "")
              << ",regime,defect_estimate" << (longrun ? ",state_error_estimate" : "") << '\n';
  else
    std::cout << std::left << std::setw(16) << "system" << std::setw(scheme_w) << "scheme" << std::setw(16) << "nodes"
              << std::setw(4) << "m" << std::right << std::setw(11) << "defect" << std::setw(11) << "+-"
              << (longrun ? "   max|H-H0|   dH/dt  err(t_N)" : "") << '\n';
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    const row& r = rows[i];
    if (!r.failure.empty()) {
      std::cerr << "geomint-symplectic: " << c.system << ", " << c.spec.scheme << ": " << r.failure << '\n';
      status = geomint::cli::exit_run_failure;
    }
    if (r.failure.empty() && r.regime != "ok") {
      std::cerr << "geomint-symplectic: " << c.system << ", " << c.spec.scheme << ": result " << r.regime
                << " (not a finding; reduce --tau)\n";
      status = geomint::cli::exit_run_failure;
    }
    if (r.failure.empty() && r.coarse)
      std::cerr << "geomint-symplectic: " << c.system << ", " << c.spec.scheme << ": coarse long run: the estimated"
                << " error at t = N tau is " << r.state_estimate << ", above 1/100 of the solution's size\n";
    if (sel.csv) {
      std::cout << c.system << ',' << c.spec.scheme << ',' << c.spec.nodes_label() << ','
                << geomint::studies::m_label(c.spec) << ',' << x.tau << ',' << r.defect;
      if (longrun) std::cout << ',' << r.max_energy << ',' << r.drift;
      std::cout << ',' << (r.failure.empty() ? r.regime : "failed") << ',' << r.defect_estimate;
      if (longrun) std::cout << ',' << r.state_estimate;
    } else {
      std::cout << std::left << std::setw(16) << c.system << std::setw(scheme_w) << c.spec.scheme << std::setw(16)
                << c.spec.nodes_label() << std::setw(4) << geomint::studies::m_label(c.spec) << std::right
                << std::setw(11) << r.defect << std::setw(11) << r.defect_estimate;
      if (longrun) std::cout << std::setw(12) << r.max_energy << std::setw(10) << r.drift << std::setw(10) << r.state_estimate;
      if (!r.failure.empty()) std::cout << "  FAILED";
      else if (r.regime != "ok") std::cout << "  OUTSIDE THE REGIME (" << r.regime << ")";
      else if (r.coarse) std::cout << "  COARSE";
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
  namespace cli = geomint::cli;
  geomint::studies::selection sel;
  extra_options x;
  cli::parser cl("geomint-symplectic", usage);
  sel.register_flags(cl, {"16", "50", "100"});
  cl.value("--tau", [&](const std::string& v) { x.tau = cli::checked_real_text("--tau", v, cli::real_bound::positive); })
      .value("--long-tau", [&](const std::string& v) { x.long_tau = cli::checked_real_text("--long-tau", v, cli::real_bound::positive); })
      .value("--q0", [&](const std::string& v) { x.q0 = cli::parse_real_list("--q0", v, cli::real_bound::finite); })
      .value("--p0", [&](const std::string& v) { x.p0 = cli::parse_real_list("--p0", v, cli::real_bound::finite); })
      .value("--long-steps", [&](const std::string& v) { x.long_steps = cli::parse_integer<long>("--long-steps", v, 0, 1'000'000'000L); })
      .toggle("--no-monitor", [&] { x.monitor = false; });
  if (const auto done = cl.parse(argc, argv)) return *done;
  try {
    if ((!x.q0.empty() || !x.p0.empty()) && sel.systems.size() != 1)
      throw cli::usage_error("--q0 / --p0 need a single --system");
    sel.check_cases();
    int status = 0;
    if (sel.digits == 16) status = run<double>(sel, x);
    else if (sel.digits == 50) status = run<cpp_bin_float_50>(sel, x);
    else status = run<cpp_bin_float_100>(sel, x);
    return cli::finish_stdout("geomint-symplectic", status);
  } catch (const cli::usage_error& e) {
    return cli::finish_stdout("geomint-symplectic", cl.fail(e.what()));
  } catch (const std::exception& e) {
    std::cerr << "geomint-symplectic: " << e.what() << '\n';
    return cli::finish_stdout("geomint-symplectic", 1);
  }
}
