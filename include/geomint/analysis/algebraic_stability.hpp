#pragma once
/// Linear stability on y'' = -y, and on y' = lambda y for rk, of a fixed-size tableau over a constexpr Q(r)
/// (methods::algebraic_number<P>: Forest-Ruth and Yoshida over Q(2^(1/3)), McLachlan's SB3A over
/// quadratic fields), in a constant expression: the analysis of field_stability.hpp, whose run-time
/// field elements allocate, with the fixed-size types of linear_stability.hpp and
/// stability_interval.hpp, so that `static_assert` can check the interval.
///
/// The step's polynomials in z = tau^2 (D = det(I + z A), tr M = Tn / D, det M = Dn / D^2) are
/// exact over Q(r) (method_verdicts.hpp's determinants at z = 0..s, interpolated). Every stability
/// condition F(z) (|tr M| <= 2 on P / Q = Tn / D in lowest terms over Q(r) when det M = 1, else
/// Jury's three) is positive just right of 0, and its bound is its first sign change for z > 0,
/// among the real roots of its norm N(z) = prod_j F(z, r_j) over Q: N(z0) is the determinant of
/// multiplication by F(z0, r) on the basis 1, r, ..., r^(n-1), at z0 = 0..n deg F, interpolated.
/// The roots of N's squarefree part are isolated exactly (Sturm, stability_interval.hpp) and F's
/// sign between them is its exact sign at a rational point: the interval end is an algebraic
/// number, the root of a rational polynomial in a rational bracket, as the rational path gives it.
/// Exact signs in Q(r): interval Horner over r's bracket (lo, hi], halved by the sign of P until
/// the interval excludes 0. Limits: at most 8 stages; N of degree at most 22 and its Sturm
/// sequence in 3072-bit integers, else a compile error (a constant expression that throws);
/// the run-time path (field_stability.hpp) has no such bound on the numbers.

#include <array>
#include <cstddef>
#include <stdexcept>

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/analysis/rk_stability.hpp"
#include "geomint/analysis/stability_interval.hpp"
#include "geomint/methods/algebraic_number.hpp"

namespace geomint {

/// The orders and the interval of the step on y'' = -y over Q(r) (linear_stability_result's
/// meaning; the constants are field_stability.hpp's, at run time).
struct algebraic_linear_stability_result {
  bool determinant_is_one = false;
  int order = 0;              ///< p: R - 2 cos tau = c tau^(p+2) + ...
  int phase_lag_order = 0;
  int dissipation_order = -1;  ///< -1 when det M = 1
  stability_interval interval{};
};

namespace analysis::detail {

/// A polynomial in z over K of degree < C (ascending).
template <class K, int C>
struct fixed_field_polynomial {
  K c[C]{};
  int degree = -1;
  constexpr void trim() {
    degree = C - 1;
    while (degree >= 0 && c[degree].is_zero()) --degree;
  }
  constexpr K operator[](int k) const { return k >= 0 && k <= degree ? c[k] : K(0); }
  constexpr bool is_zero() const { return degree < 0; }
  friend constexpr fixed_field_polynomial operator+(const fixed_field_polynomial& a, const fixed_field_polynomial& b) {
    fixed_field_polynomial r;
    for (int k = 0; k < C; ++k) r.c[k] = a.c[k] + b.c[k];
    r.trim();
    return r;
  }
  friend constexpr fixed_field_polynomial operator-(const fixed_field_polynomial& a, const fixed_field_polynomial& b) {
    fixed_field_polynomial r;
    for (int k = 0; k < C; ++k) r.c[k] = a.c[k] - b.c[k];
    r.trim();
    return r;
  }
  friend constexpr fixed_field_polynomial operator*(const fixed_field_polynomial& a, const fixed_field_polynomial& b) {
    fixed_field_polynomial r;
    if (a.degree + b.degree >= C) throw std::logic_error("geomint::algebraic_linear_stability: polynomial degree beyond its capacity");
    for (int i = 0; i <= a.degree; ++i)
      for (int j = 0; j <= b.degree; ++j) r.c[i + j] += a.c[i] * b.c[j];
    r.trim();
    return r;
  }
  friend constexpr fixed_field_polynomial operator*(const K& x, fixed_field_polynomial p) {
    for (int k = 0; k <= p.degree; ++k) p.c[k] *= x;
    p.trim();
    return p;
  }
  constexpr fixed_field_polynomial times_z() const {
    fixed_field_polynomial r;
    if (degree + 1 >= C) throw std::logic_error("geomint::algebraic_linear_stability: polynomial degree beyond its capacity");
    for (int k = 0; k <= degree; ++k) r.c[k + 1] = c[k];
    r.trim();
    return r;
  }
  constexpr K at(const K& z) const {
    K s(0);
    for (int k = degree; k >= 0; --k) s = s * z + c[k];
    return s;
  }
};

/// a = q b + remainder (b not zero); returns q and leaves the remainder in a.
template <class K, int C>
constexpr fixed_field_polynomial<K, C> divide(fixed_field_polynomial<K, C>& a, const fixed_field_polynomial<K, C>& b) {
  fixed_field_polynomial<K, C> q;
  const K inverse = K(1) / b.c[b.degree];
  while (a.degree >= b.degree) {
    const int shift = a.degree - b.degree;
    const K f = a.c[a.degree] * inverse;
    q.c[shift] = f;
    for (int j = 0; j <= b.degree; ++j) a.c[shift + j] -= f * b.c[j];
    a.c[a.degree] = K(0);  // cancels exactly
    a.trim();
  }
  q.trim();
  return q;
}

/// P / Q in lowest terms over K with Q(0) = 1.
template <class K, int C>
constexpr void reduce_fraction(fixed_field_polynomial<K, C>& P, fixed_field_polynomial<K, C>& Q) {
  fixed_field_polynomial<K, C> a = P, b = Q;
  while (!b.is_zero()) {
    divide(a, b);
    const fixed_field_polynomial<K, C> t = a;
    a = b;
    b = t;
  }
  if (a.degree > 0) {
    P = divide(P, a);
    Q = divide(Q, a);
  }
  if (Q.c[0].is_zero()) throw std::domain_error("geomint::algebraic_linear_stability: R has a pole at 0");
  const K scale = K(1) / Q.c[0];
  P = scale * P;
  Q = scale * Q;
}

/// The exact sign of x in Q(r) (see the top of the file).
template <auto P>
constexpr int exact_sign(const methods::algebraic_number<P>& x) {
  using K = methods::algebraic_number<P>;
  using Q = typename K::coefficient_type;
  if (x.is_zero()) return 0;
  if (x.is_rational()) return x.rational_value().num.sign();
  constexpr int n = decltype(P)::degree;
  auto p_at = [](const Q& y) {
    Q s(0);
    for (int k = n; k >= 0; --k) s = s * y + Q(P.c[k]);
    return s;
  };
  Q lo(P.lo), hi(P.hi);
  const int sign_hi = p_at(hi).num.sign();
  if (sign_hi == 0) {  // r = hi is rational: evaluate there
    Q s(0);
    for (int k = n - 1; k >= 0; --k) s = s * hi + x.coefficient(k);
    return s.num.sign();
  }
  for (int step = 0; step < 400; ++step) {
    // Horner over [lo, hi] (lo >= 0 or not: the four products bound each step).
    Q low = x.coefficient(n - 1), high = low;
    for (int k = n - 2; k >= 0; --k) {
      const Q p1 = low * lo, p2 = low * hi, p3 = high * lo, p4 = high * hi;
      Q mn = p1, mx = p1;
      for (const Q& v : {p2, p3, p4}) {
        if (v < mn) mn = v;
        if (mx < v) mx = v;
      }
      low = mn + x.coefficient(k);
      high = mx + x.coefficient(k);
    }
    if (Q(0) < low) return 1;
    if (high < Q(0)) return -1;
    const Q mid = (lo + hi) / Q(2);
    const int sm = p_at(mid).num.sign();
    if (sm == 0) {
      Q s(0);
      for (int k = n - 1; k >= 0; --k) s = s * mid + x.coefficient(k);
      return s.num.sign();
    }
    (sm == sign_hi ? hi : lo) = mid;
  }
  throw std::logic_error("geomint::algebraic_linear_stability: the sign was not decided");
}

/// N(z) = prod_j F(z, r_j) over Q as an integer polynomial (see the top of the file).
template <auto P, int C>
constexpr wide_polynomial norm_polynomial(const fixed_field_polynomial<methods::algebraic_number<P>, C>& F) {
  using K = methods::algebraic_number<P>;
  constexpr int n = decltype(P)::degree;
  const int degree = n * F.degree;
  if (degree > 2 * max_stability_degree + 2)
    throw std::domain_error("geomint::algebraic_linear_stability: the norm's degree exceeds 22");
  std::array<exact_number, 2 * max_stability_degree + 3> values{};
  const K r = K::generator();
  for (int z0 = 0; z0 <= degree; ++z0) {
    const K v = F.at(K(static_cast<std::int64_t>(z0)));
    std::array<std::array<exact_number, n>, n> m{};
    K column = v;
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) m[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] = column.coefficient(k);
      column = column * r;
    }
    values[static_cast<std::size_t>(z0)] = determinant<exact_number>(m, static_cast<std::size_t>(n));
  }
  const auto coefficients = interpolate<exact_number>(values, static_cast<std::size_t>(degree));
  qpoly q;
  for (int k = 0; k <= degree; ++k) q.c[k] = coefficients[static_cast<std::size_t>(k)];
  q.trim();
  if (q.degree < 0) throw std::logic_error("geomint::algebraic_linear_stability: the norm of a nonzero condition is zero");
  return widen(integer_part_scaled(q, lcm_of_denominators(q, stability_integer(1))));
}

/// The interval where every condition is >= 0 (stability_interval's conventions).
template <auto P, int C, std::size_t M>
constexpr stability_interval interval_of_conditions(stability_kind kind,
                                                    const std::array<fixed_field_polynomial<methods::algebraic_number<P>, C>, M>& conditions) {
  using K = methods::algebraic_number<P>;
  stability_interval out;
  out.kind = kind;
  for (const auto& condition : conditions) {
    if (condition.is_zero()) continue;  // holds with equality for every tau
    fixed_field_polynomial<K, C> F;
    int lowest = 0;
    while (condition.c[lowest].is_zero()) ++lowest;
    for (int k = lowest; k <= condition.degree; ++k) F.c[k - lowest] = condition.c[k];
    F.trim();
    const int below = exact_sign(F.c[0]);
    if (below < 0) {  // violated just right of 0
      out.empty = true;
      out.unbounded = false;
      return out;
    }
    // The squarefree part of the norm, without the root 0 (F(0) != 0, so N(0) != 0).
    const wide_polynomial N = norm_polynomial(F);
    wide_polynomial h = N;
    const wide_polynomial g = polynomial_gcd(N, derivative(N));
    if (g.degree > 0) h = exact_quotient(N, g);
    isolated_root root = first_sign_change(primitive_part(h), below, [&](const exact_number& x) {
      return exact_sign(F.at(K(typename K::coefficient_type(x))));
    });
    if (root.found && root.low < root.high) root.below = -sign_at(root.polynomial, root.high);  // h's own sign left of its root
    if (root.found) keep_smaller_bound(out, root);
  }
  return out;
}

/// |f(iy)|^2 as a polynomial in u = y^2.
template <class K, int C>
constexpr fixed_field_polynomial<K, C> squared_modulus_on_axis(const fixed_field_polynomial<K, C>& f) {
  fixed_field_polynomial<K, C> reflected = f;
  for (int k = 1; k <= f.degree; k += 2) reflected.c[k] = -f.c[k];
  const fixed_field_polynomial<K, C> h = f * reflected;
  fixed_field_polynomial<K, C> out;
  for (int j = 0; 2 * j <= h.degree; ++j) out.c[j] = j % 2 == 0 ? h.c[2 * j] : -h.c[2 * j];
  out.trim();
  return out;
}

}  // namespace analysis::detail

/// The verdicts of rk_stability_result on y' = lambda y over Q(r).
struct algebraic_rk_stability_result {
  bool bounded_on_imaginary_axis = false;
  bool poles_in_right_half_plane = false;
  bool a_stable = false;
  bool l_stable = false;
  stability_interval imaginary_axis{};  ///< [0, Y] with |R(iy)| <= 1; the bound is Y^2
};

/// R(z) = P / Q of an rk tableau over algebraic_number<P> in lowest terms, and the verdicts of
/// rk_stability.hpp: the imaginary-axis interval from |Q(iy)|^2 - |P(iy)|^2 (its first sign
/// change, as above), the poles by Routh's array with the exact signs of Q(r), A- and L-stability.
template <auto Field, int S>
constexpr algebraic_rk_stability_result algebraic_rk_stability(const methods::rk<methods::algebraic_number<Field>, S>& t) {
  static_assert(S <= max_exact_stages, "geomint::algebraic_rk_stability: at most max_exact_stages (8) stages");
  using K = methods::algebraic_number<Field>;
  using namespace analysis::detail;
  using poly = fixed_field_polynomial<K, 2 * max_stability_degree + 3>;
  const auto r = stability_function(t);
  poly Pn, Qd;
  for (std::size_t k = 0; k <= static_cast<std::size_t>(S); ++k) {
    Pn.c[k] = r.numerator[k];
    Qd.c[k] = r.denominator[k];
  }
  Pn.trim();
  Qd.trim();
  reduce_fraction(Pn, Qd);
  algebraic_rk_stability_result out;
  const poly e = squared_modulus_on_axis(Qd) - squared_modulus_on_axis(Pn);
  out.imaginary_axis = interval_of_conditions(e.is_zero() ? stability_kind::periodic : stability_kind::absolute, std::array<poly, 1>{e});
  out.bounded_on_imaginary_axis = !out.imaginary_axis.empty && out.imaginary_axis.unbounded;
  // Q(-w) Hurwitz: the poles of R in the right half-plane.
  out.poles_in_right_half_plane = routh_hurwitz<K, 2 * max_stability_degree + 2>(
      Qd.degree, [&](int k) { return k % 2 == 0 ? Qd.c[k] : -Qd.c[k]; }, [](const K& x) { return exact_sign(x); });
  out.a_stable = out.bounded_on_imaginary_axis && out.poles_in_right_half_plane;
  out.l_stable = out.a_stable && Pn.degree < Qd.degree;
  return out;
}

/// The step on y'' = -y of a fixed-size tableau over algebraic_number<P> (see the top of the file).
template <class Tableau>
  requires requires(const Tableau& t) { Tableau::kind; t.c; }
constexpr algebraic_linear_stability_result algebraic_linear_stability(const Tableau& t) {
  static_assert(Tableau::stages <= max_exact_stages, "geomint::algebraic_linear_stability: at most max_exact_stages (8) stages");
  using K = typename Tableau::coefficient;
  using namespace analysis::detail;
  constexpr std::size_t s = static_cast<std::size_t>(Tableau::stages);
  constexpr int C = 2 * max_stability_degree + 3;
  using poly = fixed_field_polynomial<K, C>;
  const auto r = rkn_coefficients_of(t);
  const auto d = oscillator_determinants<K>(r.c, r.a, r.bbar, r.b, s, std::array<std::array<K, s + 1>, s + 1>{}, std::array<K, s + 1>{});
  poly D, E_bbar_one, E_bbar_c, E_b_one, E_b_c;
  poly* targets[5] = {&D, &E_bbar_one, &E_bbar_c, &E_b_one, &E_b_c};
  for (std::size_t i = 0; i < 5; ++i) {
    for (std::size_t k = 0; k <= s; ++k) targets[i]->c[k] = d[i][k];
    targets[i]->trim();
  }
  const poly trace_num = D + D + (E_bbar_one + E_b_c).times_z();
  const poly det_num = (D + E_bbar_one.times_z()) * (D + E_b_c.times_z()) - (D + E_bbar_c.times_z()) * E_b_one.times_z();
  const poly excess = det_num - D * D;
  algebraic_linear_stability_result out;
  out.determinant_is_one = excess.is_zero();
  poly Pn = trace_num, Qd = D;
  reduce_fraction(Pn, Qd);
  // R - 2 cos = (P - 2 Q cos) / Q: its first nonzero coefficient.
  bool expanded = false;
  for (int k = 0; k <= Pn.degree + Qd.degree + 1 && !expanded; ++k) {
    K E = Pn[k];
    K cosine(2);  // 2 (-1)^j / (2j)!, j = k - i, from j = 0
    for (int j = 0; j <= k; ++j) {
      if (j > 0) cosine = -cosine / K(static_cast<std::int64_t>((2 * j - 1) * (2 * j)));
      E -= Qd[k - j] * cosine;
    }
    if (E.is_zero()) continue;
    out.order = 2 * k - 2;
    expanded = true;
  }
  if (!expanded) throw std::domain_error("geomint::algebraic_linear_stability: R(tau) - 2 cos(tau) has no nonzero term");
  if (out.determinant_is_one) {
    out.phase_lag_order = out.order;
    const K two(2);
    out.interval = interval_of_conditions(stability_kind::periodic, std::array<poly, 2>{two * Qd - Pn, two * Qd + Pn});
    return out;
  }
  int k = 0;
  while (excess.c[k].is_zero()) ++k;
  out.dissipation_order = 2 * k - 1;
  out.phase_lag_order = 2 * phase_series<K>(trace_num, D, det_num).index - 2;
  const poly D2 = D * D, TD = trace_num * D;
  out.interval = interval_of_conditions(stability_kind::absolute, std::array<poly, 3>{D2 - det_num, D2 + det_num - TD, D2 + det_num + TD});
  return out;
}

}  // namespace geomint
