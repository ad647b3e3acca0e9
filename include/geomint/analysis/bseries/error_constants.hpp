#pragma once
/// The principal error constants of a tableau of any kind, exactly over its coefficients (Q, or
/// Q(r) with methods::field_element): the 2-norm of the coefficients of the leading term of the
/// local error (Dormand and Prince's measure ||T^(p+1)||_2; Hairer, Norsett & Wanner I, section
/// II.3 for Runge-Kutta and II.14 for Nystrom methods; docs/references.md).
///
/// With the normalisation of series.hpp the local error of one step is
///   sum_t h^|t| / sigma(t) (a(t) - 1/gamma(t)) F(t),
/// so the coefficient of tree t is T(t) = (a(t) - 1/gamma(t)) / sigma(t), and for a method of
/// order p
///   C^2 = sum over the trees t of order p + 1 of T(t)^2.
/// - rk: one-colour trees (B-series), one component.
/// - prk: bi-coloured trees (P-series); C_1 over the trees with a colour-0 root (the first
///   component, by (A, b)), C_2 over those with a colour-1 root (the second, by (Ahat, bhat)).
/// - rkn and nystrom: the Nystrom trees of the partitioned form (partitioned_form.hpp) on
///   q' = v, v' = F: C_q over the colour-0 roots (position: the tree [u] of order p + 1 is the
///   Nystrom tree u of order p, the q-error h^(p+1) e_q(u)/sigma(u) F(u)) and C_p over the
///   colour-1 roots (velocity). These are the per-component constants ||T^(p+1)||_2 and
///   ||T'^(p+1)||_2 in which RKN constants are published, and equal the library schemes'
///   C_q, C_p of analysis/order_conditions.hpp (the same trees and coefficients).
/// C^2 = C_1^2 + C_2^2 (the combined constant of the library schemes). A component whose own
/// order exceeds p has constant 0. All exact, as squares.

#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/series.hpp"

namespace geomint::analysis::bseries {

/// The squared principal error constants at order p + 1 (see the header comment).
template <class K>
struct error_constants {
  int order = 0;         ///< p
  int components = 1;    ///< 1 (rk) or 2 (prk: colours; rkn, nystrom: q and p)
  K squared{};           ///< C^2
  K first_squared{};     ///< C_1^2 = C_q^2 (colour-0 roots); C^2 for rk
  K second_squared{};    ///< C_2^2 = C_p^2 (colour-1 roots); 0 for rk
};

namespace detail {
template <class K>
error_constants<K> constants_on(const tree_set& trees, const std::vector<K>& a, int order) {
  const std::vector<K> err = local_error_coefficients(trees, a);
  error_constants<K> out;
  out.order = order;
  out.components = trees.colours();
  out.squared = out.first_squared = out.second_squared = K(0);
  for (int t = trees.first(order + 1); t < trees.first(order + 2); ++t) {
    const K coefficient = err[static_cast<std::size_t>(t)] / K(trees[t].sigma);
    const K square = coefficient * coefficient;
    (trees[t].colour == 0 ? out.first_squared : out.second_squared) += square;
    out.squared += square;
  }
  return out;
}
}  // namespace detail

/// The constants of a Nystrom form (rkn, nystrom, a composition) of order p (analyse_method's).
template <class K>
error_constants<K> principal_error_constants(const methods::nystrom_form<K>& f, int order) {
  const tree_class kind = f.has_velocity_stages ? tree_class::nystrom : tree_class::rkn;
  const int limit = kind == tree_class::rkn ? max_tree_order_rkn : max_tree_order_nystrom;
  if (order < 0 || order + 1 > limit)
    throw std::domain_error("principal_error_constants: the trees of order p + 1 must be at most " + std::to_string(limit));
  const tree_set trees(order + 1, kind);  // the Nystrom trees only (trees.hpp, tree_class)
  return detail::constants_on(trees, elementary_weights(trees, partitioned_form_of(f)), order);
}

/// The constants of a tableau of any kind of order p (analyse_method's; std::domain_error when
/// the trees of order p + 1 exceed the generator's limit).
template <class K>
error_constants<K> principal_error_constants(const tableau_data<K>& t, int order) {
  if (t.kind == methods::method_kind::rkn || t.kind == methods::method_kind::nystrom)
    return principal_error_constants(methods::nystrom_form_of(t), order);
  const int colours = t.kind == methods::method_kind::rk ? 1 : 2;
  const int limit = colours == 1 ? max_tree_order_one_colour : max_tree_order_two_colours;
  if (order < 0 || order + 1 > limit)
    throw std::domain_error("principal_error_constants: the trees of order p + 1 must be at most " + std::to_string(limit));
  const tree_set trees(order + 1, colours);
  return detail::constants_on(trees, elementary_weights(trees, t), order);
}

}  // namespace geomint::analysis::bseries
