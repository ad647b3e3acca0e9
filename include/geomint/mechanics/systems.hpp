#pragma once
/// Built-in Lagrangian systems (LPF paper section 3).

#include <cmath>
#include <string_view>

#include "geomint/core/elementary.hpp"
#include "geomint/mechanics/lagrangian.hpp"

namespace geomint::systems {

/// L = 1/2 xdot^2 - 1/2 x^2 (eq. 15).
struct harmonic : natural<harmonic, 1> {
  static constexpr std::string_view name = "harmonic";
  /// The paper's data: x(0) = 1, xdot(0) = 1 (section 3.1).
  template <class T>
  static void initial_data(vec<T, 1>& q, vec<T, 1>& qdot) {
    q[0] = T(1);
    qdot[0] = T(1);
  }
  template <class S>
  static S potential(const vec<S, 1>& q) { return q[0] * q[0] / S(2); }
  template <class T>
  static mat<T, 1> mass_matrix() { return mat<T, 1>::Identity(); }
};

/// L = 1/2 thetadot^2 - (1 - cos theta) (eq. 20).
struct pendulum : natural<pendulum, 1> {
  static constexpr std::string_view name = "pendulum";
  /// theta(0) = 1 at rest.
  template <class T>
  static void initial_data(vec<T, 1>& q, vec<T, 1>& qdot) {
    q[0] = T(1);
    qdot[0] = T(0);
  }
  template <class S>
  static S potential(const vec<S, 1>& q) {
    using std::cos;
    return S(1) - cos(q[0]);
  }
  /// grad V = sin theta: one sine per force, where AD on V also forms the cosine (sine: fast
  /// in multiprecision, core/elementary.hpp).
  template <class S>
  static vec<S, 1> potential_gradient(const vec<S, 1>& q) {
    return vec<S, 1>(sine(q[0]));
  }
  /// The gradient on SIMD packs of stages (core/simd.hpp): a sine per stage is most of a step.
  static constexpr bool stage_parallel_forces = true;
  template <class T>
  static mat<T, 1> mass_matrix() { return mat<T, 1>::Identity(); }
};

/// L = 1/2 |qdot|^2 + 1/|q| (planar Kepler problem, mu = 1). Rotation invariant, so the
/// angular momentum q x p is the Noether quantity.
struct kepler : natural<kepler, 2> {
  static constexpr std::string_view name = "kepler";
  /// Eccentricity 1/2, semi-major axis 1, at pericentre: q = (1/2, 0), qdot = (0, sqrt 3).
  template <class T>
  static void initial_data(vec<T, 2>& q, vec<T, 2>& qdot) {
    using std::sqrt;
    q << T(1) / T(2), T(0);
    qdot << T(0), T(sqrt(T(3)));
  }
  template <class S>
  static S potential(const vec<S, 2>& q) {
    using std::sqrt;
    return S(-1) / sqrt(q[0] * q[0] + q[1] * q[1]);
  }
  /// grad V = q / |q|^3, with 1/|q| from inverse_sqrt (fast in multiprecision). It compiles on
  /// SIMD packs (core/simd.hpp), but the engine does not take it there: one square root and
  /// one division cost less than laying the stages out in packs (lpf_fixed_point<12>: 2-4%
  /// slower on packs of 2 and 4, docs/results/performance.md, "Stage forces on SIMD packs").
  template <class S>
  static vec<S, 2> potential_gradient(const vec<S, 2>& q) {
    const S r2 = q[0] * q[0] + q[1] * q[1];
    const S y = inverse_sqrt(r2);
    const S s = y * y * y;
    return vec<S, 2>(S(q[0] * s), S(q[1] * s));
  }
  template <class T>
  static mat<T, 2> mass_matrix() { return mat<T, 2>::Identity(); }
  /// q x p.
  template <class T>
  static T conserved(const vec<T, 2>& q, const vec<T, 2>& p) { return q[0] * p[1] - q[1] * p[0]; }
};

/// A unit charge in the plane in the axisymmetric, non-uniform magnetic field B_z = 1 + r^2,
/// vector potential A = a(r) (-y, x) with a(r) = (1 + r^2/2)/2:
/// L = 1/2 |qdot|^2 + A(q) . qdot (velocity-dependent, not separable). L is invariant under
/// rotations about the origin, so the canonical angular momentum x p_y - y p_x (p = qdot + A)
/// is conserved (Noether).
struct charged {
  static constexpr int dof = 2;
  static constexpr std::string_view name = "charged";
  /// q = (1, 0), qdot = (0, 1).
  template <class T>
  static void initial_data(vec<T, 2>& q, vec<T, 2>& qdot) {
    q << T(1), T(0);
    qdot << T(0), T(1);
  }
  template <class S>
  S operator()(const vec<S, 2>& q, const vec<S, 2>& v) const {
    const S r2 = q[0] * q[0] + q[1] * q[1];
    const S a = (S(1) + r2 / S(2)) / S(2);
    return (v[0] * v[0] + v[1] * v[1]) / S(2) + a * (q[0] * v[1] - q[1] * v[0]);
  }
  /// x p_y - y p_x.
  template <class T>
  static T conserved(const vec<T, 2>& q, const vec<T, 2>& p) { return q[0] * p[1] - q[1] * p[0]; }
};

}  // namespace geomint::systems
