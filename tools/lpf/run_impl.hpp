#pragma once
/// The integration loop of geomint-run for the free systems, over the shared stepper factory
/// (tools/common): the schemes are instantiated there once for all tools.
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "cli.hpp"
#include "energy_growth.hpp"
#include "progress.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "tableau_stepper.hpp"
#include "run.hpp"
#include "stepper.hpp"

namespace geomint::run {

/// A number the command-line parser has already checked (plain decimal, finite, within the
/// range of double), read in the scalar T at full precision.
template <class T>
T parse_scalar(const std::string& s) {
  if constexpr (std::is_floating_point_v<T>) {
    return T(std::strtod(s.c_str(), nullptr));
  } else {
    std::istringstream in(s);
    T v;
    in >> v;
    if (in.fail() || !in.eof()) throw std::invalid_argument("not a number: " + s);
    return v;
  }
}

/// The monitor of the run: on unless --no-monitor.
template <class T>
step_monitor<T> run_monitor(const options& o) {
  return o.monitor ? step_monitor<T>::on() : step_monitor<T>{};
}

/// Reports a failed step on stderr (after what was written to stdout).
inline int report_failure(const step_status& st) {
  std::cout.flush();
  std::cerr << "geomint-run: " << st.message() << '\n';
  if (st.reason == step_failure::left_regime) std::cerr << "geomint-run: (--no-monitor disables this check)\n";
  return geomint::cli::exit_run_failure;
}

/// The initial state (q0, p0): q0 from --q0 or the system's default; p0 from --p0 (the
/// canonical momentum) or, if not given, the momentum dL/dqdot(q0, qdot0) of the default
/// velocity at that q0 (tools/common/stepper.hpp, default_initial_state): a user's position
/// is never paired with the momentum of the default position.
template <class T>
std::pair<dynamic_vector<T>, dynamic_vector<T>> initial_data(const options& o, const any_stepper<T>& stepper) {
  return tools::default_initial_state<T>(o.system, stepper, o.q0, o.p0,
                                         [](const std::string& s) { return parse_scalar<T>(s); });
}

/// A lower bound of the order of the scheme of `spec`: midpoint and trapezoidal 2, galerkin 2m,
/// lpf on Gauss-interior nodes and its fixed-point form 2(m - 1), lpf on other nodes 2 (a
/// symmetric consistent scheme; their order is at least that). For Richardson's estimate a
/// lower bound is the safe side: its factor 2^p / (2^p - 1) only grows as p decreases.
inline int order_lower_bound(const scheme_spec& spec) {
  if (spec.scheme == "galerkin") return 2 * spec.m;
  if (spec.scheme == "lpf-fixed-point" || (spec.scheme == "lpf" && canonical_node_family(spec.nodes) == gauss_interior::name))
    return 2 * (spec.m - 1);
  return 2;
}

/// --estimate: the same run at tau/2 (two steps per step of the run), and Richardson's estimate
/// of the run's global error at each step k, |z_k(tau) - z_2k(tau/2)|_inf 2^p / (2^p - 1) with
/// p = order_lower_bound (the error of z(tau) when e(tau) = C tau^p: the asymptotic regime).
template <class T>
struct error_estimate {
  dynamic_vector<T> q, p, q_carry, p_carry;
  T factor;
  explicit error_estimate(const dynamic_vector<T>& q0, const dynamic_vector<T>& p0, int order)
      : q(q0), p(p0), q_carry(dynamic_vector<T>::Zero(q0.size())), p_carry(dynamic_vector<T>::Zero(q0.size())) {
    using std::pow;
    const T two_p = pow(T(2), T(order));
    factor = two_p / (two_p - T(1));
  }
  /// Two steps of tau/2; false (with the status in st) on failure.
  bool advance(const any_stepper<T>& stepper, const T& tau, bool compensated, const newton_options<T>& opt,
               step_status& st) {
    dynamic_vector<T> q1 = q, p1 = p;
    for (int half = 0; half < 2; ++half) {
      st = compensated ? stepper.try_step_compensated(q, p, q_carry, p_carry, tau / T(2), q1, p1, opt)
                       : stepper.try_step(q, p, tau / T(2), q1, p1, opt);
      if (!st) return false;
      q = q1;
      p = p1;
    }
    return true;
  }
  /// The estimate of the error of (qk, pk).
  T of(const dynamic_vector<T>& qk, const dynamic_vector<T>& pk) const {
    using std::max;
    return T(factor * max(T((qk - q).template lpNorm<Eigen::Infinity>()), T((pk - p).template lpNorm<Eigen::Infinity>())));
  }
};

/// The integration loop of geomint-run for a free system, in the scalar T.
template <class T>
int run_free_system(const options& o) {
  if (o.scheme == "paper23") throw std::invalid_argument("--scheme paper23 is the paper's scheme for --system circle only");
  scheme_spec spec;
  spec.scheme = o.scheme;
  spec.nodes = o.nodes;
  spec.basis = o.basis;
  spec.m = o.m;
  // --tableau FILE: the method of the file (a malformed file is a tableau_file_error naming its
  // line, an std::invalid_argument: a usage error).
  const auto stepper = o.tableau.empty()
                           ? tools::make_stepper<T>(o.system, spec)
                           : tools::make_tableau_stepper<T>(o.system, methods::nystrom_form_of(methods::read_tableau_file(o.tableau)));
  stepper->set_monitor(run_monitor<T>(o));
  const int n = stepper->dof();
  const T tau = parse_scalar<T>(o.tau);
  // Not a structured binding: the lambdas below capture q and p (Clang 14 cannot).
  dynamic_vector<T> q, p;
  std::tie(q, p) = initial_data<T>(o, *stepper);
  std::optional<error_estimate<T>> estimate;
  if (o.estimate) estimate.emplace(q, p, order_lower_bound(spec));
  long step = 0;
  T t(0);
  std::cout << std::setprecision(std::numeric_limits<T>::max_digits10);
  auto row = [&] {
    std::cout << step << ',' << t;
    for (int i = 0; i < n; ++i) std::cout << ',' << q[i];
    for (int i = 0; i < n; ++i) std::cout << ',' << p[i];
    std::cout << ',' << stepper->energy(q, p);
    if (estimate) std::cout << ',' << estimate->of(q, p);
    std::cout << '\n';
  };
  const T E0 = stepper->energy(q, p);
  if (o.csv) {
    std::cout << "step,t";
    for (int i = 1; i <= n; ++i) std::cout << ",q" << i;
    for (int i = 1; i <= n; ++i) std::cout << ",p" << i;
    std::cout << ",energy" << (estimate ? ",error_estimate" : "") << "\n";
    row();
  }
  const newton_options<T> opt;
  T max_dE(0), max_estimate(0);
  dynamic_vector<T> q1 = q, p1 = p;
  dynamic_vector<T> q_carry = dynamic_vector<T>::Zero(n), p_carry = dynamic_vector<T>::Zero(n);
  tools::energy_growth growth;
  // CPU time of the stepping loop (steps, energy monitor and rows), printed to stderr as
  // cpu_seconds=X so that outside tools can time a run without the process start-up.
  timespec cpu_start{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu_start);
  tools::progress bar("geomint-run", static_cast<std::size_t>(o.steps), "steps");
  for (long k = 0; k < o.steps; ++k) {
    if (k % 4096 == 0) bar.set(static_cast<std::size_t>(k));  // (a terminal only)
    step_status st = o.compensated ? stepper->try_step_compensated(q, p, q_carry, p_carry, tau, q1, p1, opt)
                                   : stepper->try_step(q, p, tau, q1, p1, opt);
    st.step = step;
    if (!st) {
      bar.finish();  // the message on a line of its own
      return report_failure(st);
    }
    if (estimate && !estimate->advance(*stepper, tau, o.compensated, opt, st)) {
      bar.finish();
      std::cout.flush();
      std::cerr << "geomint-run: --estimate: the run at tau/2 failed in its steps " << 2 * step << " and "
                << 2 * step + 1 << ":\n";
      st.step = 2 * step;
      return report_failure(st);
    }
    q = q1;
    p = p1;
    ++step;
    t = T(step) * tau;  // t_k = k tau, not accumulated
    using std::abs;
    const T dE = abs(stepper->energy(q, p) - E0);
    if (dE > max_dE) max_dE = dE;
    if (estimate && estimate->of(q, p) > max_estimate) max_estimate = estimate->of(q, p);
    if (o.growth) growth.add(step, static_cast<double>(dE));
    if (o.csv && (step % o.every == 0 || k + 1 == o.steps)) {
      row();
      if (!cli::stdout_ok()) return cli::exit_output;  // reported by main (finish_stdout)
    }
  }
  bar.finish();
  timespec cpu_end{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu_end);
  std::cerr << "cpu_seconds="
            << double(cpu_end.tv_sec - cpu_start.tv_sec) + double(cpu_end.tv_nsec - cpu_start.tv_nsec) * 1e-9 << '\n';
  if (!o.csv) {
    std::cout << "system " << o.system << ", scheme " << stepper->name() << ", tau " << tau << ", steps " << o.steps
              << ", digits " << o.digits << "\n";
    std::cout << "t = " << t << "\nq =";
    for (int i = 0; i < n; ++i) std::cout << ' ' << q[i];
    std::cout << "\np =";
    for (int i = 0; i < n; ++i) std::cout << ' ' << p[i];
    std::cout << "\nenergy = " << stepper->energy(q, p) << "\nmax |energy - energy0| = " << max_dE << "\n";
    if (o.compensated) std::cout << "compensated summation\n";
  }
  if (estimate) {
    // A coarse run says so: an estimated error above 1/100 of the solution's size.
    using std::max;
    const T size = max(T(q.template lpNorm<Eigen::Infinity>()), T(p.template lpNorm<Eigen::Infinity>()));
    const T final_estimate = estimate->of(q, p);
    std::ostream& out = o.csv ? std::cerr : std::cout;  // keeps a CSV clean
    out << std::setprecision(3) << "estimated global error at t = " << static_cast<double>(t) << ": "
        << static_cast<double>(final_estimate) << " (max over the run " << static_cast<double>(max_estimate)
        << "; Richardson, tau against tau/2, order >= " << order_lower_bound(spec) << ")\n";
    if (final_estimate > size / T(100) || max_estimate > size / T(100))
      out << "coarse run: the estimated error is " << static_cast<double>(T(max_estimate / size)) * 100
          << "% of the solution's size max(|q|, |p|) = " << static_cast<double>(size) << "; reduce --tau\n";
  }
  if (o.growth) growth.print(o.csv ? std::cerr : std::cout, static_cast<double>(tau));  // keeps a CSV clean
  return 0;
}

}  // namespace geomint::run
