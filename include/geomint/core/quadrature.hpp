#pragma once
/// Gauss-Legendre quadrature on [0, 1] in any scalar type: the Q-point rule is exact for
/// polynomials of degree <= 2Q - 1.
///
/// The points are the interior nodes of `gauss_interior` with m = Q + 1 (roots of the shifted
/// Legendre polynomial P_Q); the weights are w_k = 1 / ((1 - x_k^2) P_Q'(x_k)^2) with
/// x = 1 - 2 g, i.e. 1 - x^2 = 4 g (1 - g) (Abramowitz & Stegun 25.4.29, mapped to [0, 1]).
/// `constexpr` where the node solve is (double, long double); full precision at run time in
/// every Boost.Multiprecision type.

#include <array>

#include "geomint/core/nodes.hpp"

namespace geomint {

/// Points g_k and weights w_k of a quadrature rule on [0, 1].
template <class T, int Q>
struct quadrature_rule {
  std::array<T, Q> points{};
  std::array<T, Q> weights{};
};

/// The Q-point Gauss-Legendre rule on [0, 1] (Q = 1..max_floating_m).
template <int Q, class T = double>
constexpr quadrature_rule<T, Q> gauss_legendre_rule() {
  static_assert(Q >= 1, "geomint::gauss_legendre_rule: Q must be >= 1");
  static_assert(Q <= max_floating_m, "geomint::gauss_legendre_rule: Q must be <= max_floating_m (16)");
  static_assert(!std::is_same_v<T, rational>, "geomint::gauss_legendre_rule: Gauss points are irrational");
  const auto c = core::detail::node_set<gauss_interior, Q + 1, T>();
  quadrature_rule<T, Q> rule;
  for (int k = 0; k < Q; ++k) {
    const T g = c[static_cast<std::size_t>(k + 1)];
    const T dp = core::detail::legendre_at<T>(Q, g).dp;
    rule.points[static_cast<std::size_t>(k)] = g;
    rule.weights[static_cast<std::size_t>(k)] = T(1) / (T(4) * g * (T(1) - g) * dp * dp);
  }
  return rule;
}

}  // namespace geomint
