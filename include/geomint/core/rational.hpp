#pragma once
/// Exact rational numbers for constant expressions.
///
/// `geomint::rational` is a structural literal type (usable as a template argument), always
/// reduced with a positive denominator. Numerator and denominator are 64-bit; every operation
/// computes in 128-bit intermediates, reduces, and then checks that the result fits. Overflow
/// throws `std::overflow_error`: at run time that is an exception, in a constant expression it
/// is a compile error, never a wrong value.

#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "geomint/core/scalar_traits.hpp"

namespace geomint {

namespace core::detail {
__extension__ using int128 = __int128;

constexpr int128 abs128(int128 x) { return x < 0 ? -x : x; }

/// gcd of two 64-bit values (>= 1 unless both are 0); a reduced rational never holds INT64_MIN.
constexpr std::int64_t gcd64(std::int64_t a, std::int64_t b) {
  a = a < 0 ? -a : a;
  b = b < 0 ? -b : b;
  while (b != 0) {
    const std::int64_t r = a % b;
    a = b;
    b = r;
  }
  return a == 0 ? 1 : a;
}

constexpr int128 gcd128(int128 a, int128 b) {
  a = abs128(a);
  b = abs128(b);
  while (b != 0) {
    const int128 r = a % b;
    a = b;
    b = r;
  }
  return a;
}

/// Product a*b in 128 bits; overflow of the 128-bit product itself also throws.
constexpr int128 mul128(int128 a, int128 b) {
  int128 out = 0;
  if (__builtin_mul_overflow(a, b, &out)) throw std::overflow_error("geomint::rational overflow");
  return out;
}

constexpr int128 add128(int128 a, int128 b) {
  int128 out = 0;
  if (__builtin_add_overflow(a, b, &out)) throw std::overflow_error("geomint::rational overflow");
  return out;
}
}  // namespace core::detail

struct rational {
  std::int64_t num = 0;  ///< numerator, carries the sign
  std::int64_t den = 1;  ///< denominator, always > 0; gcd(num, den) = 1

  constexpr rational() = default;
  /// An integer of any integer type; implicit so that `rational r = 3;` and mixed arithmetic
  /// read naturally. Values outside -(2^63 - 1) .. 2^63 - 1 (INT64_MIN, or an unsigned value
  /// above INT64_MAX) throw std::overflow_error (a compile error in a constant expression):
  /// -INT64_MIN is not representable, so the negation and abs of such a value could not be exact.
  template <std::integral Int>
    requires(!std::is_same_v<Int, bool>)
  constexpr rational(Int n) {  // NOLINT(google-explicit-constructor)
    *this = narrow(static_cast<core::detail::int128>(n), 1);
  }
  /// n/d for integers of any integer types, reduced; d = 0 throws std::domain_error and a
  /// reduced value outside the 64-bit range throws std::overflow_error (compile errors in a
  /// constant expression).
  template <std::integral N, std::integral D>
    requires(!std::is_same_v<N, bool> && !std::is_same_v<D, bool>)
  constexpr rational(N n, D d) {
    *this = from_wide(static_cast<core::detail::int128>(n), static_cast<core::detail::int128>(d));
  }
  /// No conversion from floating point: `rational r = 0.5;` does not compile (it would have
  /// converted 0.5 to the integer 0). Write rational(1, 2), or from_double() for the exact
  /// value of a double.
  template <std::floating_point F>
  rational(F) = delete;
  template <class A, class B>
    requires(std::floating_point<A> || std::floating_point<B>)
  rational(A, B) = delete;

  /// The exact value of a finite double (a dyadic rational m 2^e), when it fits in 64 bits;
  /// std::overflow_error otherwise (e.g. 1e300 or 2^-70), std::domain_error for NaN or infinity.
  static constexpr rational from_double(double x) {
    if (!(x - x == 0.0)) throw std::domain_error("geomint::rational::from_double: not a finite number");
    if (x == 0.0) return rational();
    // x = mantissa * 2^exponent with an odd-or-zero-trailing integer mantissa (|mantissa| < 2^53).
    const bool negative = x < 0;
    double m = negative ? -x : x;
    int exponent = 0;
    while (m >= 9007199254740992.0) {  // 2^53: halving is exact in this range
      m /= 2;
      ++exponent;
      if (exponent > 62) throw std::overflow_error("geomint::rational overflow");
    }
    while (m != static_cast<double>(static_cast<std::int64_t>(m))) {  // doubling is exact
      m *= 2;
      --exponent;
      if (exponent < -62) throw std::overflow_error("geomint::rational overflow");
    }
    core::detail::int128 n = static_cast<std::int64_t>(m), d = 1;
    for (; exponent > 0; --exponent) n *= 2;
    for (; exponent < 0; ++exponent) d *= 2;
    return from_wide(negative ? -n : n, d);
  }

  /// A fraction already in lowest terms with a positive denominator; checks that it fits.
  static constexpr rational narrow(core::detail::int128 n, core::detail::int128 d) {
    constexpr core::detail::int128 lo = std::numeric_limits<std::int64_t>::min() + 1;
    constexpr core::detail::int128 hi = std::numeric_limits<std::int64_t>::max();
    if (n < lo || n > hi || d > hi) throw std::overflow_error("geomint::rational overflow");
    rational r;
    r.num = static_cast<std::int64_t>(n);
    r.den = static_cast<std::int64_t>(d);
    return r;
  }

  /// Reduces a 128-bit fraction and checks that it fits in 64 bits.
  static constexpr rational from_wide(core::detail::int128 n, core::detail::int128 d) {
    if (d == 0) throw std::domain_error("geomint::rational: zero denominator");
    if (d < 0) {
      n = -n;
      d = -d;
    }
    const core::detail::int128 g = core::detail::gcd128(n, d);
    if (g > 1) {
      n /= g;
      d /= g;
    }
    return narrow(n, d);
  }

  constexpr rational operator-() const {
    rational r;
    r.num = -num;  // num > INT64_MIN always (narrow), so this cannot overflow
    r.den = den;
    return r;
  }
  constexpr rational operator+() const { return *this; }

  /// With g = gcd(d1, d2): n1/d1 + n2/d2 = (n1 (d2/g) + n2 (d1/g)) / (d1 d2 / g), and only
  /// gcd(numerator, g) can remain to cancel (Knuth, TAOCP 4.5.1).
  friend constexpr rational operator+(rational a, rational b) {
    const std::int64_t g = core::detail::gcd64(a.den, b.den);
    const core::detail::int128 numerator =
        core::detail::add128(core::detail::mul128(a.num, b.den / g), core::detail::mul128(b.num, a.den / g));
    const core::detail::int128 denominator = core::detail::mul128(a.den / g, b.den);
    if (g == 1) return narrow(numerator, denominator);
    return from_wide(numerator, denominator);
  }
  friend constexpr rational operator-(rational a, rational b) { return a + (-b); }
  /// Cross-cancellation first (Knuth, TAOCP 4.5.1): the product of reduced fractions
  /// n1 n2 / (d1 d2) is reduced once gcd(n1, d2) and gcd(n2, d1) are divided out.
  friend constexpr rational operator*(rational a, rational b) {
    const std::int64_t g1 = core::detail::gcd64(a.num, b.den);
    const std::int64_t g2 = core::detail::gcd64(b.num, a.den);
    return narrow(core::detail::mul128(a.num / g1, b.num / g2), core::detail::mul128(a.den / g2, b.den / g1));
  }
  friend constexpr rational operator/(rational a, rational b) {
    if (b.num == 0) throw std::domain_error("geomint::rational: division by zero");
    rational inverse;
    inverse.num = b.num < 0 ? -b.den : b.den;
    inverse.den = b.num < 0 ? -b.num : b.num;
    return a * inverse;
  }
  constexpr rational& operator+=(rational b) { return *this = *this + b; }
  constexpr rational& operator-=(rational b) { return *this = *this - b; }
  constexpr rational& operator*=(rational b) { return *this = *this * b; }
  constexpr rational& operator/=(rational b) { return *this = *this / b; }

  /// Reduced form makes member-wise equality exact equality.
  friend constexpr bool operator==(const rational&, const rational&) = default;
  friend constexpr std::strong_ordering operator<=>(rational a, rational b) {
    return core::detail::mul128(a.num, b.den) <=> core::detail::mul128(b.num, a.den);
  }

  /// Conversion to any floating or multiprecision type: one rounding for num and den each
  /// (none when they fit T's mantissa) and one for the quotient.
  template <class T>
  constexpr T to() const {
    return from_int64<T>(num) / from_int64<T>(den);
  }

  std::string str() const {
    return den == 1 ? std::to_string(num) : std::to_string(num) + "/" + std::to_string(den);
  }
  friend std::ostream& operator<<(std::ostream& os, const rational& r) { return os << r.str(); }
};

constexpr rational abs(rational r) { return r.num < 0 ? -r : r; }

/// Converts the library's exact and floating scalars alike: rational -> T, T -> T.
template <class T, class U>
constexpr T scalar_cast(const U& value) {
  if constexpr (std::is_same_v<U, rational>) {
    return value.template to<T>();
  } else {
    return T(value);
  }
}

}  // namespace geomint
