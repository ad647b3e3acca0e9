#pragma once
/// The trees of the order conditions of Nystrom methods for q'' = F(q, q') (the general case)
/// and, as a subset, for q'' = f(q) (the special case), with exact elementary weights taken
/// directly from the Nystrom coefficients (c, A, Ap, bbar, b, d of methods/nystrom_form.hpp).
///
/// Hairer, Norsett & Wanner, Solving ODEs I, 2nd ed. (HNW), section II.14: write q'' = F(q, q')
/// as q' = v, v' = F(q, v). A Nystrom tree (N-tree) has vertices of two kinds: fat (a derivative
/// of F; its sons are arguments, a meagre son for a q-argument, a fat son for a v-argument) and
/// meagre (the function v, linear: no son, or one fat son, through v' = F). The trees with a fat
/// root index the v-component of the series, those with a meagre root the q-component. For
/// q'' = f(q) the fat vertices have meagre sons only (the special Nystrom trees; their counts
/// 1, 1, 2, 3, 6, 10, 20, 36, ... of fat-rooted trees are those of analysis/nystrom_trees.hpp).
/// Non-autonomous F(t, q, q') is the autonomous case with t as one more position (t'' = 0).
///
/// Order |t| = number of vertices; density gamma(t) = |t| prod gamma(sons); symmetry sigma(t) =
/// prod over distinct sons u of (multiplicity)! sigma(u)^(multiplicity) (as for rooted trees,
/// bseries/trees.hpp). Stage weights g(t) (vectors over the stages), for a fat tree the product
/// over its sons of
///   c                 (a meagre leaf: sum_j a_ij of the q-stage = c_i),
///   A g(w)            (a meagre son over the fat tree w),
///   Ap g(u)           (a fat son u),
/// with the elementary weights Phi(t) = b^T g(t) (fat root), bbar^T g(w) (meagre root over w),
/// d (the meagre root alone); the method has order p iff Phi(t) = 1/gamma(t) for every N-tree
/// with |t| <= p (HNW section II.14, the order conditions of Nystrom methods).
///
/// These are the weights of the partitioned form of partitioned_form.hpp restricted to its
/// Nystrom trees: there a meagre vertex over w contributes sum_j a_ij sum_k ahat_jk g_k(w) with
/// A Ahat = A of the Nystrom method, a meagre leaf sum_j a_ij = c_i, a fat son sum_j ahat_ij
/// g_j(u) = (Ap g(u))_i, and the roots weigh with b, b^T Ahat = bbar and sum b = d; the two
/// routes give the same order (tests/methods/test_catalogue.cpp checks it on every catalogue
/// method), this one without the 2s + 2 stages of the conversion.
///
/// Counts of N-trees by order n = 1, 2, ...: fat root 1, 2, 6, 18, 60, 204, 730, 2664, meagre
/// root 1, 1, 2, 6, 18, 60, 204, 730 (a meagre root is alone or over a fat tree of order n - 1):
/// the coefficients of F(x) = x prod_k (1 - x^k)^(-(F_k + M_k)), M(x) = x (1 + F(x)). Checked in
/// tests/analysis/test_bseries_nystrom_tree_set.cpp against that generating function and against
/// the bi-coloured trees of trees.hpp that is_nystrom_tree selects.

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/bseries/trees.hpp"
#include "geomint/methods/nystrom_form.hpp"

namespace geomint::analysis::bseries {

/// Largest order the generator accepts (general case: 9 975 fat-rooted trees of order 9).
inline constexpr int max_nystrom_tree_order = 9;

/// One N-tree.
struct n_tree {
  int order = 1;          ///< |t|, vertices of both kinds
  bool fat = true;        ///< kind of the root: fat (F, v-component) or meagre (v, q-component)
  std::vector<int> sons;  ///< indices of the root's sons, ascending (with repetition)
  std::int64_t sigma = 1;
  std::int64_t gamma = 1;
};

/// Every N-tree up to an order, by order; within an order the meagre-rooted trees first, then
/// the fat-rooted ones, by their sons.
class nystrom_tree_set {
 public:
  /// velocity_free: the special trees of q'' = f(q) (fat vertices have meagre sons only).
  nystrom_tree_set(int max_order, bool velocity_free) : max_order_(max_order), velocity_free_(velocity_free) {
    if (max_order < 1 || max_order > max_nystrom_tree_order)
      throw std::invalid_argument("geomint::analysis::bseries::nystrom_tree_set: max_order must be in 1.." +
                                  std::to_string(max_nystrom_tree_order));
    first_.assign(static_cast<std::size_t>(max_order) + 2, 0);
    for (int n = 1; n <= max_order; ++n) {
      first_[static_cast<std::size_t>(n)] = size();
      // Meagre root: alone (n = 1) or over one fat tree of order n - 1.
      if (n == 1) append(1, false, {});
      else
        for (int w = first(n - 1); w < first_[static_cast<std::size_t>(n)]; ++w)
          if (trees_[static_cast<std::size_t>(w)].fat && trees_[static_cast<std::size_t>(w)].order == n - 1) append(n, false, {w});
      // Fat root: sons of orders summing to n - 1 (meagre sons only for q'' = f(q)).
      std::vector<int> sons;
      detail::for_each_sons(
          trees_, first_[static_cast<std::size_t>(n)], n - 1, 0, sons,
          [&](const n_tree& son) { return !(velocity_free_ && son.fat); },
          [&](const std::vector<int>& s) { append(n, true, s); });
    }
    first_[static_cast<std::size_t>(max_order) + 1] = size();
  }

  int max_order() const { return max_order_; }
  bool velocity_free() const { return velocity_free_; }
  int size() const { return static_cast<int>(trees_.size()); }
  const n_tree& operator[](int t) const { return trees_.at(static_cast<std::size_t>(t)); }
  /// Index of the first tree of order n (n = max_order + 1 gives size()).
  int first(int n) const { return first_.at(static_cast<std::size_t>(n)); }
  /// Number of trees of order n, and of those with a fat (v-component) or meagre root.
  int count(int n) const { return first(n + 1) - first(n); }
  int count(int n, bool fat) const {
    int k = 0;
    for (int t = first(n); t < first(n + 1); ++t) k += trees_[static_cast<std::size_t>(t)].fat == fat;
    return k;
  }
  /// Index of the tree with this root kind and these sons (any order), -1 if there is none.
  int find(bool fat, std::vector<int> sons) const {
    std::sort(sons.begin(), sons.end());
    const auto it = index_.find({fat, sons});
    return it == index_.end() ? -1 : it->second;
  }

 private:
  void append(int n, bool fat, const std::vector<int>& sons) {
    n_tree t;
    t.order = n;
    t.fat = fat;
    t.sons = sons;
    detail::set_symmetry_and_density(t, n, sons, trees_);
    index_.emplace(std::make_pair(fat, sons), size());
    trees_.push_back(std::move(t));
  }

  int max_order_;
  bool velocity_free_;
  std::vector<n_tree> trees_;
  std::vector<int> first_;
  std::map<std::pair<bool, std::vector<int>>, int> index_;
};

/// Phi(t) for every N-tree of `trees` (see the top of the file); std::invalid_argument for the
/// general trees and a form without velocity stages (an rkn method defines no weight for them).
template <class K>
std::vector<K> elementary_weights(const nystrom_tree_set& trees, const methods::nystrom_form<K>& f) {
  if (!trees.velocity_free() && !f.has_velocity_stages)
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: an rkn method (q'' = f(q)) has no weights on the "
                                "trees of q'' = F(q, q'); use nystrom_tree_set(order, true)");
  const auto s = static_cast<std::size_t>(f.stages);
  auto apply = [&](const std::vector<std::vector<K>>& m, const std::vector<K>& v) {
    std::vector<K> out(s, K(0));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) out[i] += m[i][j] * v[j];
    return out;
  };
  auto dot = [&](const std::vector<K>& w, const std::vector<K>& v) {
    K sum(0);
    for (std::size_t i = 0; i < s; ++i) sum += w[i] * v[i];
    return sum;
  };
  const auto n = static_cast<std::size_t>(trees.size());
  // g[t]: the stage weights of a fat tree; fed[t]: the factor tree t gives a fat father.
  std::vector<std::vector<K>> g(n), fed(n);
  std::vector<K> phi(n, K(0));
  for (std::size_t t = 0; t < n; ++t) {
    const n_tree& tree = trees[static_cast<int>(t)];
    if (!tree.fat) {
      if (tree.sons.empty()) {
        phi[t] = f.d;
        fed[t] = f.c;
      } else {
        const auto& w = g[static_cast<std::size_t>(tree.sons[0])];
        phi[t] = dot(f.bbar, w);
        fed[t] = apply(f.a, w);
      }
      continue;
    }
    g[t].assign(s, K(1));
    for (int u : tree.sons)
      for (std::size_t i = 0; i < s; ++i) g[t][i] *= fed[static_cast<std::size_t>(u)][i];
    phi[t] = dot(f.b, g[t]);
    if (f.has_velocity_stages) fed[t] = apply(f.ap, g[t]);
  }
  return phi;
}

/// Phi(t) - 1/gamma(t) for every N-tree: the local error coefficients (h^|t| / sigma(t) times
/// the elementary differential in the q-component for a meagre root, the v-component for a fat
/// one).
template <class K>
std::vector<K> local_error_coefficients(const nystrom_tree_set& trees, const methods::nystrom_form<K>& f) {
  std::vector<K> err = elementary_weights(trees, f);
  for (std::size_t t = 0; t < err.size(); ++t) err[t] = err[t] - K(1) / K(trees[static_cast<int>(t)].gamma);
  return err;
}

}  // namespace geomint::analysis::bseries
