#pragma once
/// geomint-workprecision, problems: initial data, energy, force (for the explicit peers) and the
/// closed-form reference (include/geomint/analysis/closed_form_flows.hpp) in a wider scalar R.
#include <array>
#include <cmath>

#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/mechanics/systems.hpp"

namespace geomint::workprecision {

template <class T, int n>
using arr = std::array<T, n>;

/// The system's initial data (`Sys::initial_data`, mechanics/systems.hpp) as (q_0, p_0): unit
/// masses, so p_0 = qdot_0.
template <class Sys, class T>
std::array<arr<T, Sys::dof>, 2> initial_data() {
  vec<T, Sys::dof> q, qdot;
  Sys::initial_data(q, qdot);
  std::array<arr<T, Sys::dof>, 2> out;
  for (int i = 0; i < Sys::dof; ++i) {
    out[0][static_cast<std::size_t>(i)] = q[i];
    out[1][static_cast<std::size_t>(i)] = qdot[i];
  }
  return out;
}

/// f = -grad V from the system's own gradient (Sys::potential_gradient, mechanics/systems.hpp):
/// the force the explicit peers evaluate is the one geomint's schemes evaluate.
template <class Sys, class T>
void force(const arr<T, Sys::dof>& q, arr<T, Sys::dof>& f) {
  vec<T, Sys::dof> x;
  for (int i = 0; i < Sys::dof; ++i) x[i] = q[static_cast<std::size_t>(i)];
  const vec<T, Sys::dof> g = Sys::template potential_gradient<T>(x);
  for (int i = 0; i < Sys::dof; ++i) f[static_cast<std::size_t>(i)] = -g[i];
}

/// Pendulum qddot = -sin q from theta0 = 1 at rest (systems::pendulum::initial_data).
struct pendulum_problem {
  using sys = systems::pendulum;
  static constexpr int n = 1;
  static constexpr const char* name = "pendulum";
  template <class T>
  static arr<T, n> q0() { return initial_data<sys, T>()[0]; }
  template <class T>
  static arr<T, n> p0() { return initial_data<sys, T>()[1]; }
  template <class T>
  static T energy(const arr<T, n>& q, const arr<T, n>& p) {
    using std::cos;
    return p[0] * p[0] / T(2) + (T(1) - cos(q[0]));
  }
  template <class T>
  static void force(const arr<T, n>& q, arr<T, n>& f) { workprecision::force<sys>(q, f); }
  template <class R>
  static analysis::closed_form_state<R, n> exact(const R& t) { return analysis::pendulum_from_rest<R>(R(1), t); }
};

/// Kepler, a = 1, e = 1/2, from pericentre (systems::kepler::initial_data).
struct kepler_problem {
  using sys = systems::kepler;
  static constexpr int n = 2;
  static constexpr const char* name = "kepler";
  template <class T>
  static arr<T, n> q0() { return initial_data<sys, T>()[0]; }
  template <class T>
  static arr<T, n> p0() { return initial_data<sys, T>()[1]; }
  template <class T>
  static T energy(const arr<T, n>& q, const arr<T, n>& p) {
    using std::sqrt;
    return (p[0] * p[0] + p[1] * p[1]) / T(2) - T(1) / sqrt(q[0] * q[0] + q[1] * q[1]);
  }
  template <class T>
  static void force(const arr<T, n>& q, arr<T, n>& f) { workprecision::force<sys>(q, f); }
  template <class R>
  static analysis::closed_form_state<R, n> exact(const R& t) { return analysis::kepler_from_pericentre<R>(R(1) / R(2), t); }
};

}  // namespace geomint::workprecision
