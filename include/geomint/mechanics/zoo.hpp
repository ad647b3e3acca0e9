#pragma once
/// A problem zoo beside the built-in systems: classical test problems of geometric integration,
/// each with its invariants written in closed form (independently of the Lagrangian and the
/// automatic differentiation), and cited reference data where they exist.
///
///   henon_heiles      natural, 2 dof          energy
///   spring_pendulum   general, 2 dof (r, phi) energy (non-constant mass matrix diag(1, r^2))
///   double_pendulum   general, 2 dof (angles) energy (non-constant mass matrix)
///   toda3             natural, 3 dof          energy, total momentum, the cubic Lax integral
///   outer_solar       natural, 18 dof         energy, total linear and angular momentum
///   arenstorf         general, 2 dof          Jacobi constant; a periodic orbit with cited period
///
/// Constants are given as decimal strings and read in the working precision (no double literal).

#include <array>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <type_traits>

#include "geomint/core/decimal.hpp"
#include "geomint/core/elementary.hpp"
#include "geomint/mechanics/lagrangian.hpp"

namespace geomint::zoo {
namespace detail {

/// The innermost scalar of a (nested) dual, or S itself.
template <class S>
struct base_scalar {
  using type = S;
};
template <class T, int N>
struct base_scalar<geomint::dual<T, N>> {
  using type = typename base_scalar<T>::type;
};
template <int W>
struct base_scalar<geomint::double_pack<W>> {
  using type = double;
};

/// A decimal constant in the precision of S (a scalar or a nested dual over it).
template <class S>
S decimal(const char* text) {
  return S(from_decimal<typename base_scalar<S>::type>(text));
}

}  // namespace detail

/// Henon-Heiles: L = 1/2 |qdot|^2 - V, V = 1/2 (x^2 + y^2) + x^2 y - y^3 / 3 (Henon & Heiles,
/// Astron. J. 69 (1964) 73; Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed.,
/// Springer 2006, section I.3). Bounded motion for energies below 1/6.
struct henon_heiles : natural<henon_heiles, 2> {
  static constexpr std::string_view name = "henon-heiles";
  template <class S>
  static S potential(const vec<S, 2>& q) {
    const S& x = q[0];
    const S& y = q[1];
    return S((x * x + y * y) / S(2) + x * x * y - y * y * y / S(3));
  }
  /// grad V = (x + 2 x y, y + x^2 - y^2): no AD on V (also on SIMD packs, ensemble.hpp).
  template <class S>
  static vec<S, 2> potential_gradient(const vec<S, 2>& q) {
    const S& x = q[0];
    const S& y = q[1];
    return vec<S, 2>(S(x + S(2) * x * y), S(y + x * x - y * y));
  }
  template <class S>
  static mat<S, 2> mass_matrix() { return mat<S, 2>::Identity(); }
  /// H = 1/2 |qdot|^2 + V.
  template <class T>
  static T energy(const vec<T, 2>& q, const vec<T, 2>& qdot) {
    return T((qdot[0] * qdot[0] + qdot[1] * qdot[1]) / T(2) + potential<T>(q));
  }
  /// The tools' initial state (a stated choice): q0 = (0, 0), qdot0 = (3/10, 2/5), energy
  /// exactly 1/8, the energy of Henon & Heiles' surface of section where regular and chaotic
  /// orbits coexist.
  template <class T>
  static void initial_data(vec<T, 2>& q, vec<T, 2>& qdot) {
    q << T(0), T(0);
    qdot << T(3) / T(10), T(2) / T(5);
  }
};

/// Elastic (spring) pendulum in polar coordinates q = (r, phi), phi from the downward vertical;
/// unit mass, stiffness, rest length and gravity:
/// L = 1/2 (rdot^2 + r^2 phidot^2) - 1/2 (r - 1)^2 + r cos(phi). The mass matrix diag(1, r^2)
/// depends on q, so this is a general system (and LPF on Gauss nodes is not symplectic for it).
struct spring_pendulum {
  static constexpr int dof = 2;
  static constexpr std::string_view name = "spring-pendulum";
  template <class S>
  S operator()(const vec<S, 2>& q, const vec<S, 2>& qdot) const {
    using std::cos;
    const S& r = q[0];
    const S stretch = r - S(1);
    return S((qdot[0] * qdot[0] + r * r * qdot[1] * qdot[1]) / S(2) - stretch * stretch / S(2) + r * cos(q[1]));
  }
  /// H = 1/2 (rdot^2 + r^2 phidot^2) + 1/2 (r - 1)^2 - r cos(phi).
  template <class T>
  static T energy(const vec<T, 2>& q, const vec<T, 2>& qdot) {
    using std::cos;
    const T& r = q[0];
    return T((qdot[0] * qdot[0] + r * r * qdot[1] * qdot[1]) / T(2) + (r - T(1)) * (r - T(1)) / T(2) - r * cos(q[1]));
  }
  /// The tools' initial state (a stated choice, the state of the guide's symplecticity table):
  /// released from rest at r = 11/10, phi = 1/2.
  template <class T>
  static void initial_data(vec<T, 2>& q, vec<T, 2>& qdot) {
    q << T(11) / T(10), T(1) / T(2);
    qdot << T(0), T(0);
  }
};

/// Planar double pendulum in the angles (theta1, theta2) from the downward vertical; unit
/// masses, rods and gravity: L = thetadot1^2 + 1/2 thetadot2^2 + cos(theta1 - theta2)
/// thetadot1 thetadot2 + 2 cos(theta1) + cos(theta2) (mass matrix [[2, c], [c, 1]],
/// c = cos(theta1 - theta2)).
struct double_pendulum {
  static constexpr int dof = 2;
  static constexpr std::string_view name = "double-pendulum";
  template <class S>
  S operator()(const vec<S, 2>& q, const vec<S, 2>& v) const {
    using std::cos;
    return S(v[0] * v[0] + v[1] * v[1] / S(2) + cos(S(q[0] - q[1])) * v[0] * v[1] + S(2) * cos(q[0]) + cos(q[1]));
  }
  /// H = kinetic + potential = thetadot1^2 + 1/2 thetadot2^2 + c thetadot1 thetadot2
  ///     - 2 cos(theta1) - cos(theta2).
  template <class T>
  static T energy(const vec<T, 2>& q, const vec<T, 2>& v) {
    using std::cos;
    return T(v[0] * v[0] + v[1] * v[1] / T(2) + cos(T(q[0] - q[1])) * v[0] * v[1] - T(2) * cos(q[0]) - cos(q[1]));
  }
  /// The tools' initial state (a stated choice): released from rest at theta = (1/2, 1).
  template <class T>
  static void initial_data(vec<T, 2>& q, vec<T, 2>& v) {
    q << T(1) / T(2), T(1);
    v << T(0), T(0);
  }
};

/// Periodic Toda lattice of three particles: L = 1/2 |qdot|^2 - sum_i exp(q_i - q_{i+1}),
/// q_4 = q_1 (Toda, J. Phys. Soc. Japan 22 (1967) 431; Hairer, Lubich, Wanner, section X.1.5).
/// Integrable: besides H, the total momentum and the cubic integral
/// I3 = sum p_i^3 / 3 + sum (p_i + p_{i+1}) exp(q_i - q_{i+1}) (from tr L^3 of the Lax matrix;
/// {I3, H} = 0 checked symbolically) are conserved.
struct toda3 : natural<toda3, 3> {
  static constexpr std::string_view name = "toda";
  template <class S>
  static S potential(const vec<S, 3>& q) {
    using std::exp;
    return S(exp(S(q[0] - q[1])) + exp(S(q[1] - q[2])) + exp(S(q[2] - q[0])));
  }
  template <class S>
  static mat<S, 3> mass_matrix() { return mat<S, 3>::Identity(); }
  template <class T>
  static T energy(const vec<T, 3>& q, const vec<T, 3>& p) {
    return T((p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / T(2) + potential<T>(q));
  }
  /// The tools' initial state (a stated choice): q0 = (1, 0, -1), qdot0 = (1/2, 0, -1/2), zero
  /// total momentum (no drift of the centre of mass).
  template <class T>
  static void initial_data(vec<T, 3>& q, vec<T, 3>& qdot) {
    q << T(1), T(0), T(-1);
    qdot << T(1) / T(2), T(0), T(-1) / T(2);
  }
  template <class T>
  static T total_momentum(const vec<T, 3>& p) { return T(p[0] + p[1] + p[2]); }
  template <class T>
  static T cubic_integral(const vec<T, 3>& q, const vec<T, 3>& p) {
    using std::exp;
    T out = (p[0] * p[0] * p[0] + p[1] * p[1] * p[1] + p[2] * p[2] * p[2]) / T(3);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      out += (p[i] + p[j]) * exp(T(q[i] - q[j]));
    }
    return out;
  }
};

/// The outer solar system: the Sun (with the masses of the inner planets added), Jupiter,
/// Saturn, Uranus, Neptune and Pluto as point masses, q = (x_0, y_0, z_0, ..., x_5, y_5, z_5);
/// L = 1/2 sum m_i |qdot_i|^2 + G sum_{i<j} m_i m_j / |q_i - q_j|.
/// Units: solar masses, astronomical units, earth days. Masses, G and the initial data of
/// 5 September 1994 are those of Hairer, Lubich, Wanner, Geometric Numerical Integration,
/// 2nd ed., Springer 2006, section I.2.4, Table 2.1 (Pluto's mass 1/(1.3e8)).
struct outer_solar : natural<outer_solar, 18> {
  static constexpr std::string_view name = "outer-solar";
  static constexpr int bodies = 6;
  /// G in AU^3 / (solar mass day^2).
  template <class S>
  static S gravitational_constant() { return detail::decimal<S>("2.95912208286e-4"); }
  template <class S>
  static S mass(int body) {
    switch (body) {
      case 0: return detail::decimal<S>("1.00000597682");
      case 1: return detail::decimal<S>("0.000954786104043");
      case 2: return detail::decimal<S>("0.000285583733151");
      case 3: return detail::decimal<S>("0.0000437273164546");
      case 4: return detail::decimal<S>("0.0000517759138449");
      default: return S(1) / detail::decimal<S>("1.3e8");
    }
  }
  template <class S>
  static S potential(const vec<S, 18>& q) {
    using std::sqrt;
    S out(0);
    for (int i = 0; i < bodies; ++i)
      for (int j = i + 1; j < bodies; ++j) {
        const S dx = q[3 * i] - q[3 * j], dy = q[3 * i + 1] - q[3 * j + 1], dz = q[3 * i + 2] - q[3 * j + 2];
        out -= mass<S>(i) * mass<S>(j) / sqrt(S(dx * dx + dy * dy + dz * dz));
      }
    return S(gravitational_constant<S>() * out);
  }
  /// grad V: for each pair, G m_i m_j (q_i - q_j) |q_i - q_j|^-3 on body i and its opposite on j,
  /// with 1/|q_i - q_j| from inverse_sqrt (fast in multiprecision). The products G m_i m_j are
  /// formed once per scalar type (the masses are parsed from their decimal strings).
  template <class S>
  static vec<S, 18> potential_gradient(const vec<S, 18>& q) {
    static const std::array<S, bodies * (bodies - 1) / 2> coupling = [] {
      std::array<S, bodies * (bodies - 1) / 2> out;
      std::size_t k = 0;
      for (int i = 0; i < bodies; ++i)
        for (int j = i + 1; j < bodies; ++j) out[k++] = S(gravitational_constant<S>() * mass<S>(i) * mass<S>(j));
      return out;
    }();
    vec<S, 18> g = vec<S, 18>::Zero();
    std::size_t k = 0;
    for (int i = 0; i < bodies; ++i)
      for (int j = i + 1; j < bodies; ++j, ++k) {
        const S dx = q[3 * i] - q[3 * j], dy = q[3 * i + 1] - q[3 * j + 1], dz = q[3 * i + 2] - q[3 * j + 2];
        const S y = inverse_sqrt(S(dx * dx + dy * dy + dz * dz));
        const S s = coupling[k] * y * y * y;
        const S fx = s * dx, fy = s * dy, fz = s * dz;
        g[3 * i] += fx;
        g[3 * i + 1] += fy;
        g[3 * i + 2] += fz;
        g[3 * j] -= fx;
        g[3 * j + 1] -= fy;
        g[3 * j + 2] -= fz;
      }
    return g;
  }
  /// The gradient on SIMD packs of stages (core/simd.hpp): 15 pairs, a square root and a division each.
  static constexpr bool stage_parallel_forces = true;
  template <class S>
  static mat<S, 18> mass_matrix() {
    mat<S, 18> M = mat<S, 18>::Zero();
    for (int i = 0; i < 18; ++i) M(i, i) = mass<S>(i / 3);
    return M;
  }
  /// Table 2.1 of Hairer, Lubich, Wanner (positions in AU, velocities in AU/day; Sun at rest at
  /// the origin).
  template <class T>
  static void initial_data(vec<T, 18>& q, vec<T, 18>& qdot) {
    static constexpr const char* positions[18] = {
        "0",           "0",           "0",           "-3.5023653", "-3.8169847", "-1.5507963",
        "9.0755314",   "-3.0458353",  "-1.6483708",  "8.3101420",  "-16.2901086", "-7.2521278",
        "11.4707666",  "-25.7294829", "-10.8169456", "-15.5387357", "-25.2225594", "-3.1902382"};
    static constexpr const char* velocities[18] = {
        "0",          "0",           "0",           "0.00565429", "-0.00412490", "-0.00190589",
        "0.00168318", "0.00483525",  "0.00192462",  "0.00354178", "0.00137102",  "0.00055029",
        "0.00288930", "0.00114527",  "0.00039677",  "0.00276725", "-0.00170702", "-0.00136504"};
    for (int i = 0; i < 18; ++i) {
      q[i] = detail::decimal<T>(positions[i]);
      qdot[i] = detail::decimal<T>(velocities[i]);
    }
  }
  /// H = 1/2 sum |p_i|^2 / m_i + V(q) in terms of the momenta p_i = m_i qdot_i.
  template <class T>
  static T energy_qp(const vec<T, 18>& q, const vec<T, 18>& p) {
    T kinetic(0);
    for (int i = 0; i < 18; ++i) kinetic += p[i] * p[i] / mass<T>(i / 3);
    return T(kinetic / T(2) + potential<T>(q));
  }
  /// Total linear momentum sum p_i (translations; Noether).
  template <class T>
  static vec<T, 3> linear_momentum(const vec<T, 18>& p) {
    vec<T, 3> out = vec<T, 3>::Zero();
    for (int i = 0; i < bodies; ++i) out += p.template segment<3>(3 * i);
    return out;
  }
  /// Total angular momentum sum q_i x p_i (rotations; Noether).
  template <class T>
  static vec<T, 3> angular_momentum(const vec<T, 18>& q, const vec<T, 18>& p) {
    vec<T, 3> out = vec<T, 3>::Zero();
    for (int i = 0; i < bodies; ++i) {
      const vec<T, 3> qi = q.template segment<3>(3 * i), pi = p.template segment<3>(3 * i);
      out += vec<T, 3>(qi[1] * pi[2] - qi[2] * pi[1], qi[2] * pi[0] - qi[0] * pi[2], qi[0] * pi[1] - qi[1] * pi[0]);
    }
    return out;
  }
};

/// The planar restricted three-body problem in the frame rotating with the primaries (masses
/// 1 - mu at (-mu, 0) and mu at (1 - mu, 0)): a velocity-dependent (Coriolis) Lagrangian
/// L = 1/2 ((xdot - y)^2 + (ydot + x)^2) + (1 - mu)/r1 + mu/r2. Its energy is minus half the
/// Jacobi constant. With mu = 0.012277471 and the initial data below, the solution is the
/// periodic Arenstorf orbit of period 17.0652165601579625588917206249 (Hairer, Norsett,
/// Wanner, Solving Ordinary Differential Equations I, 2nd ed., Springer 1993, section II.0,
/// eq. (0.1)-(0.2)).
struct arenstorf {
  static constexpr int dof = 2;
  static constexpr std::string_view name = "arenstorf";
  template <class S>
  static S mu() { return detail::decimal<S>("0.012277471"); }
  template <class S>
  S operator()(const vec<S, 2>& q, const vec<S, 2>& v) const {
    using std::sqrt;
    const S m = mu<S>(), m1 = S(1) - m;
    const S u = v[0] - q[1], w = v[1] + q[0];
    const S d1 = q[0] + m, d2 = q[0] - m1;
    const S r1 = sqrt(S(d1 * d1 + q[1] * q[1])), r2 = sqrt(S(d2 * d2 + q[1] * q[1]));
    return S((u * u + w * w) / S(2) + m1 / r1 + m / r2);
  }
  /// H = qdot . L_qdot - L = 1/2 |qdot|^2 - 1/2 |q|^2 - (1 - mu)/r1 - mu/r2.
  template <class T>
  static T energy(const vec<T, 2>& q, const vec<T, 2>& v) {
    using std::sqrt;
    const T m = mu<T>(), m1 = T(1) - m;
    const T d1 = q[0] + m, d2 = q[0] - m1;
    return T((v[0] * v[0] + v[1] * v[1] - q[0] * q[0] - q[1] * q[1]) / T(2) - m1 / sqrt(T(d1 * d1 + q[1] * q[1])) -
             m / sqrt(T(d2 * d2 + q[1] * q[1])));
  }
  template <class T>
  static void initial_data(vec<T, 2>& q, vec<T, 2>& qdot) {
    q << detail::decimal<T>("0.994"), T(0);
    qdot << T(0), detail::decimal<T>("-2.00158510637908252240537862224");
  }
  template <class T>
  static T period() { return detail::decimal<T>("17.0652165601579625588917206249"); }
};

}  // namespace geomint::zoo
