#pragma once
/// Node families on [0, 1]: m+1 nodes c_0 = 0 < c_1 < ... < c_m = 1, the m - 1 interior ones
/// the roots of the family's interior polynomial.
///
/// - `equispaced`:        c_a = a/m, the LPF paper's choice (eq. 8); exact in `rational`.
/// - `gauss_lobatto`:     ends plus the roots of P'_m (Legendre), mapped to [0, 1].
/// - `chebyshev_lobatto`: ends plus the roots of U_{m-1} (Chebyshev, second kind):
///                        c_a = (1 - cos(pi a / m)) / 2.
/// - `gauss_interior`:    ends plus the m-1 Gauss-Legendre points (roots of P_{m-1}).
/// - `radau_right`:       0 plus the m Radau IIA points of m stages (roots of P*_m - P*_{m-1},
///                        P*_n(c) = P_n(2c - 1); 1 among them): Hairer & Wanner II, section IV.5.
/// - `radau_left`:        the m Radau IA points (roots of P*_m + P*_{m-1}; 0 among them) plus 1.
///
/// A node family is a class with the members the `node_family` concept names (its printed name,
/// whether its nodes are rational and symmetric, its interior polynomial over any field and, for
/// an irrational family, that polynomial's value and slope in any scalar); adding a family is
/// one class here and its entry in `node_families` (core/dispatch.hpp).
///
/// The irrational families are roots of a polynomial given by a three-term recurrence. They
/// are found by the same arithmetic in every scalar type: a sign-change scan, then safeguarded
/// Newton in the scalar itself. So they are `constexpr` in double and long double and reach the
/// full precision of a Boost.Multiprecision type at run time; no constant passes through a
/// double literal. The recurrences run in x = 1 - 2c, entering only as x*P = P - 2c*P, so that
/// nodes near 0 keep their relative precision; a symmetric family's roots are computed in the
/// half c < 1/2 and the upper half follows from c_{m-a} = 1 - c_a.

#include <array>
#include <concepts>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include "geomint/core/orthogonal_polynomials.hpp"
#include "geomint/core/rational.hpp"

namespace geomint {

/// Largest m for exact (rational) families: every identity in the compile-time suite fits
/// 64-bit rationals up to here.
inline constexpr int max_exact_m = 8;
/// Largest m for floating families (double, long double, multiprecision).
inline constexpr int max_floating_m = 16;

namespace core::detail {

/// Value and derivative (with respect to c) of a family's interior polynomial at c.
template <class T>
struct value_and_slope {
  T value;
  T slope;
};

/// Legendre P_n and its first two x-derivatives at x = 1 - 2c by the three-term recurrence
/// (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}, differentiated term by term.
template <class T>
struct legendre_values {
  T p, dp, d2p;
};

template <class T>
constexpr legendre_values<T> legendre_at(int n, const T& c) {
  const T two_c = c + c;
  auto times_x = [&](const T& v) { return T(v - two_c * v); };  // x*v with x = 1 - 2c
  T p_prev(0), p(1), dp_prev(0), dp(0), d2p_prev(0), d2p(0);
  for (int k = 0; k < n; ++k) {
    const T a(2 * k + 1), b(k), d(k + 1);
    const T p_next = (a * times_x(p) - b * p_prev) / d;
    const T dp_next = (a * (p + times_x(dp)) - b * dp_prev) / d;
    const T d2p_next = (a * (dp + dp + times_x(d2p)) - b * d2p_prev) / d;
    p_prev = p;
    p = p_next;
    dp_prev = dp;
    dp = dp_next;
    d2p_prev = d2p;
    d2p = d2p_next;
  }
  return {p, dp, d2p};
}

/// Chebyshev U_n and its x-derivative: U_{k+1} = 2 x U_k - U_{k-1}.
template <class T>
constexpr legendre_values<T> chebyshev_u_at(int n, const T& c) {
  const T two_c = c + c;
  auto times_x = [&](const T& v) { return T(v - two_c * v); };
  T u_prev(0), u(1), du_prev(0), du(0);
  for (int k = 0; k < n; ++k) {
    const T two(2);
    const T u_next = two * times_x(u) - u_prev;
    const T du_next = two * (u + times_x(du)) - du_prev;
    u_prev = u;
    u = u_next;
    du_prev = du;
    du = du_next;
  }
  return {u, du, T(0)};
}

/// P_m(x) + sign P_{m-1}(x) over its factor at the Radau end, w = 1 + x = 2 - 2c (sign +1: the
/// root c = 1) or w = 1 - x = 2c (sign -1: the root c = 0), with its c-slope (dx/dc = -2).
/// Not evaluated at that end (the node scan never does).
template <class T>
constexpr value_and_slope<T> radau_interior_at(int m, const T& c, int sign) {
  const auto hi = legendre_at<T>(m, c), lo = legendre_at<T>(m - 1, c);
  const T s(sign);
  const T f = hi.p + s * lo.p, df = T(-2) * (hi.dp + s * lo.dp);
  const T w = sign > 0 ? T(T(2) - c - c) : T(c + c), dw(sign > 0 ? -2 : 2);
  const T g = f / w;
  return {g, (df - g * dw) / w};
}

/// P*_m + sign P*_{m-1} (ascending in c over K) divided by its root at the Radau end: c - 1
/// (sign -1) or c (sign +1).
template <class K, std::size_t N>
constexpr std::array<K, N> radau_interior_polynomial(int m, int sign) {
  const auto hi = shifted_orthogonal_polynomial<K, N + 1>(shifted_orthogonal_kind::legendre, m);
  const auto lo = shifted_orthogonal_polynomial<K, N + 1>(shifted_orthogonal_kind::legendre, m - 1);
  std::array<K, N + 1> f{};
  for (std::size_t k = 0; k <= N; ++k) f[k] = sign > 0 ? K(hi[k] + lo[k]) : K(hi[k] - lo[k]);
  std::array<K, N> q{};
  if (sign > 0) {  // f = c q: f_0 = 0
    for (std::size_t k = 0; k < N; ++k) q[k] = f[k + 1];
  } else {  // f = (c - 1) q: synthetic division from the top
    K carry(0);
    for (std::size_t k = static_cast<std::size_t>(m); k-- > 0;) {
      carry = carry + f[k + 1];
      q[k] = carry;
    }
  }
  return q;
}

}  // namespace core::detail

struct equispaced {
  static constexpr std::string_view name = "equispaced";
  static constexpr std::string_view type_name = "equispaced";
  static constexpr bool is_rational = true;
  static constexpr bool symmetric = true;
  /// c_a = a/m.
  template <class T>
  static constexpr T node(int a, int m) {
    return T(a) / T(m);
  }
  /// prod_{a=1}^{m-1} (c - a/m), ascending, over K.
  template <class K, std::size_t N>
  static constexpr std::array<K, N> interior_polynomial(int m) {
    std::array<K, N> p{};
    p[0] = K(1);
    for (int a = 1; a < m; ++a)
      for (std::size_t k = static_cast<std::size_t>(a); k + 1 > 0; --k) p[k] = (k >= 1 ? p[k - 1] : K(0)) - node<K>(a, m) * p[k];
    return p;
  }
};
struct gauss_lobatto {
  static constexpr std::string_view name = "lobatto";
  static constexpr std::string_view type_name = "gauss_lobatto";
  static constexpr bool is_rational = false;
  static constexpr bool symmetric = true;
  template <class T>
  static constexpr core::detail::value_and_slope<T> interior_polynomial_at(int m, const T& c) {
    const auto v = core::detail::legendre_at<T>(m, c);
    return {v.dp, T(-2) * v.d2p};
  }
  template <class K, std::size_t N>
  static constexpr std::array<K, N> interior_polynomial(int m) {
    return shifted_orthogonal_polynomial<K, N>(shifted_orthogonal_kind::legendre_derivative, m);
  }
};
struct chebyshev_lobatto {
  static constexpr std::string_view name = "chebyshev";
  static constexpr std::string_view type_name = "chebyshev_lobatto";
  static constexpr bool is_rational = false;
  static constexpr bool symmetric = true;
  template <class T>
  static constexpr core::detail::value_and_slope<T> interior_polynomial_at(int m, const T& c) {
    const auto v = core::detail::chebyshev_u_at<T>(m - 1, c);
    return {v.p, T(-2) * v.dp};
  }
  template <class K, std::size_t N>
  static constexpr std::array<K, N> interior_polynomial(int m) {
    return shifted_orthogonal_polynomial<K, N>(shifted_orthogonal_kind::chebyshev_u, m - 1);
  }
};
struct gauss_interior {
  static constexpr std::string_view name = "gauss-interior";
  static constexpr std::string_view type_name = "gauss_interior";
  static constexpr bool is_rational = false;
  static constexpr bool symmetric = true;
  template <class T>
  static constexpr core::detail::value_and_slope<T> interior_polynomial_at(int m, const T& c) {
    const auto v = core::detail::legendre_at<T>(m - 1, c);
    return {v.p, T(-2) * v.dp};
  }
  template <class K, std::size_t N>
  static constexpr std::array<K, N> interior_polynomial(int m) {
    return shifted_orthogonal_polynomial<K, N>(shifted_orthogonal_kind::legendre, m - 1);
  }
};
/// The Radau IIA points of m stages (1 among them) and 0.
struct radau_right {
  static constexpr std::string_view name = "radau-right";
  static constexpr std::string_view type_name = "radau_right";
  static constexpr bool is_rational = false;
  static constexpr bool symmetric = false;
  template <class T>
  static constexpr core::detail::value_and_slope<T> interior_polynomial_at(int m, const T& c) {
    return core::detail::radau_interior_at<T>(m, c, 1);  // P_m(x) + P_{m-1}(x) = +-(P*_m - P*_{m-1})(c)
  }
  template <class K, std::size_t N>
  static constexpr std::array<K, N> interior_polynomial(int m) {
    return core::detail::radau_interior_polynomial<K, N>(m, -1);
  }
};
/// The Radau IA points of m stages (0 among them) and 1: radau_right's nodes reflected.
struct radau_left {
  static constexpr std::string_view name = "radau-left";
  static constexpr std::string_view type_name = "radau_left";
  static constexpr bool is_rational = false;
  static constexpr bool symmetric = false;
  template <class T>
  static constexpr core::detail::value_and_slope<T> interior_polynomial_at(int m, const T& c) {
    return core::detail::radau_interior_at<T>(m, c, -1);  // P_m(x) - P_{m-1}(x) = +-(P*_m + P*_{m-1})(c)
  }
  template <class K, std::size_t N>
  static constexpr std::array<K, N> interior_polynomial(int m) {
    return core::detail::radau_interior_polynomial<K, N>(m, 1);
  }
};

/// A node family: its printed name (`--nodes`) and type name, whether its nodes are rational
/// (then `node<T>(a, m)` gives c_a) and symmetric (c_{m-a} = 1 - c_a), the coefficients of its
/// interior polynomial over a field K (ascending in c, N of them: the exact tableaux) and, for
/// an irrational family, that polynomial's value and c-slope in a scalar T (the node scan).
template <class F>
concept node_family =
    requires {
      { F::name } -> std::convertible_to<std::string_view>;
      { F::type_name } -> std::convertible_to<std::string_view>;
      { F::is_rational } -> std::convertible_to<bool>;
      { F::symmetric } -> std::convertible_to<bool>;
      { F::template interior_polynomial<rational, 8>(3) } -> std::same_as<std::array<rational, 8>>;
    } && (F::is_rational ? requires { { F::template node<double>(1, 3) } -> std::same_as<double>; }
                         : requires { { F::template interior_polynomial_at<double>(3, 0.25) } -> std::same_as<core::detail::value_and_slope<double>>; });

/// True for the exact scalar type.
template <class T>
inline constexpr bool is_exact_scalar_v = std::is_same_v<T, rational>;

/// Compile-time check of (Family, m, T); each failure is a readable static_assert.
template <class Family, int M, class T>
constexpr void check_node_parameters() {
  static_assert(node_family<Family>, "geomint: Family must be a node family (geomint::node_family, core/nodes.hpp)");
  static_assert(!is_exact_scalar_v<T> || Family::is_rational,
                "geomint: this node family is irrational; use a floating or multiprecision scalar, not rational");
  static_assert(M >= 1, "geomint: m must be >= 1 (m+1 nodes including both ends)");
  static_assert(!is_exact_scalar_v<T> || M <= max_exact_m,
                "geomint: m must be <= max_exact_m (8) for exact rational nodes");
  static_assert(M <= max_floating_m, "geomint: m must be <= max_floating_m (16)");
}

namespace core::detail {

template <class T>
constexpr T abs_value(const T& x) {
  return x < T(0) ? T(-x) : x;
}

constexpr bool opposite_signs(bool a_negative, bool b_negative) { return a_negative != b_negative; }

/// Safeguarded Newton on [lo, hi] where the interior polynomial changes sign: a Newton step
/// that leaves the bracket, or does not halve the step, is replaced by bisection. Stops when
/// the step is below the scalar's epsilon relative to the root.
template <class Family, int M, class T>
constexpr T polish_root(T lo, T hi) {
  const T eps = std::numeric_limits<T>::epsilon();
  const bool lo_negative = Family::template interior_polynomial_at<T>(M, lo).value < T(0);
  T x = (lo + hi) / T(2);
  T last_step = hi - lo;
  for (int iteration = 0; iteration < 4000; ++iteration) {
    const auto f = Family::template interior_polynomial_at<T>(M, x);
    if (f.value == T(0)) return x;
    if ((f.value < T(0)) == lo_negative)
      lo = x;
    else
      hi = x;
    T next = x;
    bool newton_ok = !(f.slope == T(0));
    if (newton_ok) {
      next = x - f.value / f.slope;
      const T newton_step = abs_value(T(next - x));
      // A Newton step at the rounding level ends the iteration (quadratic convergence).
      if (newton_step <= T(4) * eps * x) return next;
      newton_ok = next > lo && next < hi && newton_step * T(2) <= last_step;
    }
    if (!newton_ok) next = (lo + hi) / T(2);
    const T step = abs_value(T(next - x));
    last_step = step;
    x = next;
    if (step <= eps * x || hi - lo <= eps * x) return x;
  }
  throw std::runtime_error("geomint: node root-finding did not converge");
}

}  // namespace core::detail

namespace core::detail {

/// The node set without the range checks of `nodes` (also serves the Gauss rule with m + 1
/// = max_floating_m + 1 points, core/quadrature.hpp).
template <class Family, int M, class T>
constexpr std::array<T, M + 1> node_set() {
  std::array<T, M + 1> c{};
  if constexpr (Family::is_rational) {
    for (int a = 0; a <= M; ++a) c[static_cast<std::size_t>(a)] = Family::template node<T>(a, M);
  } else {
    c[0] = T(0);
    c[M] = T(1);
    constexpr int interior = M - 1;  // roots of the interior polynomial
    // A symmetric family: the roots with c < 1/2 (and 1/2 itself for an odd count), the others
    // mirrored; any other family: every root in (0, 1).
    constexpr int wanted = Family::symmetric ? interior / 2 : interior;
    if constexpr (Family::symmetric && interior % 2 == 1) c[static_cast<std::size_t>(M / 2)] = T(1) / T(2);
    // Scan with spacing 1/(2 m^2 + 16), from the first grid point on: at least twice finer than
    // the smallest gap between two roots or a root and an end, 1 - x_1 ~ j_0^2 / (2 (m - 1/2)^2)
    // in x, i.e. about 1.4/m^2 in c (Gauss interior; the Lobatto, Chebyshev and Radau gaps are
    // wider), so no root lies before the first grid point, and none is an end (where the Radau
    // families' quotients are not evaluated).
    constexpr int grid = M * M + 8;
    constexpr int points = Family::symmetric ? grid : 2 * grid;  // k / (2 grid), k < points
    const auto negative_at = [](const T& x) { return Family::template interior_polynomial_at<T>(M, x).value < T(0); };
    int found = 0;
    T left = T(1) / T(2 * grid);
    bool left_negative = negative_at(left);
    for (int k = 2; k < points && found < wanted; ++k) {
      const T right = T(k) / T(2 * grid);
      const bool right_negative = negative_at(right);
      if (opposite_signs(left_negative, right_negative)) {
        const T root = polish_root<Family, M, T>(left, right);
        ++found;
        c[static_cast<std::size_t>(found)] = root;
        if constexpr (Family::symmetric) c[static_cast<std::size_t>(M - found)] = T(1) - root;
      }
      left = right;
      left_negative = right_negative;
    }
    if (found != wanted) throw std::runtime_error("geomint: node scan missed a root");
  }
  return c;
}

}  // namespace core::detail

/// The m+1 nodes of a family on [0, 1], ascending. constexpr for rational (equispaced),
/// double and long double; any Boost.Multiprecision type at run time, to full precision.
template <class Family, int M, class T = double>
constexpr std::array<T, M + 1> nodes() {
  check_node_parameters<Family, M, T>();
  return core::detail::node_set<Family, M, T>();
}

/// The nodes as a constexpr variable (rational, double, long double).
template <class Family, int M, class T = double>
inline constexpr std::array<T, M + 1> nodes_v = nodes<Family, M, T>();

}  // namespace geomint
