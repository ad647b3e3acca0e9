#pragma once
/// Whether a modified vector field given by its B-series is Hamiltonian: the symplecticity
/// conditions on trees.
///
/// HLW (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006), section IX.9.3:
/// the modified equation B(b) of a B-series method is Hamiltonian for every Hamiltonian f (the
/// method is symplectic, up to the order checked) iff
///   b(u o v) + b(v o u) = 0   for all trees u, v,
/// u o v the Butcher product (v grafted onto the root of u). Checked here for |u| + |v| up to
/// the order of the tree set, one-colour trees (Runge-Kutta methods).

#include <stdexcept>
#include <vector>

#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// Verdict of the symplecticity conditions up to an order.
struct symplecticity_verdict {
  bool holds = true;       ///< all conditions with |u| + |v| <= checked_order hold
  int checked_order = 0;   ///< the largest |u| + |v| checked
  int failing_order = 0;   ///< smallest |u| + |v| of a failing condition (0 if none)
  int u = -1, v = -1;      ///< the first failing pair (tree indices), -1 if none
};

/// Checks b(u o v) + b(v o u) = 0 for all u, v with |u| + |v| <= trees.max_order(), by
/// increasing |u| + |v|; stops at the first failure.
template <class T>
symplecticity_verdict check_symplecticity_conditions(const tree_set& trees, const std::vector<T>& b) {
  if (trees.colours() != 1)
    throw std::invalid_argument("geomint::analysis::bseries::check_symplecticity_conditions: only one-colour trees (Runge-Kutta) are supported");
  if (b.size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::check_symplecticity_conditions: one coefficient b(t) per tree is needed");
  symplecticity_verdict verdict;
  verdict.checked_order = trees.max_order();
  for (int n = 2; n <= trees.max_order(); ++n)
    for (int k = 1; 2 * k <= n; ++k)  // |u| = k <= |v| = n - k
      for (int u = trees.first(k); u < trees.first(k + 1); ++u)
        for (int v = (2 * k == n ? u : trees.first(n - k)); v < trees.first(n - k + 1); ++v) {
          const auto uv = static_cast<std::size_t>(trees.butcher_product(u, v));
          const auto vu = static_cast<std::size_t>(trees.butcher_product(v, u));
          if (b[uv] + b[vu] != T(0)) {
            verdict.holds = false;
            verdict.failing_order = n;
            verdict.u = u;
            verdict.v = v;
            return verdict;
          }
        }
  return verdict;
}

}  // namespace geomint::analysis::bseries
