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
#include <type_traits>

#include <Eigen/Core>

namespace geomint::detail {

template <class T, int N>
struct dual;

template <class X>
struct is_dual : std::false_type {};
template <class T, int N>
struct is_dual<dual<T, N>> : std::true_type {};

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

/// Scalars that may be mixed with dual<T, N>: anything T is constructible from that is not
/// itself this dual type (T, arithmetic types, lower-level duals).
template <class S, class T, int N>
concept dual_operand = !std::is_same_v<std::remove_cvref_t<S>, dual<T, N>> && std::is_constructible_v<dual<T, N>, S>;

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

/// Chain rule: f(x) with f(x.v) = value and f'(x.v) = slope.
template <class T, int N>
dual<T, N> chain(const dual<T, N>& x, const T& value, const T& slope) {
  dual<T, N> r(value);
  for (int i = 0; i < N; ++i) r.d[i] = slope * x.d[i];
  return r;
}

template <class T, int N> dual<T, N> sin(const dual<T, N>& x) { using std::sin; using std::cos; return chain(x, T(sin(x.v)), T(cos(x.v))); }
template <class T, int N> dual<T, N> cos(const dual<T, N>& x) { using std::sin; using std::cos; return chain(x, T(cos(x.v)), T(-sin(x.v))); }
template <class T, int N> dual<T, N> tan(const dual<T, N>& x) {
  using std::tan;
  const T t = tan(x.v);
  return chain(x, t, T(T(1) + t * t));
}
template <class T, int N> dual<T, N> exp(const dual<T, N>& x) { using std::exp; const T e = exp(x.v); return chain(x, e, e); }
template <class T, int N> dual<T, N> log(const dual<T, N>& x) { using std::log; return chain(x, T(log(x.v)), T(T(1) / x.v)); }
template <class T, int N> dual<T, N> sqrt(const dual<T, N>& x) {
  using std::sqrt;
  const T s = sqrt(x.v);
  return chain(x, s, T(T(1) / (s + s)));
}
template <class T, int N> dual<T, N> atan(const dual<T, N>& x) { using std::atan; return chain(x, T(atan(x.v)), T(T(1) / (T(1) + x.v * x.v))); }
template <class T, int N> dual<T, N> sinh(const dual<T, N>& x) { using std::sinh; using std::cosh; return chain(x, T(sinh(x.v)), T(cosh(x.v))); }
template <class T, int N> dual<T, N> cosh(const dual<T, N>& x) { using std::sinh; using std::cosh; return chain(x, T(cosh(x.v)), T(sinh(x.v))); }
template <class T, int N> dual<T, N> tanh(const dual<T, N>& x) {
  using std::tanh;
  const T t = tanh(x.v);
  return chain(x, t, T(T(1) - t * t));
}
template <class T, int N> dual<T, N> abs(const dual<T, N>& x) { return x.v < T(0) ? -x : x; }
/// x^k for an integer exponent (exact derivative k x^(k-1)).
template <class T, int N> dual<T, N> pow(const dual<T, N>& x, int k) {
  dual<T, N> r(1), base = x;
  unsigned e = static_cast<unsigned>(k < 0 ? -k : k);
  while (e) {
    if (e & 1u) r *= base;
    base *= base;
    e >>= 1u;
  }
  return k < 0 ? dual<T, N>(1) / r : r;
}
/// x^y for a real constant exponent y (x > 0).
template <class T, int N, class S> requires(!is_dual<S>::value && !std::is_integral_v<S>)
dual<T, N> pow(const dual<T, N>& x, const S& y) {
  using std::pow;
  const T ty(y);
  const T value = pow(x.v, ty);
  return chain(x, value, T(ty * value / x.v));
}

}  // namespace geomint::detail

/// Eigen needs NumTraits to store duals in fixed-size matrices and call dot/squaredNorm.
namespace Eigen {
template <class T, int N>
struct NumTraits<geomint::detail::dual<T, N>> : NumTraits<T> {
  using Real = geomint::detail::dual<T, N>;
  using NonInteger = Real;
  using Nested = Real;
  using Literal = Real;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1,
         ReadCost = HugeCost, AddCost = HugeCost, MulCost = HugeCost };
};
}  // namespace Eigen
