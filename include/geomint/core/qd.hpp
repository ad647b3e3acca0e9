#pragma once
/// libqd's double-double `dd_real` (106 bits, 31 digits) and quad-double `qd_real` (212 bits, 62
/// digits) as geomint scalars (Hida, Li & Bailey, "Algorithms for quad-double precision floating
/// point arithmetic", ARITH-15, 2001; Debian's libqd-dev). dd_real's arithmetic is a few inline
/// double operations: several times faster than a 50-digit software mantissa where 31 digits
/// suffice (docs/results/performance.md).
///
/// This header gives them what geomint reads of a scalar: Eigen's NumTraits, conversion of exact
/// rationals at full precision (core/scalar_traits.hpp, `double_expansion`), and the frexp and
/// round that libqd lacks. A T from a 64-bit integer is `from_int64<T>` (libqd constructs from
/// int and double only). Link libqd (`-lqd`), whose elementary functions are compiled; for that
/// reason geomint/geomint.hpp does not include this header.

#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Core>

/// libqd's exact product a*b = p + e is Dekker's split unless QD_FMS names a fused multiply-
/// subtract, and the split is only exact if the compiler does not contract it into fmas. GCC 12
/// with its default -ffp-contract=fast did so for FMA with AVX-512 (-march=native on an AVX-512
/// host; -mfma alone did not): dd_real products lost their low half, and the Gauss collocation
/// tableau in dd_real was symplectic only to 1e-16 (tests/core/test_qd_fma.cpp). Where the
/// target has FMA, the product's error is the exact fma(a, b, -p) instead, which is also
/// faster; include this header before any libqd header.
#if defined(__FMA__) && !defined(QD_FMS)
#if defined(_QD_INLINE_H)
#error "geomint/core/qd.hpp must be included before libqd's headers on a target with FMA (see the comment above)"
#endif
#define QD_FMA(a, b, c) std::fma(a, b, c)
#define QD_FMS(a, b, c) std::fma(a, b, -(c))
#endif
#include <qd/dd_real.h>
#include <qd/qd_real.h>

#include "geomint/core/scalar_traits.hpp"

namespace geomint {

/// dd_real and qd_real are unevaluated sums of 2 and 4 doubles, ordered by magnitude and
/// non-overlapping: a rational is converted term by term, each term the nearest double to
/// what the terms before it left (core/scalar_traits.hpp).
template <>
struct double_expansion<dd_real> : std::true_type {
  static constexpr int terms = 2;
  static dd_real make(const double* t) { return dd_real(t[0], t[1]); }
  static double term(const dd_real& x, int k) { return x.x[k]; }
};
template <>
struct double_expansion<qd_real> : std::true_type {
  static constexpr int terms = 4;
  static qd_real make(const double* t) { return qd_real(t[0], t[1], t[2], t[3]); }
  static double term(const qd_real& x, int k) { return x.x[k]; }
};

}  // namespace geomint

namespace geomint::core::detail {
/// Eigen's NumTraits of a sum of doubles T with `digits10` decimal digits.
template <class T>
struct qd_num_traits : Eigen::GenericNumTraits<T> {
  using Real = T;
  using NonInteger = T;
  using Literal = T;
  using Nested = T;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = double_expansion<T>::terms,
    AddCost = 10 * double_expansion<T>::terms,
    MulCost = 15 * double_expansion<T>::terms
  };
  static T epsilon() { return T(std::numeric_limits<T>::epsilon()); }
  /// Eigen's threshold for "negligible" in its decompositions: 2^10 units of epsilon, as for
  /// Boost.Multiprecision numbers (boost/multiprecision/eigen.hpp).
  static T dummy_precision() { return T(1024) * epsilon(); }
  static T highest() { return std::numeric_limits<T>::max(); }
  static T lowest() { return -std::numeric_limits<T>::max(); }
  static int digits10() { return std::numeric_limits<T>::digits10; }
  static T infinity() { return T(std::numeric_limits<double>::infinity()); }
  static T quiet_NaN() { return T(std::numeric_limits<double>::quiet_NaN()); }
};
}  // namespace geomint::core::detail

/// What libqd lacks of <cmath> and geomint calls (found by argument-dependent lookup, as libqd's
/// own functions are): frexp, with the mantissa in [1/2, 1) also where the leading double is a
/// power of two and the rest negative; round, half away from zero; trunc, libqd's aint.
namespace geomint::core::detail {
template <class T>
T qd_frexp(const T& a, int* e) {
  *e = 0;
  if (a.x[0] == 0 || !std::isfinite(a.x[0])) return a;
  (void)std::frexp(a.x[0], e);
  T m = ldexp(a, -*e);
  if (abs(m) < T(0.5)) {  // 0.5 is a power of two: exact in T
    m = mul_pwr2(m, 2);
    --*e;
  }
  return m;
}
template <class T>
T qd_round(const T& a) {
  const T f = floor(a), d = a - f;  // d in [0, 1), exact
  const T half(0.5);
  return (d > half || (d == half && a.x[0] > 0)) ? T(f + T(1)) : f;
}
}  // namespace geomint::core::detail

inline dd_real frexp(const dd_real& a, int* e) { return geomint::core::detail::qd_frexp(a, e); }
inline qd_real frexp(const qd_real& a, int* e) { return geomint::core::detail::qd_frexp(a, e); }
inline dd_real round(const dd_real& a) { return geomint::core::detail::qd_round(a); }
inline qd_real round(const qd_real& a) { return geomint::core::detail::qd_round(a); }
inline dd_real trunc(const dd_real& a) { return aint(a); }
inline qd_real trunc(const qd_real& a) { return aint(a); }

namespace Eigen {
template <>
struct NumTraits<dd_real> : geomint::core::detail::qd_num_traits<dd_real> {};
template <>
struct NumTraits<qd_real> : geomint::core::detail::qd_num_traits<qd_real> {};
}  // namespace Eigen
