#pragma once
/// Exact order of an RKN tableau by the Nystrom trees (analysis/nystrom_trees.hpp), its defects
/// at the first failing order and its principal error constant; and the quadrature order of
/// its weights.
///
/// For a tree u the stage weights Psi(u) are stage vectors of the tableau's algebra
/// (analysis/rkn_tableau.hpp), computed once per tree: Psi(u' + son) = Psi(u') * Y(son), with
/// Y(leaf) = c and Y(meagre over w) = A Psi(w). The method has order p when
///   e_p(u) = b(Psi(u)) - 1/gamma(u)                        = 0 for |u| <= p,
///   e_q(u) = bbar(Psi(u)) - 1/((|u| + 1) gamma(u))         = 0 for |u| + 1 <= p,
/// all exactly (HNW I, Theorem II.14.10). The local error of one step is then
///   p1 - p(tau) = sum_{|u| = p+1} tau^{p+1} e_p(u)/sigma(u) F(u) + O(tau^{p+2}),
///   q1 - q(tau) = sum_{|u| = p}   tau^{p+1} e_q(u)/sigma(u) F([u]) + O(tau^{p+2}),
/// with F the elementary differentials, and
///
///   principal error constant  C_{p+1} = sqrt( sum over those trees of (e(u)/sigma(u))^2 ),
///
/// the 2-norm of the coefficients of the leading local error term (the usual measure of
/// Dormand and Prince), for the position alone (the q-trees of size p), the velocity alone (the
/// p-trees of size p + 1; these two are the per-component constants ||T^(p+1)||, ||T'^(p+1)|| in
/// which RKN constants are published) and both together (C^2 = C_q^2 + C_p^2). A component whose
/// own order exceeds p has constant 0. All are stored exactly as squares, rationals.

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "geomint/analysis/nystrom_trees.hpp"
#include "geomint/analysis/rkn_tableau.hpp"

namespace geomint {

/// Which component a condition constrains.
enum class rkn_component { q, p };

/// One nonzero defect at the first failing order.
struct tree_defect {
  int tree = 0;                        ///< index in the tree table
  rkn_component component = rkn_component::p;
  exact_number defect{};               ///< e(u) (weight minus 1/gamma)
  exact_number coefficient{};          ///< e(u) / sigma(u): the coefficient of tau^{p+1} F
};

/// Order and leading error of a tableau (the summary is structural, for static_assert).
struct order_summary {
  int order = 0;                       ///< largest p with every condition up to p exact
  bool order_is_lower_bound = false;   ///< true when every condition up to the tree limit holds
  int tree_limit = 0;                  ///< largest tree size evaluated
  int conditions_checked = 0;          ///< conditions evaluated (all orders <= p + 1)
  int nonzero_defects = 0;             ///< at order p + 1
  exact_number error_constant_squared{};  ///< C_{p+1}^2 (0 when order_is_lower_bound)
  exact_number position_error_constant_squared{};  ///< C_q^2: the q-component's trees
  exact_number velocity_error_constant_squared{};  ///< C_p^2: the p-component's trees
  friend constexpr bool operator==(const order_summary&, const order_summary&) = default;
};

namespace analysis::detail {

/// Evaluates the order conditions order by order up to `max_order` (<= 17). With
/// `stop_at_first_failure` only the order is determined (the first nonzero defect ends the
/// evaluation); otherwise the whole failing order is evaluated. `defects`, if given, receives
/// the nonzero defects at order p + 1.
constexpr order_summary evaluate_order_conditions(const exact_rkn_tableau& t, int max_order, bool stop_at_first_failure,
                                                  std::vector<tree_defect>* defects) {
  if (t.stages < 1 || t.stages > max_exact_stages) throw std::domain_error("geomint: a tableau needs 1..8 stages");
  if (max_order < 1 || max_order > max_nystrom_tree_size) throw std::domain_error("geomint: the order limit must be in 1..17");
  nystrom_tree_table table;
  std::vector<stage_vector> psi;
  std::vector<stage_vector> a_psi;  // A Psi(w), for the sons meagre-over-w
  std::vector<char> have_a_psi;  // not vector<bool>: not constexpr in Clang 14
  order_summary out;
  out.tree_limit = max_order;
  auto condition = [&](int index, rkn_component component, int order, bool& failed) {
    const nystrom_tree& u = table.trees[static_cast<std::size_t>(index)];
    const stage_vector& w = psi[static_cast<std::size_t>(index)];
    exact_number e;
    if (component == rkn_component::p)
      e = t.apply_b(w) - exact_number(rational(1, u.gamma));
    else
      e = t.apply_bbar(w) - exact_number(rational(1, (u.size + 1) * u.gamma));
    ++out.conditions_checked;
    if (e.num.is_zero()) return;
    failed = true;
    const exact_number coefficient = e / exact_number(u.sigma);
    out.error_constant_squared = out.error_constant_squared + coefficient * coefficient;
    exact_number& part = component == rkn_component::q ? out.position_error_constant_squared : out.velocity_error_constant_squared;
    part = part + coefficient * coefficient;
    ++out.nonzero_defects;
    if (defects) defects->push_back(tree_defect{index, component, e, coefficient});
    (void)order;
  };
  for (int k = 1; k <= max_order; ++k) {
    extend_nystrom_trees(table);
    psi.resize(table.trees.size());
    a_psi.resize(table.trees.size());
    have_a_psi.resize(table.trees.size(), 0);
    // Stage weights of the trees of size k.
    for (int i = table.first[static_cast<std::size_t>(k)]; i < table.first[static_cast<std::size_t>(k) + 1]; ++i) {
      const nystrom_tree& u = table.trees[static_cast<std::size_t>(i)];
      if (u.rest < 0) {
        psi[static_cast<std::size_t>(i)] = t.one;
        continue;
      }
      if (u.son == 0) {  // the meagre leaf: Y = c
        psi[static_cast<std::size_t>(i)] = t.multiply_by_nodes(psi[static_cast<std::size_t>(u.rest)]);
        continue;
      }
      const std::size_t w = static_cast<std::size_t>(u.son - 1);  // the son is meagre over the tree w
      if (!have_a_psi[w]) {
        a_psi[w] = t.apply_a(psi[w]);
        have_a_psi[w] = 1;
      }
      psi[static_cast<std::size_t>(i)] = t.multiply(psi[static_cast<std::size_t>(u.rest)], a_psi[w]);
    }
    // Order k: p-conditions on trees of size k, q-conditions on trees of size k - 1.
    bool failed = false;
    for (int i = table.first[static_cast<std::size_t>(k)]; i < table.first[static_cast<std::size_t>(k) + 1]; ++i) {
      condition(i, rkn_component::p, k, failed);
      if (failed && stop_at_first_failure) break;
    }
    if (k >= 2 && !(failed && stop_at_first_failure))
      for (int i = table.first[static_cast<std::size_t>(k - 1)]; i < table.first[static_cast<std::size_t>(k)]; ++i) {
        condition(i, rkn_component::q, k, failed);
        if (failed && stop_at_first_failure) break;
      }
    if (failed) {
      out.order = k - 1;
      return out;
    }
  }
  out.order = max_order;
  out.order_is_lower_bound = true;
  return out;
}

}  // namespace analysis::detail

/// The order of a tableau by the tree conditions, evaluating up to order max_order (the result
/// is max_order when every condition up to it holds). Stops at the first nonzero defect.
constexpr int tree_order(const exact_rkn_tableau& t, int max_order = max_nystrom_tree_size) {
  return analysis::detail::evaluate_order_conditions(t, max_order, true, nullptr).order;
}

/// Order, number of nonzero defects and principal error constant (squared) at order p + 1.
constexpr order_summary order_analysis(const exact_rkn_tableau& t, int max_order = max_nystrom_tree_size) {
  return analysis::detail::evaluate_order_conditions(t, max_order, false, nullptr);
}

/// The same with the list of nonzero defects at order p + 1 (run time or constant evaluation).
inline order_summary order_analysis(const exact_rkn_tableau& t, std::vector<tree_defect>& defects,
                                    int max_order = max_nystrom_tree_size) {
  return analysis::detail::evaluate_order_conditions(t, max_order, false, &defects);
}

/// Quadrature order of the weights b on the nodes: the largest k with b(c^j) = 1/(j + 1) for
/// all j < k (checked up to `limit`).
constexpr int quadrature_order(const exact_rkn_tableau& t, int limit = 2 * max_exact_stages + 2) {
  stage_vector power = t.one;
  for (int j = 0; j < limit; ++j) {
    if (!(t.apply_b(power) == exact_number(rational(1, j + 1)))) return j;
    power = t.multiply_by_nodes(power);
  }
  return limit;
}

/// Stage order: the largest r such that the stages are exact for q'' = g(t) with g of degree
/// r - 2, i.e. A c^k = c^(k+2) / ((k+1)(k+2)) for k = 0..r-2 (componentwise powers; the stage
/// Q_i = q + c_i tau p + tau^2 sum_j a_ij g(c_j tau) then has a local error O(tau^(r+1))). At
/// least 1 (Q_i = q + c_i tau p + O(tau^2)); s + 1 for an s-stage collocation method (checked up
/// to `limit`).
constexpr int stage_order(const exact_rkn_tableau& t, int limit = 2 * max_exact_stages + 2) {
  stage_vector power = t.one;  // c^k
  for (int k = 0; k + 2 <= limit; ++k) {
    const stage_vector image = t.apply_a(power);
    const stage_vector target = t.multiply_by_nodes(t.multiply_by_nodes(power));
    const exact_number scale(rational(1, (k + 1) * (k + 2)));
    for (int i = 0; i < t.stages; ++i)
      if (!(image[i] == scale * target[i])) return k + 1;
    power = t.multiply_by_nodes(power);
  }
  return limit;
}

}  // namespace geomint
