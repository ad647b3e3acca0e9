#pragma once
/// The traits geomint reads of a scalar type, declared for every type here and specialised for
/// Boost.Multiprecision numbers by core/multiprecision.hpp: whether Eigen has its traits
/// (linalg/types.hpp, asserted by the integrators) and whether its mantissa is read directly
/// (core/mantissa.hpp, linalg/dot.hpp). One small header that both sides include, so that
/// core/multiprecision.hpp needs neither core/mantissa.hpp nor linalg/types.hpp, and parses no
/// Eigen matrix code of geomint's own.

#include <type_traits>

namespace geomint {

/// Whether Eigen has the traits of scalar S: true for built-in types; for a Boost.Multiprecision
/// number (a type with a backend_type) only once core/multiprecision.hpp is included, which
/// specialises this trait. The integrators assert it with a message naming the include.
template <class S>
struct eigen_scalar_ready : std::true_type {};
template <class S>
  requires requires { typename S::backend_type; }
struct eigen_scalar_ready<S> : std::false_type {};

/// Whether T is a number whose mantissa geomint reads directly: false here; true for Boost's
/// cpp_bin_float with stack storage, int exponents and more than 128 bits, whose mantissa is an
/// array of 64-bit limbs (core/multiprecision.hpp specialises this, with `backend`, `bits`
/// (p, the leading one at bit p - 1) and `limbs`; this header parses no Boost.Multiprecision,
/// so that files with built-in scalars stay fast to compile).
template <class T>
struct exact_mantissa_arithmetic : std::false_type {};

template <class T>
inline constexpr bool exact_mantissa_arithmetic_v = exact_mantissa_arithmetic<T>::value;

}  // namespace geomint
