#pragma once
/// Constrained example systems (LPF paper, example 3.3).

#include <cmath>
#include <string_view>

#include "geomint/mechanics/constraint.hpp"

namespace geomint::systems {

/// A free unit-mass particle in the plane, L = 1/2 |qdot|^2 (with `unit_circle`: example 3.3).
struct free_particle_2d : natural<free_particle_2d, 2> {
  static constexpr std::string_view name = "circle";
  /// On the unit circle at (1, 0) with velocity (0, 1).
  template <class T>
  static void initial_data(vec<T, 2>& q, vec<T, 2>& qdot) {
    q << T(1), T(0);
    qdot << T(0), T(1);
  }
  template <class S>
  static S potential(const vec<S, 2>&) { return S(0); }
  template <class T>
  static mat<T, 2> mass_matrix() { return mat<T, 2>::Identity(); }
};

/// f(q) = |q|^2 - 1.
struct unit_circle {
  static constexpr int count = 1;
  template <class S>
  vec<S, 1> operator()(const vec<S, 2>& q) const {
    vec<S, 1> f;
    f[0] = q[0] * q[0] + q[1] * q[1] - S(1);
    return f;
  }
};

/// Spherical pendulum: unit mass on a unit rod, gravity g = 1 along -z;
/// L = 1/2 |qdot|^2 - z, f = |q|^2 - 1.
struct spherical_pendulum : natural<spherical_pendulum, 3> {
  static constexpr std::string_view name = "spherical";
  /// 45 degrees from the downward vertical, (sin, 0, -cos)(pi/4), with velocity (0, 4/5, 0).
  template <class T>
  static void initial_data(vec<T, 3>& q, vec<T, 3>& qdot) {
    using std::sqrt;
    const T r = sqrt(T(1) / T(2));
    q << r, T(0), -r;
    qdot << T(0), T(4) / T(5), T(0);
  }
  template <class S>
  static S potential(const vec<S, 3>& q) { return q[2]; }
  template <class T>
  static mat<T, 3> mass_matrix() { return mat<T, 3>::Identity(); }
  /// The vertical angular momentum x p_y - y p_x (rotations about the z axis; Noether).
  template <class T>
  static T conserved(const vec<T, 3>& q, const vec<T, 3>& p) { return q[0] * p[1] - q[1] * p[0]; }
};

struct unit_sphere {
  static constexpr int count = 1;
  template <class S>
  vec<S, 1> operator()(const vec<S, 3>& q) const {
    vec<S, 1> f;
    f[0] = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - S(1);
    return f;
  }
};

/// Planar double pendulum in Cartesian coordinates q = (x1, y1, x2, y2): unit masses, unit
/// rods, gravity 1 along -y; L = 1/2 |qdot|^2 - y1 - y2.
struct double_pendulum_cartesian : natural<double_pendulum_cartesian, 4> {
  static constexpr std::string_view name = "double-cartesian";
  template <class S>
  static S potential(const vec<S, 4>& q) { return q[1] + q[3]; }
  template <class T>
  static mat<T, 4> mass_matrix() { return mat<T, 4>::Identity(); }
};

/// Two distance constraints: |q1|^2 = 1 and |q2 - q1|^2 = 1.
struct double_pendulum_rods {
  static constexpr int count = 2;
  template <class S>
  vec<S, 2> operator()(const vec<S, 4>& q) const {
    vec<S, 2> f;
    f[0] = q[0] * q[0] + q[1] * q[1] - S(1);
    const S dx = q[2] - q[0], dy = q[3] - q[1];
    f[1] = dx * dx + dy * dy - S(1);
    return f;
  }
};

/// The same double pendulum in angles (theta1, theta2) from the downward vertical:
/// L = thetadot1^2 + 1/2 thetadot2^2 + cos(theta1 - theta2) thetadot1 thetadot2
///     + 2 cos(theta1) + cos(theta2)   (unconstrained; a general, non-natural Lagrangian).
struct double_pendulum_angles {
  static constexpr int dof = 2;
  static constexpr std::string_view name = "double-angles";
  template <class S>
  S operator()(const vec<S, 2>& q, const vec<S, 2>& v) const {
    using std::cos;
    return v[0] * v[0] + v[1] * v[1] / S(2) + cos(S(q[0] - q[1])) * v[0] * v[1] + S(2) * cos(q[0]) + cos(q[1]);
  }
};

}  // namespace geomint::systems
