#pragma once
/// Polynomials over Z with big_integer coefficients, for constant expressions.
///
/// `geomint::integer_polynomial<L, D>` stores the coefficients of a polynomial of degree at
/// most D in ascending powers, with an exact degree (-1 for zero). Besides the ring operations:
/// exact division (`exact_quotient`, throws when the divisor does not divide), content and
/// primitive part, and the gcd in Z[x] (`polynomial_gcd`: primitive, positive leading
/// coefficient; gcd(0, b) is b made primitive, gcd(0, 0) = 0). Overflow of a coefficient or of
/// the degree bound throws, never a wrong value.

#include <cstdint>
#include <stdexcept>
#include <utility>

#include "geomint/core/big_integer.hpp"

namespace geomint {

template <int L, int D>
struct integer_polynomial {
  big_integer<L> c[D + 1]{};
  int degree = -1;  ///< -1 for the zero polynomial

  constexpr integer_polynomial() = default;
  constexpr explicit integer_polynomial(const big_integer<L>& constant) {
    c[0] = constant;
    trim();
  }
  constexpr void trim() {
    degree = D;
    while (degree >= 0 && c[degree].is_zero()) --degree;
  }
  constexpr const big_integer<L>& operator[](int k) const { return c[k]; }
  constexpr big_integer<L>& operator[](int k) { return c[k]; }
  constexpr bool is_zero() const { return degree < 0; }
  /// The leading coefficient; the zero polynomial has none (std::domain_error, a compile error
  /// in a constant expression).
  constexpr const big_integer<L>& lead() const {
    if (degree < 0) throw std::domain_error("geomint::integer_polynomial: the zero polynomial has no leading coefficient");
    return (*this)[degree];
  }

  friend constexpr integer_polynomial operator+(const integer_polynomial& a, const integer_polynomial& b) {
    integer_polynomial r;
    const int n = a.degree > b.degree ? a.degree : b.degree;
    for (int k = 0; k <= n; ++k) r[k] = a[k] + b[k];
    r.trim();
    return r;
  }
  friend constexpr integer_polynomial operator-(const integer_polynomial& a, const integer_polynomial& b) {
    integer_polynomial r;
    const int n = a.degree > b.degree ? a.degree : b.degree;
    for (int k = 0; k <= n; ++k) r[k] = a[k] - b[k];
    r.trim();
    return r;
  }
  friend constexpr integer_polynomial operator*(const integer_polynomial& a, const integer_polynomial& b) {
    integer_polynomial r;
    if (a.is_zero() || b.is_zero()) return r;
    if (a.degree + b.degree > D) throw std::overflow_error("geomint::integer_polynomial: degree overflow");
    for (int i = 0; i <= a.degree; ++i) {
      if (a[i].is_zero()) continue;
      for (int j = 0; j <= b.degree; ++j) r[i + j] += a[i] * b[j];
    }
    r.trim();
    return r;
  }
  friend constexpr integer_polynomial operator*(const big_integer<L>& k, integer_polynomial a) {
    for (int i = 0; i <= a.degree; ++i) a[i] = k * a[i];
    a.trim();
    return a;
  }
  friend constexpr bool operator==(const integer_polynomial&, const integer_polynomial&) = default;
};

/// a / b when b divides a in Z[s] (long division from the top); otherwise throws.
template <int L, int D>
constexpr integer_polynomial<L, D> exact_quotient(integer_polynomial<L, D> a, const integer_polynomial<L, D>& b) {
  if (b.is_zero()) throw std::domain_error("geomint::integer_polynomial: division by zero");
  integer_polynomial<L, D> q;
  for (int k = a.degree - b.degree; k >= 0; --k) {
    const big_integer<L> t = exact_quotient(a[k + b.degree], b.lead());
    q[k] = t;
    if (t.is_zero()) continue;
    for (int j = 0; j <= b.degree; ++j) a[k + j] -= t * b[j];
  }
  a.trim();
  if (!a.is_zero()) throw std::domain_error("geomint::integer_polynomial: inexact division");
  q.trim();
  return q;
}

/// gcd of the coefficients (content), >= 0.
template <int L, int D>
constexpr big_integer<L> content(const integer_polynomial<L, D>& a) {
  big_integer<L> g;
  for (int k = 0; k <= a.degree; ++k) g = gcd(g, a[k]);
  return g;
}

template <int L, int D>
constexpr integer_polynomial<L, D> primitive_part(integer_polynomial<L, D> a) {
  if (a.is_zero()) return a;
  const big_integer<L> g = content(a);
  for (int k = 0; k <= a.degree; ++k) a[k] = exact_quotient(a[k], g);
  return a;
}


/// a mod p for a one-limb prime p, in [0, p).
template <int L>
constexpr std::uint64_t residue(const big_integer<L>& a, std::uint32_t p) {
  std::uint32_t r = 0;
  (void)a.divide_small(p, r);
  return a.negative && r != 0 ? p - r : r;
}

constexpr std::uint64_t mod_power_u64(std::uint64_t b, std::uint64_t e, std::uint64_t p) {
  std::uint64_t r = 1;
  b %= p;
  while (e != 0) {
    if ((e & 1U) != 0) r = r * b % p;
    b = b * b % p;
    e >>= 1;
  }
  return r;
}

/// Degree of gcd(a mod p, b mod p) over F_p (p < 2^32 prime, products fit 64 bits).
template <int L, int D>
constexpr int gcd_degree_mod(const integer_polynomial<L, D>& a, const integer_polynomial<L, D>& b, std::uint32_t p) {
  std::uint64_t u[D + 1]{}, v[D + 1]{};
  auto reduce = [&](const integer_polynomial<L, D>& x, std::uint64_t (&out)[D + 1]) {
    int deg = -1;
    for (int k = 0; k <= x.degree; ++k) {
      out[k] = residue(x[k], p);
      if (out[k] != 0) deg = k;
    }
    return deg;
  };
  int du = reduce(a, u);
  int dv = reduce(b, v);
  while (dv >= 0) {
    // u <- u mod v
    const std::uint64_t inv = mod_power_u64(v[dv], p - 2, p);
    while (du >= dv) {
      const std::uint64_t f = u[du] * inv % p;
      for (int j = 0; j <= dv; ++j) {
        const int k = du - dv + j;
        u[k] = (u[k] + (p - f) * v[j]) % p;
      }
      while (du >= 0 && u[du] == 0) --du;
    }
    std::swap(u, v);
    std::swap(du, dv);
  }
  return du;
}


/// gcd in Z[s], primitive, positive leading coefficient. A coprimality certificate modulo a
/// 31-bit prime not dividing both leading coefficients settles the usual case cheaply (the
/// degree of the gcd mod p is at least the degree of the gcd over Z); otherwise the primitive
/// remainder sequence (pseudo-division, content removed at each step) computes it. That sequence
/// can outgrow the fixed width for large coprime inputs (m = 8 would need ~900 bits), hence the
/// certificate first; an overflow is an exception, never a wrong result.
template <int L, int D>
constexpr integer_polynomial<L, D> polynomial_gcd(const integer_polynomial<L, D>& a, const integer_polynomial<L, D>& b) {
  // gcd(0, b) = b up to a unit (and gcd(0, 0) = 0): the zero polynomial has no leading
  // coefficient for the certificate below.
  if (a.is_zero() || b.is_zero()) {
    integer_polynomial<L, D> u = primitive_part(a.is_zero() ? b : a);
    if (!u.is_zero() && u.lead().negative) u = big_integer<L>(-1) * u;
    return u;
  }
  for (std::uint32_t p : {2147483647U, 2147483629U, 2147483587U}) {
    if (residue(a.lead(), p) == 0 || residue(b.lead(), p) == 0) continue;
    if (gcd_degree_mod(a, b, p) == 0) return integer_polynomial<L, D>(big_integer<L>(1));
    break;
  }
  integer_polynomial<L, D> u = primitive_part(a), v = primitive_part(b);
  if (u.degree < v.degree) std::swap(u, v);
  while (!v.is_zero()) {
    // pseudo-remainder: lead(v)^(deg u - deg v + 1) u mod v, exact in Z[s]
    integer_polynomial<L, D> r = u;
    while (!r.is_zero() && r.degree >= v.degree) {
      const int shift = r.degree - v.degree;
      const big_integer<L> f = r.lead();
      r = v.lead() * r;
      for (int j = 0; j <= v.degree; ++j) r[shift + j] -= f * v[j];
      r.trim();
    }
    u = v;
    v = primitive_part(r);
  }
  if (u.lead().negative) u = big_integer<L>(-1) * u;
  return u;
}

}  // namespace geomint
