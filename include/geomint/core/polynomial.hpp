#pragma once
/// Dense polynomials of bounded degree over any field-like scalar.
///
/// `polynomial<T, N>` stores the N+1 coefficients of a polynomial of degree at most N in
/// ascending powers. It is a literal (and, for structural T, structural) type, so every
/// operation works in constant expressions for `rational`, `double` and `long double`, and
/// at run time for Boost.Multiprecision scalars. Products and antiderivatives grow the bound.

#include <array>
#include <cstddef>

#include "geomint/core/rational.hpp"

namespace geomint {

template <class T, int N>
struct polynomial {
  static_assert(N >= 0, "geomint::polynomial: the degree bound N must be >= 0");
  using scalar_type = T;
  static constexpr int max_degree = N;

  std::array<T, N + 1> coefficients{};  ///< coefficients[k] multiplies t^k

  constexpr polynomial() {
    for (auto& c : coefficients) c = T(0);
  }
  /// The constant polynomial c.
  constexpr explicit polynomial(const T& c) : polynomial() { coefficients[0] = c; }
  constexpr explicit polynomial(const std::array<T, N + 1>& coeffs) : coefficients(coeffs) {}

  /// The monomial t^k (k <= N).
  static constexpr polynomial monomial(int k) {
    polynomial p;
    p.coefficients[static_cast<std::size_t>(k)] = T(1);
    return p;
  }

  constexpr const T& operator[](int k) const { return coefficients[static_cast<std::size_t>(k)]; }
  constexpr T& operator[](int k) { return coefficients[static_cast<std::size_t>(k)]; }

  /// Exact degree (-1 for the zero polynomial).
  constexpr int degree() const {
    for (int k = N; k >= 0; --k)
      if (!(coefficients[static_cast<std::size_t>(k)] == T(0))) return k;
    return -1;
  }

  /// Horner evaluation.
  template <class U>
  constexpr U operator()(const U& t) const {
    U acc = scalar_cast<U>(coefficients[N]);
    for (int k = N - 1; k >= 0; --k) acc = acc * t + scalar_cast<U>(coefficients[static_cast<std::size_t>(k)]);
    return acc;
  }

  /// Coefficients converted to another scalar type.
  template <class U>
  constexpr polynomial<U, N> cast() const {
    polynomial<U, N> out;
    for (int k = 0; k <= N; ++k) out[k] = scalar_cast<U>((*this)[k]);
    return out;
  }

  /// Embeds the polynomial in a larger degree bound.
  template <int M>
  constexpr polynomial<T, M> widen() const {
    static_assert(M >= N, "geomint::polynomial::widen: the new bound must not be smaller");
    polynomial<T, M> out;
    for (int k = 0; k <= N; ++k) out[k] = (*this)[k];
    return out;
  }

  constexpr polynomial operator-() const {
    polynomial out;
    for (int k = 0; k <= N; ++k) out[k] = -(*this)[k];
    return out;
  }
  constexpr polynomial& operator+=(const polynomial& q) {
    for (int k = 0; k <= N; ++k) (*this)[k] += q[k];
    return *this;
  }
  constexpr polynomial& operator-=(const polynomial& q) {
    for (int k = 0; k <= N; ++k) (*this)[k] -= q[k];
    return *this;
  }
  constexpr polynomial& operator*=(const T& c) {
    for (auto& a : coefficients) a *= c;
    return *this;
  }
  constexpr polynomial& operator/=(const T& c) {
    for (auto& a : coefficients) a /= c;
    return *this;
  }
};

namespace core::detail {
constexpr int max_int(int a, int b) { return a > b ? a : b; }
}  // namespace core::detail

template <class T, int N, int M>
constexpr polynomial<T, core::detail::max_int(N, M)> operator+(const polynomial<T, N>& p, const polynomial<T, M>& q) {
  polynomial<T, core::detail::max_int(N, M)> out = p.template widen<core::detail::max_int(N, M)>();
  for (int k = 0; k <= M; ++k) out[k] += q[k];
  return out;
}
template <class T, int N, int M>
constexpr polynomial<T, core::detail::max_int(N, M)> operator-(const polynomial<T, N>& p, const polynomial<T, M>& q) {
  return p + (-q);
}
template <class T, int N, int M>
constexpr polynomial<T, N + M> operator*(const polynomial<T, N>& p, const polynomial<T, M>& q) {
  polynomial<T, N + M> out;
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j <= M; ++j) out[i + j] += p[i] * q[j];
  return out;
}
template <class T, int N>
constexpr polynomial<T, N> operator*(polynomial<T, N> p, const T& c) {
  return p *= c;
}
template <class T, int N>
constexpr polynomial<T, N> operator*(const T& c, polynomial<T, N> p) {
  return p *= c;
}
template <class T, int N>
constexpr polynomial<T, N> operator/(polynomial<T, N> p, const T& c) {
  return p /= c;
}

/// Exact equality of the represented polynomials (bounds may differ; missing terms are 0).
template <class T, int N, int M>
constexpr bool operator==(const polynomial<T, N>& p, const polynomial<T, M>& q) {
  for (int k = 0; k <= core::detail::max_int(N, M); ++k) {
    const T a = k <= N ? p[k] : T(0);
    const T b = k <= M ? q[k] : T(0);
    if (!(a == b)) return false;
  }
  return true;
}

/// First derivative; the bound drops by one (a constant's derivative is the zero constant).
template <class T, int N>
constexpr auto derivative(const polynomial<T, N>& p) {
  if constexpr (N == 0) {
    return polynomial<T, 0>{};
  } else {
    polynomial<T, N - 1> out;
    for (int k = 1; k <= N; ++k) out[k - 1] = p[k] * T(k);
    return out;
  }
}

/// k-th derivative (k >= 0).
template <int K, class T, int N>
constexpr auto derivative(const polynomial<T, N>& p) {
  static_assert(K >= 0, "geomint::derivative<K>: K must be >= 0");
  if constexpr (K == 0) {
    return p;
  } else {
    return derivative<K - 1>(derivative(p));
  }
}

/// The antiderivative that vanishes at 0.
template <class T, int N>
constexpr polynomial<T, N + 1> antiderivative(const polynomial<T, N>& p) {
  polynomial<T, N + 1> out;
  for (int k = 0; k <= N; ++k) out[k + 1] = p[k] / T(k + 1);
  return out;
}

/// Definite integral over [a, b].
template <class T, int N, class U>
constexpr U integral(const polynomial<T, N>& p, const U& a, const U& b) {
  const auto P = antiderivative(p);
  return P(b) - P(a);
}

/// Composition with the affine map t -> scale*t + shift: returns q with q(t) = p(scale*t + shift).
template <class T, int N>
constexpr polynomial<T, N> compose_affine(const polynomial<T, N>& p, const T& scale, const T& shift) {
  // Horner in polynomial arithmetic: q = (...(a_N x + a_{N-1}) x + ...) with x = scale*t + shift.
  polynomial<T, N> out(p[N]);
  for (int k = N - 1; k >= 0; --k) {
    polynomial<T, N> next;
    for (int j = 0; j <= N; ++j) {
      next[j] += out[j] * shift;
      if (j + 1 <= N) next[j + 1] += out[j] * scale;
    }
    next[0] += p[k];
    out = next;
  }
  return out;
}

}  // namespace geomint
