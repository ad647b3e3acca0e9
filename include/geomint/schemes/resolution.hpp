#pragma once
/// The resolution bound of a scheme: the largest tau * omega_max (omega_max the fastest local
/// rate of the linearised flow, solvers/step_monitor.hpp) at which a step still follows the
/// motion it is meant to approximate.
///
/// Derivation. On the harmonic oscillator xddot = -omega^2 x the s-stage Gauss method (order
/// 2s; stability function the diagonal (s, s) Pade approximant of e^z) advances the phase by
/// theta(y) = 2 arg P_s(i y) per step of y = tau omega, P_s the Pade numerator; it can never
/// advance more than s pi. Its phase error per step y - theta(y) reaches one radian at
/// y = 2.95, 4.93, 6.92, ... for s = 1, 2, 3, ... and is 1.03 to 1.05 rad at y = 2s + 1 for
/// every s = 1..16: the bound 2s + 1 is where a step's phase error is of order one, i.e. where
/// the step no longer resolves the oscillation (s = 1: 3 - 2 atan(3/2) = 1.034 rad, from the
/// closed form of the midpoint rule, theta = 2 atan(y/2)). A scheme gets the bound of the Gauss
/// method of its order:
///  - midpoint_vi (Gauss, s = 1): 3;
///  - galerkin_vi<m> (with m-point Gauss quadrature it is the m-stage Gauss collocation method;
///    Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. (2006), Theorem VI.6.4):
///    2m + 1;
///  - lpf<m> (any solver), lpf_fixed_point<m>, constrained_lpf<m> (order 2(m - 1) on Gauss-interior nodes;
///    lower on other nodes, whose bound stays that of the degree): 2(m - 1) + 1 = 2m - 1;
///  - trapezoidal_vi (Stormer-Verlet on natural systems): 2, its interval of linear stability
///    (|tau omega| < 2, ibid. section I.5; its phase error reaches one radian only beyond it).
/// A scheme of the user's own (docs/guide/design_a_scheme.md) has no known bound: infinity (no
/// resolution check) unless step_monitor::max_tau_omega is set.
#include <limits>

#include "geomint/schemes/classical.hpp"
#include "geomint/schemes/lpf.hpp"

namespace geomint {

template <int M>
struct lpf_fixed_point;
template <int M, class Family, class Basis>
struct constrained_lpf;

/// resolution_bound<Scheme>::value: the bound 2s + 1 as an integer, or 0 where none is known.
template <class Scheme>
struct resolution_bound {
  static constexpr int value = 0;
};
template <>
struct resolution_bound<midpoint_vi> {
  static constexpr int value = 3;
};
template <>
struct resolution_bound<trapezoidal_vi> {
  static constexpr int value = 2;
};
template <int M, class Family, class Basis>
struct resolution_bound<galerkin_vi<M, Family, Basis>> {
  static constexpr int value = 2 * M + 1;
};
template <int M, class Family, class Basis, class Solver>
struct resolution_bound<lpf<M, Family, Basis, Solver>> {
  static constexpr int value = 2 * M - 1;
};
template <int M>
struct resolution_bound<lpf_fixed_point<M>> {
  static constexpr int value = 2 * M - 1;
};
template <int M, class Family, class Basis>
struct resolution_bound<constrained_lpf<M, Family, Basis>> {
  static constexpr int value = 2 * M - 1;
};

/// The bound of Scheme in the scalar T (infinity where none is known).
template <class Scheme, class T>
T scheme_resolution_bound() {
  constexpr int b = resolution_bound<Scheme>::value;
  if constexpr (b > 0)
    return T(b);
  else
    return std::numeric_limits<T>::infinity();
}

}  // namespace geomint
