#pragma once
/// Exact verdicts on a tableau of any kind (methods/tableau.hpp: rk, prk, rkn, nystrom) over its
/// own coefficients: symmetry up to a permutation of the stages, stage order, and linear
/// stability. The order and symplecticity are analysis/bseries/method_analysis.hpp's.
///
/// - `symmetry_permutation(t)`, `is_symmetric(t)` (constexpr for the fixed-size tableaux over a
///   constexpr K): the method is symmetric iff its adjoint Phi*_h = Phi_{-h}^{-1} is the method
///   with the stages permuted by some sigma (Hairer, Lubich & Wanner, Geometric Numerical
///   Integration, 2nd ed., sections II.3 and V.2; for RK with sigma(i) = s + 1 - i, Theorem
///   V.2.3). The adjoint's coefficients, from one step with -h solved for the end values:
///   - rk (c = A 1):  a*_ij = b_j - a_ij, b* = b;
///   - prk: the same for (A, b) and for (Ahat, bhat), one sigma for both;
///   - rkn: c* = 1 - c, a*_ij = (1 - c_i) b_j - bbar_j + a_ij, bbar* = b - bbar, b* = b
///     (analysis/scheme_structure.hpp);
///   - nystrom: as rkn, and ap*_ij = b_j - ap_ij (V_i = v1 - h sum_j ap_ij F_j with
///     v1 = v + h sum_j b_j F_j).
///   Symmetric iff some sigma has x_sigma(i)sigma(j) = x*_ij and y_sigma(j) = y*_j for every
///   matrix x and vector y. sigma is searched among all permutations (backtracking, the
///   conditions on the stages assigned so far pruning), so stages with equal nodes may swap.
/// - `stage_order(t)`: rk and prk the largest q with B(q) and C(q) (Hairer & Wanner, Solving
///   ODEs II, section IV.15): sum_i b_i c_i^(k-1) = 1/k and sum_j a_ij c_j^(k-1) = c_i^k / k for
///   k <= q, with the tableau's c (as published: Lobatto IIIB has c != A 1, so C(1) fails; the
///   integrator steps autonomous systems and uses A 1); prk the smaller of (c, A, b) and
///   (c, Ahat, bhat).
///   rkn and nystrom as analysis/order_conditions.hpp's stage_order: the largest r with
///   A c^k = c^(k+2) / ((k+1)(k+2)) (nystrom also Ap c^k = c^(k+1) / (k+1)) for k = 0..r-2. Up
///   to 2 S + 2. Run time (tableau_data).
/// - `linear_stability(t)`: the step on y'' = -y (q' = p, p' = -q) of every kind (constexpr for
///   the fixed-size tableaux over a constexpr K, run time for tableau_data),
///   through its Nystrom form (methods/nystrom_form.hpp; rk on the first-order form, prk as
///   q' = p by (A, b) and p' = -q by (Ahat, bhat)): D = det(I + z A) and the bordered
///   determinants of linear_stability.hpp evaluated over K at z = 0..S and interpolated, then
///   that header's exact analysis (periodicity where det M = 1, else absolute stability,
///   dissipation, phase lag). Needs sum b = 1, rational polynomials and S <= 8
///   (std::domain_error naming which fails); over Q(r) `field_linear_stability(t)` (run time, any
///   S) is the same analysis for irrational polynomials (field_stability.hpp).
/// - `verdicts(t)` (run time): all of them, symmetry also on the irreducible method of a
///   reducible tableau (methods/reduction.hpp: the same map; the free drift of an rkn tableau
///   with zero weights is symmetric, its printed stage is not) (over field_element: the field path where the rational
///   one does not decide: field_oscillator, field_rk), with the stability verdict of the CSV column
///   `stability`: rk `a-stable` when A-stable (rk_stability.hpp; also when L-stable, see
///   `l_stable`), else the kind of its imaginary-axis interval; prk, rkn, nystrom `periodic`
///   (det M = 1) or `absolute`; `none` for an empty interval.

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "geomint/analysis/field_stability.hpp"
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/rk_stability.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/methods/reduction.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint {

/// A stage permutation (the stages of a tableau file are at most 64).
struct stage_permutation {
  bool found = false;
  std::array<int, 64> sigma{};  ///< sigma[i] for i < S
};

namespace analysis::detail {

/// Whether stage k may be sigma(i), with sigma(0..i-1) fixed: every adjoint condition on the
/// stages 0..i (see the header comment).
template <class Tableau>
constexpr bool adjoint_stage_fits(const Tableau& t, std::size_t i, std::size_t k, const std::array<int, 64>& sigma) {
  using K = std::remove_cvref_t<decltype(t.b[0])>;
  const bool nystrom_like = t.kind == methods::method_kind::rkn || t.kind == methods::method_kind::nystrom;
  auto at = [&](std::size_t p) { return p == i ? k : static_cast<std::size_t>(sigma[p]); };
  if (!(t.b[k] == t.b[i])) return false;
  if constexpr (requires { t.bbar; }) {
    if (nystrom_like && (!(t.c[k] == K(1) - t.c[i]) || !(t.bbar[k] == t.b[i] - t.bbar[i]))) return false;
  }
  if constexpr (requires { t.bhat; }) {
    if (t.kind == methods::method_kind::prk && !(t.bhat[k] == t.bhat[i])) return false;
  }
  auto pair_fits = [&](std::size_t p, std::size_t q) {
    const std::size_t sp = at(p), sq = at(q);
    if (!nystrom_like) {
      if (!(t.a[sp][sq] == t.b[q] - t.a[p][q])) return false;
    } else if constexpr (requires { t.bbar; }) {
      if (!(t.a[sp][sq] == (K(1) - t.c[p]) * t.b[q] - t.bbar[q] + t.a[p][q])) return false;
    }
    if constexpr (requires { t.ahat; }) {
      if (t.kind == methods::method_kind::prk && !(t.ahat[sp][sq] == t.bhat[q] - t.ahat[p][q])) return false;
    }
    if constexpr (requires { t.ap; }) {
      if (t.kind == methods::method_kind::nystrom && !(t.ap[sp][sq] == t.b[q] - t.ap[p][q])) return false;
    }
    return true;
  };
  for (std::size_t j = 0; j <= i; ++j)
    if (!pair_fits(i, j) || !pair_fits(j, i)) return false;
  return true;
}

template <class Tableau>
constexpr bool extend_adjoint_permutation(const Tableau& t, std::size_t i, std::size_t s, std::array<int, 64>& sigma,
                                          std::array<bool, 64>& used) {
  if (i == s) return true;
  for (std::size_t k = 0; k < s; ++k) {
    if (used[k] || !adjoint_stage_fits(t, i, k, sigma)) continue;
    sigma[i] = static_cast<int>(k);
    used[k] = true;
    if (extend_adjoint_permutation(t, i + 1, s, sigma, used)) return true;
    used[k] = false;
  }
  return false;
}

/// rk and prk: the largest q <= limit with B(q) and C(q) for (c, A, b).
template <class K, class Matrix, class Weights>
constexpr int rk_stage_order(const Weights& c, const Matrix& a, const Weights& b, std::size_t s, int limit) {
  Weights power = b;
  for (std::size_t i = 0; i < s; ++i) power[i] = K(1);  // c^(k-1)
  for (int k = 1; k <= limit; ++k) {
    const K inverse = K(1) / K(static_cast<std::int64_t>(k));
    K quadrature(0);
    for (std::size_t i = 0; i < s; ++i) quadrature = quadrature + b[i] * power[i];
    if (!(quadrature == inverse)) return k - 1;
    for (std::size_t i = 0; i < s; ++i) {
      K sum(0);
      for (std::size_t j = 0; j < s; ++j) sum = sum + a[i][j] * power[j];
      if (!(sum == power[i] * c[i] * inverse)) return k - 1;
    }
    for (std::size_t i = 0; i < s; ++i) power[i] = power[i] * c[i];
  }
  return limit;
}

/// rkn and nystrom: the largest r <= limit with A c^k = c^(k+2) / ((k+1)(k+2)) (and, with ap,
/// Ap c^k = c^(k+1) / (k+1)) for k = 0..r-2.
template <class K, class Matrix, class Weights>
constexpr int rkn_stage_order(const Matrix& a, const Matrix* ap, const Weights& c, std::size_t s, int limit) {
  Weights power = c;
  for (std::size_t i = 0; i < s; ++i) power[i] = K(1);  // c^k
  for (int k = 0; k + 2 <= limit; ++k) {
    const K first = K(1) / K(static_cast<std::int64_t>(k + 1)), second = first / K(static_cast<std::int64_t>(k + 2));
    for (std::size_t i = 0; i < s; ++i) {
      K sum(0), velocity(0);
      for (std::size_t j = 0; j < s; ++j) {
        sum = sum + a[i][j] * power[j];
        if (ap) velocity = velocity + (*ap)[i][j] * power[j];
      }
      if (!(sum == power[i] * c[i] * c[i] * second)) return k + 1;
      if (ap && !(velocity == power[i] * c[i] * first)) return k + 1;
    }
    for (std::size_t i = 0; i < s; ++i) power[i] = power[i] * c[i];
  }
  return limit;
}

/// The step on y'' = -y of the RKN coefficients (c, a, bbar, b) over K (see the header comment):
/// D = det(I + z A) and the bordered determinants det [[I + z A, u], [v^T, 0]] for (v, u) =
/// (bbar, 1), (bbar, c), (b, 1), (b, c) at z = 0..s, interpolated (coefficients over K, ascending).
/// `work` is an (s + 1) x (s + 1) matrix of K, `values` holds s + 1 entries.
template <class K, class Vector, class Matrix, class Work, class Values>
constexpr std::array<Values, 5> oscillator_determinants(const Vector& c, const Matrix& a, const Vector& bbar, const Vector& b,
                                                        std::size_t s, Work work, const Values& values) {
  Vector one = c;
  for (std::size_t i = 0; i < s; ++i) one[i] = K(1);
  std::array<Values, 5> out{values, values, values, values, values};
  auto bordered = [&](const K& z, const Vector* u, const Vector* v) {
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) work[i][j] = K(i == j ? 1 : 0) + z * a[i][j];
    if (!u) return determinant<K>(work, s);
    for (std::size_t i = 0; i < s; ++i) {
      work[i][s] = (*u)[i];
      work[s][i] = (*v)[i];
    }
    work[s][s] = K(0);
    return determinant<K>(work, s + 1);
  };
  for (std::size_t k = 0; k <= s; ++k) {
    const K z(static_cast<std::int64_t>(k));
    out[0][k] = bordered(z, nullptr, nullptr);
    out[1][k] = bordered(z, &one, &bbar);
    out[2][k] = bordered(z, &c, &bbar);
    out[3][k] = bordered(z, &one, &b);
    out[4][k] = bordered(z, &c, &b);
  }
  for (Values& v : out) v = interpolate<K>(v, s);
  return out;
}

/// The exact analysis of linear_stability.hpp from those determinants (rational polynomials).
template <class K, class Vector, class Matrix, class Work, class Values>
constexpr linear_stability_result oscillator_stability(const Vector& c, const Matrix& a, const Vector& bbar, const Vector& b,
                                                       std::size_t s, Work work, const Values& values) {
  const std::array<Values, 5> d = oscillator_determinants<K>(c, a, bbar, b, s, work, values);
  return linear_stability_from_determinants(to_qpoly(d[0]), to_qpoly(d[1]), to_qpoly(d[2]), to_qpoly(d[3]), to_qpoly(d[4]));
}

/// The RKN tableau of a fixed-size tableau on q'' = f(q) (methods/nystrom_form.hpp's
/// conversion: rk and prk give c = A 1, A Ahat, b^T Ahat, bhat with Ahat = A, bhat = b for rk).
template <class Tableau>
constexpr auto rkn_coefficients_of(const Tableau& t) {
  using K = typename Tableau::coefficient;
  constexpr std::size_t s = static_cast<std::size_t>(Tableau::stages);
  methods::rkn<K, Tableau::stages> r;
  K sum_b(0);
  for (std::size_t j = 0; j < s; ++j) sum_b = sum_b + t.b[j];
  if constexpr (requires { t.bbar; }) {
    r.c = t.c;
    r.a = t.a;
    r.bbar = t.bbar;
    r.b = t.b;
    sum_b = K(1);  // q1 = q + h v + ...: consistent by construction
  } else {
    const auto& ahat = [&]() -> const methods::stage_matrix<K, Tableau::stages>& {
      if constexpr (requires { t.ahat; }) return t.ahat;
      else return t.a;
    }();
    for (std::size_t i = 0; i < s; ++i) {
      K row(0), weight(0);
      for (std::size_t j = 0; j < s; ++j) {
        row = row + t.a[i][j];
        weight = weight + t.b[j] * ahat[j][i];
        K product(0);
        for (std::size_t k = 0; k < s; ++k) product = product + t.a[i][k] * ahat[k][j];
        r.a[i][j] = product;
      }
      r.c[i] = row;
      r.bbar[i] = weight;
    }
    if constexpr (requires { t.bhat; }) r.b = t.bhat;
    else r.b = t.b;
  }
  if (!(sum_b == K(1))) throw std::domain_error("the weights b do not sum to 1 (the method is not consistent)");
  return r;
}

}  // namespace analysis::detail

/// The stage permutation sigma under which the adjoint is the method itself (found = false:
/// the method is not symmetric).
template <class Tableau>
constexpr stage_permutation symmetry_permutation(const Tableau& t) {
  const auto s = static_cast<std::size_t>(t.stages);
  if (s > 64) throw std::invalid_argument("symmetry_permutation: at most 64 stages");
  stage_permutation out;
  std::array<bool, 64> used{};
  out.found = analysis::detail::extend_adjoint_permutation(t, 0, s, out.sigma, used);
  return out;
}
template <class Tableau>
constexpr bool is_symmetric(const Tableau& t) {
  return symmetry_permutation(t).found;
}

/// The stage order of a tableau of any kind (see the header comment; constexpr for the
/// fixed-size tableaux over a constexpr K).
template <class Tableau>
  requires requires(const Tableau& t) { t.kind; }
constexpr int stage_order(const Tableau& t) {
  using K = std::remove_cvref_t<decltype(t.b[0])>;
  if constexpr (requires { t.name; }) methods::detail::check_sizes(t);  // tableau_data
  const auto s = static_cast<std::size_t>(t.stages);
  const int limit = 2 * t.stages + 2;
  using analysis::detail::rk_stage_order;
  using analysis::detail::rkn_stage_order;
  int order = 0;
  if (t.kind == methods::method_kind::rk || t.kind == methods::method_kind::prk) order = rk_stage_order<K>(t.c, t.a, t.b, s, limit);
  if constexpr (requires { t.ahat; }) {
    if (t.kind == methods::method_kind::prk) order = std::min(order, rk_stage_order<K>(t.c, t.ahat, t.bhat, s, limit));
  }
  if constexpr (requires { t.bbar; }) {
    const decltype(t.a)* velocities = nullptr;
    if constexpr (requires { t.ap; }) {
      if (t.kind == methods::method_kind::nystrom) velocities = &t.ap;
    }
    if (t.kind == methods::method_kind::rkn || t.kind == methods::method_kind::nystrom)
      order = rkn_stage_order<K>(t.a, velocities, t.c, s, limit);
  }
  return order;
}

/// The exact step of a tableau of any kind on y'' = -y (see the header comment).
template <class K>
linear_stability_result linear_stability(const methods::tableau_data<K>& t) {
  const methods::nystrom_form<K> f = methods::nystrom_form_of(t);
  if (f.stages > max_exact_stages) throw std::domain_error("the exact stability analysis takes at most 8 stages");
  if (!(f.d == K(1))) throw std::domain_error("the weights b do not sum to 1 (the method is not consistent)");
  const auto s = static_cast<std::size_t>(f.stages);
  return analysis::detail::oscillator_stability<K>(f.c, f.a, f.bbar, f.b, s, std::vector<std::vector<K>>(s + 1, std::vector<K>(s + 1, K(0))),
                                                   std::vector<K>(s + 1, K(0)));
}

/// The exact step on y'' = -y of a tableau over Q(r) (field_stability.hpp; run time, any number
/// of stages): for coefficients whose stability polynomials are irrational.
inline field_linear_stability_result field_linear_stability(const methods::tableau_data<methods::field_element>& t) {
  using K = methods::field_element;
  const methods::nystrom_form<K> f = methods::nystrom_form_of(t);
  if (!(f.d == K(1))) throw std::domain_error("the weights b do not sum to 1 (the method is not consistent)");
  const auto s = static_cast<std::size_t>(f.stages);
  return field_linear_stability_from_determinants(analysis::detail::oscillator_determinants<K>(
      f.c, f.a, f.bbar, f.b, s, std::vector<std::vector<K>>(s + 1, std::vector<K>(s + 1, K(0))), std::vector<K>(s + 1, K(0))));
}

/// The exact step on y'' = -y of a fixed-size tableau of any kind (constexpr over a constexpr K).
template <class Tableau>
  requires requires(const Tableau& t) { Tableau::kind; t.c; }
constexpr linear_stability_result linear_stability(const Tableau& t) {
  static_assert(Tableau::stages <= max_exact_stages, "geomint::linear_stability: at most max_exact_stages (8) stages");
  using K = typename Tableau::coefficient;
  constexpr std::size_t s = static_cast<std::size_t>(Tableau::stages);
  const auto r = analysis::detail::rkn_coefficients_of(t);
  return analysis::detail::oscillator_stability<K>(r.c, r.a, r.bbar, r.b, s, std::array<std::array<K, s + 1>, s + 1>{},
                                                   std::array<K, s + 1>{});
}

/// The verdict of the CSV column `stability`.
enum class stability_verdict { periodic, absolute, a_stable, none };

inline std::string_view to_string(stability_verdict v) {
  switch (v) {
    case stability_verdict::periodic: return "periodic";
    case stability_verdict::absolute: return "absolute";
    case stability_verdict::a_stable: return "a-stable";
    case stability_verdict::none: return "none";
  }
  return "?";
}

/// Symmetry, stage order and linear stability of a tableau (see the header comment).
struct method_verdicts {
  bool symmetric = false;
  stage_permutation permutation{};  ///< sigma of the adjoint when symmetric
  int stage_order = 0;
  /// rk: R(z) on y' = lambda y (has_rk false when it could not be decided: rk_reason).
  bool has_rk = false;
  rk_stability_result rk{};
  std::string rk_reason;
  /// Every kind: the step on y'' = -y (has_oscillator false when not decided: oscillator_reason).
  bool has_oscillator = false;
  linear_stability_result oscillator{};
  std::string oscillator_reason;
  /// Over Q(r) with irrational stability polynomials (or more than 8 stages), instead of rk and
  /// oscillator: field_rk and field_oscillator (field_stability.hpp).
  bool rk_in_field = false;
  field_rk_stability_result field_rk{};
  bool oscillator_in_field = false;
  field_linear_stability_result field_oscillator{};
  /// The stability verdict and its interval (rk: the imaginary-axis interval; else on
  /// y'' = -y); has_stability false when neither analysis applies.
  bool has_stability = false;
  stability_verdict stability = stability_verdict::none;
  stability_interval interval{};
  bool l_stable = false;  ///< rk only
};

/// The stability verdicts of `v` (has_rk, rk, has_oscillator, oscillator, their field
/// counterparts, has_stability, stability, interval, l_stable) from the linear part of t: its
/// R(z) and its step on y'' = -y (any tableau with the same linear maps gives the same ones:
/// analysis/collocation_algebra_analysis.hpp uses that).
template <class K>
void add_stability_verdicts(method_verdicts& v, const methods::tableau_data<K>& t) {
  // result = compute() and decided = true, or the reason it could not be decided.
  auto attempt = [](auto compute, auto& result, bool& decided, std::string& reason) {
    try {
      result = compute();
      decided = true;
      reason.clear();
    } catch (const std::exception& e) {  // irrational polynomials, more than 8 stages, sum b != 1
      reason = e.what();
    }
  };
  attempt([&] { return linear_stability(t); }, v.oscillator, v.has_oscillator, v.oscillator_reason);
  if (t.kind == methods::method_kind::rk) attempt([&] { return rk_stability(t); }, v.rk, v.has_rk, v.rk_reason);
  if constexpr (std::is_same_v<K, methods::field_element>) {  // where the rational path did not decide
    if (!v.has_oscillator) attempt([&] { return field_linear_stability(t); }, v.field_oscillator, v.oscillator_in_field, v.oscillator_reason);
    if (t.kind == methods::method_kind::rk && !v.has_rk)
      attempt([&] { return field_rk_stability(t); }, v.field_rk, v.rk_in_field, v.rk_reason);
  }
  if (v.has_rk || v.rk_in_field) {
    v.has_stability = true;
    v.interval = v.has_rk ? v.rk.imaginary_axis : v.field_rk.imaginary_axis;
    v.l_stable = v.has_rk ? v.rk.l_stable : v.field_rk.l_stable;
    if (v.has_rk ? v.rk.a_stable : v.field_rk.a_stable)
      v.stability = stability_verdict::a_stable;
    else if (v.interval.empty)
      v.stability = stability_verdict::none;
    else
      v.stability = v.interval.kind == stability_kind::periodic ? stability_verdict::periodic : stability_verdict::absolute;
  } else if ((v.has_oscillator || v.oscillator_in_field) && t.kind != methods::method_kind::rk) {
    v.has_stability = true;
    v.interval = v.has_oscillator ? linear_stability_interval(v.oscillator) : v.field_oscillator.interval;
    if (v.interval.empty)
      v.stability = stability_verdict::none;
    else
      v.stability = v.interval.kind == stability_kind::periodic ? stability_verdict::periodic : stability_verdict::absolute;
  }
}

template <class K>
method_verdicts verdicts(const methods::tableau_data<K>& t) {
  method_verdicts v;
  v.permutation = symmetry_permutation(t);
  v.symmetric = v.permutation.found;
  if (!v.symmetric) {  // a reducible method is symmetric if its irreducible method is (the map is the same)
    const methods::tableau_data<K> reduced = methods::irreducible_form(t).method;
    v.symmetric = reduced.stages < t.stages && symmetry_permutation(reduced).found;
  }
  v.stage_order = stage_order(t);
  add_stability_verdicts(v, t);
  return v;
}

}  // namespace geomint
