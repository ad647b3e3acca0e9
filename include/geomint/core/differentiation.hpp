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

/// D_K for the basis `Basis` collocated at the nodes c, whatever family they come from: the
/// family-free form of `differentiation_weights`, one instantiation per (K, Basis, T, m) for
/// code that holds the nodes at run time (schemes/step_skeleton.hpp, path_weights).
template <int K, class Basis, class T, std::size_t N>
constexpr square_array<T, static_cast<int>(N)> differentiation_weights_at(const std::array<T, N>& c) {
  static_assert(K >= 0, "geomint: derivative order k must be >= 0");
  static_assert(basis_kind<Basis>, "geomint: Basis must be lagrange or bernstein");
  square_array<T, static_cast<int>(N)> D{};
  if constexpr (std::is_same_v<Basis, bernstein>) {
    for (std::size_t i = 0; i < N; ++i) D[i] = core::detail::bernstein_derivatives<K, static_cast<int>(N) - 1, T>(c[i]);
  } else {
    D = core::detail::lagrange_node_derivatives<K>(c);
  }
  return D;
}

/// D_K for the basis `Basis` collocated at the nodes of `Family`; K = 0 gives basis values.
template <int K, class Family, int M, class T = double, class Basis = lagrange>
constexpr square_array<T, M + 1> differentiation_weights() {
  return differentiation_weights_at<K, Basis>(nodes<Family, M, T>());
}

/// The weights as a constexpr variable (rational, double, long double).
template <int K, class Family, int M, class T = double, class Basis = lagrange>
inline constexpr square_array<T, M + 1> differentiation_weights_v = differentiation_weights<K, Family, M, T, Basis>();

}  // namespace geomint
