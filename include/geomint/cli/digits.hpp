#pragma once
/// `--digits D` of the tools: the scalar type of D, and D as a template argument.
#include <limits>
#include <type_traits>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace geomint::cli {

/// The scalar type of `--digits D`: double, cpp_bin_float_50, cpp_bin_float_100.
template <int Digits>
struct digits_scalar {
  static_assert(Digits == 16 || Digits == 50 || Digits == 100, "geomint tools: digits must be 16, 50 or 100");
  using type = std::conditional_t<Digits == 16, double,
                                  std::conditional_t<Digits == 50, boost::multiprecision::cpp_bin_float_50,
                                                     boost::multiprecision::cpp_bin_float_100>>;
};
template <int Digits>
using scalar_for_digits = typename digits_scalar<Digits>::type;

/// The `--digits` value of the scalar T: 16 for double, else its decimal digits (50, 100).
template <class T>
constexpr int digits_of() {
  return std::is_same_v<T, double> ? 16 : std::numeric_limits<T>::digits10;
}

/// `f.template operator()<D>()` for the run-time digits D (16, 50, or else 100; the command-line
/// parser has already checked it).
template <class F>
decltype(auto) with_digits(int digits, F&& f) {
  if (digits == 16) return f.template operator()<16>();
  if (digits == 50) return f.template operator()<50>();
  return f.template operator()<100>();
}

}  // namespace geomint::cli
