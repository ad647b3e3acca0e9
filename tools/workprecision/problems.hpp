#pragma once
/// geomint-workprecision, problems: initial data, energy, force (for the explicit peers) and the
/// reference in a wider scalar R: the closed form (include/geomint/analysis/closed_form_flows.hpp)
/// where there is one, else the Taylor-series flow (analysis/reference_flow.hpp).
///
/// Every problem has a constant diagonal mass matrix. The methods share the state (q, v), with the
/// velocity v = qdot (geomint's schemes step p = M v, which is v for unit masses), and the final
/// error is measured in it.
#include <algorithm>
#include <array>
#include <cmath>

#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"

namespace geomint::workprecision {

template <class T, int n>
using arr = std::array<T, n>;

/// The system's initial data (`Sys::initial_data`, mechanics/systems.hpp) as (q_0, qdot_0).
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

/// The diagonal of the system's constant mass matrix.
template <class Sys, class T>
arr<T, Sys::dof> masses() {
  const mat<T, Sys::dof> M = Sys::template mass_matrix<T>();
  arr<T, Sys::dof> out;
  for (int i = 0; i < Sys::dof; ++i) out[static_cast<std::size_t>(i)] = M(i, i);
  return out;
}

/// qddot = -M^{-1} grad V from the system's own gradient (Sys::potential_gradient,
/// mechanics/lagrangian.hpp): the force the explicit peers evaluate is the one geomint's schemes
/// evaluate. Unit masses skip the division.
template <class Sys, class T>
void force(const arr<T, Sys::dof>& q, arr<T, Sys::dof>& f) {
  static const arr<T, Sys::dof> m = masses<Sys, T>();
  static const bool unit = std::all_of(m.begin(), m.end(), [](const T& x) { return x == T(1); });
  vec<T, Sys::dof> x;
  for (int i = 0; i < Sys::dof; ++i) x[i] = q[static_cast<std::size_t>(i)];
  const vec<T, Sys::dof> g = Sys::template potential_gradient<T>(x);
  for (std::size_t i = 0; i < std::size_t(Sys::dof); ++i) f[i] = unit ? T(-g[int(i)]) : T(-g[int(i)] / m[i]);
}

/// What every problem takes from its system: initial data, the peers' force and the defaults
/// (T is the regime's, the goals apply, the reference is a closed form); a problem overrides them.
template <class Sys>
struct problem_of {
  using sys = Sys;
  static constexpr int n = Sys::dof;
  static constexpr double horizon = 1;  ///< T in units of the regime's
  static constexpr bool goals = true;
  static constexpr const char* reference = "closed form";
  template <class T>
  static arr<T, n> q0() { return initial_data<Sys, T>()[0]; }
  template <class T>
  static arr<T, n> v0() { return initial_data<Sys, T>()[1]; }
  template <class T>
  static void force(const arr<T, n>& q, arr<T, n>& f) { workprecision::force<Sys>(q, f); }
};

/// Pendulum qddot = -sin q from theta0 = 1 at rest (systems::pendulum::initial_data).
struct pendulum_problem : problem_of<systems::pendulum> {
  static constexpr const char* name = "pendulum";
  template <class T>
  static T energy(const arr<T, n>& q, const arr<T, n>& p) {
    using std::cos;
    return p[0] * p[0] / T(2) + (T(1) - cos(q[0]));
  }
  template <class R>
  static analysis::closed_form_state<R, n> exact(const R& t) { return analysis::pendulum_from_rest<R>(R(1), t); }
};

/// Kepler, a = 1, e = 1/2, from pericentre (systems::kepler::initial_data).
struct kepler_problem : problem_of<systems::kepler> {
  static constexpr const char* name = "kepler";
  template <class T>
  static T energy(const arr<T, n>& q, const arr<T, n>& p) {
    using std::sqrt;
    return (p[0] * p[0] + p[1] * p[1]) / T(2) - T(1) / sqrt(q[0] * q[0] + q[1] * q[1]);
  }
  template <class R>
  static analysis::closed_form_state<R, n> exact(const R& t) { return analysis::kepler_from_pericentre<R>(R(1) / R(2), t); }
};

/// The outer solar system (zoo::outer_solar, Hairer, Lubich, Wanner, section I.2.4): 18 dof,
/// units AU, days and solar masses, from 5 September 1994. T is 100 times the regime's in days
/// (double: 10^5 days, some 23 orbits of Jupiter; 50 digits: 10^4 days); no closed form, so the
/// reference is the Taylor-series flow in the wider scalar R (its energy and momenta are checked
/// in tests/analysis/test_reference_flow.cpp). The work-precision goals are set for the pendulum
/// and Kepler; here the ratios are reported without one.
struct outer_solar_problem : problem_of<zoo::outer_solar> {
  static constexpr const char* name = "outer-solar";
  static constexpr double horizon = 100;
  static constexpr bool goals = false;
  static constexpr const char* reference = "Taylor-series flow";
  template <class T>
  static T energy(const arr<T, n>& q, const arr<T, n>& v) {
    static const arr<T, n> m = masses<sys, T>();
    vec<T, n> x, p;
    for (int i = 0; i < n; ++i) {
      x[i] = q[std::size_t(i)];
      p[i] = m[std::size_t(i)] * v[std::size_t(i)];
    }
    return sys::energy_qp<T>(x, p);
  }
  template <class R>
  static analysis::closed_form_state<R, n> exact(const R& t) {
    vec<R, n> q, v;
    sys::initial_data<R>(q, v);
    analysis::reference_flow<sys, R> flow(q, vec<R, n>(sys::mass_matrix<R>() * v));
    flow.advance_to(t);
    analysis::closed_form_state<R, n> out;
    for (int i = 0; i < n; ++i) {
      out.q[std::size_t(i)] = flow.q()[i];
      out.p[std::size_t(i)] = flow.qdot()[i];
    }
    return out;
  }
};

}  // namespace geomint::workprecision
