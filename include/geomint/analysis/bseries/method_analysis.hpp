#pragma once
/// The exact order and symplecticity of a tableau of any kind (methods/tableau.hpp: a tableau
/// file, a library tableau), from the same coefficients the integrator runs.
///
/// - Order: the largest p with a(t) = 1/gamma(t) (HLW: Hairer, Lubich & Wanner, Geometric
///   Numerical Integration, 2nd ed. 2006, section III.1) for every tree with |t| <= p: rk on
///   one-colour trees (B-series), prk on two-colour trees (P-series), nystrom on the N-trees of
///   q'' = F(q, q') and rkn on the special N-trees of q'' = f(q), with the weights of the
///   Nystrom coefficients themselves (nystrom_tree_set.hpp; the same order as on the Nystrom
///   trees of the partitioned form, partitioned_form.hpp, as shown there).
/// - Symplecticity: rk and prk by the conditions on the modified field up to the order analysed
///   (symplectic_conditions.hpp; a verdict up to that order, not a proof beyond it). rkn and
///   nystrom (on q'' = f(q), d = 1) by the exact algebraic conditions of Suris 1989 (HLW Theorem
///   VI.4.10): bbar_i = b_i (1 - c_i), b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji); the tree
///   conditions do not apply to them as they stand, because the P-series of the partitioned form on the
///   trees outside the Nystrom trees depends on the conversion, not on the method.

#include <string>
#include <vector>

#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/nystrom_tree_set.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/symplectic_conditions.hpp"

namespace geomint::analysis::bseries {

/// Tree orders analysed by default: one colour up to 10, two colours up to 8.
inline constexpr int default_order_one_colour = 10;
inline constexpr int default_order_two_colours = 8;

struct method_analysis {
  int order = 0;
  bool order_is_lower_bound = false;  ///< every condition up to tree_order holds
  int tree_order = 0;                 ///< largest tree order analysed
  int colours = 1;                    ///< 1: B-series, 2: P-series
  bool symplectic = false;
  /// "tree conditions up to order N" or "RKN conditions (exact)".
  std::string symplecticity_basis;
};

namespace detail {
/// The RKN symplecticity conditions on a Nystrom form (d = 1 required).
template <class K>
bool rkn_symplectic(const methods::nystrom_form<K>& f) {
  if (!(f.d == K(1))) return false;
  const auto s = static_cast<std::size_t>(f.stages);
  for (std::size_t i = 0; i < s; ++i) {
    if (!(f.bbar[i] == f.b[i] * (K(1) - f.c[i]))) return false;
    for (std::size_t j = 0; j < s; ++j)
      if (!(f.b[i] * (f.bbar[j] - f.a[i][j]) == f.b[j] * (f.bbar[i] - f.a[j][i]))) return false;
  }
  return true;
}
}  // namespace detail

namespace detail {
/// The order from the local error coefficients `err` of trees sorted by order (a tree_set or a
/// nystrom_tree_set): one less than the order of the first tree with a nonzero one, else
/// r.tree_order as a lower bound.
template <class Trees, class K>
void order_of(const Trees& trees, const std::vector<K>& err, method_analysis& r) {
  r.order = r.tree_order;
  r.order_is_lower_bound = true;
  for (int t = 0; t < trees.size(); ++t) {
    if (err[static_cast<std::size_t>(t)] == K(0)) continue;
    r.order = trees[t].order - 1;
    r.order_is_lower_bound = false;
    return;
  }
}
}  // namespace detail

/// Order and symplecticity of a Nystrom form (an rkn or nystrom tableau, a composition:
/// methods/nystrom_form.hpp) on its N-trees (the special ones without velocity stages);
/// symplecticity by the RKN conditions (on q'' = f(q)).
template <class K>
method_analysis analyse_method(const methods::nystrom_form<K>& f, int order_two_colours = default_order_two_colours) {
  method_analysis r;
  r.colours = 2;  // N-trees have two kinds of vertices
  r.tree_order = order_two_colours;
  const nystrom_tree_set trees(r.tree_order, !f.has_velocity_stages);
  detail::order_of(trees, local_error_coefficients(trees, f), r);
  r.symplectic = detail::rkn_symplectic(f);
  r.symplecticity_basis = "RKN conditions (exact)";
  return r;
}

/// Order and symplecticity of a tableau of any kind (std::invalid_argument for inconsistent
/// sizes): rk on rooted trees, prk on bi-coloured trees, rkn and nystrom by their Nystrom form.
template <class K>
method_analysis analyse_method(const tableau_data<K>& t, int order_one_colour = default_order_one_colour,
                               int order_two_colours = default_order_two_colours) {
  if (t.kind == methods::method_kind::rkn || t.kind == methods::method_kind::nystrom)
    return analyse_method(methods::nystrom_form_of(t), order_two_colours);
  method_analysis r;
  r.colours = t.kind == methods::method_kind::rk ? 1 : 2;
  r.tree_order = r.colours == 1 ? order_one_colour : order_two_colours;
  const tree_set trees(r.tree_order, r.colours);
  const std::vector<K> a = elementary_weights(trees, t);
  detail::order_of(trees, local_error_coefficients(trees, a), r);
  r.symplectic = check_symplecticity_conditions(trees, modified_field(trees, a)).holds;
  r.symplecticity_basis = "tree conditions up to order " + std::to_string(r.tree_order);
  return r;
}

}  // namespace geomint::analysis::bseries
