#pragma once
/// Exact two-step schemes of the harmonic oscillator, derived at compile time.
///
/// For L = xdot^2/2 - x^2/2 (eq. 15) every scheme of the library reduces to
///   x^{k+1} = R(tau) x^k - x^{k-1},   R = P(s) / Q(s),   s = tau^2,
/// with P, Q integer polynomials: eq. (16) for m = 2, (18) for m = 3, (19) for m = 4 (LPF,
/// equispaced nodes) and (17) for the midpoint variational integrator. This header derives P and
/// Q exactly for the LPF scheme (include/geomint/schemes/lpf.hpp) with m = 2..8 on an exact node
/// family, and for the midpoint VI, and expands R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4))
/// for the exact leading local error term and the order p.
///
///   constexpr auto r = geomint::exact_two_step<4>();     // eq. (19)
///   static_assert(r.numerator[0] == 294912 && r.order == 4);
///   r.leading_coefficient.str();                         // "-7/7680"
///
/// Derivation (LPF, one step, nodes 0 = c_0 < ... < c_m = 1, x(c) = sum_j l_j(c) X_j): the
/// interior Euler-Lagrange rows (eq. 12) sum_j D2[i][j] X_j + s X_i = 0 (i = 1..m-1) fix the
/// interior values; the end momentum (eq. 10, times tau) is sum_j D1[m][j] X_j = A(s) X_0 +
/// B(s) X_m; by the symmetry of the nodes the start momentum is -(B X_0 + A X_m), and momentum
/// matching (eq. 11) gives R = -2 B / A. With the Schur complement, A and B are the bordered
/// determinants det[[M(s), D2[I][0]], [D1[m][I], D1[m][0]]] / det M(s) (and the same with
/// column m), M(s) = D2[I][I] + s Id; both are computed by one fraction-free (Bareiss)
/// elimination over Z[s]. All arithmetic is exact: a fixed-width big integer whose overflow
/// throws (a compile error in a constant expression, never a wrong value).

#include <array>
#include <bit>
#include <compare>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "geomint/core/differentiation.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/core/rational.hpp"

namespace geomint {

namespace detail {

// ---------------------------------------------------------------------------------------------
// Fixed-width signed big integer: sign and magnitude, L little-endian 32-bit limbs, 64-bit
// intermediates. Structural (public members only), always normalised: limbs at and above
// `size` are zero and zero is never negative, so member-wise equality is value equality.
// ---------------------------------------------------------------------------------------------

template <int L>
struct big_int {
  static_assert(L >= 2, "geomint::detail::big_int needs at least two limbs");
  std::uint32_t limb[L]{};  ///< magnitude (C arrays: far cheaper than std::array in constant evaluation)
  int size = 0;             ///< limbs in use; limb[size - 1] != 0 unless the value is 0
  bool negative = false;    ///< never true for zero

  constexpr big_int() = default;
  /// Any 64-bit integer; implicit, so that mixed arithmetic reads naturally.
  constexpr big_int(std::int64_t v) {  // NOLINT(google-explicit-constructor)
    const std::uint64_t mag = v < 0 ? std::uint64_t(0) - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    limb[0] = static_cast<std::uint32_t>(mag);
    limb[1] = static_cast<std::uint32_t>(mag >> 32);
    size = limb[1] != 0 ? 2 : (limb[0] != 0 ? 1 : 0);
    negative = v < 0;
  }

  constexpr bool is_zero() const { return size == 0; }
  constexpr int sign() const { return size == 0 ? 0 : (negative ? -1 : 1); }

  /// True when the value is an int64 (INT64_MIN excluded, like geomint::rational).
  constexpr bool fits_int64() const {
    if (size > 2) return false;
    const std::uint64_t mag = magnitude64();
    return mag <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  }
  /// Checked narrowing to int64; throws std::overflow_error when it does not fit.
  constexpr std::int64_t to_int64() const {
    if (!fits_int64()) throw std::overflow_error("geomint::big_int: value does not fit in int64");
    const auto mag = static_cast<std::int64_t>(magnitude64());
    return negative ? -mag : mag;
  }

  /// Decimal representation (run time).
  std::string str() const {
    if (size == 0) return "0";
    std::string digits;
    big_int rest = *this;
    rest.negative = false;
    while (!rest.is_zero()) {
      std::uint32_t chunk = 0;
      rest = rest.divide_small(1000000000U, chunk);
      for (int d = 0; d < 9; ++d) {
        digits.insert(digits.begin(), static_cast<char>('0' + chunk % 10));
        chunk /= 10;
        if (rest.is_zero() && chunk == 0) break;
      }
    }
    return negative ? "-" + digits : digits;
  }
  friend std::ostream& operator<<(std::ostream& os, const big_int& x) { return os << x.str(); }

  // --- magnitude helpers ---------------------------------------------------------------------
  constexpr std::uint64_t magnitude64() const {
    return (size > 1 ? static_cast<std::uint64_t>(limb[1]) << 32 : 0) | (size > 0 ? limb[0] : 0);
  }
  constexpr void normalise() {
    while (size > 0 && limb[size - 1] == 0) --size;
    if (size == 0) negative = false;
  }

  static constexpr int compare_magnitude(const big_int& a, const big_int& b) {
    if (a.size != b.size) return a.size < b.size ? -1 : 1;
    for (int i = a.size - 1; i >= 0; --i) {
      const int k = i;
      if (a.limb[k] != b.limb[k]) return a.limb[k] < b.limb[k] ? -1 : 1;
    }
    return 0;
  }
  /// |a| + |b| (non-negative).
  static constexpr big_int add_magnitude(const big_int& a, const big_int& b) {
    big_int r;
    const int n = a.size > b.size ? a.size : b.size;
    std::uint64_t carry = 0;
    for (int i = 0; i < n; ++i) {
      const int k = i;
      carry += static_cast<std::uint64_t>(a.limb[k]) + b.limb[k];
      r.limb[k] = static_cast<std::uint32_t>(carry);
      carry >>= 32;
    }
    r.size = n;
    if (carry != 0) {
      if (n == L) throw std::overflow_error("geomint::big_int overflow");
      r.limb[n] = static_cast<std::uint32_t>(carry);
      r.size = n + 1;
    }
    return r;
  }
  /// |a| - |b| for |a| >= |b| (non-negative).
  static constexpr big_int subtract_magnitude(const big_int& a, const big_int& b) {
    big_int r;
    std::int64_t borrow = 0;
    for (int i = 0; i < a.size; ++i) {
      const int k = i;
      std::int64_t t = static_cast<std::int64_t>(a.limb[k]) - b.limb[k] - borrow;
      borrow = t < 0 ? 1 : 0;
      if (t < 0) t += std::int64_t(1) << 32;
      r.limb[k] = static_cast<std::uint32_t>(t);
    }
    r.size = a.size;
    r.normalise();
    return r;
  }
  /// |this| / d for a one-limb d; the remainder goes to `remainder`.
  constexpr big_int divide_small(std::uint32_t d, std::uint32_t& remainder) const {
    big_int q;
    std::uint64_t rest = 0;
    for (int i = size - 1; i >= 0; --i) {
      const int k = i;
      rest = (rest << 32) | limb[k];
      q.limb[k] = static_cast<std::uint32_t>(rest / d);
      rest %= d;
    }
    q.size = size;
    q.normalise();
    remainder = static_cast<std::uint32_t>(rest);
    return q;
  }

  // --- arithmetic ----------------------------------------------------------------------------
  constexpr big_int operator-() const {
    big_int r = *this;
    if (r.size != 0) r.negative = !r.negative;
    return r;
  }
  friend constexpr big_int operator+(const big_int& a, const big_int& b) {
    if (a.negative == b.negative) {
      big_int r = add_magnitude(a, b);
      r.negative = a.negative && r.size != 0;
      return r;
    }
    const int c = compare_magnitude(a, b);
    if (c == 0) return big_int();
    big_int r = c > 0 ? subtract_magnitude(a, b) : subtract_magnitude(b, a);
    r.negative = c > 0 ? a.negative : b.negative;
    return r;
  }
  friend constexpr big_int operator-(const big_int& a, const big_int& b) { return a + (-b); }
  friend constexpr big_int operator*(const big_int& a, const big_int& b) {
    if (a.size == 0 || b.size == 0) return big_int();
    if (a.size + b.size - 1 > L) throw std::overflow_error("geomint::big_int overflow");
    // Product digits go straight into the result unless they may need the (L+1)-th limb.
    big_int r;
    std::uint32_t spill[L + 1]{};
    std::uint32_t* w = a.size + b.size <= L ? r.limb : spill;
    for (int i = 0; i < a.size; ++i) {
      std::uint64_t carry = 0;
      const std::uint64_t ai = a.limb[i];
      for (int j = 0; j < b.size; ++j) {
        const int k = i + j;
        carry += w[k] + ai * b.limb[j];  // < 2^64: (2^32-1)^2 + 2 (2^32-1)
        w[k] = static_cast<std::uint32_t>(carry);
        carry >>= 32;
      }
      w[i + b.size] = static_cast<std::uint32_t>(carry);
    }
    int n = a.size + b.size;
    while (n > 0 && w[n - 1] == 0) --n;
    if (n > L) throw std::overflow_error("geomint::big_int overflow");
    if (w == spill)
      for (int i = 0; i < n; ++i) r.limb[i] = spill[i];
    r.size = n;
    r.negative = a.negative != b.negative;
    return r;
  }

  struct division;
  /// Truncated division (like built-in integers): a = q b + r, |r| < |b|, sign(r) = sign(a).
  /// Knuth's algorithm D (TAOCP 4.3.1) on 32-bit digits, as in Hacker's Delight `divmnu`.
  static constexpr division divmod(const big_int& a, const big_int& b);

  friend constexpr big_int operator/(const big_int& a, const big_int& b) { return divmod(a, b).quotient; }
  friend constexpr big_int operator%(const big_int& a, const big_int& b) { return divmod(a, b).remainder; }
  constexpr big_int& operator+=(const big_int& b) { return *this = *this + b; }
  constexpr big_int& operator-=(const big_int& b) { return *this = *this - b; }
  constexpr big_int& operator*=(const big_int& b) { return *this = *this * b; }

  friend constexpr bool operator==(const big_int&, const big_int&) = default;
  friend constexpr std::strong_ordering operator<=>(const big_int& a, const big_int& b) {
    if (a.negative != b.negative) return a.negative ? std::strong_ordering::less : std::strong_ordering::greater;
    const int c = compare_magnitude(a, b);
    const int signed_c = a.negative ? -c : c;
    return signed_c < 0 ? std::strong_ordering::less
                        : (signed_c > 0 ? std::strong_ordering::greater : std::strong_ordering::equal);
  }

  // Hidden friends (found by argument-dependent lookup only, so that they never shadow other
  // abs/gcd overloads in geomint::detail).
  friend constexpr big_int abs(big_int x) {
    x.negative = false;
    return x;
  }
  /// gcd(|a|, |b|) >= 0 (Euclid); gcd(0, 0) = 0.
  friend constexpr big_int gcd(big_int a, big_int b) {
    a.negative = false;
    b.negative = false;
    while (!b.is_zero()) {
      big_int r = divmod(a, b).remainder;
      a = b;
      b = r;
    }
    return a;
  }
};

template <int L>
struct big_int<L>::division {
  big_int quotient;
  big_int remainder;
};

template <int L>
constexpr typename big_int<L>::division big_int<L>::divmod(const big_int& a, const big_int& b) {
  if (b.is_zero()) throw std::domain_error("geomint::big_int: division by zero");
  division out;
  if (compare_magnitude(a, b) < 0) {
    out.remainder = a;
    return out;
  }
  if (b.size == 1) {
    std::uint32_t rest = 0;
    out.quotient = a.divide_small(b.limb[0], rest);
    out.remainder = big_int(static_cast<std::int64_t>(rest));
  } else {
    constexpr std::uint64_t base = std::uint64_t(1) << 32;
    const int m = a.size;
    const int n = b.size;
    const int s = std::countl_zero(b.limb[n - 1]);  // normalise: top bit of v set
    std::uint32_t vn[L]{};
    std::uint32_t un[L + 1]{};
    for (int i = n - 1; i > 0; --i)
      vn[i] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(b.limb[i]) << s) |
                                         (static_cast<std::uint64_t>(b.limb[i - 1]) >> (32 - s)));
    vn[0] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(b.limb[0]) << s);
    un[m] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(a.limb[m - 1]) >> (32 - s));
    for (int i = m - 1; i > 0; --i)
      un[i] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(a.limb[i]) << s) |
                                         (static_cast<std::uint64_t>(a.limb[i - 1]) >> (32 - s)));
    un[0] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(a.limb[0]) << s);
    for (int j = m - n; j >= 0; --j) {
      const std::uint64_t top = (static_cast<std::uint64_t>(un[j + n]) << 32) | un[j + n - 1];
      std::uint64_t qhat = top / vn[n - 1];
      std::uint64_t rhat = top % vn[n - 1];
      while (qhat >= base || qhat * vn[n - 2] > ((rhat << 32) | un[j + n - 2])) {
        --qhat;
        rhat += vn[n - 1];
        if (rhat >= base) break;
      }
      std::int64_t borrow = 0;
      std::int64_t t = 0;
      for (int i = 0; i < n; ++i) {
        const std::uint64_t p = qhat * vn[i];
        t = static_cast<std::int64_t>(un[i + j]) - borrow - static_cast<std::int64_t>(p & 0xFFFFFFFFU);
        un[i + j] = static_cast<std::uint32_t>(t);
        borrow = static_cast<std::int64_t>(p >> 32) - (t >> 32);
      }
      t = static_cast<std::int64_t>(un[j + n]) - borrow;
      un[j + n] = static_cast<std::uint32_t>(t);
      if (t < 0) {  // qhat was one too large: add v back
        --qhat;
        std::uint64_t carry = 0;
        for (int i = 0; i < n; ++i) {
          carry += static_cast<std::uint64_t>(un[i + j]) + vn[i];
          un[i + j] = static_cast<std::uint32_t>(carry);
          carry >>= 32;
        }
        un[j + n] = static_cast<std::uint32_t>(un[j + n] + carry);
      }
      out.quotient.limb[j] = static_cast<std::uint32_t>(qhat);
    }
    out.quotient.size = m - n + 1;
    out.quotient.normalise();
    for (int i = 0; i < n; ++i)
      out.remainder.limb[i] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(un[i]) >> s) |
                                                         ((static_cast<std::uint64_t>(un[i + 1]) << (32 - s)) & 0xFFFFFFFFU));
    out.remainder.size = n;
    out.remainder.normalise();
  }
  out.quotient.negative = (a.negative != b.negative) && !out.quotient.is_zero();
  out.remainder.negative = a.negative && !out.remainder.is_zero();
  return out;
}

/// a / b when b divides a; otherwise throws std::domain_error.
template <int L>
constexpr big_int<L> exact_quotient(const big_int<L>& a, const big_int<L>& b) {
  const auto d = big_int<L>::divmod(a, b);
  if (!d.remainder.is_zero()) throw std::domain_error("geomint::big_int: inexact division");
  return d.quotient;
}

// ---------------------------------------------------------------------------------------------
// Exact big rationals: always reduced, positive denominator (structural).
// ---------------------------------------------------------------------------------------------

template <int L>
struct big_rational {
  big_int<L> num{};
  big_int<L> den{1};

  constexpr big_rational() = default;
  constexpr big_rational(std::int64_t n) : num(n) {}  // NOLINT(google-explicit-constructor)
  constexpr big_rational(const rational& r) : num(r.num), den(r.den) {}  // NOLINT(google-explicit-constructor)
  constexpr big_rational(const big_int<L>& n, const big_int<L>& d) : num(n), den(d) {
    if (den.is_zero()) throw std::domain_error("geomint::big_rational: zero denominator");
    if (den.negative) {
      num = -num;
      den = -den;
    }
    const big_int<L> g = gcd(num, den);
    if (!(g == big_int<L>(1)) && !g.is_zero()) {
      num = exact_quotient(num, g);
      den = exact_quotient(den, g);
    }
  }

  /// True when numerator and denominator fit geomint::rational (64 bits each).
  constexpr bool fits_rational() const { return num.fits_int64() && den.fits_int64(); }
  /// Checked conversion; throws std::overflow_error when it does not fit.
  constexpr rational to_rational() const { return rational(num.to_int64(), den.to_int64()); }
  constexpr int sign() const { return num.sign(); }

  std::string str() const { return den == big_int<L>(1) ? num.str() : num.str() + "/" + den.str(); }
  friend std::ostream& operator<<(std::ostream& os, const big_rational& x) { return os << x.str(); }

  friend constexpr big_rational operator-(big_rational a) {
    a.num = -a.num;
    return a;
  }
  friend constexpr big_rational operator+(const big_rational& a, const big_rational& b) {
    return big_rational(a.num * b.den + b.num * a.den, a.den * b.den);
  }
  friend constexpr big_rational operator-(const big_rational& a, const big_rational& b) { return a + (-b); }
  friend constexpr big_rational operator*(const big_rational& a, const big_rational& b) {
    return big_rational(a.num * b.num, a.den * b.den);
  }
  friend constexpr big_rational operator/(const big_rational& a, const big_rational& b) {
    if (b.num.is_zero()) throw std::domain_error("geomint::big_rational: division by zero");
    return big_rational(a.num * b.den, a.den * b.num);
  }

  /// Reduced form makes member-wise equality exact equality.
  friend constexpr bool operator==(const big_rational&, const big_rational&) = default;
  friend constexpr std::strong_ordering operator<=>(const big_rational& a, const big_rational& b) {
    return a.num * b.den <=> b.num * a.den;
  }
  /// Comparison with geomint::rational (exact, whatever the sizes).
  friend constexpr bool operator==(const big_rational& a, const rational& b) { return a == big_rational(b); }
  friend constexpr std::strong_ordering operator<=>(const big_rational& a, const rational& b) {
    return a <=> big_rational(b);
  }
  friend constexpr bool operator==(const big_rational& a, std::int64_t b) { return a == big_rational(b); }
  friend constexpr std::strong_ordering operator<=>(const big_rational& a, std::int64_t b) {
    return a <=> big_rational(b);
  }
};

// ---------------------------------------------------------------------------------------------
// Polynomials over Z with big coefficients, degree <= D.
// ---------------------------------------------------------------------------------------------

template <int L, int D>
struct zpoly {
  big_int<L> c[D + 1]{};
  int degree = -1;  ///< -1 for the zero polynomial

  constexpr zpoly() = default;
  constexpr explicit zpoly(const big_int<L>& constant) {
    c[0] = constant;
    trim();
  }
  constexpr void trim() {
    degree = D;
    while (degree >= 0 && c[degree].is_zero()) --degree;
  }
  constexpr const big_int<L>& operator[](int k) const { return c[k]; }
  constexpr big_int<L>& operator[](int k) { return c[k]; }
  constexpr bool is_zero() const { return degree < 0; }
  constexpr const big_int<L>& lead() const { return (*this)[degree]; }

  friend constexpr zpoly operator+(const zpoly& a, const zpoly& b) {
    zpoly r;
    const int n = a.degree > b.degree ? a.degree : b.degree;
    for (int k = 0; k <= n; ++k) r[k] = a[k] + b[k];
    r.trim();
    return r;
  }
  friend constexpr zpoly operator-(const zpoly& a, const zpoly& b) {
    zpoly r;
    const int n = a.degree > b.degree ? a.degree : b.degree;
    for (int k = 0; k <= n; ++k) r[k] = a[k] - b[k];
    r.trim();
    return r;
  }
  friend constexpr zpoly operator*(const zpoly& a, const zpoly& b) {
    zpoly r;
    if (a.is_zero() || b.is_zero()) return r;
    if (a.degree + b.degree > D) throw std::overflow_error("geomint::detail::zpoly: degree overflow");
    for (int i = 0; i <= a.degree; ++i) {
      if (a[i].is_zero()) continue;
      for (int j = 0; j <= b.degree; ++j) r[i + j] += a[i] * b[j];
    }
    r.trim();
    return r;
  }
  friend constexpr zpoly operator*(const big_int<L>& k, zpoly a) {
    for (int i = 0; i <= a.degree; ++i) a[i] = k * a[i];
    a.trim();
    return a;
  }
  friend constexpr bool operator==(const zpoly&, const zpoly&) = default;
};

/// a / b when b divides a in Z[s] (long division from the top); otherwise throws.
template <int L, int D>
constexpr zpoly<L, D> exact_quotient(zpoly<L, D> a, const zpoly<L, D>& b) {
  if (b.is_zero()) throw std::domain_error("geomint::detail::zpoly: division by zero");
  zpoly<L, D> q;
  for (int k = a.degree - b.degree; k >= 0; --k) {
    const big_int<L> t = exact_quotient(a[k + b.degree], b.lead());
    q[k] = t;
    if (t.is_zero()) continue;
    for (int j = 0; j <= b.degree; ++j) a[k + j] -= t * b[j];
  }
  a.trim();
  if (!a.is_zero()) throw std::domain_error("geomint::detail::zpoly: inexact division");
  q.trim();
  return q;
}

/// gcd of the coefficients (content), >= 0.
template <int L, int D>
constexpr big_int<L> content(const zpoly<L, D>& a) {
  big_int<L> g;
  for (int k = 0; k <= a.degree; ++k) g = gcd(g, a[k]);
  return g;
}

template <int L, int D>
constexpr zpoly<L, D> primitive_part(zpoly<L, D> a) {
  if (a.is_zero()) return a;
  const big_int<L> g = content(a);
  for (int k = 0; k <= a.degree; ++k) a[k] = exact_quotient(a[k], g);
  return a;
}

/// a mod p for a one-limb prime p, in [0, p).
template <int L>
constexpr std::uint64_t residue(const big_int<L>& a, std::uint32_t p) {
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
constexpr int gcd_degree_mod(const zpoly<L, D>& a, const zpoly<L, D>& b, std::uint32_t p) {
  std::uint64_t u[D + 1]{}, v[D + 1]{};
  auto reduce = [&](const zpoly<L, D>& x, std::uint64_t (&out)[D + 1]) {
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
constexpr zpoly<L, D> polynomial_gcd(const zpoly<L, D>& a, const zpoly<L, D>& b) {
  for (std::uint32_t p : {2147483647U, 2147483629U, 2147483587U}) {
    if (residue(a.lead(), p) == 0 || residue(b.lead(), p) == 0) continue;
    if (gcd_degree_mod(a, b, p) == 0) return zpoly<L, D>(big_int<L>(1));
    break;
  }
  zpoly<L, D> u = primitive_part(a), v = primitive_part(b);
  if (u.degree < v.degree) std::swap(u, v);
  while (!v.is_zero()) {
    // pseudo-remainder: lead(v)^(deg u - deg v + 1) u mod v, exact in Z[s]
    zpoly<L, D> r = u;
    while (!r.is_zero() && r.degree >= v.degree) {
      const int shift = r.degree - v.degree;
      const big_int<L> f = r.lead();
      r = v.lead() * r;
      for (int j = 0; j <= v.degree; ++j) r[shift + j] -= f * v[j];
      r.trim();
    }
    u = v;
    v = primitive_part(r);
  }
  if (u.lead().negative) u = big_int<L>(-1) * u;
  return u;
}

// ---------------------------------------------------------------------------------------------
// The scheme's R = P / Q from the momentum coefficients A, B; reduction; error series.
// ---------------------------------------------------------------------------------------------

/// Limbs of the elimination and of the leading error coefficient: 384 bits. The largest
/// intermediate (m = 8) has 199 bits.
inline constexpr int exact_limbs = 12;

}  // namespace detail

/// The exact leading error coefficient: a reduced big rational (to_string: `str()`), comparable
/// with geomint::rational.
using exact_rational = detail::big_rational<detail::exact_limbs>;

/// x^{k+1} = R(tau) x^k - x^{k-1} for L = xdot^2/2 - x^2/2 (eq. 15), R = P(s)/Q(s), s = tau^2,
/// in lowest terms (gcd(P, Q) = 1 in Z[s], integer content 1, Q(0) > 0), and its local error
/// R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4)), so the scheme has order p. Structural.
struct exact_two_step_scheme {
  static constexpr int capacity = max_exact_m + 1;
  int m = 0;  ///< interpolation degree of the LPF scheme; 0 for the midpoint VI (17)
  int numerator_degree = -1;
  int denominator_degree = -1;
  std::array<std::int64_t, capacity> numerator{};    ///< P, ascending powers of s = tau^2
  std::array<std::int64_t, capacity> denominator{};  ///< Q, ascending powers of s = tau^2
  int order = 0;                                     ///< p
  exact_rational leading_coefficient{};              ///< c

  /// Power of tau in the leading error term: p + 2.
  constexpr int leading_power() const { return order + 2; }

  /// R(tau) in T (Horner in s; one conversion per integer coefficient).
  template <class T>
  constexpr T R(const T& tau) const {
    const T s = tau * tau;
    T p(0), q(0);
    for (int k = numerator_degree; k >= 0; --k) p = p * s + T(numerator[static_cast<std::size_t>(k)]);
    for (int k = denominator_degree; k >= 0; --k) q = q * s + T(denominator[static_cast<std::size_t>(k)]);
    return p / q;
  }

  friend constexpr bool operator==(const exact_two_step_scheme&, const exact_two_step_scheme&) = default;
};

namespace detail {

template <int D>
using exact_poly = zpoly<exact_limbs, D>;

/// n! as a big integer.
constexpr big_int<exact_limbs> big_factorial(int n) {
  big_int<exact_limbs> f(1);
  for (int k = 2; k <= n; ++k) f *= big_int<exact_limbs>(k);
  return f;
}

/// Reduces R = -2 B / A, narrows it to int64 coefficients and expands R - 2 cos(tau).
template <int D>
constexpr exact_two_step_scheme finish_two_step(int m, const exact_poly<D>& A, const exact_poly<D>& B) {
  using big = big_int<exact_limbs>;
  exact_poly<D> P = big(-2) * B;
  exact_poly<D> Q = A;
  if (Q.is_zero()) throw std::domain_error("geomint::exact_two_step: degenerate scheme (A = 0)");
  const exact_poly<D> G = polynomial_gcd(P, Q);
  if (G.degree > 0) {
    P = exact_quotient(P, G);
    Q = exact_quotient(Q, G);
  }
  const big g = gcd(content(P), content(Q));
  for (int k = 0; k <= P.degree; ++k) P[k] = exact_quotient(P[k], g);
  for (int k = 0; k <= Q.degree; ++k) Q[k] = exact_quotient(Q[k], g);
  if (Q[0].is_zero()) throw std::domain_error("geomint::exact_two_step: R has a pole at tau = 0");
  if (Q[0].negative) {
    P = big(-1) * P;
    Q = big(-1) * Q;
  }

  exact_two_step_scheme out;
  out.m = m;
  if (P.degree >= exact_two_step_scheme::capacity || Q.degree >= exact_two_step_scheme::capacity)
    throw std::overflow_error("geomint::exact_two_step: degree exceeds the result's capacity");
  out.numerator_degree = P.degree;
  out.denominator_degree = Q.degree;
  for (int k = 0; k <= P.degree; ++k) out.numerator[static_cast<std::size_t>(k)] = P[k].to_int64();
  for (int k = 0; k <= Q.degree; ++k) out.denominator[static_cast<std::size_t>(k)] = Q[k].to_int64();

  // R - 2 cos = (P - Q C) / Q with C = 2 cos(tau) = sum_k 2 (-1)^k s^k / (2k)!. The coefficient
  // of s^k of (P - Q C) times (2k)! is the integer
  //   E_k = (2k)! P_k - sum_i Q_i 2 (-1)^(k-i) (2k)! / (2(k-i))!.
  // P - Q C cannot vanish beyond s^(deg P + deg Q + 1) (else P/Q = 2 cos), so that bounds the
  // search; the first nonzero E_j gives c = E_j / ((2j)! Q_0) and p = 2j - 2.
  const int last = P.degree + Q.degree + 1;
  for (int k = 0; k <= last; ++k) {
    big E = k <= P.degree ? big_factorial(2 * k) * P[k] : big(0);
    for (int i = 0; i <= k && i <= Q.degree; ++i) {
      big ratio(2);  // 2 (2k)! / (2(k-i))!
      for (int f = 2 * (k - i) + 1; f <= 2 * k; ++f) ratio *= big(f);
      if ((k - i) % 2 == 0) E -= Q[i] * ratio;
      else E += Q[i] * ratio;
    }
    if (!E.is_zero()) {
      out.order = 2 * k - 2;
      out.leading_coefficient = exact_rational(E, big_factorial(2 * k) * Q[0]);
      return out;
    }
  }
  throw std::domain_error("geomint::exact_two_step: R(tau) - 2 cos(tau) has no nonzero term");
}

/// LCM of the denominators of a range of rationals (int64; the weights for m <= 8 are small).
template <class Range>
constexpr std::int64_t denominator_lcm(const Range& values) {
  std::int64_t l = 1;
  for (const rational& v : values) l = l / gcd64(l, v.den) * v.den;
  return l;
}

/// The LPF derivation (eqs. 10-12 on the harmonic oscillator): see the header comment.
template <int M, class Family>
constexpr exact_two_step_scheme lpf_two_step() {
  using big = big_int<exact_limbs>;
  constexpr int D = 2 * M;  // Bareiss products of k-minors have degree <= 2(m-1)
  using poly = exact_poly<D>;
  const auto D1 = differentiation_weights<1, Family, M, rational>();
  const auto D2 = differentiation_weights<2, Family, M, rational>();

  // Integer scales: the interior rows of D2 by L2, the momentum row D1[m] by L1; both bordered
  // determinants get the same factor L2^(m-1) L1, which cancels in R.
  std::int64_t L2 = 1;
  for (int i = 1; i < M; ++i) L2 = L2 / gcd64(L2, denominator_lcm(D2[static_cast<std::size_t>(i)])) *
                                   denominator_lcm(D2[static_cast<std::size_t>(i)]);
  const std::int64_t L1 = denominator_lcm(D1[static_cast<std::size_t>(M)]);
  auto integer = [](const rational& v, std::int64_t scale) {
    const rational scaled = v * rational(scale);
    if (scaled.den != 1) throw std::logic_error("geomint::exact_two_step: weight scaling is not integral");
    return scaled.num;
  };
  // The start momentum is -(B X_0 + A X_m) only for nodes symmetric about 1/2.
  const auto c = nodes<Family, M, rational>();
  for (int i = 0; i <= M; ++i)
    if (c[static_cast<std::size_t>(i)] + c[static_cast<std::size_t>(M - i)] != rational(1))
      throw std::logic_error("geomint::exact_two_step: the derivation needs nodes symmetric about 1/2");

  // Rows 0..m-2: interior nodes 1..m-1; row m-1: the end momentum. Columns 0..m-2: interior
  // nodes; column m-1: node 0; column m: node m.
  poly a[M][M + 1]{};
  auto node_of_column = [](int col) { return col < M - 1 ? col + 1 : (col == M - 1 ? 0 : M); };
  for (int row = 0; row < M - 1; ++row)
    for (int col = 0; col <= M; ++col) {
      const int i = row + 1, j = node_of_column(col);
      poly& e = a[row][col];
      e[0] = big(integer(D2[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], L2));
      if (i == j) e[1] = big(L2);  // + s X_i (the potential's force, times tau^2)
      e.trim();
    }
  for (int col = 0; col <= M; ++col) {
    poly& e = a[M - 1][col];
    e[0] = big(integer(D1[static_cast<std::size_t>(M)][static_cast<std::size_t>(node_of_column(col))], L1));
    e.trim();
  }

  // Fraction-free elimination (Bareiss): after step k the entry (i, j) is the minor on rows
  // 0..k, i and columns 0..k, j. The pivots are the leading principal minors of M(s), whose
  // leading term is (L2 s)^(k+1), so none vanishes and the divisions are exact.
  poly previous(big(1));
  for (int k = 0; k < M - 1; ++k) {
    for (int i = k + 1; i < M; ++i)
      for (int j = k + 1; j <= M; ++j) a[i][j] = exact_quotient(a[k][k] * a[i][j] - a[i][k] * a[k][j], previous);
    previous = a[k][k];
  }
  // A det M = det(bordered with column 0), B det M = det(bordered with column m).
  const poly& A = a[M - 1][M - 1];
  const poly& B = a[M - 1][M];
  return finish_two_step<D>(M, A, B);
}

/// The midpoint VI (scheme 17): L_d(x0, x1) = tau L(x(1/2), x'(1/2)) on the linear path
/// x(c) = (1 - c) x0 + c x1. Its end momentum (times tau) is
///   A x0 + B x1,  A = phi0'(b) phi1'(b) - s phi0(b) phi1(b),  B = phi1'(b)^2 - s phi1(b)^2,
/// at b = 1/2 with phi0 = 1 - c, phi1 = c; scaled by 4 to integers.
constexpr exact_two_step_scheme midpoint_two_step() {
  using big = big_int<exact_limbs>;
  using poly = exact_poly<2>;
  const rational b(1, 2), phi0 = rational(1) - b, phi1 = b, dphi0(-1), dphi1(1);
  const rational a0 = dphi0 * dphi1, a1 = -(phi0 * phi1), b0 = dphi1 * dphi1, b1 = -(phi1 * phi1);
  const std::int64_t scale = denominator_lcm(std::array<rational, 4>{a0, a1, b0, b1});
  poly A, B;
  A[0] = big((a0 * rational(scale)).num);
  A[1] = big((a1 * rational(scale)).num);
  B[0] = big((b0 * rational(scale)).num);
  B[1] = big((b1 * rational(scale)).num);
  A.trim();
  B.trim();
  return finish_two_step<2>(0, A, B);
}

}  // namespace detail

/// The LPF scheme's exact two-step form for the harmonic oscillator (eq. 15) on an exact node
/// family: eq. (16) for m = 2, (18) for m = 3, (19) for m = 4 (equispaced), m up to 8.
template <int M, class Family = equispaced>
constexpr exact_two_step_scheme exact_two_step() {
  static_assert(node_family<Family>,
                "geomint::exact_two_step: Family must be a node family (equispaced, gauss_lobatto, ...)");
  static_assert(M >= 2 && M <= max_exact_m, "geomint::exact_two_step: m must be in 2..8");
  if constexpr (node_family<Family>) {
    static_assert(Family::is_rational,
                  "geomint::exact_two_step: the node family must be exact (rational nodes, e.g. equispaced)");
    if constexpr (Family::is_rational && M >= 2 && M <= max_exact_m) return detail::lpf_two_step<M, Family>();
  }
  return {};
}

/// The midpoint variational integrator's exact two-step form: eq. (17), R = (8 - 2s)/(4 + s).
constexpr exact_two_step_scheme exact_midpoint_two_step() { return detail::midpoint_two_step(); }

/// The results as constexpr variables (each evaluated once per program).
template <int M, class Family = equispaced>
inline constexpr exact_two_step_scheme exact_two_step_v = exact_two_step<M, Family>();
inline constexpr exact_two_step_scheme exact_midpoint_two_step_v = exact_midpoint_two_step();

}  // namespace geomint
