#pragma once
/// Linear stability of an RKN tableau (analysis/rkn_tableau.hpp) on y'' = -y, exactly.
///
/// One step maps (q, tau p) linearly: with z = tau^2, X = (I + z A)^{-1},
///   M = [[1 - z bbar X 1, 1 - z bbar X c], [-z b X 1, 1 - z b X c]],
/// and every entry is a rational function of z computed exactly from bordered determinants:
/// v^T adj(I + z A) u = -det [[I + z A, u], [v^T, 0]] (fraction-free Bareiss elimination over
/// Q[z]). With D = det(I + z A): t = tr M = Tn / D, d = det M = Dn / D^2 (integer polynomials
/// after one common scaling). The two-step form of the scheme is x^{k+1} = t x^k - d x^{k-1}.
/// Whether d = 1 identically is decided exactly (Dn - D^2 is the zero polynomial): true for
/// every symplectic method (and the library's schemes), false for e.g. the explicit
/// non-symplectic RKN methods. R = t = P(z)/Q(z) is reduced to lowest terms in Z[z] (gcd,
/// content, Q(0) > 0) and expanded: R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4)).
///
/// Phase lag and dissipation (van der Houwen and Sommeijer, "Explicit Runge-Kutta(-Nystrom)
/// methods with reduced phase errors for computing oscillating solutions", SIAM J. Numer. Anal.
/// 24 (1987) 595-617), with H = tau:
///   phi(H) = H - arccos(t / (2 sqrt(d))) = c_phi H^(q+1) + O(H^(q+3))   (phase lag, order q),
///   d(H)   = 1 - sqrt(d)                 = c_d H^(r+1) + O(H^(r+3))     (dissipation, order r).
/// Since t / (2 sqrt d) = cos H + e H^(q+2) + ... gives phi = e H^(q+1) + ..., c_phi = e; both
/// series are computed exactly in z (power series of 1/D and d^(-1/2)). With d = 1 the method
/// has no dissipation (dissipation_order = -1) and c_phi = c / 2.
///
/// Stability interval (0, tau*) on y'' = -y: where the roots of l^2 - t l + d lie in the closed
/// unit disk. With d = 1 (interval of periodicity): |t| <= 2, i.e. 2Q - P >= 0 and 2Q + P >= 0.
/// Otherwise (interval of absolute stability, spectral radius <= 1; Jury's conditions for a real
/// quadratic): d <= 1 and |t| <= 1 + d, i.e. D^2 - Dn >= 0, D^2 + Dn - Tn D >= 0 and
/// D^2 + Dn + Tn D >= 0 (the factor D^2 > 0 does not change signs; d >= -1 is the sum of the
/// last two). Each condition polynomial F
/// must be positive just right of z = 0 (else the interval is empty), and tau*^2 is the
/// smallest positive root of odd multiplicity (a sign change) of any of them, infinite when
/// there is none. Roots of even multiplicity inside are isolated points where a root of modulus 1
/// touches the circle (a double root +-1 there, a Jordan block, is measure-zero and ignored).
/// The root is an exact algebraic number isolated in a rational interval (stability_interval.hpp:
/// `refined` narrows it, `compare_squared` compares it with a rational exactly). Everything is
/// constexpr; coefficients in Q(r): field_stability.hpp.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/analysis/stability_interval.hpp"
#include "geomint/core/integer_polynomial.hpp"

namespace geomint {

/// The exact two-step form and linear stability of a tableau. Structural.
struct linear_stability_result {
  stability_polynomial numerator{};    ///< P(z), z = tau^2: tr M = P / Q in lowest terms
  stability_polynomial denominator{};  ///< Q(z), Q(0) > 0, gcd(P, Q) = 1, integer content 1
  stability_polynomial step_denominator{};        ///< D = det(I + z A), scaled to integers
  stability_polynomial trace_polynomial{};        ///< Tn: tr M = Tn / D (same scaling)
  stability_polynomial determinant_polynomial{};  ///< Dn: det M = Dn / D^2 (same scaling)
  bool determinant_is_one = false;     ///< det M = 1 identically (x^{k+1} = R x^k - x^{k-1})
  int order = 0;                       ///< p: R - 2 cos tau = c tau^(p+2) + ...
  exact_number leading_coefficient{};  ///< c
  int phase_lag_order = 0;             ///< q: phi(H) = c_phi H^(q+1) + O(H^(q+3))
  exact_number phase_lag_constant{};   ///< c_phi
  int dissipation_order = -1;          ///< r: 1 - sqrt(det M) = c_d H^(r+1) + ...; -1 when det M = 1
  exact_number dissipation_constant{};  ///< c_d (0 when det M = 1)
  friend constexpr bool operator==(const linear_stability_result&, const linear_stability_result&) = default;
};

namespace analysis::detail {

/// Polynomials in z with exact rational coefficients (degree bound 2 max_stability_degree + 2).
struct qpoly {
  static constexpr int capacity = 2 * max_stability_degree + 3;
  exact_number c[capacity];
  int degree = -1;
  constexpr void trim() {
    degree = capacity - 1;
    while (degree >= 0 && c[degree].num.is_zero()) --degree;
  }
  friend constexpr qpoly operator+(const qpoly& a, const qpoly& b) {
    qpoly r;
    for (int k = 0; k < capacity; ++k) r.c[k] = a.c[k] + b.c[k];
    r.trim();
    return r;
  }
  friend constexpr qpoly operator-(const qpoly& a, const qpoly& b) {
    qpoly r;
    for (int k = 0; k < capacity; ++k) r.c[k] = a.c[k] - b.c[k];
    r.trim();
    return r;
  }
  friend constexpr qpoly operator*(const qpoly& a, const qpoly& b) {
    qpoly r;
    if (a.degree < 0 || b.degree < 0) return r;
    if (a.degree + b.degree >= capacity) throw std::overflow_error("geomint: stability polynomial degree overflow");
    for (int i = 0; i <= a.degree; ++i)
      for (int j = 0; j <= b.degree; ++j) r.c[i + j] = r.c[i + j] + a.c[i] * b.c[j];
    r.trim();
    return r;
  }
  /// Exact quotient (throws when b does not divide a).
  friend constexpr qpoly operator/(qpoly a, const qpoly& b) {
    if (b.degree < 0) throw std::domain_error("geomint: polynomial division by zero");
    qpoly q;
    for (int k = a.degree - b.degree; k >= 0; --k) {
      const exact_number t = a.c[k + b.degree] / b.c[b.degree];
      q.c[k] = t;
      for (int j = 0; j <= b.degree; ++j) a.c[k + j] = a.c[k + j] - t * b.c[j];
    }
    a.trim();
    if (a.degree >= 0) throw std::domain_error("geomint: inexact polynomial division");
    q.trim();
    return q;
  }
};

constexpr qpoly constant_poly(const exact_number& v) {
  qpoly p;
  p.c[0] = v;
  p.trim();
  return p;
}
constexpr qpoly z_times(const qpoly& p) {
  qpoly r;
  for (int k = 0; k + 1 < qpoly::capacity; ++k) r.c[k + 1] = p.c[k];
  r.trim();
  return r;
}

/// det [[I + z A, u], [v^T, 0]] (bordered = true) or det(I + z A) by Bareiss over Q[z].
constexpr qpoly bordered_determinant(const exact_rkn_tableau& t, bool bordered, const stage_vector& u, const exact_number* v) {
  const int s = t.stages;
  const int n = bordered ? s + 1 : s;
  qpoly a[max_exact_stages + 1][max_exact_stages + 1];
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) {
      qpoly e;
      e.c[0] = exact_number(i == j ? 1 : 0);
      e.c[1] = t.a[i][j];
      e.trim();
      a[i][j] = e;
    }
    if (bordered) a[i][s] = constant_poly(u[i]);
  }
  if (bordered) {
    for (int j = 0; j < s; ++j) a[s][j] = constant_poly(v[j]);
    a[s][s] = qpoly{};
  }
  // The leading principal minors of I + z A are 1 at z = 0: never zero polynomials.
  qpoly previous = constant_poly(exact_number(1));
  for (int k = 0; k < n - 1; ++k) {
    for (int i = k + 1; i < n; ++i)
      for (int j = k + 1; j < n; ++j) a[i][j] = (a[k][k] * a[i][j] - a[i][k] * a[k][j]) / previous;
    previous = a[k][k];
  }
  return a[n - 1][n - 1];
}

/// Integer polynomial from a rational one: times the lcm of the denominators.
constexpr stability_polynomial integer_part_scaled(const qpoly& p, const stability_integer& scale) {
  stability_polynomial r;
  for (int k = 0; k <= p.degree; ++k) {
    const exact_number v = p.c[k] * exact_number(scale, stability_integer(1));
    if (!(v.den() == stability_integer(1))) throw std::logic_error("geomint: scaling did not clear the denominators");
    r[k] = v.num;
  }
  r.trim();
  return r;
}

constexpr stability_integer lcm_of_denominators(const qpoly& p, stability_integer l) {
  for (int k = 0; k <= p.degree; ++k) l = l / gcd(l, p.c[k].den()) * p.c[k].den();
  return l;
}

constexpr stability_integer factorial(int n) {
  stability_integer f(1);
  for (int k = 2; k <= n; ++k) f *= stability_integer(k);
  return f;
}

/// The first nonzero coefficient of t / (2 sqrt d) - cos H as a power series in z = H^2, with
/// t = Tn / D and d = Dn / D^2 (exact power series of 1/D, 1/D^2 and d^(-1/2); the last by
/// d y' = -(1/2) d' y, i.e. n y_n = sum_{k=1..n} (k/2 - n) d_k y_{n-k}, d_0 = 1). Returns the
/// index n and the coefficient e (phi(H) = e H^(2n-1) + ...). K: exact_number (Poly: qpoly) or,
/// at run time, field_element (field_stability.hpp); Poly has coefficients c[k], k <= degree.
template <class K>
struct series_term {
  int index = -1;
  K coefficient{};
};
template <class K, class Poly>
constexpr series_term<K> phase_series(const Poly& Tn, const Poly& D, const Poly& Dn) {
  constexpr int terms = 2 * max_stability_degree + 8;
  K inv_d[terms], inv_d2[terms], det[terms], y[terms], tr[terms];
  K cosine(1);  // (-1)^n / (2n)!
  for (int n = 0; n < terms; ++n) {
    if (n > 0) cosine = -cosine / K((2 * n - 1) * (2 * n));
    K sum;
    for (int k = 1; k <= n && k <= D.degree; ++k) sum = sum + D.c[k] * inv_d[n - k];
    inv_d[n] = n == 0 ? K(1) / D.c[0] : -sum / D.c[0];
    K s2, sd, st;
    for (int k = 0; k <= n; ++k) s2 = s2 + inv_d[k] * inv_d[n - k];
    inv_d2[n] = s2;
    for (int k = 0; k <= n && k <= Dn.degree; ++k) sd = sd + Dn.c[k] * inv_d2[n - k];
    det[n] = sd;
    for (int k = 0; k <= n && k <= Tn.degree; ++k) st = st + Tn.c[k] * inv_d[n - k];
    tr[n] = st;
    if (n == 0) {
      if (!(det[0] == K(1))) throw std::domain_error("geomint::linear_stability: det M(0) != 1");
      y[0] = K(1);
    } else {
      K sy;
      for (int k = 1; k <= n; ++k) sy = sy + (K(k - 2 * n) / K(2)) * det[k] * y[n - k];
      y[n] = sy / K(n);
    }
    K w;
    for (int k = 0; k <= n; ++k) w = w + tr[k] * y[n - k];
    w = w / K(2);
    if (!(w == cosine)) return {n, w - cosine};
  }
  throw std::domain_error("geomint::linear_stability: t / (2 sqrt d) - cos H vanishes to the series length");
}

/// P / Q in lowest terms in Z[z]: divided by gcd(P, Q) and the common content, Q(0) > 0.
constexpr void reduce_fraction(stability_polynomial& P, stability_polynomial& Q) {
  const stability_polynomial G = polynomial_gcd(P, Q);
  if (G.degree > 0) {
    P = exact_quotient(P, G);
    Q = exact_quotient(Q, G);
  }
  const stability_integer g = gcd(content(P), content(Q));
  for (int k = 0; k <= P.degree; ++k) P[k] = exact_quotient(P[k], g);
  for (int k = 0; k <= Q.degree; ++k) Q[k] = exact_quotient(Q[k], g);
  if (Q[0].is_zero()) throw std::domain_error("geomint::linear_stability: R has a pole at tau = 0");
  if (Q[0].negative) {
    P = stability_integer(-1) * P;
    Q = stability_integer(-1) * Q;
  }
}

/// The analysis of the header comment from D = det(I + z A) and the bordered determinants
/// E(v, u) = det [[I + z A, u], [v^T, 0]] (any tableau whose RKN step on y'' = -y they describe).
constexpr linear_stability_result linear_stability_from_determinants(const qpoly& D, const qpoly& E_bbar_one, const qpoly& E_bbar_c,
                                                                     const qpoly& E_b_one, const qpoly& E_b_c) {
  // tr M = (2 D + z (E(bbar, 1) + E(b, c))) / D.
  const qpoly trace_num = D + D + z_times(E_bbar_one + E_b_c);
  // det M D^2 = (D + z E(bbar,1)) (D + z E(b,c)) - (D + z E(bbar,c)) z E(b,1).
  const qpoly det_num = (D + z_times(E_bbar_one)) * (D + z_times(E_b_c)) - (D + z_times(E_bbar_c)) * z_times(E_b_one);
  linear_stability_result out;
  out.determinant_is_one = (det_num - D * D).degree < 0;

  // One scaling lambda clears every denominator: lambda D, lambda Tn and lambda^2 Dn are integral.
  stability_integer scale = lcm_of_denominators(trace_num, stability_integer(1));
  scale = lcm_of_denominators(D, scale);
  scale = lcm_of_denominators(det_num, scale);
  out.step_denominator = integer_part_scaled(D, scale);
  out.trace_polynomial = integer_part_scaled(trace_num, scale);
  out.determinant_polynomial = integer_part_scaled(det_num, scale * scale);
  stability_polynomial P = out.trace_polynomial;
  stability_polynomial Q = out.step_denominator;
  reduce_fraction(P, Q);
  out.numerator = P;
  out.denominator = Q;
  // R - 2 cos: the integer E_k = (2k)! P_k - sum_i Q_i 2 (-1)^(k-i) (2k)!/(2(k-i))! is (2k)! times
  // the coefficient of z^k of P - Q 2 cos; the first nonzero one gives c = E_k / ((2k)! Q_0).
  const int last = P.degree + Q.degree + 1;
  bool expanded = false;
  for (int k = 0; k <= last && !expanded; ++k) {
    stability_integer E = k <= P.degree ? factorial(2 * k) * P[k] : stability_integer(0);
    for (int i = 0; i <= k && i <= Q.degree; ++i) {
      stability_integer ratio(2);
      for (int f = 2 * (k - i) + 1; f <= 2 * k; ++f) ratio *= stability_integer(f);
      if ((k - i) % 2 == 0) E -= Q[i] * ratio;
      else E += Q[i] * ratio;
    }
    if (!E.is_zero()) {
      out.order = 2 * k - 2;
      out.leading_coefficient = exact_number(E, factorial(2 * k) * Q[0]);
      expanded = true;
    }
  }
  if (!expanded)
    throw std::domain_error("geomint::linear_stability: R(tau) - 2 cos(tau) has no nonzero term");
  if (out.determinant_is_one) {
    out.phase_lag_order = out.order;
    out.phase_lag_constant = out.leading_coefficient / exact_number(2);
    return out;
  }
  // Dissipation: d - 1 = (Dn - D^2) / D^2 = delta z^k + ..., so 1 - sqrt(d) = -(delta / 2) H^(2k) + ...
  const qpoly excess = det_num - D * D;
  int k = 0;
  while (excess.c[k].num.is_zero()) ++k;
  out.dissipation_order = 2 * k - 1;
  out.dissipation_constant = -(excess.c[k] / (D.c[0] * D.c[0])) / exact_number(2);
  const series_term<exact_number> phase = phase_series<exact_number>(trace_num, D, det_num);
  out.phase_lag_order = 2 * phase.index - 2;
  out.phase_lag_constant = phase.coefficient;
  return out;
}

}  // namespace analysis::detail

/// The exact two-step form, order of R, phase lag and dissipation of a tableau.
constexpr linear_stability_result linear_stability(const exact_rkn_tableau& t) {
  using analysis::detail::bordered_determinant;
  return analysis::detail::linear_stability_from_determinants(
      bordered_determinant(t, false, t.one, t.b), bordered_determinant(t, true, t.one, t.bbar),
      bordered_determinant(t, true, t.c, t.bbar), bordered_determinant(t, true, t.one, t.b), bordered_determinant(t, true, t.c, t.b));
}

/// The exact stability interval: of periodicity when det M = 1, of absolute stability otherwise.
constexpr stability_interval linear_stability_interval(const linear_stability_result& r) {
  using analysis::detail::wide_polynomial;
  using analysis::detail::widen;
  stability_interval out;
  out.kind = r.determinant_is_one ? stability_kind::periodic : stability_kind::absolute;
  wide_polynomial conditions[3];
  int count = 0;
  if (r.determinant_is_one) {
    const wide_polynomial P = widen(r.numerator), two_q = analysis::detail::wide_integer(2) * widen(r.denominator);
    conditions[count++] = two_q - P;  // 2 - R >= 0
    conditions[count++] = two_q + P;  // 2 + R >= 0
  } else {
    const wide_polynomial D = widen(r.step_denominator), Tn = widen(r.trace_polynomial), Dn = widen(r.determinant_polynomial);
    const wide_polynomial D2 = D * D, TD = Tn * D;
    conditions[count++] = D2 - Dn;       // d <= 1
    conditions[count++] = D2 + Dn - TD;  // 1 + d - t >= 0
    conditions[count++] = D2 + Dn + TD;  // 1 + d + t >= 0
  }
  for (int i = 0; i < count; ++i) {
    if (conditions[i].is_zero()) continue;  // holds with equality for every tau
    const wide_polynomial F = analysis::detail::without_zero_roots(conditions[i]);
    if (F[0].sign() < 0) {  // violated just right of tau = 0
      out.empty = true;
      out.unbounded = false;
      return out;
    }
    const analysis::detail::isolated_root root = analysis::detail::smallest_odd_positive_root(F);
    if (root.found) analysis::detail::keep_smaller_bound(out, root);
  }
  return out;
}

}  // namespace geomint
