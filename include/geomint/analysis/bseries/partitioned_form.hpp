#pragma once
/// Every tableau kind as data for the B-/P-series of series.hpp: rk and prk as they are; an rkn
/// or nystrom tableau, and a Nystrom form (methods/nystrom_form.hpp: every composition), as a
/// partitioned Runge-Kutta pair on the first-order form
///   q' = v (colour 0),   v' = F(q, v) (colour 1; F(q) for rkn).
///
/// The conversion. A partitioned pair (A, b) on q and (Ahat, bhat) on v gives on this system
/// Q_i = q + h sum_j a_ij V_j, V_i = v + h sum_j ahat_ij F_j: the Nystrom method with
/// abar = A Ahat, bbar = b^T Ahat (HNW: Hairer, Norsett & Wanner, Solving ODEs I, section II.14;
/// the relation methods/nystrom_form.hpp uses for prk tableaux). A Nystrom method
///   Q_i = q + c_i h v + h^2 sum_j abar_ij F_j,  V_i = v + h sum_j ap_ij F_j,
///   q1  = q + d h v + h^2 sum_j bbar_j F_j,    v1  = v + h sum_j b_j F_j
/// has no canonical factor abar = A Ahat with A 1 = c (an rkn gives no Ahat; a factor, when
/// one exists, is not unique: Stormer-Verlet is Lobatto IIIA x IIIB, HLW: Hairer, Lubich &
/// Wanner, Geometric Numerical Integration, 2006, section II.2.2), so the pair used here has
/// 2s + 2 stages, each a (Q, V) pair:
///   stage 0:       V = v               (ahat row 0; A row 0),
///   stage i:       the Nystrom stage: V_i = v + h sum_j ap_ij F_j and
///                  Q_i = q + h ((c_i - 1) V_0 + X_i), since h X_i = h v + h^2 sum_j abar_ij F_j,
///   stage s + i:   X_i = v + h sum_j abar_ij F_j (ahat row abar_i; A row 0),
///   stage 2s + 1:  B   = v + h sum_j bbar_j F_j  (ahat row bbar; A row 0),
///   weights:       q1 = q + h ((d - 1) V_0 + B),  v1 = v + h sum_j b_j F_j,
/// F evaluated at every stage but weighted only at the Nystrom stages (rkn: ap = 0). This is
/// exact: the pair computes the same q1, v1 as the Nystrom method, so its P-series agrees with
/// the method on every tree whose elementary differential is not identically zero on the
/// first-order form (is_nystrom_tree below). On the other trees (a colour-0 vertex with two
/// children or a colour-0 child: derivatives of f(q, v) = v that vanish) the method defines no
/// P-series coefficient;
/// analyses of rkn and nystrom tableaux use the Nystrom trees only. Not constexpr (tableau_data
/// and nystrom_form carry a std::string name); for fixed-size tableaux nystrom_weights.hpp gives
/// the same coefficients from the Nystrom coefficients directly, at compile time.

#include <vector>

#include "geomint/analysis/bseries/series.hpp"
#include "geomint/methods/nystrom_form.hpp"

namespace geomint::analysis::bseries {

/// The (2s + 2)-stage pair of a Nystrom form (see the top of the file); c of the pair is the
/// stage time of each (Q, V): 0, c_i, 0, 0.
template <class K>
tableau_data<K> partitioned_form_of(const methods::nystrom_form<K>& f) {
  const auto s = static_cast<std::size_t>(f.stages);
  const std::size_t n = 2 * s + 2;
  tableau_data<K> p;
  p.kind = methods::method_kind::prk;
  p.stages = static_cast<int>(n);
  p.name = f.name;
  p.c.assign(n, K(0));
  p.a.assign(n, std::vector<K>(n, K(0)));
  p.ahat.assign(n, std::vector<K>(n, K(0)));
  p.b.assign(n, K(0));
  p.bhat.assign(n, K(0));
  for (std::size_t i = 0; i < s; ++i) {
    p.c[1 + i] = f.c[i];
    p.a[1 + i][0] = f.c[i] - K(1);
    p.a[1 + i][1 + s + i] = K(1);
    for (std::size_t j = 0; j < s; ++j) {
      if (f.has_velocity_stages) p.ahat[1 + i][1 + j] = f.ap[i][j];
      p.ahat[1 + s + i][1 + j] = f.a[i][j];
    }
    p.ahat[n - 1][1 + i] = f.bbar[i];
    p.bhat[1 + i] = f.b[i];
  }
  p.b[0] = f.d - K(1);
  p.b[n - 1] = K(1);
  return p;
}

/// The pair of any tableau kind: rk and prk as they are, rkn and nystrom through their Nystrom form.
template <class K>
tableau_data<K> partitioned_form_of(const tableau_data<K>& t) {
  if (t.kind == methods::method_kind::rk || t.kind == methods::method_kind::prk) return t;
  return partitioned_form_of(methods::nystrom_form_of(t));
}

/// Whether the elementary differential of two-colour tree t is not identically zero on
/// q' = v (colour 0), v' = F (colour 1): every colour-0 vertex has no child or one child of
/// colour 1 (f = v is linear in v, constant in q); for F = F(q) (velocity_free) every colour-1
/// vertex has colour-0 children only. These are the trees of the Nystrom series (HNW section
/// II.14, Nystrom trees).
constexpr bool is_nystrom_tree(const tree_set& trees, int t, bool velocity_free) {
  const rooted_tree& tree = trees[t];
  if (tree.colour == 0) {
    if (tree.subtrees.empty()) return true;
    return tree.subtrees.size() == 1 && trees[tree.subtrees[0]].colour == 1 && is_nystrom_tree(trees, tree.subtrees[0], velocity_free);
  }
  for (int u : tree.subtrees) {
    if (velocity_free && trees[u].colour == 1) return false;
    if (!is_nystrom_tree(trees, u, velocity_free)) return false;
  }
  return true;
}

}  // namespace geomint::analysis::bseries
