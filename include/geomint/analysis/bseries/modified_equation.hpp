#pragma once
/// The modified equation of a method given by its B-series (or P-series), exactly.
///
/// HLW (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006), section IX.9.1:
/// if one step is y1 = B(a, y0) with a(empty) = 1, the modified differential equation is
///   y' = f~(y),   h f~(y) = B(b, y) = sum_t h^|t| / sigma(t) b(t) F(t)(y),   b(empty) = 0,
/// and b is found from a, tree by tree in increasing order, by the recursion of HLW section
/// IX.9.1 (the theorem giving the modified equation of a B-series method)
///   b(t) = a(t) - sum_{j=2}^{|t|} (1/j!) (d_b^{j-1} b)(t),
/// where d_b is the Lie derivative along B(b) acting on coefficients (the lemma on the Lie
/// derivative of B-series in the same section):
///   (d_b c)(t) = c(empty) b(t) + sum over edges of t of c(root part) b(cut-off part),
/// the sum over edges being the edge cuts of trees.hpp. It is the coefficient form of
/// y(h) = exp(h L_{f~}) y: a = delta_empty + b + d_b b / 2! + d_b^2 b / 3! + ..., and every term
/// with j >= 2 involves b only on trees smaller than t. The same law holds for P-series with
/// two colours (the Lie derivative grafts trees onto vertices of either colour alike).
///
/// Check: a = 1/gamma (exact flow) gives b(single vertex) = 1 and b(t) = 0 otherwise.
/// constexpr: with geomint::rational the field is exact at compile time (trees.hpp, series.hpp).

#include <stdexcept>
#include <vector>

#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// The coefficients b(t) of the modified vector field, one per tree of `trees`, from the
/// coefficients a(t) of one step (a(empty) = 1 implied). The h^(n-1) term of f~ is
/// sum_{|t| = n} b(t) / sigma(t) F(t).
template <class T>
constexpr std::vector<T> modified_field(const tree_set& trees, const std::vector<T>& a) {
  const auto n_trees = static_cast<std::size_t>(trees.size());
  if (a.size() != n_trees)
    throw std::invalid_argument("geomint::analysis::bseries::modified_field: one coefficient a(t) per tree is needed");
  // lie[t][k] = (d_b^k b)(t); it vanishes for k >= |t| (k + 1 factors b of order >= 1 each).
  std::vector<std::vector<T>> lie(n_trees);
  std::vector<T> b(n_trees);
  std::vector<const edge_cut*> live;       // the cuts of t whose cut-off part has b != 0
  std::vector<T> inverse_factorial{T(1)};  // 1/j!, j = 0, 1, ...
  for (std::size_t t = 0; t < n_trees; ++t) {
    const int order = trees[static_cast<int>(t)].order;
    lie[t].assign(static_cast<std::size_t>(order), T(0));
    live.clear();
    for (const edge_cut& cut : trees.cuts(static_cast<int>(t)))
      if (!detail::known_zero(b[static_cast<std::size_t>(cut.cut_part)])) live.push_back(&cut);
    T value = a[t];
    for (int k = 1; k < order; ++k) {
      T sum(0);
      for (const edge_cut* cut : live) {
        const auto& root_part = lie[static_cast<std::size_t>(cut->root_part)];
        if (static_cast<std::size_t>(k - 1) >= root_part.size() || detail::known_zero(root_part[static_cast<std::size_t>(k - 1)]))
          continue;
        T term = root_part[static_cast<std::size_t>(k - 1)] * b[static_cast<std::size_t>(cut->cut_part)];
        if (cut->multiplicity != 1) term *= T(cut->multiplicity);
        sum += term;
      }
      if (!detail::known_zero(sum)) {
        // 1/(k+1)!, formed once per order (a division of T can cost an inversion).
        while (inverse_factorial.size() <= static_cast<std::size_t>(k + 1))
          inverse_factorial.push_back(inverse_factorial.back() / T(static_cast<int>(inverse_factorial.size())));
        value -= sum * inverse_factorial[static_cast<std::size_t>(k + 1)];
      }
      lie[t][static_cast<std::size_t>(k)] = std::move(sum);
    }
    b[t] = value;
    lie[t][0] = std::move(value);
  }
  return b;
}

}  // namespace geomint::analysis::bseries
