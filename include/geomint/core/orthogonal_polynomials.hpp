#pragma once
/// Exact coefficients of the polynomials that define the node families (core/nodes.hpp) and the
/// Gauss methods: shifted Legendre P_n(2x - 1), the derivative P'_n(y) at y = 2x - 1 (Lobatto
/// interior nodes) and shifted Chebyshev U_n(2x - 1) (Chebyshev-Lobatto interior nodes), in the
/// monomial basis in x, over any field K: exact numbers at compile time (the exact RKN tableaux,
/// analysis/node_polynomial.hpp), exact rationals at run time (the collocation families,
/// methods/collocation_families.hpp), by the three-term recurrences
///   (k+1) P_{k+1} = (2k+1) y P_k - k P_{k-1},   P'_{k+1} = (k+1) P_k + y P'_k,
///   U_{k+1} = 2 y U_k - U_{k-1}.
/// core/nodes.hpp evaluates the same recurrences at a point in a floating scalar, to find the
/// nodes themselves.

#include <array>
#include <cstddef>
#include <stdexcept>

namespace geomint {

/// Which polynomial of the family.
enum class shifted_orthogonal_kind {
  legendre,             ///< P_n(2x - 1)
  legendre_derivative,  ///< P'_n(y) at y = 2x - 1 (degree n - 1)
  chebyshev_u           ///< U_n(2x - 1)
};

/// The coefficients (ascending powers of x; zero above the degree) of the polynomial `kind` of
/// index n over K; Capacity >= n + 1 coefficients (std::domain_error otherwise).
template <class K, std::size_t Capacity>
constexpr std::array<K, Capacity> shifted_orthogonal_polynomial(shifted_orthogonal_kind kind, int n) {
  if (n < 0 || static_cast<std::size_t>(n) + 1 > Capacity)
    throw std::domain_error("geomint::shifted_orthogonal_polynomial: the index must be in 0..Capacity - 1");
  // P_0 = U_0 = 1, P'_0 = 0, P_{-1} = U_{-1} = 0.
  std::array<K, Capacity> prev{}, cur{}, dcur{};
  cur[0] = K(1);
  // r = y v with y = 2x - 1, v of degree deg (deg + 1 < Capacity).
  auto times_y = [](const std::array<K, Capacity>& v, std::array<K, Capacity>& r, int deg) {
    for (int k = deg + 1; k >= 0; --k) {
      K t = -v[static_cast<std::size_t>(k)];
      if (k >= 1) t = t + K(2) * v[static_cast<std::size_t>(k - 1)];
      r[static_cast<std::size_t>(k)] = t;
    }
  };
  for (int k = 0; k < n; ++k) {
    std::array<K, Capacity> yc{}, next{}, dnext{};
    times_y(cur, yc, k);
    if (kind == shifted_orthogonal_kind::chebyshev_u) {
      for (std::size_t j = 0; j <= static_cast<std::size_t>(k + 1); ++j) next[j] = K(2) * yc[j] - prev[j];
    } else {
      std::array<K, Capacity> ydc{};
      times_y(dcur, ydc, k);
      for (std::size_t j = 0; j <= static_cast<std::size_t>(k + 1); ++j) {
        next[j] = (K(2 * k + 1) * yc[j] - K(k) * prev[j]) / K(k + 1);
        dnext[j] = K(k + 1) * cur[j] + ydc[j];
      }
    }
    prev = cur;
    cur = next;
    dcur = dnext;
  }
  return kind == shifted_orthogonal_kind::legendre_derivative ? dcur : cur;
}

}  // namespace geomint
