#pragma once
/// Bases of degree m on [0, 1] as polynomials: Lagrange on a node family (eq. 8) and
/// Bernstein (eq. 13). Both interpolate the ends: phi_0(0) = 1, phi_m(1) = 1 and every other
/// phi_j vanishes at both ends, which is what turns the discrete Euler-Lagrange equation into
/// a momentum match (eq. 9-11).

#include <array>
#include <cstddef>
#include <string_view>

#include "geomint/core/nodes.hpp"
#include "geomint/core/polynomial.hpp"
#include "geomint/core/scalar_traits.hpp"

namespace geomint {

/// Basis tags.
struct lagrange {
  static constexpr std::string_view name = "lagrange";
};
struct bernstein {
  static constexpr std::string_view name = "bernstein";
};

template <class Basis>
concept basis_kind = std::is_same_v<Basis, lagrange> || std::is_same_v<Basis, bernstein>;

template <class T, int M>
using basis_polynomials = std::array<polynomial<T, M>, M + 1>;

/// Barycentric weights w_j = 1 / prod_{k != j} (c_j - c_k) of a node set.
template <class T, std::size_t N>
constexpr std::array<T, N> barycentric_weights(const std::array<T, N>& c) {
  std::array<T, N> w{};
  for (std::size_t j = 0; j < N; ++j) {
    T product(1);
    for (std::size_t k = 0; k < N; ++k)
      if (k != j) product *= T(c[j] - c[k]);
    w[j] = T(1) / product;
  }
  return w;
}

namespace core::detail {
/// D_K[i][j] = l_j^(K)(c_i) for the Lagrange basis on the nodes c, by the barycentric recursion
/// (exact for rational nodes, backward stable in floating point):
///   D_1[i][j] = (w_j / w_i) / (c_i - c_j),
///   D_k[i][j] = k / (c_i - c_j) * ((w_j / w_i) D_{k-1}[i][i] - D_{k-1}[i][j]),   i != j,
///   D_k[i][i] = -sum_{j != i} D_k[i][j]   (the derivative of a constant vanishes);
/// K = 0 gives the identity.
template <int K, class T, std::size_t N>
constexpr std::array<std::array<T, N>, N> lagrange_node_derivatives(const std::array<T, N>& c) {
  static_assert(K >= 0, "geomint: derivative order k must be >= 0");
  const auto w = barycentric_weights(c);
  std::array<std::array<T, N>, N> D{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) D[i][j] = (i == j) ? T(1) : T(0);
  for (int k = 1; k <= K; ++k) {
    std::array<std::array<T, N>, N> next{};
    for (std::size_t i = 0; i < N; ++i) {
      T diagonal(0);
      for (std::size_t j = 0; j < N; ++j) {
        if (j == i) continue;
        const T ratio = w[j] / w[i];
        const T value = (k == 1) ? T(ratio / T(c[i] - c[j])) : T(T(k) / T(c[i] - c[j]) * T(ratio * D[i][i] - D[i][j]));
        next[i][j] = value;
        diagonal -= value;
      }
      next[i][i] = diagonal;
    }
    D = next;
  }
  return D;
}

/// l_j(t) for all j by the barycentric formula of the second kind,
///   l_j(t) = (w_j / (t - c_j)) / sum_k (w_k / (t - c_k)),
/// exactly e_i at a node t = c_i. Forward stable for node sets with a small Lebesgue constant
/// (Higham, "The numerical stability of barycentric Lagrange interpolation", IMA J. Numer.
/// Anal. 24 (2004) 547-556), unlike the monomial coefficients of the l_j, which lose about
/// log10 of their largest coefficient in digits (some 2^(2m)).
template <class T, std::size_t N>
constexpr std::array<T, N> lagrange_values_at(const std::array<T, N>& c, const T& t) {
  std::array<T, N> l{};
  for (std::size_t i = 0; i < N; ++i)
    if (t == c[i]) {
      l[i] = T(1);
      return l;
    }
  const auto w = barycentric_weights(c);
  T sum(0);
  for (std::size_t i = 0; i < N; ++i) {
    l[i] = w[i] / T(t - c[i]);
    sum += l[i];
  }
  for (auto& v : l) v /= sum;
  return l;
}
}  // namespace core::detail

/// l_j(t), j = 0..N-1, for the Lagrange polynomials on any N distinct nodes c (not only a
/// family's), at any t: the barycentric formula above, for code that holds its own nodes
/// (e.g. the stages of methods/collocation_rkn.hpp).
template <class T, std::size_t N>
constexpr std::array<T, N> lagrange_values_at(const std::array<T, N>& c, const T& t) {
  return core::detail::lagrange_values_at(c, t);
}

/// Lagrange basis l_a(t) = prod_{b != a} (t - c_b) / (c_a - c_b) on a node family (eq. 8).
template <class Family, int M, class T = double>
constexpr basis_polynomials<T, M> lagrange_basis() {
  const auto c = nodes<Family, M, T>();
  const auto w = barycentric_weights(c);
  basis_polynomials<T, M> basis{};
  for (int a = 0; a <= M; ++a) {
    polynomial<T, M> l(w[static_cast<std::size_t>(a)]);
    for (int b = 0; b <= M; ++b) {
      if (b == a) continue;
      // l <- l * (t - c_b), in place: the degree bound M is never exceeded.
      const T root = c[static_cast<std::size_t>(b)];
      for (int k = M; k >= 1; --k) l[k] = l[k - 1] - root * l[k];
      l[0] = -root * l[0];
    }
    basis[static_cast<std::size_t>(a)] = l;
  }
  return basis;
}

/// n choose k as an exact integer; C(n-k+i, i) = C(n-k+i-1, i-1) (n-k+i) / i divides exactly.
/// Overflow throws (a compile error in a constant expression).
constexpr std::int64_t binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  std::int64_t r = 1;
  for (int i = 1; i <= k; ++i) {
    std::int64_t product = 0;
    if (__builtin_mul_overflow(r, std::int64_t(n - k + i), &product))
      throw std::overflow_error("geomint::binomial overflow");
    r = product / i;
  }
  return r;
}

/// Bernstein basis b_{a,m}(t) = C(m, a) t^a (1 - t)^(m - a) (eq. 13).
template <int M, class T = double>
constexpr basis_polynomials<T, M> bernstein_basis() {
  static_assert(M >= 1 && M <= max_floating_m, "geomint: Bernstein degree m must be in [1, max_floating_m]");
  basis_polynomials<T, M> basis{};
  for (int a = 0; a <= M; ++a) {
    // (1 - t)^(m-a) = sum_j C(m-a, j) (-t)^j
    polynomial<T, M> b;
    for (int j = 0; j <= M - a; ++j) {
      const std::int64_t sign = (j % 2 == 0) ? 1 : -1;
      b[a + j] = from_int64<T>(binomial(M, a) * binomial(M - a, j) * sign);
    }
    basis[static_cast<std::size_t>(a)] = b;
  }
  return basis;
}

/// The basis polynomials of a (Basis, Family, m, T) choice; the family only matters for Lagrange.
template <class Basis, class Family, int M, class T = double>
constexpr basis_polynomials<T, M> basis_polynomials_of() {
  static_assert(basis_kind<Basis>, "geomint: Basis must be lagrange or bernstein");
  check_node_parameters<Family, M, T>();
  if constexpr (std::is_same_v<Basis, lagrange>)
    return lagrange_basis<Family, M, T>();
  else
    return bernstein_basis<M, T>();
}

namespace core::detail {
/// b_{a,n}(t) evaluated directly as C(n,a) t^a (1-t)^(n-a) (all terms positive on [0,1]).
template <class T>
constexpr T bernstein_value(int a, int n, const T& t) {
  if (a < 0 || a > n) return T(0);
  T value = from_int64<T>(binomial(n, a));
  const T one_minus_t = T(1) - t;
  for (int i = 0; i < a; ++i) value *= t;
  for (int i = 0; i < n - a; ++i) value *= one_minus_t;
  return value;
}

/// Bernstein k-th derivatives at t by the stable difference form
///   b_{j,m}^(k)(t) = m!/(m-k)! sum_i (-1)^(k-i) C(k,i) b_{j-i,m-k}(t).
template <int K, int M, class T>
constexpr std::array<T, M + 1> bernstein_derivatives(const T& t) {
  std::array<T, M + 1> out{};
  if constexpr (K > M) {
    for (auto& v : out) v = T(0);
  } else {
    T falling(1);  // m!/(m-k)!
    for (int i = 0; i < K; ++i) falling *= T(M - i);
    for (int j = 0; j <= M; ++j) {
      T sum(0);
      for (int i = 0; i <= K; ++i) {
        const T term = from_int64<T>(binomial(K, i)) * bernstein_value<T>(j - i, M - K, t);
        if ((K - i) % 2 == 0)
          sum += term;
        else
          sum -= term;
      }
      out[static_cast<std::size_t>(j)] = falling * sum;
    }
  }
  return out;
}

/// Lagrange k-th derivatives at t on the nodes c: l_j^(k) has degree m - k, so
///   l_j^(k)(t) = sum_i l_i(t) D_k[i][j]   exactly,
/// with l_i(t) by the barycentric formula and D_k by the barycentric recursion (both stable;
/// the monomial form of the l_j lost digits from m = 9 on in double).
template <int K, class T, std::size_t N>
constexpr std::array<T, N> lagrange_derivatives_at(const std::array<T, N>& c, const T& t) {
  std::array<T, N> out{};
  if constexpr (K >= static_cast<int>(N)) {
    for (auto& v : out) v = T(0);
  } else {
    const auto l = lagrange_values_at(c, t);
    if constexpr (K == 0) {
      out = l;
    } else {
      const auto D = lagrange_node_derivatives<K>(c);
      for (std::size_t j = 0; j < N; ++j) {
        T sum(0);
        for (std::size_t i = 0; i < N; ++i) sum += l[i] * D[i][j];
        out[j] = sum;
      }
    }
  }
  return out;
}
}  // namespace core::detail

/// k-th derivatives of all basis functions at t: out[j] = phi_j^(k)(t), any k >= 0 (Bernstein:
/// `core::detail::bernstein_derivatives`; Lagrange on the family's nodes:
/// `core::detail::lagrange_derivatives_at`). The family-free forms let code that holds the
/// nodes at run time share one instantiation across node families.
template <int K, class Basis, class Family, int M, class T>
constexpr std::array<T, M + 1> basis_derivatives(const T& t) {
  static_assert(K >= 0, "geomint: derivative order k must be >= 0");
  check_node_parameters<Family, M, T>();
  if constexpr (std::is_same_v<Basis, bernstein>)
    return core::detail::bernstein_derivatives<K, M, T>(t);
  else
    return core::detail::lagrange_derivatives_at<K>(nodes<Family, M, T>(), t);
}

/// Values of all basis functions at t.
template <class Basis, class Family, int M, class T>
constexpr std::array<T, M + 1> basis_values(const T& t) {
  return basis_derivatives<0, Basis, Family, M, T>(t);
}

}  // namespace geomint
