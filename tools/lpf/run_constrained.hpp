#pragma once
/// geomint-run for the constrained systems (circle, spherical pendulum): the constrained LPF
/// integrator (eq. 4-5 with the momentum projection) or, on the circle, the paper's printed
/// scheme (23). CSV rows carry a `constraint` column: max |f_l(q)| at the step.
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>

#include "geomint/constrained_integrator.hpp"
#include "geomint/core/dispatch.hpp"
#include "geomint/mechanics/constrained_systems.hpp"
#include "geomint/schemes/paper23.hpp"
#include "run.hpp"

namespace geomint::run {

/// The system's initial data (mechanics/constrained_systems.hpp), overridden by --q0 / --p0.
template <class Sys, class T>
std::pair<vec<T, Sys::dof>, vec<T, Sys::dof>> constrained_initial_data(const options& o) {
  constexpr int n = Sys::dof;
  vec<T, n> q, p;
  Sys::initial_data(q, p);  // unit masses: the velocity is the momentum
  auto read = [&](const std::vector<std::string>& in, vec<T, n>& out, const char* flag) {
    if (in.empty()) return;
    if (static_cast<int>(in.size()) != n)
      throw std::invalid_argument(std::string(flag) + " needs " + std::to_string(n) + " values for this system");
    for (int i = 0; i < n; ++i) out[i] = parse_scalar<T>(in[static_cast<std::size_t>(i)]);
  };
  read(o.q0, q, "--q0");
  read(o.p0, p, "--p0");
  return {q, p};
}

template <class T, int n>
void constrained_header(const options& o) {
  if (!o.csv) return;
  std::cout << "step,t";
  for (int i = 1; i <= n; ++i) std::cout << ",q" << i;
  for (int i = 1; i <= n; ++i) std::cout << ",p" << i;
  std::cout << ",energy,constraint\n";
}

template <class T, int n>
void constrained_row(long step, const T& t, const vec<T, n>& q, const vec<T, n>& p, const T& energy, const T& constraint) {
  std::cout << step << ',' << t;
  for (int i = 0; i < n; ++i) std::cout << ',' << q[i];
  for (int i = 0; i < n; ++i) std::cout << ',' << p[i];
  std::cout << ',' << energy << ',' << constraint << '\n';
}

template <class T>
void constrained_summary(const options& o, const std::string& system, const std::string& label, const T& tau,
                         const T& energy_error, const T& worst_constraint) {
  if (o.csv) return;
  std::cout << "system " << system << ", scheme " << label << ", tau " << tau << ", steps " << o.steps << ", digits "
            << o.digits << "\nmax |energy - energy0| = " << energy_error
            << "\nmax constraint violation = " << worst_constraint << "\n";
}

/// The constrained LPF integrator for m = M with the family and basis chosen at run time.
template <int M, class Family, class Basis, class Sys, class Con, class T>
int run_constrained_fb(const options& o) {
  constexpr int n = Sys::dof;
  const T tau = parse_scalar<T>(o.tau);
  using scheme = constrained_lpf<M, Family, Basis>;
  constrained_integrator<scheme, Sys, Con, T> integrator(Sys{}, Con{}, tau);
  integrator.set_monitor(run_monitor<T>(o));
  integrator.set_compensated_summation(o.compensated);
  const auto [q0, p0] = constrained_initial_data<Sys, T>(o);
  // M = identity for both systems, so the momentum p0 is the initial velocity.
  auto s = integrator.initial_state(q0, p0);
  std::cout << std::setprecision(std::numeric_limits<T>::max_digits10);
  constrained_header<T, n>(o);
  const T energy0 = integrator.energy(s);
  T worst_energy(0), worst_constraint = integrator.violation(s);
  if (o.csv) constrained_row<T, n>(s.step, s.t, s.q, s.p, energy0, integrator.violation(s));
  cli::progress bar("geomint-run", static_cast<std::size_t>(o.steps), "steps");
  for (long k = 0; k < o.steps; ++k) {
    if (k % 4096 == 0) bar.set(static_cast<std::size_t>(k));  // (a terminal only)
    const step_status st = integrator.try_step(s);
    if (!st) {
      bar.finish();  // the message on a line of its own
      return report_failure(o, st);
    }
    using std::abs;
    const T energy = integrator.energy(s), violation = integrator.violation(s);
    if (abs(T(energy - energy0)) > worst_energy) worst_energy = abs(T(energy - energy0));
    if (violation > worst_constraint) worst_constraint = violation;
    if (o.csv && (s.step % o.every == 0 || k + 1 == o.steps)) {
      constrained_row<T, n>(s.step, s.t, s.q, s.p, energy, violation);
      if (!cli::stdout_ok()) return cli::exit_output;  // reported by main (finish_stdout)
    }
  }
  bar.finish();
  constrained_summary<T>(o, std::string(Sys::name), scheme::name(), tau, worst_energy, worst_constraint);
  return 0;
}

/// The paper's scheme (23) on the circle, as printed: x^0 = q0, x^1 from one step of the
/// constrained LPF integrator (m = 2, the same fitted parabola). The momentum column is the
/// scheme's own, the slope of the fitted parabola at t_k: (x^{k-1} - 4 eta + 3 x^k)/tau with
/// eta = (x^{k-1} + x^k)/|x^{k-1} + x^k|.
template <class T>
int run_paper23(const options& o) {
  using Sys = systems::free_particle_2d;
  using Con = systems::unit_circle;
  const T tau = parse_scalar<T>(o.tau);
  constrained_integrator<constrained_lpf<2>, Sys, Con, T> starter(Sys{}, Con{}, tau);
  const step_monitor<T> monitor = run_monitor<T>(o).for_scheme(scheme_resolution_bound<constrained_lpf<2>, T>());
  starter.set_monitor(monitor);
  const auto [q0, p0] = constrained_initial_data<Sys, T>(o);
  auto s = starter.initial_state(q0, p0);
  std::cout << std::setprecision(std::numeric_limits<T>::max_digits10);
  constrained_header<T, 2>(o);
  const T energy0 = starter.energy(s);
  if (o.csv) constrained_row<T, 2>(0, T(0), s.q, s.p, energy0, starter.violation(s));
  vec<T, 2> prev = s.q;
  T worst_energy(0), worst_constraint(0);
  if (o.steps >= 1) {
    if (const step_status st = starter.try_step(s); !st) return report_failure(o, st);
  }
  vec<T, 2> curr = s.q;
  auto measure = [&](const vec<T, 2>& q, const vec<T, 2>& p) {
    return measure_monitor_point<Sys, T>(Sys{}, q, p, monitor.checks_resolution());
  };
  monitor_point<T> previous = measure(s.q, s.p);
  for (long k = 1; k <= o.steps; ++k) {
    if (k >= 2) {
      vec<T, 2> next;
      try {
        next = paper23_step<T>(prev, curr, k - 1);
      } catch (const integration_error& e) {
        return report_failure(o, e.status());
      }
      prev = curr;
      curr = next;
    }
    const vec<T, 2> eta = (prev + curr).normalized();
    const vec<T, 2> p = k == 1 ? s.p : vec<T, 2>((prev - T(4) * eta + T(3) * curr) / tau);
    using std::abs;
    const T energy = p.squaredNorm() / T(2), violation = abs(T(curr.squaredNorm() - T(1)));
    step_status checked;
    checked.step = k - 1;
    const monitor_point<T> current = measure(curr, p);
    monitor.check(tau, previous, current, checked);
    if (!checked) return report_failure(o, checked);
    previous = current;
    if (abs(T(energy - energy0)) > worst_energy) worst_energy = abs(T(energy - energy0));
    if (violation > worst_constraint) worst_constraint = violation;
    if (o.csv && (k % o.every == 0 || k == o.steps)) {
      constrained_row<T, 2>(k, T(k) * tau, curr, p, energy, violation);
      if (!cli::stdout_ok()) return cli::exit_output;  // reported by main (finish_stdout)
    }
  }
  constrained_summary<T>(o, "circle", "paper (23) as printed", tau, worst_energy, worst_constraint);
  return 0;
}

template <class Sys, class Con, class T>
int run_constrained_system(const options& o) {
  if (o.scheme == "paper23") {
    if constexpr (std::is_same_v<Sys, systems::free_particle_2d>) {
      return run_paper23<T>(o);
    } else {
      throw std::invalid_argument("--scheme paper23 is the paper's scheme for --system circle only");
    }
  }
  if (o.scheme != "lpf") throw std::invalid_argument("--system " + o.system + " supports --scheme lpf|paper23");
  if (o.m > 8) throw std::invalid_argument("--system " + o.system + ": the constrained integrator is compiled for m = 2..8");
  return with_int<2, 8>(o.m, [&]<int M>() {
    return with_node_family(o.nodes, [&]<class Family>() {
      return with_basis(o.basis, [&]<class Basis>() { return run_constrained_fb<M, Family, Basis, Sys, Con, T>(o); });
    });
  });
}

}  // namespace geomint::run
