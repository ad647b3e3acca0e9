#pragma once
/// Decimal constants in the working precision, for every scalar type: no constant passes
/// through a double literal. Free of Boost.Multiprecision, so that headers with constants (the
/// problem zoo) stay cheap to parse for built-in scalars.

#include <cstdlib>
#include <type_traits>

namespace geomint {

/// A decimal constant read in the precision of T: strtof/strtod/strtold for the built-in types
/// (correctly rounded), the multiprecision type's own parser otherwise. Never through double.
template <class T>
T from_decimal(const char* text) {
  if constexpr (std::is_same_v<T, float>) return std::strtof(text, nullptr);
  else if constexpr (std::is_same_v<T, double>) return std::strtod(text, nullptr);
  else if constexpr (std::is_floating_point_v<T>) return static_cast<T>(std::strtold(text, nullptr));
  else return T(text);
}

}  // namespace geomint
