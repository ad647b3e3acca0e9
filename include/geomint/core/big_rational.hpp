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
  big_integer<L> num;            ///< numerator
  big_integer<L> den_minus_one;  ///< denominator - 1 (>= 0)

  /// The denominator is stored minus one so that the all-zero object is the value 0 = 0/1:
  /// zero-, value- and default-initialisation agree bit for bit, and no compiler path that
  /// zero-fills an array of exact numbers can produce 0/0. (GCC 12 does zero-fill: it folds the
  /// default-initialisation of a local array of a class whose constexpr constructor sets a
  /// nonzero member into a memset plus a constructor loop over the first elements only, and in
  /// constant evaluation a copied element of a partly assigned value-initialised array came out
  /// zero-filled; with a denominator stored as is, both read as 0/0.)
  constexpr big_rational() = default;
  constexpr big_rational(std::int64_t n) : num(n), den_minus_one() {}  // NOLINT(google-explicit-constructor)
  constexpr big_rational(const rational& r)  // NOLINT(google-explicit-constructor)
      : num(r.num), den_minus_one(big_integer<L>(r.den) - big_integer<L>(1)) {}
  constexpr big_rational(const big_integer<L>& n, const big_integer<L>& d) : num(n), den_minus_one() {
    if (d.is_zero()) throw std::domain_error("geomint::big_rational: zero denominator");
    big_integer<L> den = d;
    if (den.negative) {
      num = -num;
      den = -den;
    }
    const big_integer<L> g = gcd(num, den);
    if (!(g == big_integer<L>(1)) && !g.is_zero()) {
      num = exact_quotient(num, g);
      den = exact_quotient(den, g);
    }
    den_minus_one = den - big_integer<L>(1);
  }

  /// The denominator (> 0).
  constexpr big_integer<L> den() const { return den_minus_one + big_integer<L>(1); }
  /// True for an integer (denominator 1).
  constexpr bool is_integer() const { return den_minus_one.is_zero(); }

  /// True when numerator and denominator fit geomint::rational (64 bits each).
  constexpr bool fits_rational() const { return num.fits_int64() && den().fits_int64(); }
  /// Checked conversion; throws std::overflow_error when it does not fit.
  constexpr rational to_rational() const { return rational(num.to_int64(), den().to_int64()); }
  constexpr int sign() const { return num.sign(); }

  std::string str() const { return is_integer() ? num.str() : num.str() + "/" + den().str(); }
  friend std::ostream& operator<<(std::ostream& os, const big_rational& x) { return os << x.str(); }

  friend constexpr big_rational operator-(big_rational a) {
    a.num = -a.num;
    return a;
  }
  friend constexpr big_rational operator+(const big_rational& a, const big_rational& b) {
    if (a.num.is_zero()) return copy_of(b);
    if (b.num.is_zero()) return copy_of(a);
    if (a.is_integer() && b.is_integer()) return from_integer(a.num + b.num);
    const big_integer<L> da = a.den(), db = b.den();
    return big_rational(a.num * db + b.num * da, da * db);
  }
  /// a - b without a copy of b: GCC 12 treats a by-value copy of a subobject of a constexpr
  /// variable, modified in the callee, as a modification of that variable ("modification of
  /// 'x' is not a constant expression").
  friend constexpr big_rational operator-(const big_rational& a, const big_rational& b) {
    if (b.num.is_zero()) return copy_of(a);
    if (a.is_integer() && b.is_integer()) return from_integer(a.num - b.num);
    const big_integer<L> da = a.den(), db = b.den();
    return big_rational(a.num * db - b.num * da, da * db);
  }
  friend constexpr big_rational operator*(const big_rational& a, const big_rational& b) {
    if (a.num.is_zero() || b.num.is_zero()) return big_rational();
    if (a.is_integer() && b.is_integer()) return from_integer(a.num * b.num);
    return big_rational(a.num * b.num, a.den() * b.den());
  }
  friend constexpr big_rational operator/(const big_rational& a, const big_rational& b) {
    if (b.num.is_zero()) throw std::domain_error("geomint::big_rational: division by zero");
    return big_rational(a.num * b.den(), a.den() * b.num);
  }
  constexpr big_rational& operator+=(const big_rational& b) { return *this = *this + b; }
  constexpr big_rational& operator-=(const big_rational& b) { return *this = *this - b; }
  constexpr big_rational& operator*=(const big_rational& b) { return *this = *this * b; }
  constexpr big_rational& operator/=(const big_rational& b) { return *this = *this / b; }

  /// Reduced form makes member-wise equality exact equality.
  friend constexpr bool operator==(const big_rational&, const big_rational&) = default;
  friend constexpr std::strong_ordering operator<=>(const big_rational& a, const big_rational& b) {
    return a.num * b.den() <=> b.num * a.den();
  }
  /// x, member by member into a new object: GCC 12 takes a returned copy of a subobject of a
  /// constexpr variable, later assigned to, for a modification of that variable.
  static constexpr big_rational copy_of(const big_rational& x) {
    big_rational r;
    r.num = x.num;
    r.den_minus_one = x.den_minus_one;
    return r;
  }
  /// An integer n as n/1 (no reduction needed).
  static constexpr big_rational from_integer(const big_integer<L>& n) {
    big_rational r;
    r.num = n;
    return r;
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
