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
/// - The order of each component: the largest p with those conditions for the trees of that
///   component up to p (the root's colour: prk colour 0 for (A, b), colour 1 for (Ahat, bhat);
///   N-trees: a meagre root for the position, a fat one for the velocity), the local order of
///   that component; the method's order is the smaller.
/// - Symplecticity of a tableau: the exact algebraic conditions on its irreducible method
///   (analysis/tableau_symplecticity.hpp: rk, prk, and rkn and nystrom on q'' = f(q)). Of a
///   Nystrom form (a composition) with d = 1: the RKN conditions of Suris 1989 (HLW Theorem
///   VI.4.10), bbar_i = b_i (1 - c_i), b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji), on its stages
///   as they stand. The tree conditions on the modified field (symplectic_conditions.hpp) are the
///   independent check of the tests; they do not apply to rkn and nystrom as they stand,
///   because the P-series of the partitioned form on the trees outside the Nystrom trees depends
///   on the conversion, not on the method.

#include <array>
#include <string>
#include <vector>

#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/nystrom_tree_set.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/tableau_symplecticity.hpp"

namespace geomint::analysis::bseries {

/// Tree orders analysed by default: one colour up to 10, two colours up to 8.
inline constexpr int default_order_one_colour = 10;
inline constexpr int default_order_two_colours = 8;

struct method_analysis {
  int order = 0;
  bool order_is_lower_bound = false;  ///< every condition up to tree_order holds
  int tree_order = 0;                 ///< largest tree order analysed
  int colours = 1;                    ///< 1: B-series, 2: P-series
  /// The local order of each component: prk (A, b) and (Ahat, bhat); rkn, nystrom and Nystrom
  /// forms position and velocity; rk the one component (both entries equal).
  std::array<int, 2> component_order{};
  std::array<bool, 2> component_order_is_lower_bound{};
  bool symplectic = false;
  /// The conditions the verdict is from, e.g. "b_i a_ij + b_j a_ji = b_i b_j, exact, on the
  /// irreducible method of 1 stage" or "RKN conditions (exact)".
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
/// The component of a tree's series: the root's colour (tree_set) or kind (N-trees: meagre,
/// the position, 0; fat, the velocity, 1).
inline int component_of(const tree_set& trees, int t) { return trees.colours() == 1 ? 0 : trees[t].colour; }
inline int component_of(const nystrom_tree_set& trees, int t) { return trees[t].fat ? 1 : 0; }

/// The orders from the local error coefficients `err` of trees sorted by order (a tree_set or
/// a nystrom_tree_set): per component one less than the order of its first tree with a nonzero
/// one, else r.tree_order as a lower bound; the method's order the smaller.
template <class Trees, class K>
void order_of(const Trees& trees, const std::vector<K>& err, method_analysis& r) {
  r.component_order = {r.tree_order, r.tree_order};
  r.component_order_is_lower_bound = {true, true};
  for (int t = 0; t < trees.size(); ++t) {
    const auto k = static_cast<std::size_t>(component_of(trees, t));
    if (err[static_cast<std::size_t>(t)] == K(0) || !r.component_order_is_lower_bound[k]) continue;
    r.component_order[k] = trees[t].order - 1;
    r.component_order_is_lower_bound[k] = false;
  }
  if (r.colours == 1 || trees.size() == 0) {  // one component
    r.component_order[1] = r.component_order[0];
    r.component_order_is_lower_bound[1] = r.component_order_is_lower_bound[0];
  }
  const std::size_t low = r.component_order[1] < r.component_order[0] ? 1 : 0;
  r.order = r.component_order[low];
  r.order_is_lower_bound = r.component_order_is_lower_bound[0] && r.component_order_is_lower_bound[1];
}

/// The basis text of a symplecticity verdict from the exact conditions.
template <class K>
std::string conditions_text(const tableau_symplecticity<K>& v) {
  return v.matrix_condition + (v.weight_condition.empty() ? std::string() : " and " + v.weight_condition) +
         ", exact, on the irreducible method of " + std::to_string(v.irreducible_stages) +
         (v.irreducible_stages == 1 ? " stage" : " stages");
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
  method_analysis r;
  if (t.kind == methods::method_kind::rkn || t.kind == methods::method_kind::nystrom) {
    r = analyse_method(methods::nystrom_form_of(t), order_two_colours);
  } else {
    r.colours = t.kind == methods::method_kind::rk ? 1 : 2;
    r.tree_order = r.colours == 1 ? order_one_colour : order_two_colours;
    const tree_set trees(r.tree_order, r.colours);
    detail::order_of(trees, local_error_coefficients(trees, elementary_weights(trees, t)), r);
  }
  const tableau_symplecticity<K> v = symplecticity_conditions(t);
  r.symplectic = v.symplectic;
  r.symplecticity_basis = detail::conditions_text(v);
  return r;
}

}  // namespace geomint::analysis::bseries
