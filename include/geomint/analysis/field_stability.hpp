#pragma once
/// Linear stability over a real algebraic number field Q(r) (methods/number_field.hpp), exactly,
/// at run time: the analyses of linear_stability.hpp (the RKN step on y'' = -y) and
/// rk_stability.hpp (R(z) on y' = lambda y) for methods whose stability polynomials have
/// irrational coefficients (Forest-Ruth, Yoshida, Suzuki over Q(2^(1/3)); any `field` tableau file).
///
/// The polynomials in z over Q(r) are exact (field_element arithmetic): P / Q is reduced by the
/// Euclidean algorithm over Q(r) with Q(0) = 1; the series of linear_stability.hpp (order of
/// R - 2 cos, phase lag, dissipation) give their constants in Q(r). The sign of a nonzero element
/// is decided exactly (methods::exact_sign: interval evaluation at r's refined rational bracket).
///
/// Intervals. Every condition F(z) (linear_stability.hpp: |t| <= 2, or Jury's conditions;
/// rk_stability.hpp: |Q(iy)|^2 - |P(iy)|^2) is a polynomial over Q(r) that must be positive just
/// right of z = 0, and the bound is its first sign change for z > 0. The real roots of F are among
/// those of its norm
///   N(z) = Res_y(m(y), F(z, y)) = prod_j F(z, r_j)     (r_j the roots of m, r among them),
/// a polynomial over Q: m is the field polynomial without the factors at whose roots every
/// coefficient of F vanishes (so N != 0), N(z0) the determinant of multiplication by F(z0, y)
/// modulo the monic m, at z0 = 0..deg N, interpolated. The positive roots of the squarefree part
/// of N are isolated exactly (Sturm sequences, stability_interval.hpp); F has no root between two
/// of them, so its sign there is F's exact sign at a rational point, and the first root of N
/// where that sign changes is the bound: an exact algebraic number, the root of N's squarefree
/// part in its rational bracket. Roots of the conjugates F(z, r_j), r_j != r, are passed over
/// since F keeps its sign there. Run time only (field_element allocates); rational polynomials
/// take the constexpr path of linear_stability.hpp and rk_stability.hpp.

#include <algorithm>
#include <boost/multiprecision/cpp_int.hpp>
#include <array>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/rk_stability.hpp"
#include "geomint/analysis/stability_interval.hpp"
#include "geomint/methods/number_field.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint {

/// The step on y'' = -y of a method over Q(r) (linear_stability_result's fields, with constants
/// and polynomials in Q(r), ascending powers of z = tau^2) and its interval.
struct field_linear_stability_result {
  std::vector<methods::field_element> numerator, denominator;  ///< tr M = P / Q, gcd 1 over Q(r), Q(0) = 1
  std::vector<methods::field_element> step_denominator;        ///< D = det(I + z A)
  std::vector<methods::field_element> trace_polynomial;        ///< Tn: tr M = Tn / D
  std::vector<methods::field_element> determinant_polynomial;  ///< Dn: det M = Dn / D^2
  bool determinant_is_one = false;
  int order = 0;                                 ///< p: R - 2 cos tau = c tau^(p+2) + ...
  methods::field_element leading_coefficient{};  ///< c
  int phase_lag_order = 0;
  methods::field_element phase_lag_constant{};
  int dissipation_order = -1;  ///< -1 when det M = 1
  methods::field_element dissipation_constant{};
  stability_interval interval{};  ///< of periodicity (det M = 1) or of absolute stability
};

/// The verdicts of rk_stability_result for R(z) over Q(r).
struct field_rk_stability_result {
  std::vector<methods::field_element> numerator, denominator;  ///< R = P / Q, gcd 1 over Q(r), Q(0) = 1
  bool bounded_on_imaginary_axis = false;
  bool poles_in_right_half_plane = false;
  bool a_stable = false;
  bool l_stable = false;
  stability_interval imaginary_axis{};
};

namespace analysis::detail {

using methods::exact_rational;
using methods::field_element;

/// A polynomial in z over Q(r), trimmed (the leading coefficient's value is not 0); c and degree
/// as qpoly's (phase_series reads both).
struct field_polynomial {
  std::vector<field_element> c;
  int degree = -1;
  field_polynomial() = default;
  explicit field_polynomial(std::vector<field_element> v) : c(std::move(v)) { trim(); }
  void trim() {
    degree = static_cast<int>(c.size()) - 1;
    while (degree >= 0 && c[static_cast<std::size_t>(degree)].is_zero()) --degree;
    c.resize(static_cast<std::size_t>(degree + 1));
  }
  field_element operator[](int k) const { return k >= 0 && k <= degree ? c[static_cast<std::size_t>(k)] : field_element(); }
  bool is_zero() const { return degree < 0; }
  bool is_rational() const {
    for (const field_element& x : c)
      if (!x.is_rational()) return false;
    return true;
  }
};

inline field_polynomial combine(const field_polynomial& a, const field_polynomial& b, int sign) {
  std::vector<field_element> r(static_cast<std::size_t>(std::max(a.degree, b.degree) + 1));
  for (int k = 0; k < static_cast<int>(r.size()); ++k) r[static_cast<std::size_t>(k)] = sign > 0 ? a[k] + b[k] : a[k] - b[k];
  return field_polynomial(std::move(r));
}
inline field_polynomial operator+(const field_polynomial& a, const field_polynomial& b) { return combine(a, b, 1); }
inline field_polynomial operator-(const field_polynomial& a, const field_polynomial& b) { return combine(a, b, -1); }
inline field_polynomial operator*(const field_polynomial& a, const field_polynomial& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<field_element> r(static_cast<std::size_t>(a.degree + b.degree + 1));
  for (int i = 0; i <= a.degree; ++i)
    for (int j = 0; j <= b.degree; ++j) r[static_cast<std::size_t>(i + j)] += a[i] * b[j];
  return field_polynomial(std::move(r));
}
inline field_polynomial operator*(const field_element& x, field_polynomial p) {
  for (field_element& v : p.c) v = x * v;
  p.trim();
  return p;
}
inline field_polynomial times_z(const field_polynomial& p) {
  std::vector<field_element> r(1, field_element());
  r.insert(r.end(), p.c.begin(), p.c.end());
  return field_polynomial(std::move(r));
}
/// a = q b + remainder over Q(r) (b not zero); returns q, leaves the remainder in a.
inline field_polynomial field_divide(field_polynomial& a, const field_polynomial& b) {
  std::vector<field_element> q(static_cast<std::size_t>(std::max(a.degree - b.degree + 1, 0)));
  const field_element inverse = b[b.degree].inverse();
  while (a.degree >= b.degree) {
    const int shift = a.degree - b.degree;
    const field_element f = a[a.degree] * inverse;
    q[static_cast<std::size_t>(shift)] = f;
    for (int j = 0; j <= b.degree; ++j) a.c[static_cast<std::size_t>(shift + j)] -= f * b[j];
    a.c[static_cast<std::size_t>(a.degree)] = field_element();  // cancels exactly
    a.trim();
  }
  return field_polynomial(std::move(q));
}
/// gcd over Q(r) (Euclid; not normalised).
inline field_polynomial field_gcd(field_polynomial a, field_polynomial b) {
  while (!b.is_zero()) {
    field_divide(a, b);
    std::swap(a, b);
  }
  return a;
}
/// P / Q in lowest terms over Q(r) with Q(0) = 1 (Q(0) != 0 required).
inline void reduce_fraction(field_polynomial& P, field_polynomial& Q) {
  const field_polynomial G = field_gcd(P, Q);
  if (G.degree > 0) {
    P = field_divide(P, G);
    Q = field_divide(Q, G);
  }
  if (Q[0].is_zero()) throw std::domain_error("R has a pole at 0");
  const field_element scale = Q[0].inverse();
  P = scale * P;
  Q = scale * Q;
}
inline field_polynomial without_zero_roots(const field_polynomial& F) {
  int k = 0;
  while (F[k].is_zero()) ++k;
  return field_polynomial(std::vector<field_element>(F.c.begin() + k, F.c.end()));
}
inline field_element value_at(const field_polynomial& F, const exact_rational& x) {
  field_element s;
  for (int k = F.degree; k >= 0; --k) s = s * field_element(x) + F[k];
  return s;
}
inline exact_rational to_rational(const exact_number& x) {
  using boost::multiprecision::cpp_int;
  return exact_rational(cpp_int(x.num.str()), cpp_int(x.den().str()));
}

/// N(z) = Res_y(m_F(y), F(z, y)) over Q (see the header comment).
inline methods::detail::poly rational_norm(const field_polynomial& F) {
  namespace md = methods::detail;
  std::shared_ptr<const methods::algebraic_field> field;
  for (const field_element& x : F.c)
    if (!x.is_rational()) field = x.field();
  if (!field) {
    md::poly out;
    for (const field_element& x : F.c) out.push_back(x.rational_value());
    md::trim(out);
    return out;
  }
  md::poly common = field->polynomial();
  for (const field_element& x : F.c) common = md::gcd(common, x.coefficients());
  md::poly m, rest;
  md::divide(field->polynomial(), common, m, rest);
  const auto n = static_cast<std::size_t>(md::degree(m));
  const auto degree = n * static_cast<std::size_t>(F.degree);
  std::vector<exact_rational> values(degree + 1);
  for (std::size_t z = 0; z <= degree; ++z) {
    md::poly g;  // F(z, y)
    exact_rational power = 1;
    for (const field_element& x : F.c) {
      g = md::add_scaled(g, x.coefficients(), power);
      power *= exact_rational(static_cast<long>(z));
    }
    md::poly column = md::remainder(g, m);  // y^j F(z, y) mod m, j = 0..n-1
    std::vector<std::vector<exact_rational>> product(n, std::vector<exact_rational>(n, exact_rational(0)));
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t i = 0; i < column.size(); ++i) product[i][j] = column[i];
      column = md::remainder(md::multiply(column, {exact_rational(0), exact_rational(1)}), m);
    }
    values[z] = determinant<exact_rational>(product, n);
  }
  md::poly out = interpolate<exact_rational>(values, degree);
  md::trim(out);
  return out;
}

/// The squarefree part of N without the root 0.
inline methods::detail::poly squarefree_without_zero_roots(methods::detail::poly N) {
  namespace md = methods::detail;
  if (N.empty()) throw std::logic_error("geomint: the norm of a nonzero stability polynomial is zero");
  std::size_t k = 0;
  while (N[k] == 0) ++k;
  N.erase(N.begin(), N.begin() + static_cast<std::ptrdiff_t>(k));
  md::poly h, rest;
  md::divide(N, md::gcd(N, md::derivative(N)), h, rest);
  if (md::degree(h) > 2 * max_stability_degree + 2)
    throw std::domain_error("the norm of a stability polynomial over Q(r) has degree " + std::to_string(md::degree(h)) + " (at most " +
                            std::to_string(2 * max_stability_degree + 2) + ")");
  return h;
}

/// h over Z, primitive (the polynomial of the bound, stability_interval's form).
inline wide_polynomial primitive_integer_polynomial(const methods::detail::poly& h) {
  using boost::multiprecision::cpp_int;
  cpp_int scale = 1;
  for (const exact_rational& x : h) scale = boost::multiprecision::lcm(scale, boost::multiprecision::denominator(x));
  wide_polynomial w;
  for (std::size_t i = 0; i < h.size(); ++i)
    w[static_cast<int>(i)] = to_exact_integer<root_limbs>(boost::multiprecision::numerator(exact_rational(h[i] * scale)));
  w.trim();
  return primitive_part(w);
}

/// The first positive sign change of F over Q(r) (F(0) != 0): the root of the squarefree norm
/// where F's exact sign changes (see the header comment). The Sturm sequence is formed over Q
/// (methods/number_field.hpp): a norm's remainder sequence outgrows the wide integers (McLachlan's
/// SB3A-5 over Q(sqrt 722025967665) needs more than 3072 bits).
inline isolated_root field_first_sign_change(const field_polynomial& F) {
  const methods::detail::poly h = squarefree_without_zero_roots(rational_norm(F));
  const std::vector<methods::detail::poly> sturm = methods::detail::sturm_sequence(h);
  const wide_polynomial w = primitive_integer_polynomial(h);
  isolated_root root = first_sign_change(
      w, [&](const exact_number& x) { return methods::detail::sign_changes(sturm, to_rational(x)); }, methods::exact_sign(F[0]),
      [&](const exact_number& x) { return methods::exact_sign(value_at(F, to_rational(x))); });
  if (root.found && root.low < root.high) root.below = -sign_at(w, root.high);  // h's own sign left of its simple root
  return root;
}

/// The interval where every condition is >= 0 (stability_interval's conventions).
inline stability_interval interval_of_conditions(stability_kind kind, const std::vector<field_polynomial>& conditions) {
  stability_interval out;
  out.kind = kind;
  for (const field_polynomial& condition : conditions) {
    if (condition.is_zero()) continue;  // holds with equality for every tau
    const field_polynomial F = without_zero_roots(condition);
    if (methods::exact_sign(F[0]) < 0) {  // violated just right of 0
      out.empty = true;
      out.unbounded = false;
      return out;
    }
    const isolated_root root = field_first_sign_change(F);
    if (root.found) keep_smaller_bound(out, root);
  }
  return out;
}

/// 2 (-1)^k / (2k)!: the coefficient of z^k in 2 cos(tau), z = tau^2.
inline field_element two_cos_coefficient(int k) {
  boost::multiprecision::cpp_int f = 1;
  for (int j = 2; j <= 2 * k; ++j) f *= j;
  return field_element(exact_rational(boost::multiprecision::cpp_int(k % 2 == 0 ? 2 : -2), f));
}

/// |f(iy)|^2 as a polynomial in u = y^2 (squared_modulus_on_axis over Q(r)).
inline field_polynomial squared_modulus_on_axis(const field_polynomial& f) {
  field_polynomial reflected = f;
  for (int k = 1; k <= f.degree; k += 2) reflected.c[static_cast<std::size_t>(k)] = -f[k];
  const field_polynomial h = f * reflected;
  std::vector<field_element> out;
  for (int j = 0; 2 * j <= h.degree; ++j) out.push_back(j % 2 == 0 ? h[2 * j] : -h[2 * j]);
  return field_polynomial(std::move(out));
}

}  // namespace analysis::detail

/// The analysis of linear_stability.hpp over Q(r), from D = det(I + z A) and the bordered
/// determinants E(bbar, 1), E(bbar, c), E(b, 1), E(b, c) (linear_stability_from_determinants's
/// arguments in that order, ascending coefficients).
inline field_linear_stability_result field_linear_stability_from_determinants(const std::array<std::vector<methods::field_element>, 5>& d) {
  using namespace analysis::detail;
  const field_polynomial D(d[0]), E_bbar_one(d[1]), E_bbar_c(d[2]), E_b_one(d[3]), E_b_c(d[4]);
  const field_polynomial trace_num = D + D + times_z(E_bbar_one + E_b_c);
  const field_polynomial det_num = (D + times_z(E_bbar_one)) * (D + times_z(E_b_c)) - (D + times_z(E_bbar_c)) * times_z(E_b_one);
  const field_polynomial excess = det_num - D * D;
  field_linear_stability_result out;
  out.determinant_is_one = excess.is_zero();
  out.step_denominator = D.c;
  out.trace_polynomial = trace_num.c;
  out.determinant_polynomial = det_num.c;
  field_polynomial P = trace_num, Q = D;
  reduce_fraction(P, Q);
  out.numerator = P.c;
  out.denominator = Q.c;
  // R - 2 cos = (P - 2 Q cos) / Q: its first nonzero coefficient E_k / Q(0), Q(0) = 1.
  bool expanded = false;
  for (int k = 0; k <= P.degree + Q.degree + 1 && !expanded; ++k) {
    field_element E = P[k];
    for (int i = 0; i <= k && i <= Q.degree; ++i) E -= Q[i] * two_cos_coefficient(k - i);
    if (E.is_zero()) continue;
    out.order = 2 * k - 2;
    out.leading_coefficient = E;
    expanded = true;
  }
  if (!expanded) throw std::domain_error("geomint::field_linear_stability: R(tau) - 2 cos(tau) has no nonzero term");
  const field_element two(2);
  if (out.determinant_is_one) {
    out.phase_lag_order = out.order;
    out.phase_lag_constant = out.leading_coefficient / two;
    out.interval = interval_of_conditions(stability_kind::periodic, {two * Q - P, two * Q + P});
    return out;
  }
  int k = 0;
  while (excess[k].is_zero()) ++k;
  out.dissipation_order = 2 * k - 1;
  out.dissipation_constant = -(excess[k] / (D[0] * D[0])) / two;
  const series_term<field_element> phase = phase_series<field_element>(trace_num, D, det_num);
  out.phase_lag_order = 2 * phase.index - 2;
  out.phase_lag_constant = phase.coefficient;
  const field_polynomial D2 = D * D, TD = trace_num * D;
  out.interval = interval_of_conditions(stability_kind::absolute, {D2 - det_num, D2 + det_num - TD, D2 + det_num + TD});
  return out;
}

/// The verdicts of rk_stability(R) for R = P / Q over Q(r).
inline field_rk_stability_result field_rk_stability(const rational_function<std::vector<methods::field_element>>& r) {
  using namespace analysis::detail;
  field_polynomial P(r.numerator), Q(r.denominator);
  reduce_fraction(P, Q);
  field_rk_stability_result out;
  out.numerator = P.c;
  out.denominator = Q.c;
  const field_polynomial e = squared_modulus_on_axis(Q) - squared_modulus_on_axis(P);
  out.imaginary_axis = interval_of_conditions(e.is_zero() ? stability_kind::periodic : stability_kind::absolute, {e});
  out.bounded_on_imaginary_axis = !out.imaginary_axis.empty && out.imaginary_axis.unbounded;
  // Q(-w) Hurwitz (Routh's array, rk_stability.hpp).
  out.poles_in_right_half_plane = routh_hurwitz<field_element, 2 * max_stability_degree + 2>(
      Q.degree, [&](int k) { return k % 2 == 0 ? Q[k] : -Q[k]; }, [](const field_element& x) { return methods::exact_sign(x); });
  out.a_stable = out.bounded_on_imaginary_axis && out.poles_in_right_half_plane;
  out.l_stable = out.a_stable && P.degree < Q.degree;
  return out;
}

/// The verdicts of an rk tableau over Q(r) (any coefficients; run time).
inline field_rk_stability_result field_rk_stability(const methods::tableau_data<methods::field_element>& t) {
  return field_rk_stability(stability_function(t));
}

}  // namespace geomint
