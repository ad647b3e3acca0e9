#pragma once
/// Exact rationals with big_integer numerator and denominator, for constant expressions.
///
/// `geomint::big_rational<L>` is always reduced with a positive denominator, so member-wise
/// equality is value equality; it is structural and compares exactly with geomint::rational and
/// with 64-bit integers. Overflow of the underlying big_integer<L> throws (a compile error in a
/// constant expression, never a wrong value).

#include <compare>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>

#include "geomint/core/big_integer.hpp"
#include "geomint/core/rational.hpp"

namespace geomint {

template <int L>
struct big_rational {
  big_integer<L> num{};
  big_integer<L> den{1};

  /// Zero. User-provided (not defaulted): GCC 12 at -O2 zero-fills value-initialised arrays of
  /// a class with a defaulted constructor instead of applying den{1}.
  constexpr big_rational() : num(), den(1) {}
  constexpr big_rational(std::int64_t n) : num(n) {}  // NOLINT(google-explicit-constructor)
  constexpr big_rational(const rational& r) : num(r.num), den(r.den) {}  // NOLINT(google-explicit-constructor)
  constexpr big_rational(const big_integer<L>& n, const big_integer<L>& d) : num(n), den(d) {
    if (den.is_zero()) throw std::domain_error("geomint::big_rational: zero denominator");
    if (den.negative) {
      num = -num;
      den = -den;
    }
    const big_integer<L> g = gcd(num, den);
    if (!(g == big_integer<L>(1)) && !g.is_zero()) {
      num = exact_quotient(num, g);
      den = exact_quotient(den, g);
    }
  }

  /// True when numerator and denominator fit geomint::rational (64 bits each).
  constexpr bool fits_rational() const { return num.fits_int64() && den.fits_int64(); }
  /// Checked conversion; throws std::overflow_error when it does not fit.
  constexpr rational to_rational() const { return rational(num.to_int64(), den.to_int64()); }
  constexpr int sign() const { return num.sign(); }

  std::string str() const { return den == big_integer<L>(1) ? num.str() : num.str() + "/" + den.str(); }
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

}  // namespace geomint
