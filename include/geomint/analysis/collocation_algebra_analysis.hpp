#pragma once
/// The exact analysis of an rk method over its stage algebra Q[x]/(N)
/// (methods/collocation_algebra.hpp: Radau IIA and IA with s = 5), with the results and the
/// verdict types of the tableau analysis (bseries/method_analysis.hpp, method_verdicts.hpp), so
/// geomint-scheme prints both alike. Everything is rational; in the monomial basis (V_ik = c_i^k,
/// W = diag(b), G = V^T W V the Gram matrix, beta_k = b(x^k)):
/// - order: the elementary weights on rooted trees (HLW section III.1.2), g(t) = prod over the
///   subtrees u of A g(u) (products modulo N), Phi(t) = b(g(t)), against 1/gamma(t); the error
///   constants from the same weights (bseries/error_constants.hpp);
/// - symplecticity: b_i a_ij + b_j a_ji = b_i b_j (HLW Theorem VI.4.3) is W A + A^T W = b b^T,
///   in coordinates G A + A^T G = beta beta^T (both sides multiplied by V^T and V); the
///   conditions are necessary for an irreducible method, and a method with nonzero weights
///   (G nonsingular) and C(1) (A 1 = x: distinct stage values on y' = 1) is irreducible (no
///   stage unused, no two stages equal on every problem); otherwise a failed condition decides
///   nothing (Lobatto IIIB, s = 2, is the implicit midpoint rule) and analyse_method throws;
/// - stage order: the largest q with B(q), b(x^(k-1)) = 1/k, and C(q), A x^(k-1) = x^k / k mod N;
/// - symmetry: the adjoint a*_ij = b_j - a_ij with its stages permuted by sigma, c_sigma(i) =
///   1 - c_i, needs the nodes symmetric, N(1 - x) = (-1)^s N(x); then sigma is the automorphism
///   P: u(x) -> u(1 - x) of Q[x]/(N), and the method is symmetric iff P (e_0 beta^T - A) P = A
///   and beta P = beta (HLW section V.2);
/// - linear stability: R(z) = 1 + z b^T (I - z A)^(-1) 1 and the step on y'' = -y depend only
///   on (A, b, 1) up to a similarity, so they are those of the rational tableau
///   (T^(-1) A T, beta^T T) with T 1 = e_0 (T = I - sum_(k>=1) e_k e_0^T; c = A 1), analysed by
///   method_verdicts.hpp (`linear_equivalent_tableau`; its nonlinear order conditions are not
///   the method's, so it is used for the linear verdicts only).

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/analysis/bseries/error_constants.hpp"
#include "geomint/analysis/bseries/method_analysis.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/methods/collocation_algebra.hpp"

namespace geomint::analysis {

using methods::exact_rational;
using methods::rk_stage_algebra;

/// The symplecticity conditions in the monomial basis: D = G A + A^T G - beta beta^T.
struct stage_algebra_symplecticity {
  bool symplectic = false;
  bool irreducible = false;  ///< nonzero weights and C(1): the conditions are also necessary
  rk_stage_algebra::matrix defect;
  int defect_k = -1, defect_l = -1;  ///< the first nonzero entry (row-major, 0-based), -1 when none
};

inline stage_algebra_symplecticity symplecticity_conditions(const rk_stage_algebra& m) {
  const auto s = static_cast<std::size_t>(m.stages);
  const rk_stage_algebra::matrix g = m.gram();
  stage_algebra_symplecticity r;
  r.defect.assign(s, rk_stage_algebra::vector(s, exact_rational(0)));
  for (std::size_t k = 0; k < s; ++k)
    for (std::size_t l = 0; l < s; ++l) {
      exact_rational d = -m.b[k] * m.b[l];
      for (std::size_t j = 0; j < s; ++j) d += g[k][j] * m.a[j][l] + m.a[j][k] * g[j][l];
      r.defect[k][l] = d;
      if (!d.is_zero() && r.defect_k < 0) {
        r.defect_k = static_cast<int>(k);
        r.defect_l = static_cast<int>(l);
      }
    }
  r.symplectic = r.defect_k < 0;
  bool weights_nonzero = true;
  try {
    (void)methods::detail::solve_exact(g, rk_stage_algebra::vector(s, exact_rational(0)));
  } catch (const std::logic_error&) {
    weights_nonzero = false;
  }
  r.irreducible = weights_nonzero && m.apply_a(m.one()) == m.nodes();
  return r;
}

/// The largest q <= 2s + 2 with B(q) and C(q).
inline int stage_order(const rk_stage_algebra& m) {
  const int limit = 2 * m.stages + 2;
  for (int k = 1; k <= limit; ++k) {
    const exact_rational inverse(1, k);
    if (m.apply_b(m.power(k - 1)) != inverse) return k - 1;
    rk_stage_algebra::vector expected = m.power(k);
    for (auto& x : expected) x *= inverse;
    if (m.apply_a(m.power(k - 1)) != expected) return k - 1;
  }
  return limit;
}

/// Whether the method is its own adjoint up to a permutation of the stages (see the top).
inline bool is_symmetric(const rk_stage_algebra& m) {
  const auto s = static_cast<std::size_t>(m.stages);
  // N(1 - x) by Horner's rule, against (-1)^s N(x).
  rk_stage_algebra::vector reflected(1, exact_rational(0));
  for (std::size_t k = m.node_polynomial.size(); k-- > 0;) {
    rk_stage_algebra::vector next(reflected.size() + 1, exact_rational(0));
    for (std::size_t i = 0; i < reflected.size(); ++i) {
      next[i] += reflected[i];
      next[i + 1] -= reflected[i];
    }
    next[0] += m.node_polynomial[k];
    reflected = std::move(next);
  }
  reflected.resize(s + 1);
  const int sign = s % 2 == 0 ? 1 : -1;
  for (std::size_t k = 0; k <= s; ++k)
    if (reflected[k] != sign * m.node_polynomial[k]) return false;
  // P: column l = (1 - x)^l mod N.
  rk_stage_algebra::matrix p(s, rk_stage_algebra::vector(s));
  rk_stage_algebra::vector power = m.one(), one_minus_x = m.one();
  if (s > 1) one_minus_x[1] = -1;
  else one_minus_x = m.reduce({exact_rational(1), exact_rational(-1)});
  for (std::size_t l = 0; l < s; ++l) {
    for (std::size_t k = 0; k < s; ++k) p[k][l] = power[k];
    power = m.multiply(power, one_minus_x);
  }
  auto times = [&](const rk_stage_algebra::matrix& x, const rk_stage_algebra::matrix& y) {
    rk_stage_algebra::matrix z(s, rk_stage_algebra::vector(s, exact_rational(0)));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t k = 0; k < s; ++k)
        for (std::size_t j = 0; j < s; ++j) z[i][j] += x[i][k] * y[k][j];
    return z;
  };
  rk_stage_algebra::matrix adjoint(s, rk_stage_algebra::vector(s));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) adjoint[i][j] = (i == 0 ? m.b[j] : exact_rational(0)) - m.a[i][j];
  if (times(times(p, adjoint), p) != m.a) return false;
  for (std::size_t l = 0; l < s; ++l) {
    exact_rational sum = 0;
    for (std::size_t k = 0; k < s; ++k) sum += m.b[k] * p[k][l];
    if (sum != m.b[l]) return false;
  }
  return true;
}

/// A rational rk tableau with the method's R(z) and step on y'' = -y (see the top of the file).
inline methods::tableau_data<methods::field_element> linear_equivalent_tableau(const rk_stage_algebra& m) {
  const auto s = static_cast<std::size_t>(m.stages);
  // T = I - sum_(k>=1) e_k e_0^T, T^(-1) = I + sum_(k>=1) e_k e_0^T.
  auto t_entry = [](std::size_t i, std::size_t j, int sign) {
    return exact_rational(i == j ? 1 : (j == 0 ? sign : 0));
  };
  methods::tableau_data<methods::field_element> d;
  d.kind = methods::method_kind::rk;
  d.stages = m.stages;
  d.name = m.name + " (linear part)";
  d.a.assign(s, std::vector<methods::field_element>(s));
  d.b.assign(s, methods::field_element());
  d.c.assign(s, methods::field_element());
  for (std::size_t i = 0; i < s; ++i) {
    for (std::size_t j = 0; j < s; ++j) {
      exact_rational sum = 0;
      for (std::size_t k = 0; k < s; ++k)
        for (std::size_t l = 0; l < s; ++l) sum += t_entry(i, k, 1) * m.a[k][l] * t_entry(l, j, -1);
      d.a[i][j] = sum;
    }
    exact_rational weight = 0;
    for (std::size_t k = 0; k < s; ++k) weight += m.b[k] * t_entry(k, i, -1);
    d.b[i] = weight;
  }
  for (std::size_t i = 0; i < s; ++i) {
    methods::field_element row;
    for (std::size_t j = 0; j < s; ++j) row += d.a[i][j];
    d.c[i] = row;
  }
  return d;
}

/// Symmetry, stage order and the stability verdicts (method_verdicts.hpp's fields).
inline method_verdicts verdicts(const rk_stage_algebra& m) {
  method_verdicts v;
  v.symmetric = is_symmetric(m);
  v.stage_order = stage_order(m);
  add_stability_verdicts(v, linear_equivalent_tableau(m));
  return v;
}

namespace bseries {

/// Phi(t) for every one-colour tree (see the top of the file), as field elements over Q.
inline std::vector<methods::field_element> elementary_weights(const tree_set& trees, const rk_stage_algebra& m) {
  if (trees.colours() != 1)
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: a Runge-Kutta method needs one-colour trees");
  const auto n = static_cast<std::size_t>(trees.size());
  std::vector<rk_stage_algebra::vector> fed(n);
  std::vector<methods::field_element> phi(n);
  for (std::size_t t = 0; t < n; ++t) {
    const rooted_tree& tree = trees[static_cast<int>(t)];
    rk_stage_algebra::vector g = tree.subtrees.empty() ? m.one() : fed[static_cast<std::size_t>(tree.subtrees[0])];
    for (std::size_t k = 1; k < tree.subtrees.size(); ++k) g = m.multiply(g, fed[static_cast<std::size_t>(tree.subtrees[k])]);
    fed[t] = m.apply_a(g);
    phi[t] = methods::field_element(m.apply_b(g));
  }
  return phi;
}

/// Rooted trees analysed by default: to order 10, and to 2s + 1 (at most 14) for s >= 5, so that
/// the order 2s of Gauss is decided (each tree costs one product modulo N, with rationals).
inline int default_tree_order(const rk_stage_algebra& m) {
  return std::min(max_tree_order_one_colour, std::max(default_order_one_colour, 2 * m.stages + 1));
}

/// Order (rooted trees up to `tree_order`, 0: default_tree_order) and symplecticity.
inline method_analysis analyse_method(const rk_stage_algebra& m, int tree_order = 0) {
  method_analysis r;
  r.colours = 1;
  r.tree_order = tree_order > 0 ? tree_order : default_tree_order(m);
  const tree_set trees(r.tree_order, 1);
  detail::order_of(trees, local_error_coefficients(trees, elementary_weights(trees, m)), r);
  const stage_algebra_symplecticity conditions = symplecticity_conditions(m);
  if (!conditions.symplectic && !conditions.irreducible)
    throw std::domain_error("geomint::analysis: the symplecticity conditions fail on a method over Q[x]/(N) that may be reducible "
                            "(a zero weight, or A 1 != x): not decided");
  r.symplectic = conditions.symplectic;
  r.symplecticity_basis = "b_i a_ij + b_j a_ji = b_i b_j as G A + A^T G = beta beta^T on Q[x]/(N), exact, on the irreducible "
                          "method of " + std::to_string(m.stages) + " stages";
  return r;
}

/// The squared principal error constant at order p + 1 (rooted trees).
inline error_constants<methods::field_element> principal_error_constants(const rk_stage_algebra& m, int order) {
  if (order < 0 || order + 1 > max_tree_order_one_colour)
    throw std::domain_error("principal_error_constants: the trees of order p + 1 must be at most " +
                            std::to_string(max_tree_order_one_colour));
  const tree_set trees(order + 1, 1);
  return detail::constants_on(trees, elementary_weights(trees, m), order);
}

}  // namespace bseries
}  // namespace geomint::analysis
