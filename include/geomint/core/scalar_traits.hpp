#pragma once
/// The traits geomint reads of a scalar type, declared for every type here and specialised for
/// Boost.Multiprecision numbers by core/multiprecision.hpp: whether Eigen has its traits
/// (linalg/types.hpp, asserted by the integrators) and whether its mantissa is read directly
/// (core/mantissa.hpp, linalg/dot.hpp). One small header that both sides include, so that
/// core/multiprecision.hpp needs neither core/mantissa.hpp nor linalg/types.hpp, and parses no
/// Eigen matrix code of geomint's own.

#include <cstdint>
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

/// Whether T is an unevaluated sum of `terms` doubles, ordered by magnitude and
/// non-overlapping, built by `make(const double*)`: false here; libqd's dd_real and qd_real are
/// (core/qd.hpp). Exact rationals convert to such a T term by term (methods/number_field.hpp).
template <class T>
struct double_expansion : std::false_type {};

/// x in a wider type R: a sum of doubles term by term (exact when R spans its terms, as 100
/// digits span a dd_real), other types by R's conversion.
template <class R, class T>
R widen(const T& x) {
  if constexpr (double_expansion<T>::value) {
    R sum(0);
    for (int k = 0; k < double_expansion<T>::terms; ++k) sum += R(double_expansion<T>::term(x, k));
    return sum;
  } else {
    return R(x);
  }
}

/// x of a wider type H (a Boost.Multiprecision number, an exact rational) in T: a sum of doubles
/// term by term, each term the nearest double to what the terms before it left (within half a
/// unit of the sum's last bit), other types by T's conversion.
template <class T, class H>
T narrow(const H& x) {
  if constexpr (double_expansion<T>::value) {
    double terms[double_expansion<T>::terms];
    H rest = x;
    for (double& t : terms) {
      t = static_cast<double>(rest);
      rest -= H(t);
    }
    return double_expansion<T>::make(terms);
  } else {
    return T(x);
  }
}

/// T from a 64-bit integer, exactly: T's own constructor where it has one; otherwise (libqd's
/// types construct from int and double only) from its upper and lower 32 bits, each exact in a
/// double, and an exact product by 2^32.
template <class T>
constexpr T from_int64(std::int64_t v) {
  if constexpr (std::is_constructible_v<T, std::int64_t>) {
    return T(v);
  } else {
    constexpr std::int64_t base = std::int64_t(1) << 32;
    const std::int64_t hi = v / base, lo = v % base;
    return T(static_cast<double>(hi)) * T(static_cast<double>(base)) + T(static_cast<double>(lo));
  }
}

}  // namespace geomint
