#pragma once
/// Forward-mode automatic differentiation: a small, nestable dual number.
///
/// Why not Eigen's AutoDiffScalar: the LPF residual needs the Euler-Lagrange expression
/// dL/dq - d/dt dL/dqdot (second derivatives of L, eq. 12) and Newton needs its Jacobian, so
/// L is differentiated three times. Eigen's AutoDiffScalar (3.4) cannot be nested three deep
/// over a Boost.Multiprecision scalar: Eigen internally builds `Scalar(0)` from an int, and for
/// the middle level that needs two user-defined conversions (int -> number -> AutoDiffScalar),
/// which C++ does not allow, so it fails to compile (checked with Eigen 3.4.0, Boost 1.74).
/// This type has fixed-size derivative storage (std::array, no allocation), converts from any
/// arithmetic type through every nesting level, and finds math functions by ADL, so the same
/// user Lagrangian runs over double, long double and any Boost.Multiprecision type.

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "geomint/core/elementary.hpp"

namespace geomint {

template <class T, int N>
struct dual;

template <class X>
struct is_dual : std::false_type {};
template <class T, int N>
struct is_dual<dual<T, N>> : std::true_type {};

/// Whether S is T or a lower level of T (for T = dual<dual<double, 2>, 2>: dual<double, 2>
/// and double): the non-arithmetic scalars a dual over T mixes with.
template <class S, class T>
struct is_lower_level : std::is_same<S, T> {};
template <class S, class U, int M>
struct is_lower_level<S, dual<U, M>> : std::bool_constant<std::is_same_v<S, dual<U, M>> || is_lower_level<S, U>::value> {};

/// A value and N partial derivatives; T may itself be a dual (nesting gives higher orders).
template <class T, int N>
struct dual {
  static_assert(N >= 1, "geomint: a dual number needs at least one derivative direction");
  T v{};
  std::array<T, N> d{};

  dual() : v(0) { d.fill(T(0)); }
  /// A constant (all derivatives zero). Implicit, so constants mix freely with duals.
  dual(const T& value) : v(value) { d.fill(T(0)); }  // NOLINT
  template <class S>
    requires(std::is_arithmetic_v<S> && !std::is_same_v<S, T>)
  dual(S value) : v(T(value)) {  // NOLINT
    d.fill(T(0));
  }
  /// A constant of a lower level, e.g. the multiprecision base scalar inside a nested dual.
  template <class S>
    requires(!std::is_arithmetic_v<S> && !std::is_same_v<S, T> && is_lower_level<S, T>::value)
  dual(const S& value) : v(T(value)) {  // NOLINT
    d.fill(T(0));
  }
  /// Not a conversion to use: it exists so that a qualified call such as `std::cos(x)` on a
  /// dual (which has no std:: overload) selects std::cos(long double) and stops here with a
  /// readable message, instead of a long "no matching function" list. The same message appears
  /// when a dual is assigned to a built-in floating-point variable inside a Lagrangian.
  operator long double() const {  // NOLINT
    static_assert(N < 0,
                  "geomint: a math function was called qualified (e.g. std::cos(q[0])) on a geomint dual number, "
                  "or a dual was stored in a double. Write `using std::cos;` and call `cos(q[0])` unqualified "
                  "(the same for sin, sqrt, exp, log, atan2, pow, ...), and keep intermediates in the scalar "
                  "type S of your templated operator().");
    return 0;
  }
  /// The independent variable number `k` with value `value`.
  static dual variable(const T& value, int k) {
    dual x(value);
    x.d[static_cast<std::size_t>(k)] = T(1);
    return x;
  }

  dual& operator+=(const dual& o) {
    v += o.v;
    for (int i = 0; i < N; ++i) d[i] += o.d[i];
    return *this;
  }
  dual& operator-=(const dual& o) {
    v -= o.v;
    for (int i = 0; i < N; ++i) d[i] -= o.d[i];
    return *this;
  }
  dual& operator*=(const dual& o) {
    for (int i = 0; i < N; ++i) d[i] = d[i] * o.v + v * o.d[i];
    v *= o.v;
    return *this;
  }
  dual& operator/=(const dual& o) {
    const T inv = T(1) / o.v;
    v *= inv;
    for (int i = 0; i < N; ++i) d[i] = (d[i] - v * o.d[i]) * inv;
    return *this;
  }
};

/// Scalars that may be mixed with dual<T, N>: arithmetic types, T and every lower level of T.
template <class S, class T, int N>
concept dual_operand = std::is_arithmetic_v<std::remove_cvref_t<S>> || is_lower_level<std::remove_cvref_t<S>, T>::value;

template <class T, int N> dual<T, N> operator+(dual<T, N> a, const dual<T, N>& b) { return a += b; }
template <class T, int N> dual<T, N> operator-(dual<T, N> a, const dual<T, N>& b) { return a -= b; }
template <class T, int N> dual<T, N> operator*(dual<T, N> a, const dual<T, N>& b) { return a *= b; }
template <class T, int N> dual<T, N> operator/(dual<T, N> a, const dual<T, N>& b) { return a /= b; }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator+(dual<T, N> a, const S& b) { return a += dual<T, N>(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator+(const S& a, dual<T, N> b) { return b += dual<T, N>(a); }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator-(dual<T, N> a, const S& b) { return a -= dual<T, N>(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator-(const S& a, const dual<T, N>& b) { return dual<T, N>(a) -= b; }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator*(dual<T, N> a, const S& b) {
  const T s(b);
  a.v *= s;
  for (auto& x : a.d) x *= s;
  return a;
}
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator*(const S& a, dual<T, N> b) { return b * a; }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator/(dual<T, N> a, const S& b) { return a /= dual<T, N>(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> operator/(const S& a, const dual<T, N>& b) { return dual<T, N>(a) /= b; }
template <class T, int N> dual<T, N> operator-(dual<T, N> a) {
  a.v = -a.v;
  for (auto& x : a.d) x = -x;
  return a;
}
template <class T, int N> dual<T, N> operator+(const dual<T, N>& a) { return a; }

/// Comparisons look at values only (used for branches inside a Lagrangian).
template <class T, int N> bool operator<(const dual<T, N>& a, const dual<T, N>& b) { return a.v < b.v; }
template <class T, int N> bool operator>(const dual<T, N>& a, const dual<T, N>& b) { return a.v > b.v; }
template <class T, int N> bool operator<=(const dual<T, N>& a, const dual<T, N>& b) { return a.v <= b.v; }
template <class T, int N> bool operator>=(const dual<T, N>& a, const dual<T, N>& b) { return a.v >= b.v; }
template <class T, int N> bool operator==(const dual<T, N>& a, const dual<T, N>& b) { return a.v == b.v; }
template <class T, int N> bool operator!=(const dual<T, N>& a, const dual<T, N>& b) { return !(a.v == b.v); }

/// Comparisons with plain scalars (exact matches, so they win over any built-in candidate).
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator<(const dual<T, N>& a, const S& b) { return a.v < T(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator<(const S& a, const dual<T, N>& b) { return T(a) < b.v; }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator>(const dual<T, N>& a, const S& b) { return a.v > T(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator>(const S& a, const dual<T, N>& b) { return T(a) > b.v; }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator<=(const dual<T, N>& a, const S& b) { return a.v <= T(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator<=(const S& a, const dual<T, N>& b) { return T(a) <= b.v; }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator>=(const dual<T, N>& a, const S& b) { return a.v >= T(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator>=(const S& a, const dual<T, N>& b) { return T(a) >= b.v; }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator==(const dual<T, N>& a, const S& b) { return a.v == T(b); }
template <class T, int N, class S> requires dual_operand<S, T, N>
bool operator!=(const dual<T, N>& a, const S& b) { return !(a.v == T(b)); }

/// Chain rule: f(x) with f(x.v) = value and f'(x.v) = slope.
template <class T, int N>
dual<T, N> chain(const dual<T, N>& x, const T& value, const T& slope) {
  dual<T, N> r(value);
  for (int i = 0; i < N; ++i) r.d[i] = slope * x.d[i];
  return r;
}


/// The elementary functions. Each evaluates f and f' on the value through an unqualified call
/// (std:: for built-in types, ADL for Boost.Multiprecision and for lower-level duals), so they
/// nest to any depth. Derivatives are the textbook formulas (Abramowitz & Stegun, ch. 4).
///
/// sin and cos together: each level of a nested dual needs both of the level below, so
/// separate sin and cos would evaluate the innermost sin and cos 2^depth times; jointly, once
/// each, by the scalar sin_cos of core/elementary.hpp (fast in multiprecision).
template <class T, int N>
std::pair<dual<T, N>, dual<T, N>> sin_cos(const dual<T, N>& x) {
  const std::pair<T, T> sc = sin_cos(x.v);
  return {chain(x, sc.first, sc.second), chain(x, sc.second, T(-sc.first))};
}
template <class T, int N> dual<T, N> sin(const dual<T, N>& x) { return sin_cos(x).first; }
template <class T, int N> dual<T, N> cos(const dual<T, N>& x) { return sin_cos(x).second; }
/// tan' = 1 + tan^2.
template <class T, int N> dual<T, N> tan(const dual<T, N>& x) {
  using std::tan;
  const T t = tan(x.v);
  return chain(x, t, T(T(1) + t * t));
}
/// asin' = 1 / sqrt(1 - x^2) (|x| < 1).
template <class T, int N> dual<T, N> asin(const dual<T, N>& x) {
  using std::asin;
  using std::sqrt;
  return chain(x, T(asin(x.v)), T(T(1) / sqrt(T(T(1) - x.v * x.v))));
}
/// acos' = -1 / sqrt(1 - x^2) (|x| < 1).
template <class T, int N> dual<T, N> acos(const dual<T, N>& x) {
  using std::acos;
  using std::sqrt;
  return chain(x, T(acos(x.v)), T(T(-1) / sqrt(T(T(1) - x.v * x.v))));
}
/// atan' = 1 / (1 + x^2).
template <class T, int N> dual<T, N> atan(const dual<T, N>& x) { using std::atan; return chain(x, T(atan(x.v)), T(T(1) / (T(1) + x.v * x.v))); }
/// atan2(y, x): d = (x dy - y dx) / (x^2 + y^2).
template <class T, int N> dual<T, N> atan2(const dual<T, N>& y, const dual<T, N>& x) {
  using std::atan2;
  const T r2 = x.v * x.v + y.v * y.v;
  dual<T, N> r(T(atan2(y.v, x.v)));
  for (int i = 0; i < N; ++i) r.d[i] = (x.v * y.d[i] - y.v * x.d[i]) / r2;
  return r;
}
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> atan2(const dual<T, N>& y, const S& x) { return atan2(y, dual<T, N>(x)); }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> atan2(const S& y, const dual<T, N>& x) { return atan2(dual<T, N>(y), x); }
template <class T, int N> dual<T, N> sinh(const dual<T, N>& x) { using std::sinh; using std::cosh; return chain(x, T(sinh(x.v)), T(cosh(x.v))); }
template <class T, int N> dual<T, N> cosh(const dual<T, N>& x) { using std::sinh; using std::cosh; return chain(x, T(cosh(x.v)), T(sinh(x.v))); }
/// tanh' = 1 - tanh^2.
template <class T, int N> dual<T, N> tanh(const dual<T, N>& x) {
  using std::tanh;
  const T t = tanh(x.v);
  return chain(x, t, T(T(1) - t * t));
}
template <class T, int N> dual<T, N> exp(const dual<T, N>& x) { using std::exp; const T e = exp(x.v); return chain(x, e, e); }
/// expm1' = exp = expm1 + 1.
template <class T, int N> dual<T, N> expm1(const dual<T, N>& x) {
  using std::expm1;
  const T e = expm1(x.v);
  return chain(x, e, T(e + T(1)));
}
template <class T, int N> dual<T, N> log(const dual<T, N>& x) { using std::log; return chain(x, T(log(x.v)), T(T(1) / x.v)); }
/// log1p' = 1 / (1 + x).
template <class T, int N> dual<T, N> log1p(const dual<T, N>& x) { using std::log1p; return chain(x, T(log1p(x.v)), T(T(1) / (T(1) + x.v))); }
/// sqrt' = 1 / (2 sqrt) (x > 0).
template <class T, int N> dual<T, N> sqrt(const dual<T, N>& x) {
  using std::sqrt;
  const T s = sqrt(x.v);
  return chain(x, s, T(T(1) / (s + s)));
}
/// cbrt' = 1 / (3 cbrt^2) (x != 0).
template <class T, int N> dual<T, N> cbrt(const dual<T, N>& x) {
  using std::cbrt;
  const T c = cbrt(x.v);
  return chain(x, c, T(T(1) / (T(3) * c * c)));
}
/// hypot(x, y) = sqrt(x^2 + y^2): d = (x dx + y dy) / hypot (not both zero).
template <class T, int N> dual<T, N> hypot(const dual<T, N>& x, const dual<T, N>& y) {
  using std::hypot;
  const T h = hypot(x.v, y.v);
  dual<T, N> r(h);
  for (int i = 0; i < N; ++i) r.d[i] = (x.v * x.d[i] + y.v * y.d[i]) / h;
  return r;
}
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> hypot(const dual<T, N>& x, const S& y) { return hypot(x, dual<T, N>(y)); }
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> hypot(const S& x, const dual<T, N>& y) { return hypot(dual<T, N>(x), y); }
/// |x| (derivative sign(x); at x = 0 the derivative of x is kept).
template <class T, int N> dual<T, N> abs(const dual<T, N>& x) { return x.v < T(0) ? -x : x; }
template <class T, int N> dual<T, N> fabs(const dual<T, N>& x) { return abs(x); }
/// x^k for an integer exponent (exact derivative k x^(k-1), by repeated multiplication).
template <class T, int N> dual<T, N> pow(const dual<T, N>& x, int k) {
  dual<T, N> r(1), base = x;
  unsigned e = k < 0 ? 0u - static_cast<unsigned>(k) : static_cast<unsigned>(k);  // |k|, also for INT_MIN
  while (e) {
    if (e & 1u) r *= base;
    base *= base;
    e >>= 1u;
  }
  return k < 0 ? dual<T, N>(1) / r : r;
}
/// x^y for a constant exponent y (x > 0): d = y x^(y-1) dx.
template <class T, int N, class S> requires(dual_operand<S, T, N> && !std::is_integral_v<S>)
dual<T, N> pow(const dual<T, N>& x, const S& y) {
  using std::pow;
  const T ty(y);
  const T value = pow(x.v, ty);
  return chain(x, value, T(ty * value / x.v));
}
/// a^y for a constant base a > 0: d = log(a) a^y dy.
template <class T, int N, class S> requires dual_operand<S, T, N>
dual<T, N> pow(const S& a, const dual<T, N>& y) {
  using std::pow;
  using std::log;
  const T ta(a);
  const T value = pow(ta, y.v);
  return chain(y, value, T(log(ta) * value));
}
/// x^y with both dual (x > 0): d = x^y (y/x dx + log(x) dy).
template <class T, int N> dual<T, N> pow(const dual<T, N>& x, const dual<T, N>& y) {
  using std::pow;
  using std::log;
  const T value = pow(x.v, y.v);
  const T dx = y.v * value / x.v, dy = T(log(x.v) * value);
  dual<T, N> r(value);
  for (int i = 0; i < N; ++i) r.d[i] = dx * x.d[i] + dy * y.d[i];
  return r;
}

}  // namespace geomint

/// Eigen needs NumTraits to store duals in fixed-size matrices and call dot/squaredNorm.
namespace Eigen {
template <class T, int N>
struct NumTraits<geomint::dual<T, N>> : NumTraits<T> {
  using Real = geomint::dual<T, N>;
  using NonInteger = Real;
  using Nested = Real;
  using Literal = Real;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1,
         ReadCost = HugeCost, AddCost = HugeCost, MulCost = HugeCost };
};
}  // namespace Eigen
