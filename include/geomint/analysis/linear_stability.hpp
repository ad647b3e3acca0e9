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
/// The root is an exact algebraic number: the squarefree part of F, its Sturm sequence (exact
/// primitive remainder sequence) and exact bisection isolate it in a rational interval
/// (low, high] holding no other root; `refined` narrows it and `compare_squared` compares it
/// with a rational exactly. Everything is constexpr.

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
/// index n and the coefficient e (phi(H) = e H^(2n-1) + ...).
struct series_term {
  int index = -1;
  exact_number coefficient{};
};
constexpr series_term phase_series(const qpoly& Tn, const qpoly& D, const qpoly& Dn) {
  constexpr int terms = 2 * max_stability_degree + 8;
  exact_number inv_d[terms], inv_d2[terms], det[terms], y[terms], tr[terms];
  exact_number cosine(1);  // (-1)^n / (2n)!
  for (int n = 0; n < terms; ++n) {
    if (n > 0) cosine = -cosine / exact_number((2 * n - 1) * (2 * n));
    exact_number sum;
    for (int k = 1; k <= n && k <= D.degree; ++k) sum = sum + D.c[k] * inv_d[n - k];
    inv_d[n] = n == 0 ? exact_number(1) / D.c[0] : -sum / D.c[0];
    exact_number s2, sd, st;
    for (int k = 0; k <= n; ++k) s2 = s2 + inv_d[k] * inv_d[n - k];
    inv_d2[n] = s2;
    for (int k = 0; k <= n && k <= Dn.degree; ++k) sd = sd + Dn.c[k] * inv_d2[n - k];
    det[n] = sd;
    for (int k = 0; k <= n && k <= Tn.degree; ++k) st = st + Tn.c[k] * inv_d[n - k];
    tr[n] = st;
    if (n == 0) {
      if (!(det[0] == exact_number(1))) throw std::domain_error("geomint::linear_stability: det M(0) != 1");
      y[0] = exact_number(1);
    } else {
      exact_number sy;
      for (int k = 1; k <= n; ++k) sy = sy + exact_number(rational(k - 2 * n, 2)) * det[k] * y[n - k];
      y[n] = sy / exact_number(n);
    }
    exact_number w;
    for (int k = 0; k <= n; ++k) w = w + tr[k] * y[n - k];
    w = w / exact_number(2);
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
  const series_term phase = phase_series(trace_num, D, det_num);
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

/// Which interval a method has on y'' = -y.
enum class stability_kind {
  periodic,  ///< det M = 1: interval of periodicity (|tr M| <= 2)
  absolute   ///< det M != 1: interval of absolute stability (spectral radius <= 1)
};

namespace analysis::detail {

/// Exact root isolation: wide integers for the Sturm sequences and for the signs at rational
/// points (the sequences of degree-16 polynomials and points of 130-bit numerators need some
/// 2500 bits; an overflow throws, never a wrong sign).
inline constexpr int root_limbs = 96;
using wide_integer = big_integer<root_limbs>;
using wide_polynomial = integer_polynomial<root_limbs, 2 * max_stability_degree + 2>;

template <int L>
constexpr wide_integer widen(const big_integer<L>& x) {
  wide_integer w;
  for (int k = 0; k < x.size; ++k) w.limb[k] = x.limb[k];
  w.size = x.size;
  w.negative = x.negative;
  return w;
}
constexpr wide_polynomial widen(const stability_polynomial& p) {
  wide_polynomial w;
  for (int k = 0; k <= p.degree; ++k) w[k] = widen(p[k]);
  w.trim();
  return w;
}

/// Sign of p at the rational x = n / d (d > 0): the sign of sum_k p_k n^k d^(deg - k).
constexpr int sign_at(const wide_polynomial& p, const exact_number& x) {
  if (p.is_zero()) return 0;
  const wide_integer n = widen(x.num), d = widen(x.den());
  wide_integer v, dk(1);
  for (int k = p.degree; k >= 0; --k) {
    v = v * n;
    if (!p[k].is_zero()) v += p[k] * dk;
    if (k > 0) dk = dk * d;
  }
  return v.sign();
}

constexpr wide_polynomial derivative(const wide_polynomial& p) {
  wide_polynomial r;
  for (int k = 1; k <= p.degree; ++k) r[k - 1] = wide_integer(k) * p[k];
  r.trim();
  return r;
}

/// The Sturm sequence of a squarefree p: p, p', then -(positive multiple of the remainder),
/// primitive (pseudo-division by |lead| keeps the signs; the content removed is positive).
struct sturm_sequence {
  wide_polynomial p[2 * max_stability_degree + 3];
  int length = 0;
  /// Sign changes at x (zeros skipped).
  constexpr int variations(const exact_number& x) const {
    int count = 0, last = 0;
    for (int i = 0; i < length; ++i) {
      const int sg = sign_at(p[i], x);
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++count;
      last = sg;
    }
    return count;
  }
};
constexpr sturm_sequence make_sturm_sequence(const wide_polynomial& h) {
  sturm_sequence s;
  s.p[0] = h;
  s.p[1] = derivative(h);
  s.length = 2;
  while (s.p[s.length - 1].degree > 0) {
    const wide_polynomial& v = s.p[s.length - 1];
    wide_polynomial r = s.p[s.length - 2];
    while (!r.is_zero() && r.degree >= v.degree) {
      const int shift = r.degree - v.degree;
      const wide_integer f = v.lead().negative ? -r.lead() : r.lead();
      r = abs(v.lead()) * r;
      for (int j = 0; j <= v.degree; ++j) r[shift + j] -= f * v[j];
      r.trim();
    }
    if (r.is_zero()) throw std::logic_error("geomint: Sturm sequence of a polynomial that is not squarefree");
    s.p[s.length] = wide_integer(-1) * primitive_part(r);
    ++s.length;
  }
  return s;
}

/// bits(|x|): 0 for 0.
constexpr int bit_length(const wide_integer& x) {
  if (x.size == 0) return 0;
  int bits = 32 * (x.size - 1);
  for (std::uint32_t top = x.limb[x.size - 1]; top != 0; top >>= 1) ++bits;
  return bits;
}

constexpr exact_number power_of_two(int e) {
  exact_number r(1);
  const exact_number two(2);
  for (int k = 0; k < e; ++k) r = r * two;
  for (int k = 0; k > e; --k) r = r / two;
  return r;
}

/// A positive real root of F (F(0) != 0), isolated: the only root of F in (low, high], F has the
/// sign `below` on (low, root); low == high when the root is that rational.
struct isolated_root {
  bool found = false;
  wide_polynomial polynomial{};
  exact_number low{}, high{};
  int below = 0;
};

/// The smallest positive root of odd multiplicity of F (F(0) != 0): Sturm sequence of the
/// squarefree part h = F / gcd(F, F'), bisection from the Cauchy bound until one root of h is
/// isolated, and a sign test of F on both sides of it (an even root is passed over).
constexpr isolated_root smallest_odd_positive_root(const wide_polynomial& F) {
  isolated_root out;
  out.polynomial = F;
  out.below = F[0].sign();
  if (F.degree < 1) return out;
  wide_polynomial h = F;
  const wide_polynomial g = polynomial_gcd(F, derivative(F));
  if (g.degree > 0) h = exact_quotient(F, g);
  if (h.degree < 1) return out;
  const sturm_sequence sturm = make_sturm_sequence(h);
  // Cauchy: every root is below 1 + max |h_k / h_n| <= 2^e.
  int top = 0;
  for (int k = 0; k < h.degree; ++k) top = std::max(top, bit_length(h[k]));
  const int e = std::max(1, top - bit_length(h.lead()) + 2);
  const exact_number upper = power_of_two(e), two(2);
  exact_number lo(0);
  while (true) {
    const int v_upper = sturm.variations(upper);
    if (sturm.variations(lo) - v_upper == 0) return out;  // no root left: no sign change
    exact_number a = lo, b = upper;
    int v_a = sturm.variations(a), v_b = v_upper;
    while (v_a - v_b > 1) {
      const exact_number mid = (a + b) / two;
      const int v_mid = sturm.variations(mid);
      if (v_a - v_mid >= 1) {
        b = mid;
        v_b = v_mid;
      } else {
        a = mid;
        v_a = v_mid;
      }
    }
    // One root r of h in (a, b]; F has the sign `below` on (lo, r).
    if (sign_at(h, b) == 0) {  // r = b: the sign just right of it
      exact_number c = b + (b - a);
      while (sturm.variations(b) - sturm.variations(c) > 0) c = (b + c) / two;
      if (sign_at(F, c) != out.below) {
        out.found = true;
        out.low = out.high = b;
        return out;
      }
    } else if (sign_at(F, b) != out.below) {
      out.found = true;
      out.low = a;
      out.high = b;
      return out;
    }
    lo = b;
  }
}

/// Halves (low, high] around the root until high - low <= 2^-bits high.
constexpr void refine(isolated_root& r, int bits) {
  const exact_number two(2), tolerance = power_of_two(-bits);
  while (r.low < r.high && tolerance * r.high < r.high - r.low) {
    const exact_number mid = (r.low + r.high) / two;
    const int s = sign_at(r.polynomial, mid);
    if (s == 0) {
      r.low = r.high = mid;
    } else if (s == r.below) {
      r.low = mid;
    } else {
      r.high = mid;
    }
  }
}

/// sign(x - root), exactly.
constexpr int compare_with_root(const isolated_root& r, const exact_number& x) {
  if (!(r.low < x)) return r.low == r.high && x == r.low ? 0 : -1;
  if (r.high < x) return 1;
  const int s = sign_at(r.polynomial, x);
  return s == 0 ? 0 : (s == r.below ? -1 : 1);
}

/// F / z^k with F(0) != 0 (F not zero).
constexpr wide_polynomial without_zero_roots(wide_polynomial F) {
  int k = 0;
  while (F[k].is_zero()) ++k;
  wide_polynomial r;
  for (int j = k; j <= F.degree; ++j) r[j - k] = F[j];
  r.trim();
  return primitive_part(r);
}

}  // namespace analysis::detail

/// The stability interval (0, tau*) of a method on y'' = -y (see the header comment): empty,
/// unbounded, or tau*^2 = z* an exact algebraic number, the isolated root of `bound`.
struct stability_interval {
  stability_kind kind = stability_kind::periodic;
  bool empty = false;
  bool unbounded = true;
  analysis::detail::isolated_root bound{};  ///< z* = tau*^2 with its polynomial and bracket
  /// sign(z - z*) for a rational z = tau^2 (-1: inside the interval; unbounded: always -1).
  constexpr int compare_squared(const exact_number& z) const {
    if (empty) return 1;
    if (unbounded) return -1;
    return analysis::detail::compare_with_root(bound, z);
  }
  /// z* bracketed by (low, high] with high - low <= 2^-bits high.
  constexpr stability_interval refined(int bits) const {
    stability_interval r = *this;
    if (!empty && !unbounded) analysis::detail::refine(r.bound, bits);
    return r;
  }
  constexpr const exact_number& low() const { return bound.low; }
  constexpr const exact_number& high() const { return bound.high; }
};

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
    analysis::detail::isolated_root root = analysis::detail::smallest_odd_positive_root(F);
    if (!root.found) continue;
    if (out.unbounded) {
      out.bound = root;
      out.unbounded = false;
      continue;
    }
    // Keep the smaller of two algebraic numbers: narrow both brackets until they are disjoint or
    // one's rational bracket end is the other's root.
    for (int bits = 8;; bits += 8) {
      if (!(out.bound.low < root.high)) {  // root <= root.high <= out.bound.low < out.bound
        out.bound = root;
        break;
      }
      if (!(root.low < out.bound.high)) break;  // out.bound <= out.bound.high <= root.low < root
      if (root.low == root.high && analysis::detail::compare_with_root(out.bound, root.low) >= 0) {
        out.bound = root;
        break;
      }
      if (out.bound.low == out.bound.high && analysis::detail::compare_with_root(root, out.bound.low) >= 0) break;
      if (bits > 192) {
        // Brackets still overlapping at 2^-192: equal when the polynomials share a factor (a
        // common root); otherwise no decision (an exception, never a guess).
        if (polynomial_gcd(out.bound.polynomial, root.polynomial).degree > 0) break;
        throw std::logic_error("geomint::linear_stability_interval: cannot separate two bounds");
      }
      analysis::detail::refine(out.bound, bits);
      analysis::detail::refine(root, bits);
    }
  }
  return out;
}

}  // namespace geomint
