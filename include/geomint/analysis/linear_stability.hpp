#pragma once
/// Linear stability of an RKN tableau (analysis/rkn_tableau.hpp) on y'' = -y, exactly.
///
/// One step maps (q, tau p) linearly: with z = tau^2, X = (I + z A)^{-1},
///   M = [[1 - z bbar X 1, 1 - z bbar X c], [-z b X 1, 1 - z b X c]],
/// and every entry is a rational function of z computed exactly from bordered determinants:
/// v^T adj(I + z A) u = -det [[I + z A, u], [v^T, 0]] (fraction-free Bareiss elimination over
/// Q[z]). The two-step form of the scheme is x^{k+1} = tr(M) x^{k} - det(M) x^{k-1}; for the
/// library's schemes det M = 1 and R(tau) = tr M is exact_scheme.hpp's R (eq. 16-19 for
/// equispaced LPF). R = P(z)/Q(z) is reduced to lowest terms in Z[z] (gcd, content, Q(0) > 0)
/// and expanded: R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4)).
///
/// Phase lag (dispersion; van der Houwen and Sommeijer, SIAM J. Numer. Anal. 24 (1987) 595-617):
/// with det M = 1 the numerical frequency theta(tau) solves 2 cos theta = R(tau), and
/// tau - theta = (c/2) tau^(p+1) + O(tau^(p+3)): phase-lag order p, constant c/2.
///
/// Interval of periodicity (0, tau*): |R| <= 2 for 0 < tau < tau*, and |R| - 2 changes sign at
/// tau*^2, the smallest positive root of odd multiplicity of (P - 2Q)(P + 2Q); infinite when
/// there is none. The root is located by an exact-arithmetic scan of the sign of P - 2Q and
/// P + 2Q on the grid z = k/64 up to z = 4096 (and a sign test beyond, at z = 2^40) and refined
/// by exact bisection (run time); a pair of roots closer than 1/64 would be missed by the scan.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/core/integer_polynomial.hpp"

namespace geomint {

/// Degree bound of the stability polynomials.
inline constexpr int max_stability_degree = max_exact_stages + 2;
using stability_integer = big_integer<exact_algebra_limbs>;
using stability_polynomial = integer_polynomial<exact_algebra_limbs, 2 * max_stability_degree + 2>;

/// The exact two-step form and linear stability of a tableau. Structural.
struct linear_stability_result {
  stability_polynomial numerator{};    ///< P(z), z = tau^2
  stability_polynomial denominator{};  ///< Q(z), Q(0) > 0, gcd(P, Q) = 1, integer content 1
  bool determinant_is_one = false;     ///< det M = 1 exactly (two-step form x^{k+1} = R x^k - x^{k-1})
  int order = 0;                       ///< p: R - 2 cos tau = c tau^(p+2) + ...
  exact_number leading_coefficient{};  ///< c
  int phase_lag_order = 0;             ///< p (when det M = 1)
  exact_number phase_lag_constant{};   ///< c / 2
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

}  // namespace analysis::detail

/// The exact two-step form, order of R, phase lag of a tableau.
constexpr linear_stability_result linear_stability(const exact_rkn_tableau& t) {
  using analysis::detail::qpoly;
  const qpoly D = analysis::detail::bordered_determinant(t, false, t.one, t.b);
  const qpoly E_bbar_one = analysis::detail::bordered_determinant(t, true, t.one, t.bbar);
  const qpoly E_bbar_c = analysis::detail::bordered_determinant(t, true, t.c, t.bbar);
  const qpoly E_b_one = analysis::detail::bordered_determinant(t, true, t.one, t.b);
  const qpoly E_b_c = analysis::detail::bordered_determinant(t, true, t.c, t.b);
  // tr M = (2 D + z (E(bbar, 1) + E(b, c))) / D.
  const qpoly trace_num = D + D + analysis::detail::z_times(E_bbar_one + E_b_c);
  // det M D^2 = (D + z E(bbar,1)) (D + z E(b,c)) - (D + z E(bbar,c)) z E(b,1).
  const qpoly det_num = (D + analysis::detail::z_times(E_bbar_one)) * (D + analysis::detail::z_times(E_b_c)) -
                        (D + analysis::detail::z_times(E_bbar_c)) * analysis::detail::z_times(E_b_one);
  linear_stability_result out;
  out.determinant_is_one = (det_num - D * D).degree < 0;

  stability_integer scale = analysis::detail::lcm_of_denominators(trace_num, stability_integer(1));
  scale = analysis::detail::lcm_of_denominators(D, scale);
  stability_polynomial P = analysis::detail::integer_part_scaled(trace_num, scale);
  stability_polynomial Q = analysis::detail::integer_part_scaled(D, scale);
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
  out.numerator = P;
  out.denominator = Q;
  // R - 2 cos: the integer E_k = (2k)! P_k - sum_i Q_i 2 (-1)^(k-i) (2k)!/(2(k-i))! is (2k)! times
  // the coefficient of z^k of P - Q 2 cos; the first nonzero one gives c = E_k / ((2k)! Q_0).
  const int last = P.degree + Q.degree + 1;
  for (int k = 0; k <= last; ++k) {
    stability_integer E = k <= P.degree ? analysis::detail::factorial(2 * k) * P[k] : stability_integer(0);
    for (int i = 0; i <= k && i <= Q.degree; ++i) {
      stability_integer ratio(2);
      for (int f = 2 * (k - i) + 1; f <= 2 * k; ++f) ratio *= stability_integer(f);
      if ((k - i) % 2 == 0) E -= Q[i] * ratio;
      else E += Q[i] * ratio;
    }
    if (!E.is_zero()) {
      out.order = 2 * k - 2;
      out.leading_coefficient = exact_number(E, analysis::detail::factorial(2 * k) * Q[0]);
      out.phase_lag_order = out.order;
      out.phase_lag_constant = out.leading_coefficient / exact_number(2);
      return out;
    }
  }
  throw std::domain_error("geomint::linear_stability: R(tau) - 2 cos(tau) has no nonzero term");
}

/// The interval of periodicity (see the header comment): the polynomial F (P - 2Q or P + 2Q,
/// primitive) whose smallest positive root of odd multiplicity z* = tau*^2 bounds it, and z*
/// bracketed by exact rationals [low, high] with high - low <= 2^-120 (run time).
struct stability_interval {
  bool unbounded = true;
  stability_polynomial bounding_polynomial{};
  exact_number low{}, high{};
};

inline stability_interval periodicity_interval(const linear_stability_result& r) {
  stability_interval out;
  const stability_polynomial two_q = stability_integer(2) * r.denominator;
  const stability_polynomial candidates[2] = {r.numerator - two_q, r.numerator + two_q};
  // sign F(n/d) = sign of sum_k F_k n^k d^(deg - k) (d > 0), in 1536-bit integers: F has degree
  // <= 8 and the points have numerators and denominators below 2^133 (z < 4096, width 2^-120),
  // so the sum stays below 2^1300 for coefficients below 2^230 (overflow would throw).
  using wide = big_integer<48>;
  auto widen = [](const stability_integer& x) {
    wide w;
    for (int k = 0; k < x.size; ++k) w.limb[k] = x.limb[k];
    w.size = x.size;
    w.negative = x.negative;
    return w;
  };
  auto sign = [&](const stability_polynomial& p, const exact_number& z) {
    const wide n = widen(z.num), d = widen(z.den());
    wide v;
    for (int k = p.degree; k >= 0; --k) {
      wide dk(1);
      for (int j = 0; j < p.degree - k; ++j) dk *= d;
      v = v * n + widen(p[k]) * dk;
    }
    return v.sign();
  };
  constexpr int steps_per_unit = 64, last_unit = 4096;
  exact_number best_low, best_high;
  bool found = false;
  for (const stability_polynomial& F : candidates) {
    if (F.degree < 1) continue;
    exact_number left(0);
    // Near 0 the sign is that of the lowest nonzero coefficient; start just above 0.
    int left_sign = 0;
    for (int k = 0; k <= F.degree && left_sign == 0; ++k) left_sign = F[k].sign();
    exact_number lo, hi;
    bool bracketed = false;
    for (int k = 1; k <= steps_per_unit * last_unit && !bracketed; ++k) {
      const exact_number z(rational(k, steps_per_unit));
      if (found && !(z < best_high)) break;
      const int sz = sign(F, z);
      if (sz != 0 && sz != left_sign) {  // an odd number of roots (with multiplicity) in (left, z]
        lo = left;
        hi = z;
        bracketed = true;
      }
      if (sz != 0) left = z;
    }
    if (!bracketed && !found) {
      const exact_number far(stability_integer(std::int64_t(1) << 40), stability_integer(1));
      if (sign(F, far) != left_sign) {
        lo = left;
        hi = far;
        bracketed = true;
      }
    }
    if (!bracketed) continue;
    exact_number width_bound(1);
    for (int b = 0; b < 120; ++b) width_bound = width_bound / exact_number(2);
    for (int iteration = 0; iteration < 400 && width_bound < hi - lo; ++iteration) {
      const exact_number mid = (lo + hi) / exact_number(2);
      const int sm = sign(F, mid);
      if (sm == 0) {
        lo = hi = mid;
        break;
      }
      if (sm == left_sign) lo = mid;
      else hi = mid;
    }
    if (!found || hi < best_high) {
      best_low = lo;
      best_high = hi;
      out.bounding_polynomial = F;
      found = true;
    }
  }
  if (found) {
    out.unbounded = false;
    out.low = best_low;
    out.high = best_high;
    const stability_integer g = content(out.bounding_polynomial);
    for (int k = 0; k <= out.bounding_polynomial.degree; ++k) out.bounding_polynomial[k] = exact_quotient(out.bounding_polynomial[k], g);
  }
  return out;
}

}  // namespace geomint
