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

/// Pendulum qddot = -sin q from theta0 = 1 at rest.
struct pendulum_problem {
  using sys = systems::pendulum;
  static constexpr int n = 1;
  static constexpr const char* name = "pendulum";
  template <class T>
  static arr<T, n> q0() { return {T(1)}; }
  template <class T>
  static arr<T, n> p0() { return {T(0)}; }
  template <class T>
  static T energy(const arr<T, n>& q, const arr<T, n>& p) {
    using std::cos;
    return p[0] * p[0] / T(2) + (T(1) - cos(q[0]));
  }
  template <class T>
  static void force(const arr<T, n>& q, arr<T, n>& f) {
    using std::sin;
    f[0] = -sin(q[0]);
  }
  template <class R>
  static analysis::closed_form_state<R, n> exact(const R& t) { return analysis::pendulum_from_rest<R>(R(1), t); }
};

/// Kepler, a = 1, e = 1/2, from pericentre: q0 = (1/2, 0), p0 = (0, sqrt 3).
struct kepler_problem {
  using sys = systems::kepler;
  static constexpr int n = 2;
  static constexpr const char* name = "kepler";
  template <class T>
  static arr<T, n> q0() { return {T(1) / T(2), T(0)}; }
  template <class T>
  static arr<T, n> p0() {
    using std::sqrt;
    return {T(0), T(sqrt(T(3)))};
  }
  template <class T>
  static T energy(const arr<T, n>& q, const arr<T, n>& p) {
    using std::sqrt;
    return (p[0] * p[0] + p[1] * p[1]) / T(2) - T(1) / sqrt(q[0] * q[0] + q[1] * q[1]);
  }
  template <class T>
  static void force(const arr<T, n>& q, arr<T, n>& f) {
    using std::sqrt;
    const T r2 = q[0] * q[0] + q[1] * q[1];
    const T s = T(1) / (r2 * sqrt(r2));
    f[0] = -q[0] * s;
    f[1] = -q[1] * s;
  }
  template <class R>
  static analysis::closed_form_state<R, n> exact(const R& t) { return analysis::kepler_from_pericentre<R>(R(1) / R(2), t); }
};

}  // namespace geomint::workprecision
