#pragma once
/// Whether a modified vector field given by its B- or P-series is Hamiltonian: the
/// symplecticity conditions on trees.
///
/// One colour (Runge-Kutta methods), HLW (Hairer, Lubich, Wanner, Geometric Numerical
/// Integration, 2nd ed. 2006), section IX.9.3: the modified equation B(b) of a B-series method
/// is Hamiltonian for every Hamiltonian (the method is symplectic, up to the order checked) iff
///   b(u o v) + b(v o u) = 0   for all trees u, v,
/// u o v the Butcher product (v grafted onto the root of u).
///
/// Two colours (partitioned methods on p' = -H_q(p,q), colour 0, q' = H_p(p,q), colour 1, H
/// not necessarily separable): the same argument on P-trees. The elementary Hamiltonian of a
/// P-tree, H^(m)(F(t_1), ..., F(t_m)) with the derivative in p for a colour-0 subtree and in q
/// for a colour-1 subtree, does not depend on the root's colour, and its Hamiltonian vector
/// field has p-component F(t with root colour 0) and q-component F(t with root colour 1) with
/// the same coefficient; moving the root across an edge joining vertices of different colours
/// changes its sign (f = -H_q against g = +H_p). Hence the conditions
///   b(t) = b(t')               for t, t' differing only in the root's colour,
///   b(u o v) + b(v o u) = 0    for u, v with roots of different colours.
/// tests/analysis/test_bseries_symplectic_conditions.cpp checks that they hold for the
/// symplectic pairs of HLW section VI.4 (Lobatto IIIA-IIIB, symplectic Euler) and fail for
/// non-symplectic ones.

#include <stdexcept>
#include <vector>

#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// Which symplecticity condition failed first.
enum class symplecticity_condition {
  none,              ///< all hold
  butcher_products,  ///< b(u o v) + b(v o u) != 0
  root_colour,       ///< b(u) != b(v), u and v the same P-tree with roots of colours 0 and 1
};

/// Verdict of the symplecticity conditions up to an order.
struct symplecticity_verdict {
  bool holds = true;       ///< all conditions up to checked_order hold
  int checked_order = 0;   ///< the largest order (|u| + |v|, or |t|) checked
  int failing_order = 0;   ///< smallest order of a failing condition (0 if none)
  symplecticity_condition failed = symplecticity_condition::none;
  int u = -1, v = -1;      ///< the first failing pair (tree indices), -1 if none
};

/// Checks the conditions up to trees.max_order(), by increasing order; stops at the first
/// failure.
template <class T>
symplecticity_verdict check_symplecticity_conditions(const tree_set& trees, const std::vector<T>& b) {
  if (b.size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::check_symplecticity_conditions: one coefficient b(t) per tree is needed");
  symplecticity_verdict verdict;
  verdict.checked_order = trees.max_order();
  const auto fail = [&verdict](int n, symplecticity_condition which, int u, int v) {
    verdict.holds = false;
    verdict.failing_order = n;
    verdict.failed = which;
    verdict.u = u;
    verdict.v = v;
    return verdict;
  };
  for (int n = 1; n <= trees.max_order(); ++n) {
    if (trees.colours() == 2)
      for (int t = trees.first(n); t < trees.first(n + 1); ++t) {
        if (trees[t].colour != 0) continue;
        const int other = trees.find(1, trees[t].subtrees);
        if (b[static_cast<std::size_t>(t)] != b[static_cast<std::size_t>(other)])
          return fail(n, symplecticity_condition::root_colour, t, other);
      }
    for (int k = 1; 2 * k <= n; ++k)  // |u| = k <= |v| = n - k
      for (int u = trees.first(k); u < trees.first(k + 1); ++u)
        for (int v = (2 * k == n ? u : trees.first(n - k)); v < trees.first(n - k + 1); ++v) {
          if (trees.colours() == 2 && trees[u].colour == trees[v].colour) continue;
          const auto uv = static_cast<std::size_t>(trees.butcher_product(u, v));
          const auto vu = static_cast<std::size_t>(trees.butcher_product(v, u));
          if (b[uv] + b[vu] != T(0)) return fail(n, symplecticity_condition::butcher_products, u, v);
        }
  }
  return verdict;
}

}  // namespace geomint::analysis::bseries
