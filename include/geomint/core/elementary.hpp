#pragma once
/// Elementary functions for any scalar that are fast in multiprecision, for the forces of
/// systems evaluated many times per step. Boost.Multiprecision's own functions are made for
/// one-off accuracy: its square root of a 50-digit cpp_bin_float works bit by bit, its sine sums
/// a hypergeometric series with a division per term.
/// - inverse_sqrt: a double-double seed refined by Newton's method in the scalar.
/// - sin_cos, sine, cosine: for |x| < 9/8, a table of sin and cos at multiples of 1/128 and
///   short Taylor series of the offset; further out, one of the scalar's own sin and cos and
///   the other from a square root near one.
/// Built-in types and types of run-time precision keep the library's functions; dual numbers
/// (ad/dual.hpp) call these on their values.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include <boost/math/constants/constants.hpp>

#include "geomint/core/mantissa.hpp"

namespace geomint {

namespace core::detail {
/// Scalars with a precision fixed above double's (Boost.Multiprecision numbers of fixed
/// precision, quad precision): elementary functions start from double and refine. A
/// variable-precision type such as Boost's mpfr_float reports INT_MAX digits and is left out.
template <class T>
inline constexpr bool refines_from_double_v =
    !std::is_arithmetic_v<T> && std::numeric_limits<T>::is_specialized && !std::numeric_limits<T>::is_integer &&
    std::numeric_limits<T>::digits > std::numeric_limits<double>::digits &&
    std::numeric_limits<T>::digits < std::numeric_limits<int>::max();

/// sqrt(a) for a in [1/2, 1] in a multiprecision type: the double square root refined by
/// Newton's iteration y <- (y + a/y)/2, which doubles the correct bits each time, to the
/// precision of T: two corrections at 50 digits, each a division, where Boost's cpp_bin_float
/// sqrt works on the doubled integer mantissa.
template <class T>
T sqrt_near_one(const T& a) {
  using std::sqrt;
  T y(sqrt(to_double(a)));
  for (int bits = std::numeric_limits<double>::digits - 1; bits < std::numeric_limits<T>::digits + 2; bits *= 2)
    y = T(T(y + T(a / y)) / T(2));
  return y;
}

/// sin and cos at a_j = j / 128, j = 0..144 (so on [0, 9/8]), and the Taylor coefficients
/// (-1)^k / (2k+1)! and (-1)^k / (2k)! for k < terms, the fewest for which the first omitted
/// term, 2^(-8 (2 terms)) / (2 terms)!, is below eps / 8 for offsets |s| <= 1/256 (8 terms for
/// 50 digits). Built once per scalar type (a function-local static, thread-safe), from the
/// scalar's own sin and cos (within an ulp there: Boost's cos is accurate to eps absolute, not
/// relative, as it nears pi/2, which is why the table stops at 9/8).
template <class T>
struct sine_table {
  static constexpr int per_unit = 128;
  static constexpr int entries = 9 * per_unit / 8 + 1;
  std::array<T, entries> at, sin, cos;
  std::array<T, 64> odd{}, even{};
  int terms = 0;

  static sine_table make() {
    using std::cos;
    using std::sin;
    sine_table t;
    for (int j = 0; j < entries; ++j) {
      const auto J = static_cast<std::size_t>(j);
      t.at[J] = T(j) / T(per_unit);
      t.sin[J] = sin(t.at[J]);
      t.cos[J] = cos(t.at[J]);
    }
    const T eps = std::numeric_limits<T>::epsilon();
    const T s_max = T(1) / T(2 * per_unit);
    T factorial(1), power(1);  // (2k)!, s_max^(2k)
    for (int k = 0; k < 63; ++k) {
      const auto K = static_cast<std::size_t>(k);
      const T sign = k % 2 == 0 ? T(1) : T(-1);
      t.even[K] = sign / factorial;
      factorial *= T(2 * k + 1);
      t.odd[K] = sign / factorial;
      factorial *= T(2 * k + 2);
      power *= s_max * s_max;
      t.terms = k + 1;
      if (power / factorial < eps / T(8)) break;
    }
    return t;
  }
};

template <class T>
const sine_table<T>& sine_table_of() {
  static const sine_table<T> table = sine_table<T>::make();
  return table;
}

/// |x| = a + s with a = j / 128 the table point nearest |x| (s exact: both are multiples of the
/// ulp of |x|; |s| <= 1/256), and S(s), C(s) the Taylor series of sin s and cos s to T's
/// precision (about 16 multiplications for 50 digits). For |x| < 9/8 neither sin a C + cos a S
/// nor cos a C - sin a S cancels by more than half (|S| <= 1/256 <= sin a for j >= 1, and
/// cos a >= 2/5), so both keep a few units of the last place relative to the result.
template <class T>
struct sine_reduction {
  std::size_t j = 0;
  bool negative = false;
  T S, C;

  /// False (nothing computed) unless |x| < 9/8.
  bool reduce(const T& x) {
    using table_type = sine_table<T>;
    const double xd = to_double(x);
    if (!(std::abs(xd) < double(table_type::entries - 1) / table_type::per_unit)) return false;
    const auto& t = sine_table_of<T>();
    negative = x < T(0);
    j = static_cast<std::size_t>(std::lround(std::abs(xd) * table_type::per_unit));
    const T s = (negative ? T(-x) : x) - t.at[j];
    const T u = fast_product(s, s);
    const auto last = static_cast<std::size_t>(t.terms - 1);
    S = t.odd[last];
    C = t.even[last];
    for (std::size_t k = last; k-- > 0;) {
      S = fast_sum(fast_product(S, u), t.odd[k]);
      C = fast_sum(fast_product(C, u), t.even[k]);
    }
    S = fast_product(S, s);
    return true;
  }
  /// sin(a + s) = sin a C + cos a S, with the sign of x.
  T sine() const {
    const auto& t = sine_table_of<T>();
    const T v = fast_sum(fast_product(t.sin[j], C), fast_product(t.cos[j], S));
    return negative ? T(-v) : v;
  }
  /// cos(a + s) = cos a C - sin a S.
  T cosine() const {
    const auto& t = sine_table_of<T>();
    return fast_difference(fast_product(t.cos[j], C), fast_product(t.sin[j], S));
  }
};

/// Outside the table: the quadrant k of x (x near k pi/2) says which of sin x, cos x is at most
/// 1/sqrt 2 in magnitude; that one is evaluated by the scalar's own function and the other is
/// sqrt(1 - s^2) with the quadrant's sign. There 1 - s^2 >= 1/2, so the square root adds a few
/// units of the last place; a k off by one next to a quadrant boundary (|s| near 1/sqrt 2) keeps
/// that bound and the signs. False for arguments too large for k to be exact.
template <class T>
bool sin_cos_by_quadrant(const T& x, std::pair<T, T>& out) {
  using std::abs;
  using std::cos;
  using std::floor;
  using std::round;
  using std::sin;
  const T largest = T(1) / (T(16) * std::numeric_limits<T>::epsilon());
  if (!(abs(x) < largest && abs(x) < from_int64<T>(std::int64_t(1) << 60))) return false;
  const T k = T(round(T(x * boost::math::constants::two_div_pi<T>())));
  const T k_mod_4 = T(k - T(4) * T(floor(T(k / T(4)))));  // exact: k is an integer below 2^60
  const int quadrant = k_mod_4 < T(1) ? 0 : k_mod_4 < T(2) ? 1 : k_mod_4 < T(3) ? 2 : 3;
  const T small = (quadrant % 2 == 0) ? T(sin(x)) : T(cos(x));
  if (!(abs(small) <= T(3) / T(4))) return false;
  const T other = sqrt_near_one(T(T(1) - small * small));
  switch (quadrant) {
    case 0: out = {small, other}; break;           // x near 2 j pi
    case 1: out = {other, small}; break;           // x near 2 j pi + pi/2
    case 2: out = {small, T(-other)}; break;       // x near 2 j pi + pi
    default: out = {T(-other), small}; break;      // x near 2 j pi + 3 pi/2
  }
  return true;
}
}  // namespace core::detail

/// The double x in T, exactly. In multiprecision (core::detail::refines_from_double_v) through
/// its 53-bit integer mantissa and an exponent shift (frexp, ldexp), much cheaper than Boost's
/// generic conversion from a floating type; non-finite x, and other types, by T's own
/// conversion.
template <class T>
T from_double(double x) {
  if constexpr (core::detail::refines_from_double_v<T>) {
    if (std::isfinite(x)) {
      using std::ldexp;
      int e = 0;
      static_assert(std::numeric_limits<double>::digits == 53, "geomint::from_double: IEEE double expected");
      const double m = std::frexp(x, &e);  // x = m 2^e, |m| in [1/2, 1): m 2^53 is an integer
      return T(ldexp(from_int64<T>(static_cast<long long>(m * 0x1p53)), e - std::numeric_limits<double>::digits));
    }
  }
  return T(x);
}

/// 1 / sqrt(x), within a few ulps of T. In multiprecision (core::detail::refines_from_double_v):
/// a seed of about 103 bits from double-double arithmetic (1 / sqrt of the leading double of x
/// scaled by a power of 4 into [1/4, 4), and one Newton step y + y (1 - x y^2) / 2 with x to two
/// doubles and the products exact by fma),
/// then Newton's iteration in T, which about doubles the correct bits each time (one iteration
/// for 50 digits, two for 100). Where double cannot hold x as a positive normal number (and for x <= 0 or
/// not finite): 1 / sqrt(x) in T. Other types: 1 / sqrt(x).
template <class T>
T inverse_sqrt(const T& x) {
  using std::sqrt;
  if constexpr (core::detail::refines_from_double_v<T>) {
    const double unscaled = to_double(x);
    if (!(unscaled >= std::numeric_limits<double>::min() && unscaled <= std::numeric_limits<double>::max()))
      return T(T(1) / sqrt(x));
    // x = 4^k xs with xs in [1/4, 4), exactly, so that the seed's products stay far from
    // double's underflow: 1/sqrt(x) = 2^-k / sqrt(xs).
    using std::ldexp;
    int e = 0;
    std::frexp(unscaled, &e);
    const int k = e / 2;
    const T xs = ldexp(x, -2 * k);
    const double high = to_double(xs);
    const double low = to_double(fast_difference(xs, from_double<T>(high)));
    const double y0 = 1 / std::sqrt(high);
    // r = 1 - x y0^2 to about 2^-104: y0^2 = p + pe and high p = t + te exactly; 1 - t is exact
    // (t is within a few ulps of 1).
    const double p = y0 * y0, pe = std::fma(y0, y0, -p);
    const double t = high * p, te = std::fma(high, p, -t);
    const double r = (1 - t) - (te + high * pe + low * p);
    T y = from_double<T>(y0) + from_double<T>(y0 * r / 2);
    for (int bits = 2 * std::numeric_limits<double>::digits - 3; bits < std::numeric_limits<T>::digits + 1; bits = 2 * bits - 1)
      add_into(y, y, T(ldexp(fast_product(y, fast_difference(T(1), fast_product(fast_product(xs, y), y))), -1)));  // (halving by the exponent)
    return T(ldexp(y, -k));
  } else {
    return T(T(1) / sqrt(x));
  }
}

/// (sin x, cos x), within a few units of the last place of each. In multiprecision
/// (core::detail::refines_from_double_v): for |x| < 9/8 from the table and the Taylor series of
/// the offset (core::detail::sine_reduction: about 16 multiplications for 50 digits), further
/// out by quadrant (core::detail::sin_cos_by_quadrant: one of
/// the scalar's sin and cos). Elsewhere, and in other types: the scalar's own sin and cos.
template <class T>
std::pair<T, T> sin_cos(const T& x) {
  if constexpr (core::detail::refines_from_double_v<T>) {
    core::detail::sine_reduction<T> r;
    if (r.reduce(x)) return {r.sine(), r.cosine()};
    std::pair<T, T> out;
    if (core::detail::sin_cos_by_quadrant(x, out)) return out;
  }
  using std::cos;
  using std::sin;
  return {T(sin(x)), T(cos(x))};
}

/// sin x: as the first of sin_cos(x) for |x| < 9/8 (without forming the cosine), else the
/// scalar's own sin.
template <class T>
T sine(const T& x) {
  if constexpr (core::detail::refines_from_double_v<T>) {
    core::detail::sine_reduction<T> r;
    if (r.reduce(x)) return r.sine();
  }
  using std::sin;
  return T(sin(x));
}

/// cos x: as sine.
template <class T>
T cosine(const T& x) {
  if constexpr (core::detail::refines_from_double_v<T>) {
    core::detail::sine_reduction<T> r;
    if (r.reduce(x)) return r.cosine();
  }
  using std::cos;
  return T(cos(x));
}

}  // namespace geomint
