#pragma once
/// The integration loop of geomint-run for the free systems, over the shared stepper factory
/// (tools/common): the schemes are instantiated there once for all tools.
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <limits>
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

/// The system's default initial data (tools/common/stepper.hpp), overridden by --q0 / --p0.
template <class T>
std::pair<dynamic_vector<T>, dynamic_vector<T>> initial_data(const options& o, const any_stepper<T>& stepper) {
  auto [q, qdot] = tools::default_initial_data<T>(o.system);
  dynamic_vector<T> p = stepper.momentum(q, qdot);
  const int n = stepper.dof();
  auto read = [&](const std::vector<std::string>& in, dynamic_vector<T>& out, const char* flag) {
    if (in.empty()) return;
    if (static_cast<int>(in.size()) != n)
      throw std::invalid_argument(std::string(flag) + " needs " + std::to_string(n) + " value(s) for this system");
    for (int i = 0; i < n; ++i) out[i] = parse_scalar<T>(in[static_cast<std::size_t>(i)]);
  };
  read(o.q0, q, "--q0");
  read(o.p0, p, "--p0");
  return {q, p};
}

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
  long step = 0;
  T t(0);
  std::cout << std::setprecision(std::numeric_limits<T>::max_digits10);
  auto row = [&] {
    std::cout << step << ',' << t;
    for (int i = 0; i < n; ++i) std::cout << ',' << q[i];
    for (int i = 0; i < n; ++i) std::cout << ',' << p[i];
    std::cout << ',' << stepper->energy(q, p) << '\n';
  };
  const T E0 = stepper->energy(q, p);
  if (o.csv) {
    std::cout << "step,t";
    for (int i = 1; i <= n; ++i) std::cout << ",q" << i;
    for (int i = 1; i <= n; ++i) std::cout << ",p" << i;
    std::cout << ",energy\n";
    row();
  }
  const newton_options<T> opt;
  T max_dE(0);
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
    q = q1;
    p = p1;
    ++step;
    t = T(step) * tau;  // t_k = k tau, not accumulated
    using std::abs;
    const T dE = abs(stepper->energy(q, p) - E0);
    if (dE > max_dE) max_dE = dE;
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
  if (o.growth) growth.print(o.csv ? std::cerr : std::cout, static_cast<double>(tau));  // keeps a CSV clean
  return 0;
}

}  // namespace geomint::run
