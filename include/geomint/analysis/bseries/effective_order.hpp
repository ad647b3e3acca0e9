#pragma once
/// The effective order of a B- or P-series method (Butcher, The effective order of Runge-Kutta
/// methods, in: Conference on the Numerical Solution of Differential Equations, Lecture Notes in
/// Math. 109, Springer 1969, 133-139; HLW: Hairer, Lubich & Wanner, Geometric Numerical
/// Integration, 2nd ed. 2006, section V.3.3 on processing): the largest q for which a
/// near-identity B-series map chi (the processor) makes chi^{-1} o Phi o chi of order q.
///
/// Computation on modified fields (modified_equation.hpp). Write Phi = exp(Y), Y = B(b) the
/// modified field times h, and chi = exp(Z), Z = B(z) any B-series field. Then chi^{-1} o Phi o
/// chi = exp(e^{ad Z} Y) (the pull-back of Y by chi, for one sign convention of the bracket;
/// z ranges over all fields, so the sign is immaterial), and the processed method has order q
/// iff (e^{ad Z} Y)(t) = 1 on the one-vertex trees and 0 on the trees of orders 2..q. The Lie
/// bracket of B-series fields in the 1/sigma normalisation is
///   [x, y](w) = sum over the edge cuts of w (root part u, cut part v, multiplicity m) of
///               m (x(u) y(v) - y(u) x(v))
/// (grafting, as in the Lie derivative of modified_equation.hpp).
///
/// Order by order: the part z_k of z on the trees of order k first enters at order k + 1,
/// linearly, through [z_k, b_1] (b_1 = the one-vertex part of b: the field f itself); every
/// other contribution at order n involves z below order n - 1 only. So, with z known below
/// order n - 1, the order-n condition is the linear system [z_{n-1}, b_1] = -(e^{ad Z'} Y)_n,
/// Z' = Z without z_{n-1}. The component of z along Y is immaterial (exp(lambda Y) commutes with
/// Phi, so chi o exp(lambda Y) processes Phi as chi does): z is set to zero on the one-vertex
/// tree (one colour) or on the one-vertex tree of colour 1 (two colours). Where the system has
/// a unique solution (z -> [z, b_1] injective on the order's unknowns, which is checked), the
/// verdict is exact; where it is not, the computation stops with a lower bound (the choice of
/// the free part of z_{n-1} would enter the later orders non-linearly).

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "geomint/analysis/bseries/conjugate_symplecticity.hpp"
#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// Verdict on the effective order.
template <class T>
struct effective_order_verdict {
  int order = 0;                      ///< the effective order (a lower bound if order_is_lower_bound)
  bool order_is_lower_bound = false;  ///< every condition up to `order` holds; beyond, undecided
  bool processor_not_unique = false;  ///< stopped because z at some order was not unique
  std::vector<T> processor;           ///< z (chi = exp(B(z))) on the trees below order + 1, else 0
};

/// The Lie bracket [x, y] of two B-/P-series fields (one coefficient per tree).
template <class T>
std::vector<T> lie_bracket(const tree_set& trees, const std::vector<T>& x, const std::vector<T>& y) {
  std::vector<T> out(static_cast<std::size_t>(trees.size()), T(0));
  for (int w = 0; w < trees.size(); ++w)
    for (const edge_cut& cut : trees.cuts(w)) {
      const auto u = static_cast<std::size_t>(cut.root_part), v = static_cast<std::size_t>(cut.cut_part);
      out[static_cast<std::size_t>(w)] += T(cut.multiplicity) * (x[u] * y[v] - y[u] * x[v]);
    }
  return out;
}

/// e^{ad z} b = b + [z, b] + [z, [z, b]]/2! + ..., exact on every tree of `trees` (each bracket
/// raises the lowest order by at least one).
template <class T>
std::vector<T> processed_field(const tree_set& trees, const std::vector<T>& z, const std::vector<T>& b) {
  std::vector<T> sum = b, term = b;
  for (int k = 1; k <= trees.max_order(); ++k) {
    term = lie_bracket(trees, z, term);
    for (auto& value : term) value = value / T(k);
    for (std::size_t t = 0; t < sum.size(); ++t) sum[t] += term[t];
  }
  return sum;
}

/// The effective order of the method with modified field b (modified_field of its series), up
/// to trees.max_order(). One colour needs b = 1 on the single vertex; two colours b = 1 on
/// both (a consistent method), else the effective order is 0.
template <class T>
effective_order_verdict<T> effective_order(const tree_set& trees, const std::vector<T>& b) {
  const auto n_trees = static_cast<std::size_t>(trees.size());
  if (b.size() != n_trees)
    throw std::invalid_argument("geomint::analysis::bseries::effective_order: one coefficient b(t) per tree is needed");
  effective_order_verdict<T> verdict;
  verdict.processor.assign(n_trees, T(0));
  for (int t = trees.first(1); t < trees.first(2); ++t)
    if (b[static_cast<std::size_t>(t)] != T(1)) return verdict;
  std::vector<T> f(n_trees, T(0));  // b_1
  for (int t = trees.first(1); t < trees.first(2); ++t) f[static_cast<std::size_t>(t)] = T(1);
  const int fixed = trees.leaf(trees.colours() - 1);  // z = 0 there
  std::vector<T>& z = verdict.processor;
  for (int n = 2; n <= trees.max_order(); ++n) {
    const std::vector<T> known = processed_field(trees, z, b);
    // [z_{n-1}, f](w) for |w| = n: cuts with the cut part a single vertex give z(root part),
    // cuts with the root part a single vertex give -z(cut part).
    detail::linear_system<T> system;
    bool consistent = true;
    for (int w = trees.first(n); w < trees.first(n + 1) && consistent; ++w) {
      detail::linear_form<T> equation;
      equation.constant = known[static_cast<std::size_t>(w)];
      for (const edge_cut& cut : trees.cuts(w)) {
        const T m(cut.multiplicity);
        if (trees[cut.cut_part].order == 1 && trees[cut.root_part].order == n - 1 && cut.root_part != fixed)
          equation.add(cut.root_part, m);
        if (trees[cut.root_part].order == 1 && trees[cut.cut_part].order == n - 1 && cut.cut_part != fixed)
          equation.add(cut.cut_part, T(0) - m);
      }
      consistent = system.add(std::move(equation));
    }
    if (!consistent) {
      verdict.order = n - 1;
      return verdict;
    }
    int unknowns = 0;
    for (int t = trees.first(n - 1); t < trees.first(n); ++t) unknowns += t != fixed;
    if (system.rank() < unknowns) {
      verdict.order = n;
      verdict.order_is_lower_bound = true;
      verdict.processor_not_unique = true;
      return verdict;
    }
    for (int t = trees.first(n - 1); t < trees.first(n); ++t)
      if (t != fixed) z[static_cast<std::size_t>(t)] = system.value_of(t);
  }
  verdict.order = trees.max_order();
  verdict.order_is_lower_bound = true;
  return verdict;
}

}  // namespace geomint::analysis::bseries
