#pragma once
/// The `symplectic` front end (geomint-symplectic): the symplecticity defect ||J^T Omega J -
/// Omega|| of the one-step map of each scheme on the systems of a system_list, and (with
/// --long-steps) its long-time energy behaviour; with a ladder of steps (--tau T1,T2,...) the
/// fitted order of the defect beside its predicted order (analysis/bseries/lpf_symplecticity_defect.hpp).
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <tuple>

#include "geomint/analysis/bseries/lpf_symplecticity_defect.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/cli/study.hpp"

namespace geomint::cli {

namespace symplectic_detail {

using boost::multiprecision::cpp_bin_float_100;
using boost::multiprecision::cpp_bin_float_50;

struct extra_options {
  std::vector<std::string> tau = {"0.25"};
  std::string long_tau;
  std::vector<std::string> q0, p0;
  long long_steps = 0;
  bool monitor = true;
};

/// The initial state (q0, p0) of a case in the scalar T (default_initial_state: --p0 or
/// the default velocity's momentum at q0).
template <class T, class List>
analysis::phase_vector<T> initial_state(List list, const std::string& system, const any_stepper<T>& stepper,
                                        const extra_options& x) {
  dynamic_vector<T> q, p;
  try {
    std::tie(q, p) = default_initial_state<T>(list, system, stepper, x.q0, x.p0,
                                                     [](const std::string& s) { return parse_number<T>("--q0/--p0", s); });
  } catch (const std::invalid_argument& e) {  // a wrong count of values: a usage error
    throw usage_error(e.what());
  }
  analysis::phase_vector<T> z(2 * stepper.dof());
  z << q, p;
  return z;
}

struct row {
  std::string defect = "nan", max_energy = "nan", drift = "nan", failure, regime = "ok";
  std::string defect_estimate = "nan", state_estimate = "nan";
  bool coarse = false;  ///< the long run's estimated error above 1/100 of the solution's size
  double defect_value = std::nan("");  ///< the defect, for the fitted order of a ladder of tau
};

/// The predicted order r of the defect, C tau^r + O(tau^(r+1)), of a case; std::nullopt where it
/// vanishes identically: the variational integrators (midpoint, trapezoidal, galerkin: a discrete
/// Lagrangian, symplectic for every regular Lagrangian; Marsden & West 2001) and LPF where its
/// Nystrom map is a symplectic RKN method (lpf_symplecticity_defect.hpp).
template <class List>
std::optional<int> predicted_defect_order(List list, const study_case& c) {
  if (c.spec.scheme != "lpf" && c.spec.scheme != "lpf-fixed-point") return std::nullopt;
  const auto lagrangian = with_system(list, c.system, []<class Sys>() {
    return natural_system<Sys> ? analysis::lagrangian_class::natural : analysis::lagrangian_class::general;
  });
  return analysis::lpf_defect_order(c.spec.nodes_label(), c.spec.m, lagrangian);
}

/// The fitted order log(d1 / d0) / log(tau1 / tau0) between two rungs of the ladder, 2 decimals.
inline std::string fitted_order(double d0, double d1, double tau0, double tau1) {
  if (!(d0 > 0) || !(d1 > 0) || tau0 == tau1) return "nan";
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << std::log(d1 / d0) / std::log(tau1 / tau0);
  return out.str();
}

template <class T>
std::string sci(const T& v) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(2) << v;
  return out.str();
}

template <class T, class List>
int run(const std::string& program, const selection<List>& sel, const extra_options& x) {
  const List list;
  const auto cases = sel.cases();
  std::vector<T> taus;  // checked finite > 0 by the parser
  for (const std::string& t : x.tau) taus.push_back(parse_number<T>("--tau", t));
  const std::size_t rungs = taus.size();
  const bool ladder = rungs > 1;
  const double long_tau = x.long_tau.empty() ? static_cast<double>(taus.front()) : parse_number<double>("--long-tau", x.long_tau);
  // Check --q0 / --p0 here: the workers below report failures per case, not usage errors.
  if (!x.q0.empty() || !x.p0.empty()) {
    const std::string& system = sel.systems.front();
    const auto n = static_cast<std::size_t>(with_system(list, system, []<class Sys>() { return Sys::dof; }));
    for (const auto* v : {&x.q0, &x.p0}) {
      if (!v->empty() && v->size() != n)
        throw usage_error("--q0 / --p0 need " + std::to_string(n) + " value(s) for " + system);
      for (const std::string& s : *v) parse_number<T>("--q0/--p0", s);
    }
  }
  std::vector<row> rows(cases.size() * rungs);  // case-major: rows[i * rungs + k] at taus[k]
  const auto start = std::chrono::steady_clock::now();
  parallel_for(rows.size(), sel.threads, [&](std::size_t job) {
    const std::size_t i = job / rungs;
    const T& tau = taus[job % rungs];
    row& r = rows[job];
    const auto& c = cases[i];
    try {
      const auto stepper = make_stepper<T>(list, c.system, c.spec);
      if (x.monitor) stepper->set_monitor(step_monitor<T>::on());
      const analysis::phase_vector<T> z0 = initial_state<T>(list, c.system, *stepper, x);
      const analysis::phase_matrix<T> J = analysis::one_step_jacobian<T>(*stepper, tau, z0);
      // With the difference step doubled: the defect's estimate.
      const analysis::phase_matrix<T> J2 =
          analysis::one_step_jacobian<T>(*stepper, tau, z0, T(2) * analysis::default_difference_step<T>());
      const T defect = analysis::symplectic_defect<T>(J);
      r.defect = sci(defect);
      r.defect_value = static_cast<double>(defect);
      {
        using std::abs;
        r.defect_estimate = sci(T(abs(T(analysis::symplectic_defect<T>(J2) - defect))));
      }
      // A defect of order one is no measurement of symplecticity: the map is outside the
      // regime where the finite-difference Jacobian means anything (tau far too large).
      if (!(defect <= T(1))) r.regime = "outside: defect above 1";
      if (x.long_steps > 0) {
        const auto fast = make_stepper<double>(list, c.system, c.spec);
        if (x.monitor) fast->set_monitor(step_monitor<double>::on());
        const analysis::phase_vector<double> zd = initial_state<double>(list, c.system, *fast, x);
        const auto e = analysis::energy_behaviour<double>(*fast, zd, long_tau, x.long_steps);
        if (!e.ok) r.failure = "long run failed after " + std::to_string(e.steps) + " steps: " + e.failure;
        r.max_energy = sci(e.max_error);
        r.drift = sci(e.drift);
        if (e.ok) {
          // The same run at tau/2: Richardson's estimate of the global error at t = N tau,
          // |z(tau) - z(tau/2)| 2^p / (2^p - 1) <= 2 |z(tau) - z(tau/2)| for every order p >= 1.
          const auto half = analysis::energy_behaviour<double>(*fast, zd, long_tau / 2, 2 * x.long_steps);
          if (!half.ok) {
            r.failure = "the run at tau/2 (error estimate) failed after " + std::to_string(half.steps) + " steps: " + half.failure;
          } else {
            const double estimate = 2 * (e.last - half.last).template lpNorm<Eigen::Infinity>();
            r.state_estimate = sci(estimate);
            r.coarse = !(estimate <= half.last.template lpNorm<Eigen::Infinity>() / 100);
          }
        }
      }
    } catch (const std::exception& e) {
      r.failure = e.what();
    }
  }, program.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int status = 0;
  const int scheme_w = scheme_column_width(cases);
  const bool longrun = x.long_steps > 0;
  if (sel.csv)
    std::cout << "system,scheme,nodes,m,tau,defect" << (longrun ? ",max_energy_error,energy_drift" : "")
              << ",regime,defect_estimate" << (longrun ? ",state_error_estimate" : "")
              << (ladder ? ",fitted_order,predicted_order" : "") << '\n';
  else {
    std::cout << std::left << std::setw(16) << "system" << std::setw(scheme_w) << "scheme" << std::setw(16) << "nodes"
              << std::setw(4) << "m" << std::right;
    if (ladder) std::cout << std::setw(12) << "tau";
    std::cout << std::setw(11) << "defect" << std::setw(11) << "+-" << (longrun ? "   max|H-H0|   dH/dt  err(t_N)" : "")
              << (ladder ? "  fitted  predicted" : "") << '\n';
  }
  for (std::size_t job = 0; job < rows.size(); ++job) {
    const std::size_t i = job / rungs, k = job % rungs;
    const auto& c = cases[i];
    const row& r = rows[job];
    std::string fitted = "nan", predicted = "inf";
    if (ladder) {
      if (k > 0)
        fitted = fitted_order(rows[job - 1].defect_value, r.defect_value, static_cast<double>(taus[k - 1]),
                              static_cast<double>(taus[k]));
      if (const auto order = predicted_defect_order(list, c)) predicted = std::to_string(*order);
    }
    if (!r.failure.empty()) {
      std::cerr << program << ": " << c.system << ", " << c.spec.scheme << ": " << r.failure << '\n';
      status = exit_run_failure;
    }
    if (r.failure.empty() && r.regime != "ok") {
      std::cerr << program << ": " << c.system << ", " << c.spec.scheme << ": result " << r.regime
                << " (not a finding; reduce --tau)\n";
      status = exit_run_failure;
    }
    if (r.failure.empty() && r.coarse)
      std::cerr << program << ": " << c.system << ", " << c.spec.scheme << ": coarse long run: the estimated"
                << " error at t = N tau is " << r.state_estimate << ", above 1/100 of the solution's size\n";
    if (sel.csv) {
      std::cout << c.system << ',' << c.spec.scheme << ',' << c.spec.nodes_label() << ','
                << m_label(c.spec) << ',' << x.tau[k] << ',' << r.defect;
      if (longrun) std::cout << ',' << r.max_energy << ',' << r.drift;
      std::cout << ',' << (r.failure.empty() ? r.regime : "failed") << ',' << r.defect_estimate;
      if (longrun) std::cout << ',' << r.state_estimate;
      if (ladder) std::cout << ',' << fitted << ',' << predicted;
    } else {
      std::cout << std::left << std::setw(16) << c.system << std::setw(scheme_w) << c.spec.scheme << std::setw(16)
                << c.spec.nodes_label() << std::setw(4) << m_label(c.spec) << std::right;
      if (ladder) std::cout << std::setw(12) << x.tau[k];
      std::cout << std::setw(11) << r.defect << std::setw(11) << r.defect_estimate;
      if (longrun) std::cout << std::setw(12) << r.max_energy << std::setw(10) << r.drift << std::setw(10) << r.state_estimate;
      if (ladder) std::cout << std::setw(8) << fitted << std::setw(11) << predicted;
      if (!r.failure.empty()) std::cout << "  FAILED";
      else if (r.regime != "ok") std::cout << "  OUTSIDE THE REGIME (" << r.regime << ")";
      else if (r.coarse) std::cout << "  COARSE";
    }
    std::cout << '\n';
  }
  std::string tau_list;
  for (const std::string& t : x.tau) tau_list += (tau_list.empty() ? "" : ",") + t;
  std::cerr << program << ": " << cases.size() << " case(s), tau = " << tau_list << ", "
            << std::numeric_limits<T>::digits10 << " digits";
  if (longrun) std::cerr << ", " << x.long_steps << " long steps of " << long_tau << " in double";
  std::cerr << "; " << std::fixed << std::setprecision(1) << seconds << " s on " << sel.threads << " thread(s)\n";
  return status;
}

}  // namespace symplectic_detail

/// The usage text of a `symplectic` program over the systems `names`.
inline std::string symplectic_usage(const std::string& program, const std::vector<std::string>& names) {
  const std::string pad(program.size() + 8, ' ');
  return "usage: " + program + " [--system S[,S...]|all] [--scheme S[,S...]|all] [--nodes F[,F...]|all]\n" + pad +
         "[--m M|A..B (2..8)] [--digits 16|50|100] [--tau T[,T2...]] [--q0 a[,b...]] [--p0 a[,b...]]\n" + pad +
         "[--long-steps N (0..10^9)] [--long-tau T] [--threads K (1..64)] [--csv] [--no-monitor]\n"
         "The Jacobian J of the one-step map (q, p) -> (q1, p1) at (q0, p0) with step tau, by central\n"
         "differences with Richardson extrapolation in --digits digit arithmetic (default 50, tau 0.25),\n"
         "and the defect max |(J^T Omega J - Omega)_ij|: zero up to about eps^(4/5) for a symplectic map.\n"
         "With --long-steps N also N steps of size --long-tau in double: max |H - H0| and the drift of\n"
         "H - H0. With a ladder --tau T1,T2,... (no --long-steps) one row per tau, each with the order\n"
         "fitted to the defects at it and the tau before, log(d_k/d_{k-1})/log(tau_k/tau_{k-1}), and the\n"
         "predicted order (inf: the defect vanishes identically). The rows and columns of\n"
         "geomint-symplectic (docs/guide/your_own_tools.md).\n"
         + selection_usage(names) +
         "regime is 'ok', 'failed' or 'outside: ...'; any case not 'ok' makes the exit status 3. The step\n"
         "monitor is on (--no-monitor turns it off).\n";
}

/// The `symplectic` program over the systems of `list`; returns the exit status (0, 2 usage, 3
/// a case failed or outside its regime, 4 output).
template <class List>
int symplectic_main(List list, int argc, const char* const* argv, study_tool tool = {}) {
  using namespace symplectic_detail;
  if (tool.program.empty()) tool.program = "geomint-symplectic";
  selection<List> sel(tool, 50);
  extra_options x;
  parser cl(tool.program, tool.usage.empty() ? symplectic_usage(tool.program, system_names(list)) : tool.usage);
  sel.register_flags(cl, {"16", "50", "100"}, tool);
  cl.value("--tau", [&](const std::string& v) { x.tau = parse_real_list("--tau", v, real_bound::positive); })
      .value("--long-tau", [&](const std::string& v) { x.long_tau = checked_real_text("--long-tau", v, real_bound::positive); })
      .value("--q0", [&](const std::string& v) { x.q0 = parse_real_list("--q0", v, real_bound::finite); })
      .value("--p0", [&](const std::string& v) { x.p0 = parse_real_list("--p0", v, real_bound::finite); })
      .value("--long-steps", [&](const std::string& v) { x.long_steps = parse_integer<long>("--long-steps", v, 0, 1'000'000'000L); })
      .toggle("--no-monitor", [&] { x.monitor = false; });
  if (const auto done = cl.parse(argc, argv)) return *done;
  try {
    if ((!x.q0.empty() || !x.p0.empty()) && sel.systems.size() != 1)
      throw usage_error("--q0 / --p0 need a single --system");
    if (x.tau.size() > 1 && x.long_steps > 0)
      throw usage_error("--long-steps needs a single --tau (a ladder of tau measures the defect only)");
    sel.check_cases();
    int status = 0;
    if (sel.digits == 16) status = run<double>(tool.program, sel, x);
    else if (sel.digits == 50) status = run<cpp_bin_float_50>(tool.program, sel, x);
    else status = run<cpp_bin_float_100>(tool.program, sel, x);
    return finish_stdout(tool.program, status);
  } catch (const usage_error& e) {
    return finish_stdout(tool.program, cl.fail(e.what()));
  } catch (const std::exception& e) {
    std::cerr << tool.program << ": " << e.what() << '\n';
    return finish_stdout(tool.program, 1);
  }
}

}  // namespace geomint::cli
