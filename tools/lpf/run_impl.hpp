#pragma once
/// The integration loop of geomint-run for one system and scalar. The LPF family and basis
/// only change the weight matrices, so they are chosen at run time here: one engine per m.
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "geomint/lpf/integrator.hpp"
#include "geomint/lpf/systems.hpp"
#include "run.hpp"

namespace geomint::run {

template <class T>
T parse_scalar(const std::string& s) {
  std::size_t used = 0;
  if constexpr (std::is_floating_point_v<T>) {
    const double v = std::stod(s, &used);
    if (used != s.size()) throw std::invalid_argument("not a number: " + s);
    return T(v);
  } else {
    std::istringstream in(s);
    T v;
    in >> v;
    if (in.fail() || !in.eof()) throw std::invalid_argument("not a number: " + s);
    return v;
  }
}

/// Default initial data: harmonic (1, 1) as in the paper; pendulum theta = 1 at rest;
/// Kepler e = 0.5 at pericentre; charged particle at (1, 0) with velocity (0, 1).
template <class Sys, class T>
std::pair<vec<T, Sys::dof>, vec<T, Sys::dof>> initial_data(const options& o, const Sys& sys) {
  constexpr int n = Sys::dof;
  vec<T, n> q, qdot;
  if constexpr (n == 1) {
    q[0] = T(1);
    qdot[0] = std::is_same_v<Sys, systems::harmonic> ? T(1) : T(0);
  } else if constexpr (std::is_same_v<Sys, systems::kepler>) {
    using std::sqrt;
    q << T(1) / T(2), T(0);
    qdot << T(0), sqrt(T(3));
  } else {
    q << T(1), T(0);
    qdot << T(0), T(1);
  }
  vec<T, n> p = momentum<Sys, T>(sys, q, qdot);
  auto read = [&](const std::vector<std::string>& in, vec<T, n>& out, const char* flag) {
    if (in.empty()) return;
    if (static_cast<int>(in.size()) != n)
      throw std::invalid_argument(std::string(flag) + " needs " + std::to_string(n) + " value(s) for this system");
    for (int i = 0; i < n; ++i) out[i] = parse_scalar<T>(in[static_cast<std::size_t>(i)]);
  };
  read(o.q0, q, "--q0");
  read(o.p0, p, "--p0");
  return {q, p};
}

template <class Engine, class Sys, class T>
int run_loop(const options& o, const Sys& sys, const Engine& engine, const std::string& label) {
  constexpr int n = Sys::dof;
  using state = phase_state<T, n>;
  const T tau = parse_scalar<T>(o.tau);
  // The stepping interface of geomint::integrator, with the engine chosen at run time.
  auto [q, p] = initial_data<Sys, T>(o, sys);
  state s;
  s.q = q;
  s.p = p;
  auto energy = [&](const state& st) {
    vec<T, n> v;
    if (!detail::derivatives<Sys, T>::velocity(sys, st.q, st.p, v)) return std::numeric_limits<T>::quiet_NaN();
    return energy_qv<Sys, T>(sys, st.q, v);
  };
  std::cout << std::setprecision(std::numeric_limits<T>::max_digits10);
  auto row = [&](const state& st) {
    std::cout << st.step << ',' << st.t;
    for (int i = 0; i < n; ++i) std::cout << ',' << st.q[i];
    for (int i = 0; i < n; ++i) std::cout << ',' << st.p[i];
    std::cout << ',' << energy(st) << '\n';
  };
  const T E0 = energy(s);
  if (o.csv) {
    std::cout << "step,t";
    for (int i = 1; i <= n; ++i) std::cout << ",q" << i;
    for (int i = 1; i <= n; ++i) std::cout << ",p" << i;
    std::cout << ",energy\n";
    row(s);
  }
  const newton_options<T> opt;
  T max_dE(0);
  for (long k = 0; k < o.steps; ++k) {
    step_status st;
    st.step = s.step;
    if (!detail::is_finite(tau) || !(tau > T(0))) {
      st.reason = step_failure::invalid_step_size;
    } else if (!detail::all_finite(s.q) || !detail::all_finite(s.p)) {
      st.reason = step_failure::non_finite_input;
    } else {
      vec<T, n> q1 = vec<T, n>::Zero(), p1 = vec<T, n>::Zero();
      st = engine.one_step(s.q, s.p, tau, q1, p1, opt);
      st.step = s.step;
      if (st) {
        s.q = q1;
        s.p = p1;
        s.t += tau;
        ++s.step;
      }
    }
    if (!st) {
      std::cout.flush();
      std::cerr << "geomint-run: " << st.message() << '\n';
      return 3;
    }
    using std::abs;
    const T dE = abs(energy(s) - E0);
    if (dE > max_dE) max_dE = dE;
    if (o.csv && (s.step % o.every == 0 || k + 1 == o.steps)) row(s);
  }
  if (!o.csv) {
    std::cout << "system " << Sys::name << ", scheme " << label << ", tau " << tau << ", steps " << o.steps
              << ", digits " << std::numeric_limits<T>::digits10 << "\n";
    std::cout << "t = " << s.t << "\nq =";
    for (int i = 0; i < n; ++i) std::cout << ' ' << s.q[i];
    std::cout << "\np =";
    for (int i = 0; i < n; ++i) std::cout << ' ' << s.p[i];
    std::cout << "\nenergy = " << energy(s) << "\nmax |energy - energy0| = " << max_dE << "\n";
  }
  return 0;
}

template <int M, class Family, class Basis, class Sys, class T>
int run_lpf_fb(const options& o, const Sys& sys) {
  const detail::lpf_engine<Sys, T, M> engine(
      sys, detail::to_matrix<T, M + 1>(differentiation_weights<0, Family, M, T, Basis>()),
      detail::to_matrix<T, M + 1>(differentiation_weights<1, Family, M, T, Basis>()),
      detail::to_matrix<T, M + 1>(differentiation_weights<2, Family, M, T, Basis>()), nodes<Family, M, T>());
  return run_loop<detail::lpf_engine<Sys, T, M>, Sys, T>(o, sys, engine, lpf<M, Family, Basis>::name());
}

template <int M, class Family, class Sys, class T>
int run_lpf_f(const options& o, const Sys& sys) {
  if (o.basis == "bernstein") return run_lpf_fb<M, Family, bernstein, Sys, T>(o, sys);
  return run_lpf_fb<M, Family, lagrange, Sys, T>(o, sys);
}

template <int M, class Sys, class T>
int run_lpf(const options& o, const Sys& sys) {
  if (o.nodes == "lobatto") return run_lpf_f<M, gauss_lobatto, Sys, T>(o, sys);
  if (o.nodes == "chebyshev") return run_lpf_f<M, chebyshev_lobatto, Sys, T>(o, sys);
  if (o.nodes == "gauss-interior") return run_lpf_f<M, gauss_interior, Sys, T>(o, sys);
  return run_lpf_f<M, equispaced, Sys, T>(o, sys);
}

template <class Scheme, class Sys, class T>
int run_scheme(const options& o, const Sys& sys) {
  const typename Scheme::template engine<Sys, T> engine(sys);
  return run_loop<decltype(engine), Sys, T>(o, sys, engine, Scheme::name());
}

/// m = 2..8 compiled in (the caller has checked the range).
template <class Sys, class T>
int run_system(const options& o) {
  const Sys sys{};
  if (o.scheme == "paper23") throw std::invalid_argument("--scheme paper23 is the paper's scheme for --system circle only");
  if (o.scheme == "midpoint") return run_scheme<midpoint_vi, Sys, T>(o, sys);
  if (o.scheme == "trapezoidal") return run_scheme<trapezoidal_vi, Sys, T>(o, sys);
  if (o.scheme == "galerkin") {
    switch (o.m) {
      case 2: return run_scheme<galerkin_vi<2>, Sys, T>(o, sys);
      case 3: return run_scheme<galerkin_vi<3>, Sys, T>(o, sys);
      case 4: return run_scheme<galerkin_vi<4>, Sys, T>(o, sys);
      case 5: return run_scheme<galerkin_vi<5>, Sys, T>(o, sys);
      case 6: return run_scheme<galerkin_vi<6>, Sys, T>(o, sys);
      case 7: return run_scheme<galerkin_vi<7>, Sys, T>(o, sys);
      default: return run_scheme<galerkin_vi<8>, Sys, T>(o, sys);
    }
  }
  switch (o.m) {
    case 2: return run_lpf<2, Sys, T>(o, sys);
    case 3: return run_lpf<3, Sys, T>(o, sys);
    case 4: return run_lpf<4, Sys, T>(o, sys);
    case 5: return run_lpf<5, Sys, T>(o, sys);
    case 6: return run_lpf<6, Sys, T>(o, sys);
    case 7: return run_lpf<7, Sys, T>(o, sys);
    default: return run_lpf<8, Sys, T>(o, sys);
  }
}

}  // namespace geomint::run
