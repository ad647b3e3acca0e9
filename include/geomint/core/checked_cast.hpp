#pragma once
/// Checked conversions and integer arithmetic: a real to an integer only when its truncation
/// fits the integer type, and signed sums and products only when they do not overflow. A real
/// outside the integer's range (or NaN, or infinite) converted with static_cast is undefined
/// behaviour, as is a signed overflow; here both give an empty result or an exception naming
/// the value, never a wrong number.
///
/// The range test is exact in every binary floating type: trunc(x) fits a signed integer of
/// `digits` value bits iff -2^digits <= trunc(x) < 2^digits, and 2^digits is exactly
/// representable (ldexp), unlike the integer's maximum 2^digits - 1 in double.

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "geomint/core/scalar_traits.hpp"

namespace geomint {

namespace detail {
/// x as a double, for messages: a sum of doubles (core/scalar_traits.hpp) by its leading term.
template <class Real>
double approximately(const Real& x) {
  if constexpr (double_expansion<Real>::value) return double_expansion<Real>::term(x, 0);
  else return static_cast<double>(x);
}

/// x with 6 significant digits (1e+300, not 301 digits), for messages.
inline std::string short_number(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}
}  // namespace detail

/// trunc(x) as Int, or nothing when x is NaN, infinite or its truncation is outside Int.
template <class Int, class Real>
std::optional<Int> checked_integer(const Real& x) {
  static_assert(std::is_integral_v<Int> && !std::is_same_v<Int, bool>, "geomint::checked_integer: Int must be an integer type");
  using std::ldexp;
  using std::trunc;
  const Real t = trunc(x);
  const Real bound = ldexp(Real(1), std::numeric_limits<Int>::digits);  // 2^digits: one past the maximum
  const Real low = std::is_signed_v<Int> ? Real(-bound) : Real(0);
  if (!(t >= low && t < bound)) return std::nullopt;  // also NaN and infinity
  if constexpr (double_expansion<Real>::value) {
    // The terms of an integer are integers; their sum fits Int, one term alone may not
    // (2^63 - 1 = 2^63 + (-1)), so they are added in 128 bits.
    __extension__ using wide = __int128;
    wide sum = 0;
    for (int k = 0; k < double_expansion<Real>::terms; ++k) sum += static_cast<wide>(double_expansion<Real>::term(t, k));
    return static_cast<Int>(sum);
  } else {
    return static_cast<Int>(t);
  }
}

/// trunc(x) as Int; throws std::out_of_range naming `what` when it does not fit.
template <class Int, class Real>
Int integer_or_throw(const Real& x, const char* what) {
  if (const auto v = checked_integer<Int>(x)) return *v;
  throw std::out_of_range(std::string(what) + ": " + detail::short_number(detail::approximately(x)) +
                          " is not finite or outside the range of the integer type");
}

/// a + b, or nothing on overflow.
template <class Int>
std::optional<Int> checked_add(Int a, Int b) {
  Int out;
  if (__builtin_add_overflow(a, b, &out)) return std::nullopt;
  return out;
}

/// a - b, or nothing on overflow.
template <class Int>
std::optional<Int> checked_sub(Int a, Int b) {
  Int out;
  if (__builtin_sub_overflow(a, b, &out)) return std::nullopt;
  return out;
}

/// a * b, or nothing on overflow.
template <class Int>
std::optional<Int> checked_mul(Int a, Int b) {
  Int out;
  if (__builtin_mul_overflow(a, b, &out)) return std::nullopt;
  return out;
}

}  // namespace geomint
