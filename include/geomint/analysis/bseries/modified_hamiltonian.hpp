#pragma once
/// The modified Hamiltonian of a symplectic B-series method, per free tree, exactly.
///
/// HLW (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006), section IX.9.3:
/// for y' = f(y) = J^{-1} grad H(y), the elementary Hamiltonian of a rooted tree
/// t = [t_1, ..., t_m] is H(t)(y) = H^(m+1)(y)(F(t_1)(y), ..., F(t_m)(y)) (H(tau) = H). Moving
/// the root along an edge (u o v -> v o u) changes the sign of H(t), and, when the symplecticity
/// conditions b(u o v) + b(v o u) = 0 hold, of b(t): the product b(t) H(t) depends only on the
/// free tree theta (the rooted tree with its root forgotten). The modified equation is then
/// Hamiltonian with
///   H~ = sum over free trees theta, not superfluous, of h^(|theta| - 1) b(t)/sigma(theta) H(t),
/// t any rooted tree of theta, sigma(theta) the number of automorphisms of theta. Superfluous
/// free trees are those of the form u o u (an edge whose halves are equal): their H(t) vanishes.
///
/// Free trees are the classes of rooted trees under moving the root along an edge. By
/// orbit-stabiliser, theta with n vertices has sigma(t) automorphisms fixing the root of t and
/// n = sum over its rooted trees t of sigma(theta)/sigma(t), so
///   sigma(theta) = n / sum over t of 1/sigma(t).
/// Example (the midpoint rule, b([tau,tau]) = -1/12): the path of 3 vertices, rooted trees
/// [tau,tau] (sigma 2) and [[tau]] (sigma 1), sigma(theta) = 3/(1/2 + 1) = 2, term
/// -h^2/24 H''(f,f).

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/analysis/bseries/symplectic_conditions.hpp"
#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// One free tree: its rooted trees and automorphism count.
struct free_tree {
  int order = 1;
  int representative = -1;        ///< the rooted tree of smallest index in the class
  std::vector<int> rooted;        ///< all rooted trees of the class (tree indices, ascending)
  std::int64_t sigma = 1;         ///< automorphisms of the free tree
  bool superfluous = false;       ///< of the form u o u: its elementary Hamiltonian vanishes
};

/// The free trees of a one-colour tree_set, by order.
inline std::vector<free_tree> free_trees(const tree_set& trees) {
  if (trees.colours() != 1)
    throw std::invalid_argument("geomint::analysis::bseries::free_trees: only one-colour trees are supported");
  std::vector<int> class_of(static_cast<std::size_t>(trees.size()), -1);
  std::vector<free_tree> out;
  for (int start = 0; start < trees.size(); ++start) {
    if (class_of[static_cast<std::size_t>(start)] >= 0) continue;
    free_tree theta;
    theta.order = trees[start].order;
    theta.representative = start;
    const int id = static_cast<int>(out.size());
    std::vector<int> pending = {start};
    class_of[static_cast<std::size_t>(start)] = id;
    while (!pending.empty()) {
      const int t = pending.back();
      pending.pop_back();
      theta.rooted.push_back(t);
      const std::vector<int>& subtrees = trees[t].subtrees;
      for (std::size_t i = 0; i < subtrees.size(); ++i) {
        std::vector<int> rest = subtrees;
        rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
        const int rest_tree = trees.find(trees[t].colour, rest);  // t = rest_tree o subtrees[i]
        if (rest_tree == subtrees[i]) theta.superfluous = true;
        const int moved = trees.butcher_product(subtrees[i], rest_tree);  // root moved to subtrees[i]
        if (class_of[static_cast<std::size_t>(moved)] < 0) {
          class_of[static_cast<std::size_t>(moved)] = id;
          pending.push_back(moved);
        }
      }
    }
    std::sort(theta.rooted.begin(), theta.rooted.end());
    // sigma(theta) = n / sum 1/sigma(t) = n L / sum (L / sigma(t)), L a common multiple.
    std::int64_t common = 1;
    for (int t : theta.rooted) common = std::lcm(common, trees[t].sigma);
    std::int64_t sum = 0;
    for (int t : theta.rooted) sum += common / trees[t].sigma;
    theta.sigma = theta.order * common / sum;
    out.push_back(std::move(theta));
  }
  return out;
}

/// One term h^(order - 1) coefficient H(tree) of the modified Hamiltonian.
template <class T>
struct hamiltonian_term {
  int order = 1;
  int tree = -1;       ///< the rooted tree t whose elementary Hamiltonian H(t) the term uses
  T coefficient{};     ///< b(t)/sigma(theta)
};

/// The modified Hamiltonian's terms with non-zero coefficients, by order, from the modified
/// field b of a one-colour tree_set. Throws std::domain_error naming the failing pair of trees
/// if the symplecticity conditions fail (the modified field is not Hamiltonian).
template <class T>
std::vector<hamiltonian_term<T>> modified_hamiltonian(const tree_set& trees, const std::vector<T>& b) {
  if (trees.colours() != 1)
    throw std::invalid_argument("geomint::analysis::bseries::modified_hamiltonian: only one-colour trees are supported");
  if (b.size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::modified_hamiltonian: one coefficient b(t) per tree is needed");
  const symplecticity_verdict verdict = check_symplecticity_conditions(trees, b);
  if (!verdict.holds)
    throw std::domain_error("geomint::analysis::bseries::modified_hamiltonian: b(u o v) + b(v o u) != 0 for the trees " +
                            std::to_string(verdict.u) + " and " + std::to_string(verdict.v) + " (order " +
                            std::to_string(verdict.failing_order) + "): the modified field is not Hamiltonian");
  std::vector<hamiltonian_term<T>> out;
  for (const free_tree& theta : free_trees(trees)) {
    if (theta.superfluous) continue;
    const T coefficient = b[static_cast<std::size_t>(theta.representative)] / T(theta.sigma);
    if (coefficient != T(0)) out.push_back({theta.order, theta.representative, coefficient});
  }
  return out;
}

}  // namespace geomint::analysis::bseries
