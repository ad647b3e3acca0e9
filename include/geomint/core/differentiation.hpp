#pragma once
/// Differentiation weights D_k[i][j] = phi_j^(k)(c_i): the k-th derivative at node c_i of the
/// path sum_j phi_j(t) X_j is sum_j D_k[i][j] X_j (on a unit step; divide by tau^k).
///
/// Lagrange weights use the barycentric recursion (`core::detail::lagrange_node_derivatives`,
/// core/basis.hpp: exact for rational nodes, and backward stable in floating point, unlike
/// differentiating monomial coefficients).
/// Bernstein weights evaluate the stable difference form of basis_derivatives at the nodes.

#include <array>
#include <cstddef>

#include "geomint/core/basis.hpp"

namespace geomint {

template <class T, int N>
using square_array = std::array<std::array<T, N>, N>;

/// D_K for the basis `Basis` collocated at the nodes of `Family`; K = 0 gives basis values.
template <int K, class Family, int M, class T = double, class Basis = lagrange>
constexpr square_array<T, M + 1> differentiation_weights() {
  static_assert(K >= 0, "geomint: derivative order k must be >= 0");
  static_assert(basis_kind<Basis>, "geomint: Basis must be lagrange or bernstein");
  check_node_parameters<Family, M, T>();
  constexpr std::size_t n = M + 1;
  const auto c = nodes<Family, M, T>();
  square_array<T, M + 1> D{};
  if constexpr (std::is_same_v<Basis, bernstein>) {
    for (std::size_t i = 0; i < n; ++i) D[i] = basis_derivatives<K, bernstein, Family, M, T>(c[i]);
  } else {
    D = core::detail::lagrange_node_derivatives<K>(c);
  }
  return D;
}

/// The weights as a constexpr variable (rational, double, long double).
template <int K, class Family, int M, class T = double, class Basis = lagrange>
inline constexpr square_array<T, M + 1> differentiation_weights_v = differentiation_weights<K, Family, M, T, Basis>();

}  // namespace geomint
