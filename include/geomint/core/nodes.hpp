#pragma once
/// Node families on [0, 1]: m+1 nodes c_0 = 0 < c_1 < ... < c_m = 1.
///
/// - `equispaced`:        c_a = a/m, the LPF paper's choice (eq. 8); exact in `rational`.
/// - `gauss_lobatto`:     ends plus the roots of P'_m (Legendre), mapped to [0, 1].
/// - `chebyshev_lobatto`: ends plus the roots of U_{m-1} (Chebyshev, second kind):
///                        c_a = (1 - cos(pi a / m)) / 2.
/// - `gauss_interior`:    ends plus the m-1 Gauss-Legendre points (roots of P_{m-1}).
///
/// The irrational families are roots of a polynomial given by a three-term recurrence. They
/// are found by the same arithmetic in every scalar type: a sign-change scan, then safeguarded
/// Newton in the scalar itself. So they are `constexpr` in double and long double and reach the
/// full precision of a Boost.Multiprecision type at run time; no constant passes through a
/// double literal. Roots are computed in the half c < 1/2, with x = 1 - 2c entering the
/// recurrence only as x*P = P - 2c*P, so that nodes near 0 keep their relative precision;
/// the upper half follows from the symmetry c_{m-a} = 1 - c_a.

#include <array>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include "geomint/core/rational.hpp"

namespace geomint {

/// Largest m for exact (rational) families: every identity in the compile-time suite fits
/// 64-bit rationals up to here.
inline constexpr int max_exact_m = 8;
/// Largest m for floating families (double, long double, multiprecision).
inline constexpr int max_floating_m = 16;

struct equispaced {
  static constexpr std::string_view name = "equispaced";
  static constexpr bool is_rational = true;
};
struct gauss_lobatto {
  static constexpr std::string_view name = "lobatto";
  static constexpr bool is_rational = false;
};
struct chebyshev_lobatto {
  static constexpr std::string_view name = "chebyshev";
  static constexpr bool is_rational = false;
};
struct gauss_interior {
  static constexpr std::string_view name = "gauss-interior";
  static constexpr bool is_rational = false;
};

template <class Family>
concept node_family = std::is_same_v<Family, equispaced> || std::is_same_v<Family, gauss_lobatto> ||
                      std::is_same_v<Family, chebyshev_lobatto> || std::is_same_v<Family, gauss_interior>;

/// True for the exact scalar type.
template <class T>
inline constexpr bool is_exact_scalar_v = std::is_same_v<T, rational>;

/// Compile-time check of (Family, m, T); each failure is a readable static_assert.
template <class Family, int M, class T>
constexpr void check_node_parameters() {
  static_assert(node_family<Family>,
                "geomint: Family must be equispaced, gauss_lobatto, chebyshev_lobatto or gauss_interior");
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

/// Value and derivative (with respect to c) of a family's defining polynomial at x = 1 - 2c.
template <class T>
struct value_and_slope {
  T value;
  T slope;
};

/// Legendre P_n and its first two x-derivatives by the three-term recurrence
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

/// The polynomial whose roots are the interior nodes (degree m-1 in x), and its c-slope.
template <class Family, int M, class T>
constexpr value_and_slope<T> defining_polynomial(const T& c) {
  // dx/dc = -2.
  if constexpr (std::is_same_v<Family, gauss_lobatto>) {
    const auto v = legendre_at<T>(M, c);
    return {v.dp, T(-2) * v.d2p};
  } else if constexpr (std::is_same_v<Family, gauss_interior>) {
    const auto v = legendre_at<T>(M - 1, c);
    return {v.p, T(-2) * v.dp};
  } else {
    static_assert(std::is_same_v<Family, chebyshev_lobatto>);
    const auto v = chebyshev_u_at<T>(M - 1, c);
    return {v.p, T(-2) * v.dp};
  }
}

constexpr bool opposite_signs(bool a_negative, bool b_negative) { return a_negative != b_negative; }

/// Safeguarded Newton on [lo, hi] where the defining polynomial changes sign: a Newton step
/// that leaves the bracket, or does not halve the step, is replaced by bisection. Stops when
/// the step is below the scalar's epsilon relative to the root.
template <class Family, int M, class T>
constexpr T polish_root(T lo, T hi) {
  const T eps = std::numeric_limits<T>::epsilon();
  const bool lo_negative = defining_polynomial<Family, M, T>(lo).value < T(0);
  T x = (lo + hi) / T(2);
  T last_step = hi - lo;
  for (int iteration = 0; iteration < 4000; ++iteration) {
    const auto f = defining_polynomial<Family, M, T>(x);
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
  if constexpr (std::is_same_v<Family, equispaced>) {
    for (int a = 0; a <= M; ++a) c[static_cast<std::size_t>(a)] = T(a) / T(M);
  } else {
    c[0] = T(0);
    c[M] = T(1);
    constexpr int interior = M - 1;  // roots of the defining polynomial
    constexpr int lower = interior / 2;  // roots with c < 1/2
    if constexpr (interior % 2 == 1) c[static_cast<std::size_t>(M / 2)] = T(1) / T(2);
    // Scan (0, 1/2) with spacing 1/(2 m^2 + 16): at least twice finer than the smallest gap
    // between two roots or a root and the end, 1 - x_1 ~ j_0^2 / (2 (m - 1/2)^2) in x, i.e.
    // about 1.4/m^2 in c (Gauss interior; the Lobatto and Chebyshev gaps are wider).
    constexpr int grid = M * M + 8;
    int found = 0;
    T left = T(0);
    bool left_negative = defining_polynomial<Family, M, T>(left).value < T(0);
    for (int k = 1; k < grid && found < lower; ++k) {
      const T right = T(k) / T(2 * grid);
      const bool right_negative = defining_polynomial<Family, M, T>(right).value < T(0);
      if (opposite_signs(left_negative, right_negative)) {
        const T root = polish_root<Family, M, T>(left, right);
        ++found;
        c[static_cast<std::size_t>(found)] = root;
        c[static_cast<std::size_t>(M - found)] = T(1) - root;
      }
      left = right;
      left_negative = right_negative;
    }
    if (found != lower) throw std::runtime_error("geomint: node scan missed a root");
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
