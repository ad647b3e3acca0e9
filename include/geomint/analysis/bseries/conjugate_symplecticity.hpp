#pragma once
/// Conjugate symplecticity up to an order, from the modified field of a B- or P-series method:
/// the largest r for which a modified energy of elementary Hamiltonians is conserved by the
/// method to O(h^(r+1)).
///
/// Characterisation. A B-series method is conjugate to a symplectic B-series method (formally,
/// all orders) iff it conserves exactly a modified Hamiltonian H~ = H + sum over free trees of
/// h^(|theta| - 1) gamma(theta) H(theta) (Chartier, Faou & Murua, An algebraic approach to
/// invariant preserving integrators: the case of quadratic and Hamiltonian invariants, Numer.
/// Math. 103 (2006) 575-590; HLW: Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd
/// ed. 2006, sections VI.8 and IX.9.4); up to order r, conjugate symplecticity and conservation
/// of such an H~ to O(h^(r+1)) go together (Hairer & Zbinden, On conjugate-symplecticity of
/// B-series integrators, IMA J. Numer. Anal. 33 (2013) 57-79). The verdict here is the second
/// statement, computed exactly.
///
/// Computation. Write H~ = sum over rooted trees u of c(u)/sigma(u) H(u) (c = 1 on the one-vertex
/// trees, one unknown gamma(theta) per non-superfluous free tree carried by one rooted tree of
/// it, modified_hamiltonian.hpp). Along the modified field h f~ = B(b) (modified_equation.hpp),
/// H(u)'F(t) is the sum over the vertices of u of H(t grafted there), so
///   h dH~/dt = sum over rooted trees w of h^(|w| - 1) (d_b c)(w)/sigma(w) H(w),
///   (d_b c)(w) = sum over the edge cuts of w (root part u, cut part t, multiplicity m) of m c(u) b(t)
/// (the Lie derivative of modified_equation.hpp without its empty-tree term), and with
/// H(w) = s(w) H(theta) the coefficient of H(theta) is sum over w in theta of s(w) (d_b c)(w)/sigma(w).
/// The elementary Hamiltonians of distinct non-superfluous free trees are independent (HLW section
/// IX.9.3), so H~(y1) = H~(y0) + O(h^(r+1)) for some gamma iff these linear equations in gamma
/// are consistent for the free trees of order 2 .. r + 1. They are solved exactly, order by
/// order, by Gaussian elimination on all unknowns together (an unknown of order n - 1 first
/// appears in the equations of order n, but remains free for the later ones).
///
/// With `marked` (hamiltonian_trees: separable or natural H; the Nystrom trees of an RKN's
/// partitioned form) b is taken as zero on unmarked trees (their F vanishes for the class),
/// and equations and unknowns are kept only for free trees with a marked rooted tree.

#include <cstddef>
#include <map>
#include <stdexcept>
#include <vector>

#include "geomint/analysis/bseries/modified_hamiltonian.hpp"
#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// Verdict on conjugate symplecticity.
struct conjugate_symplecticity_verdict {
  /// The largest r <= checked_order with a modified energy conserved to O(h^(r+1)).
  int order = 0;
  /// Whether the conditions hold up to checked_order (then order is a lower bound).
  bool order_is_lower_bound = false;
  /// trees.max_order() - 1: equations of free trees up to trees.max_order() are solved.
  int checked_order = 0;
  /// A free tree (index in free_trees) of order `order` + 2 whose equation cannot be met; -1 if none.
  int failing_free_tree = -1;
};

namespace detail {
/// A linear form sum coefficient[x] x + constant over the unknowns.
template <class T>
struct linear_form {
  std::map<int, T> coefficient;
  T constant{0};
  void add(int x, const T& value) {
    T& entry = coefficient[x];
    entry += value;
    if (entry == T(0)) coefficient.erase(x);
  }
  void subtract_multiple(const linear_form& row, const T& factor) {
    for (const auto& [x, value] : row.coefficient) add(x, T(0) - factor * value);
    constant -= factor * row.constant;
  }
};

/// Reduced row echelon form: each pivot row has coefficient 1 on its pivot and 0 on every other
/// pivot. add() returns false if the equation (form = 0) contradicts the ones before.
template <class T>
class linear_system {
 public:
  bool add(linear_form<T> row) {
    for (const auto& [pivot, pivot_row] : rows_) {
      const auto it = row.coefficient.find(pivot);
      if (it != row.coefficient.end()) row.subtract_multiple(pivot_row, T(it->second));
    }
    if (row.coefficient.empty()) return row.constant == T(0);
    const int pivot = row.coefficient.begin()->first;
    const T scale = row.coefficient.begin()->second;
    for (auto& [x, value] : row.coefficient) value = value / scale;
    row.constant = row.constant / scale;
    for (auto& [other, other_row] : rows_) {
      const auto it = other_row.coefficient.find(pivot);
      if (it != other_row.coefficient.end()) other_row.subtract_multiple(row, T(it->second));
    }
    rows_.emplace(pivot, std::move(row));
    return true;
  }
  /// Number of independent equations.
  int rank() const { return static_cast<int>(rows_.size()); }
  /// The value of unknown x when every unknown is a pivot (the solution is unique).
  T value_of(int x) const {
    const auto it = rows_.find(x);
    return it == rows_.end() ? T(0) : T(0) - it->second.constant;
  }

 private:
  std::map<int, linear_form<T>> rows_;
};
}  // namespace detail

/// The conjugate-symplecticity verdict of the modified field b (one coefficient per tree of
/// `trees`, from modified_field), decided on the free trees up to trees.max_order().
template <class T>
conjugate_symplecticity_verdict conjugate_symplecticity(const tree_set& trees, const std::vector<T>& b,
                                                        const std::vector<bool>* marked = nullptr) {
  const auto n_trees = static_cast<std::size_t>(trees.size());
  if (b.size() != n_trees || (marked && marked->size() != n_trees))
    throw std::invalid_argument("geomint::analysis::bseries::conjugate_symplecticity: one coefficient b(t) (and one mark) per tree is needed");
  const auto is_marked = [marked](int t) { return !marked || (*marked)[static_cast<std::size_t>(t)]; };
  const std::vector<free_tree> classes = free_trees(trees);
  // For every rooted tree: its class and sign; per class, whether H(theta) is kept and the rooted
  // tree carrying c (its unknown, or the constant 1 for the one-vertex class).
  std::vector<int> class_of(n_trees), sign_of(n_trees);
  std::vector<int> carrier(classes.size(), -1);
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const free_tree& theta = classes[k];
    for (std::size_t i = 0; i < theta.rooted.size(); ++i) {
      class_of[static_cast<std::size_t>(theta.rooted[i])] = static_cast<int>(k);
      sign_of[static_cast<std::size_t>(theta.rooted[i])] = theta.sign[i];
    }
    if (theta.superfluous) continue;
    for (int t : theta.rooted)
      if (is_marked(t)) {
        carrier[k] = t;
        break;
      }
  }
  const auto b_of = [&](int t) { return is_marked(t) ? b[static_cast<std::size_t>(t)] : T(0); };
  conjugate_symplecticity_verdict verdict;
  verdict.checked_order = trees.max_order() - 1;
  detail::linear_system<T> system;
  for (int n = 2; n <= trees.max_order(); ++n) {
    for (std::size_t k = 0; k < classes.size(); ++k) {
      const free_tree& theta = classes[k];
      if (theta.order != n || carrier[k] < 0) continue;
      // sum over w in theta of s(w)/sigma(w) sum over cuts m c(root part) b(cut part).
      detail::linear_form<T> equation;
      for (std::size_t i = 0; i < theta.rooted.size(); ++i) {
        const int w = theta.rooted[i];
        for (const edge_cut& cut : trees.cuts(w)) {
          const T bt = b_of(cut.cut_part);
          const auto u_class = static_cast<std::size_t>(class_of[static_cast<std::size_t>(cut.root_part)]);
          if (bt == T(0) || carrier[u_class] != cut.root_part) continue;  // c(u) = 0 off the carriers
          const T factor = T(theta.sign[i] * cut.multiplicity) * bt / T(trees[w].sigma);
          if (trees[cut.root_part].order == 1)
            equation.constant += factor;
          else
            equation.add(static_cast<int>(u_class), factor);
        }
      }
      if (!system.add(std::move(equation))) {
        verdict.order = n - 2;
        verdict.failing_free_tree = static_cast<int>(k);
        return verdict;
      }
    }
  }
  verdict.order = verdict.checked_order;
  verdict.order_is_lower_bound = true;
  return verdict;
}

}  // namespace geomint::analysis::bseries
