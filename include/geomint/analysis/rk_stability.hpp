#pragma once
/// Linear stability of a Runge-Kutta method on y' = lambda y, exactly (Hairer & Wanner, Solving
/// Ordinary Differential Equations II, 2nd ed., sections IV.2 and IV.3; docs/references.md).
///
/// One step maps y to R(z) y, z = h lambda, with the stability function (HW II, section IV.3)
///   R(z) = P(z) / Q(z),   P(z) = det(I - z A + z 1 b^T),   Q(z) = det(I - z A).
///
/// - `stability_function(t)`: P and Q over the tableau's own coefficient type K, ascending
///   powers, not reduced. Both determinants are evaluated at z = 0..S over K (Gaussian
///   elimination, exact) and interpolated (Newton's divided differences). Constexpr for the
///   fixed-size methods::rk<K, S> over a constexpr K (geomint::rational, exact_number); at run
///   time for methods::tableau_data<K> (exact_rational, field_element of methods/number_field.hpp).
/// - `rk_stability(t)` (or of a `rational_function`): the exact verdicts on R in lowest terms in
///   Z[z]. Constexpr; R's coefficients must be rational (a field_element R with an irrational
///   coefficient is a std::domain_error naming it: `field_rk_stability` of field_stability.hpp
///   decides it at run time; the Q(r) tableaux of the literature, Gauss and Radau with sqrt 3,
///   sqrt 6, sqrt 15, have rational R) and S <= max_exact_stages:
///   - bounded on the imaginary axis: E(y) = |Q(iy)|^2 - |P(iy)|^2 = e(y^2) >= 0 for every real
///     y, i.e. e(u) >= 0 for u >= 0. e(0) = 0; e / u^k must be positive at 0 and have no
///     positive root of odd multiplicity (Sturm sequences and exact bisection of
///     linear_stability.hpp);
///   - no pole in Re z <= 0: Q(-w) is a Hurwitz polynomial (Routh's array with a positive first
///     column; a zero in it makes a Hurwitz determinant vanish, so the polynomial is not Hurwitz);
///   - A-stable iff both (|R| <= 1 on Re z <= 0 by the maximum principle; HW II, section IV.3),
///     L-stable iff A-stable and deg P < deg Q, i.e. R(inf) = 0 (HW II, section IV.3);
///   - the imaginary-axis interval [0, Y]: the largest Y with |R(iy)| <= 1 on [0, Y]. Y^2 is the
///     smallest positive root of odd multiplicity of e, an exact algebraic number held as a
///     `stability_interval` (compare_squared(y^2), refined(bits)); unbounded (Y = inf) when there
///     is none, empty (Y = 0) when e < 0 just right of 0. Its kind is `periodic` when
///     |R(iy)| = 1 identically (e = 0), else `absolute`. On y'' = -y written as q' = p, p' = -q
///     the method's step matrix has the eigenvalues R(+-i tau), so Y is also its interval there.
///
///   constexpr auto euler = geomint::methods::make_rk<geomint::rational>({1}, {{1}}, {1});
///   static_assert(geomint::rk_stability(euler).l_stable);

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/methods/number_field.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint {

/// P(z) / Q(z), coefficients in ascending powers of z (a std::array or std::vector of K).
template <class Coefficients>
struct rational_function {
  Coefficients numerator{};
  Coefficients denominator{};
};

/// The exact linear-stability verdicts of a Runge-Kutta method on y' = lambda y.
struct rk_stability_result {
  stability_polynomial numerator{};    ///< P: R = P / Q in lowest terms in Z[z]
  stability_polynomial denominator{};  ///< Q, Q(0) > 0
  bool bounded_on_imaginary_axis = false;  ///< |R(iy)| <= 1 for every real y
  bool poles_in_right_half_plane = false;  ///< every pole of R has Re z > 0 (or R is a polynomial)
  bool a_stable = false;                   ///< |R(z)| <= 1 for Re z <= 0
  bool l_stable = false;                   ///< A-stable and R(inf) = 0
  stability_interval imaginary_axis{};     ///< [0, Y] with |R(iy)| <= 1; the bound is Y^2
};

namespace analysis::detail {

/// det m (n x n) over a field K: Gaussian elimination, pivots found by exact comparison with 0.
template <class K, class Matrix>
constexpr K determinant(Matrix m, std::size_t n) {
  K det(1);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    while (pivot < n && m[pivot][k] == K(0)) ++pivot;
    if (pivot == n) return K(0);
    if (pivot != k) {
      std::swap(m[pivot], m[k]);
      det = K(0) - det;
    }
    det = det * m[k][k];
    for (std::size_t i = k + 1; i < n; ++i) {
      if (m[i][k] == K(0)) continue;
      const K f = m[i][k] / m[k][k];
      for (std::size_t j = k; j < n; ++j) m[i][j] = m[i][j] - f * m[k][j];
    }
  }
  return det;
}

/// The coefficients (ascending) of the polynomial of degree <= n through (k, v[k]), k = 0..n:
/// Newton's divided differences on the nodes 0..n, expanded by Horner's rule.
template <class K, class Vec>
constexpr Vec interpolate(Vec v, std::size_t n) {
  for (std::size_t k = 1; k <= n; ++k)
    for (std::size_t j = n; j >= k; --j) v[j] = (v[j] - v[j - 1]) / K(static_cast<std::int64_t>(k));
  Vec p = v;
  for (std::size_t j = 0; j <= n; ++j) p[j] = K(0);
  p[0] = v[n];
  for (std::size_t k = n; k-- > 0;) {  // p <- p (z - k) + v[k]
    const K node(static_cast<std::int64_t>(k));
    for (std::size_t j = n - k; j >= 1; --j) p[j] = p[j - 1] - node * p[j];
    p[0] = v[k] - node * p[0];
  }
  return p;
}

/// P and Q of the header comment at z = 0..s, interpolated: `work` is an s x s matrix of K,
/// `out` holds s + 1 entries.
template <class K, class Matrix, class Weights, class Vec>
constexpr void stability_polynomials(const Matrix& a, const Weights& b, std::size_t s, Matrix work, rational_function<Vec>& out) {
  for (std::size_t k = 0; k <= s; ++k) {
    const K z(static_cast<std::int64_t>(k));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) work[i][j] = K(i == j ? 1 : 0) - z * a[i][j];
    out.denominator[k] = determinant<K>(work, s);
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) work[i][j] = work[i][j] + z * b[j];
    out.numerator[k] = determinant<K>(work, s);
  }
  out.numerator = interpolate<K>(out.numerator, s);
  out.denominator = interpolate<K>(out.denominator, s);
}

/// The exact number of a coefficient: geomint::rational and exact_number at compile time;
/// exact_rational and rational field_elements at run time (std::overflow_error beyond 512 bits,
/// std::domain_error for an irrational field_element).
constexpr exact_number to_exact(const rational& x) { return exact_number(x); }
constexpr exact_number to_exact(const exact_number& x) { return x; }
/// An algebraic_number (constexpr): its value when rational, else std::domain_error (a compile
/// error in a constant expression).
template <auto P>
constexpr exact_number to_exact(const methods::algebraic_number<P>& x) {
  static_assert(std::is_same_v<typename methods::algebraic_number<P>::coefficient_type, exact_number>,
                "geomint: algebraic_number and the exact analyses share one big_rational type");
  if (!x.is_rational()) throw std::domain_error("the coefficient is not rational (the exact stability verdicts need rational polynomials)");
  return x.rational_value();
}
/// A big_integer<L> from a cpp_int (std::overflow_error when it does not fit).
template <int L = exact_algebra_limbs>
big_integer<L> to_exact_integer(boost::multiprecision::cpp_int x) {
  const bool negative = x < 0;
  if (negative) x = -x;
  std::vector<std::uint32_t> limbs;
  while (x != 0) {
    const boost::multiprecision::cpp_int low = x & 0xffffffffu;
    limbs.push_back(low.convert_to<std::uint32_t>());
    x >>= 32;
  }
  big_integer<L> r;
  const big_integer<L> base(std::int64_t(1) << 32);
  for (auto it = limbs.rbegin(); it != limbs.rend(); ++it) r = r * base + big_integer<L>(static_cast<std::int64_t>(*it));
  return negative ? -r : r;
}
inline exact_number to_exact(const methods::exact_rational& x) {
  return exact_number(to_exact_integer(boost::multiprecision::numerator(x)), to_exact_integer(boost::multiprecision::denominator(x)));
}
inline exact_number to_exact(const methods::field_element& x) {
  if (!x.is_rational())
    throw std::domain_error("the coefficient is not rational (the exact stability verdicts need rational polynomials)");
  return to_exact(x.rational_value());
}

/// A polynomial over K (ascending coefficients) as a qpoly.
template <class Vec>
constexpr qpoly to_qpoly(const Vec& v) {
  qpoly p;
  if (v.size() > static_cast<std::size_t>(qpoly::capacity)) throw std::overflow_error("geomint: stability polynomial degree overflow");
  for (std::size_t k = 0; k < v.size(); ++k) p.c[k] = to_exact(v[k]);
  p.trim();
  return p;
}

/// |f(iy)|^2 as a polynomial in u = y^2: with h(z) = f(z) f(-z) (even), sum_j (-1)^j h_2j u^j.
constexpr wide_polynomial squared_modulus_on_axis(const wide_polynomial& f) {
  wide_polynomial reflected = f;
  for (int k = 1; k <= f.degree; k += 2) reflected[k] = -f[k];
  const wide_polynomial h = f * reflected;
  wide_polynomial out;
  for (int j = 0; 2 * j <= h.degree; ++j) out[j] = j % 2 == 0 ? h[2 * j] : -h[2 * j];
  out.trim();
  return out;
}

/// Whether every root of the degree-n polynomial with coefficients coefficient(k) has a negative
/// real part (Routh's array; HW II, section IV.3 and Hurwitz's criterion: the first column is
/// positive iff every Hurwitz determinant is). K: exact_number, or field_element at run time;
/// `sign` gives the exact sign of a K; at most Width - 2 = n.
template <class K, int Width, class Coefficient, class Sign>
constexpr bool routh_hurwitz(int n, const Coefficient& coefficient, const Sign& sign) {
  if (n <= 0) return true;
  if (n + 2 > Width) throw std::overflow_error("geomint: Routh array of too high a degree");
  K upper[Width], lower[Width];
  const K lead(sign(coefficient(n)));
  for (int k = 0; n - 2 * k >= 0; ++k) upper[k] = lead * coefficient(n - 2 * k);
  for (int k = 0; n - 1 - 2 * k >= 0; ++k) lower[k] = lead * coefficient(n - 1 - 2 * k);
  for (int row = 1; row <= n; ++row) {
    if (sign(lower[0]) <= 0) return false;
    K next[Width];
    for (int k = 0; k + 1 < Width; ++k) next[k] = (lower[0] * upper[k + 1] - upper[0] * lower[k + 1]) / lower[0];
    for (int k = 0; k < Width; ++k) {
      upper[k] = lower[k];
      lower[k] = next[k];
    }
  }
  return true;
}
constexpr bool hurwitz(const stability_polynomial& g) {
  return routh_hurwitz<exact_number, max_stability_degree + 2>(
      g.degree, [&](int k) { return exact_number::from_integer(g[k]); }, [](const exact_number& x) { return x.sign(); });
}

}  // namespace analysis::detail

/// R(z) = P(z) / Q(z) of an rk tableau over its coefficients (constexpr).
template <class K, int S>
constexpr rational_function<std::array<K, static_cast<std::size_t>(S) + 1>> stability_function(const methods::rk<K, S>& t) {
  rational_function<std::array<K, static_cast<std::size_t>(S) + 1>> r;
  analysis::detail::stability_polynomials<K>(t.a, t.b, static_cast<std::size_t>(S), t.a, r);
  return r;
}

/// R(z) of an rk tableau with its stage count known at run time (std::invalid_argument for
/// another kind or inconsistent sizes).
template <class K>
rational_function<std::vector<K>> stability_function(const methods::tableau_data<K>& t) {
  if (t.kind != methods::method_kind::rk)
    throw std::invalid_argument("stability_function: an rk tableau is needed, got " + std::string(methods::to_string(t.kind)));
  const auto s = static_cast<std::size_t>(t.stages);
  bool sizes = t.stages >= 1 && t.a.size() == s && t.b.size() == s;
  for (const auto& row : t.a) sizes = sizes && row.size() == s;
  if (!sizes) throw std::invalid_argument("stability_function: a must be S x S and b have S entries");
  rational_function<std::vector<K>> r{std::vector<K>(s + 1, K(0)), std::vector<K>(s + 1, K(0))};
  analysis::detail::stability_polynomials<K>(t.a, t.b, s, t.a, r);
  return r;
}

/// The exact verdicts of the header comment for R = P / Q.
template <class Coefficients>
constexpr rk_stability_result rk_stability(const rational_function<Coefficients>& r) {
  using namespace analysis::detail;
  const qpoly P = to_qpoly(r.numerator), Q = to_qpoly(r.denominator);
  const stability_integer scale = lcm_of_denominators(Q, lcm_of_denominators(P, stability_integer(1)));
  rk_stability_result out;
  out.numerator = integer_part_scaled(P, scale);
  out.denominator = integer_part_scaled(Q, scale);
  reduce_fraction(out.numerator, out.denominator);
  // E: |Q(iy)|^2 - |P(iy)|^2 as a polynomial in u = y^2.
  const wide_polynomial e = squared_modulus_on_axis(widen(out.denominator)) - squared_modulus_on_axis(widen(out.numerator));
  stability_interval& axis = out.imaginary_axis;
  axis.kind = e.is_zero() ? stability_kind::periodic : stability_kind::absolute;
  if (e.is_zero()) {
    out.bounded_on_imaginary_axis = true;
  } else {
    const wide_polynomial F = without_zero_roots(e);
    if (F[0].sign() < 0) {
      axis.empty = true;
      axis.unbounded = false;
    } else {
      const isolated_root root = smallest_odd_positive_root(F);
      if (root.found) {
        axis.bound = root;
        axis.unbounded = false;
      } else {
        out.bounded_on_imaginary_axis = true;
      }
    }
  }
  stability_polynomial reflected = out.denominator;  // Q(-w)
  for (int k = 1; k <= reflected.degree; k += 2) reflected[k] = -reflected[k];
  out.poles_in_right_half_plane = hurwitz(reflected);
  out.a_stable = out.bounded_on_imaginary_axis && out.poles_in_right_half_plane;
  out.l_stable = out.a_stable && out.numerator.degree < out.denominator.degree;
  return out;
}

/// The verdicts of an rk tableau (fixed size: constexpr; tableau_data: run time).
template <class K, int S>
constexpr rk_stability_result rk_stability(const methods::rk<K, S>& t) {
  static_assert(S <= max_exact_stages, "geomint::rk_stability: at most max_exact_stages (8) stages");
  return rk_stability(stability_function(t));
}
template <class K>
rk_stability_result rk_stability(const methods::tableau_data<K>& t) {
  if (t.stages > max_exact_stages) throw std::domain_error("rk_stability: at most 8 stages");
  return rk_stability(stability_function(t));
}

}  // namespace geomint
