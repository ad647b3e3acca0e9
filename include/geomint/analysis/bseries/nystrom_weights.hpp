#pragma once
/// Exact P-series coefficients of one step of a fixed-size Runge-Kutta-Nystrom tableau
/// (methods::rkn, for q'' = f(q)), Nystrom tableau (methods::nystrom, for q'' = F(q, q')) or
/// composition of either, computed from the Nystrom coefficients directly: constexpr, so over
/// geomint::rational the series of such a tableau is exact inside a static_assert (as series.hpp
/// gives it for rk and prk tableaux). The run-time route, partitioned_form_of
/// (partitioned_form.hpp), goes through tableau_data and nystrom_form, whose std::string name
/// Clang 14 cannot build in a constant expression with libstdc++ 12.
///
/// On q' = v (colour 0), v' = F (colour 1), with Psi(u) the stage vector of a colour-1 tree u
/// (HNW: Hairer, Norsett & Wanner, Solving ODEs I, 2nd ed., section II.14, the order conditions
/// of Nystrom methods; the same weights as nystrom_tree_set.hpp and rkn_series.hpp):
///   Psi_i(u) = prod over the children w of u of Y_i(w),
///   Y(colour-0 leaf) = c,  Y(colour-0 tree [v]) = A Psi(v),  Y(colour-1 tree w) = Ap Psi(w),
///   a(u) = sum_i b_i Psi_i(u),  a(colour-0 leaf) = d,  a([v]) = sum_i bbar_i Psi_i(v),
/// with A the h^2 position coefficients abar and d = 1 (a tableau; a composition of k steps
/// gamma_l h has d = gamma_1 + ... + gamma_k). These are the coefficients of the Nystrom trees
/// (is_nystrom_tree of partitioned_form.hpp): a colour-0 vertex has no child or one colour-1
/// child, and for F = F(q) a colour-1 vertex has colour-0 children only. Every other tree gets 0.
///
/// Tree sets (two colours; a one-colour set is a std::invalid_argument):
/// - tree_class::rkn: every tree is a Nystrom tree of q'' = f(q). An rkn tableau's series; also
///   a nystrom tableau's, as the method on q'' = f(q) (Ap does not enter these weights).
/// - tree_class::nystrom: the Nystrom trees of q'' = F(q, q'), for a nystrom tableau. An rkn
///   tableau is refused (std::invalid_argument): it has no velocity stages, so it defines no
///   method on F(q, q'), and zeros on the velocity-dependent trees would make series_order and
///   modified_field on this class silently wrong.
/// - tree_class::all: the Nystrom trees of the tableau's class get their weights, the others 0
///   (as rkn_series.hpp does); compare on the Nystrom trees only (nystrom_trees of
///   rkn_series.hpp), since 0 is not the exact flow's 1/gamma there.
/// The classes are closed under subtrees and edge cuts, so series_order and modified_field of
/// series.hpp and modified_equation.hpp work on the class sets directly.

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/bseries/trees.hpp"
#include "geomint/methods/composition.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::analysis::bseries {

namespace detail {
/// The stage vectors of one tree: Psi (colour 1) and Y, the factor it gives its parent.
template <class K, int S>
struct nystrom_stage_values {
  bool nystrom = false;  ///< a Nystrom tree of the tableau's class: weighted, the others 0
  methods::stage_vector<K, S> psi{};
  methods::stage_vector<K, S> fed{};
};

/// sum_i w_i x_i, skipping zero terms (explicit tableaux are mostly zeros, and in a constant
/// expression every exact product counts against the compiler's evaluation limit).
template <class K, int S>
constexpr K sparse_dot(const methods::stage_vector<K, S>& w, const methods::stage_vector<K, S>& x) {
  const K zero(0);
  K sum = zero;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i)
    if (!(w[i] == zero) && !(x[i] == zero)) sum += w[i] * x[i];
  return sum;
}
template <class K, int S>
constexpr methods::stage_vector<K, S> sparse_product(const methods::stage_matrix<K, S>& m, const methods::stage_vector<K, S>& x) {
  methods::stage_vector<K, S> out{};
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) out[i] = sparse_dot<K, S>(m[i], x);
  return out;
}

/// a(t) of an rkn or nystrom tableau (see the top of the file), d the coefficient of h v in q1.
template <class K, int S, class Tableau>
constexpr std::vector<K> nystrom_tableau_weights(const tree_set& trees, const Tableau& method, const K& d) {
  constexpr bool velocity_stages = requires(const Tableau& t) { t.ap; };
  if (trees.colours() != 2)
    throw std::invalid_argument(
        "geomint::analysis::bseries::elementary_weights: an rkn or nystrom tableau needs two-colour trees (q' = v colour 0, v' = F colour 1)");
  if (!velocity_stages && trees.kind() == tree_class::nystrom)
    throw std::invalid_argument(
        "geomint::analysis::bseries::elementary_weights: an rkn tableau (q'' = f(q)) has no weights on the trees of q'' = F(q, q'); use tree_class::rkn");
  // Ap enters only through a colour-1 child of a colour-1 vertex, which the rkn class lacks.
  const bool feed_velocity = velocity_stages && trees.kind() != tree_class::rkn;
  const auto n = static_cast<std::size_t>(trees.size());
  std::vector<nystrom_stage_values<K, S>> v(n);
  std::vector<K> a(n, K(0));
  for (std::size_t t = 0; t < n; ++t) {
    const rooted_tree& tree = trees[static_cast<int>(t)];
    nystrom_stage_values<K, S>& x = v[t];
    if (tree.colour == 0) {
      // q' = v: the leaf, or one colour-1 child.
      if (tree.subtrees.empty()) {
        x.nystrom = true;
        x.fed = method.c;
        a[t] = d;
      } else if (tree.subtrees.size() == 1 && trees[tree.subtrees[0]].colour == 1 &&
                 v[static_cast<std::size_t>(tree.subtrees[0])].nystrom) {
        const auto& psi = v[static_cast<std::size_t>(tree.subtrees[0])].psi;
        x.nystrom = true;
        x.fed = sparse_product<K, S>(method.a, psi);
        a[t] = sparse_dot<K, S>(method.bbar, psi);
      }
      continue;
    }
    // v' = F: colour-0 children, and colour-1 children only through velocity stages.
    bool nystrom = true;
    for (int w : tree.subtrees)
      nystrom = nystrom && v[static_cast<std::size_t>(w)].nystrom && (feed_velocity || trees[w].colour == 0);
    if (!nystrom) continue;
    x.nystrom = true;
    for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) x.psi[i] = K(1);
    for (int w : tree.subtrees)
      for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) x.psi[i] *= v[static_cast<std::size_t>(w)].fed[i];
    a[t] = sparse_dot<K, S>(method.b, x.psi);
    if constexpr (velocity_stages)
      if (feed_velocity) x.fed = sparse_product<K, S>(method.ap, x.psi);
  }
  return a;
}
}  // namespace detail

/// a(t) of one step of an rkn tableau on every Nystrom tree of q'' = f(q) in `trees` (class rkn,
/// or all with 0 on the other trees); a(empty) = 1.
template <class K, int S>
constexpr std::vector<K> elementary_weights(const tree_set& trees, const methods::rkn<K, S>& method) {
  return detail::nystrom_tableau_weights<K, S>(trees, method, K(1));
}

/// a(t) of one step of a nystrom tableau on every Nystrom tree of q'' = F(q, q') in `trees`
/// (class nystrom; class rkn: the method on q'' = f(q); all: 0 on the other trees).
template <class K, int S>
constexpr std::vector<K> elementary_weights(const tree_set& trees, const methods::nystrom<K, S>& method) {
  return detail::nystrom_tableau_weights<K, S>(trees, method, K(1));
}

/// a(t) of one step of a composition of an rkn or nystrom tableau (its tableau_of,
/// methods/composition.hpp, with d = the sum of the steps), on the trees of its base's class.
template <class Base, int M>
  requires(Base::kind == methods::method_kind::rkn || Base::kind == methods::method_kind::nystrom)
constexpr std::vector<typename Base::coefficient> elementary_weights(const tree_set& trees,
                                                                     const methods::composition<Base, M>& method) {
  const auto composed = methods::tableau_of(method);
  return detail::nystrom_tableau_weights<typename Base::coefficient, Base::stages * M>(trees, composed.tableau, composed.d);
}

}  // namespace geomint::analysis::bseries
