#pragma once
/// The modified Hamiltonian of a symplectic B-series (Runge-Kutta) or P-series (partitioned
/// Runge-Kutta, and RKN/Nystrom through partitioned_form.hpp) method, per free tree, exactly.
///
/// HLW (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006), sections IX.9.2-
/// IX.9.3 (one colour) and IX.10 (bi-coloured trees). Elementary Hamiltonians:
/// - one colour, y' = f(y) = J^{-1} grad H(y): H(t) = H^(m+1)(y)(F(t_1)(y), ..., F(t_m)(y)) for
///   t = [t_1, ..., t_m], H(single vertex) = H;
/// - two colours, p' = -H_q (the p-colour) and q' = H_p (the q-colour): H(t) = the m-th
///   derivative of H, in p for each subtree with a p-coloured root (F(t_i) is a p-vector) and in
///   q for each with a q-coloured root, applied to F(t_1), ..., F(t_m). It does not depend on the
///   colour of t's root.
/// Moving the root of t = u o v (v grafted on the root of u) to the root of v gives v o u', u'
/// being u with its root recoloured to the colour opposite to v's (one colour: u' = u), and
///   H(v o u') = -H(u o v)
/// (one colour: H'(y)^T J^{-1} grad; two colours: the same with f = -H_q, g = H_p: the edge
/// keeps its derivative in p at one end and in q at the other). A free tree theta is a class of
/// rooted trees under these moves (and, with two colours, under recolouring the root); each
/// rooted tree t of the class carries a sign s(t) = (-1)^(number of moves from the class's
/// representative), and s(t) H(t) is the same for all of them. When the modified field B(b)
/// (modified_equation.hpp) satisfies the symplecticity conditions, b(t) s(t) is constant on each
/// class, and the modified equation is Hamiltonian with
///   H~ = sum over free trees theta, not superfluous, of h^(|theta| - 1) b(t)/sigma(theta) H(t),
/// t any rooted tree of theta, sigma(theta) the number of automorphisms of theta (for two
/// colours: of the free tree whose edges keep the orientation p-end/q-end). By orbit-stabiliser
/// over the vertices of theta (with the root's colour fixed): sigma(theta) = n / sum over the
/// rooted trees t of theta with a given root colour of 1/sigma(t).
/// Check of the formula: J^{-1} grad (H(t)) = sum over the vertices of theta of s F(t re-rooted
/// there), which groups into sigma(theta)/sigma(t) copies of each rooted tree.
///
/// Superfluous free trees: a class that reaches a rooted tree with both signs; then H(t) = -H(t)
/// = 0. With one colour these are the trees u o u (HLW section IX.9.3; the moves swap the two
/// halves of the central edge). With two colours there are none: a move keeps each edge's
/// orientation (its p-end and q-end), an automorphism exchanging the halves of an edge would
/// reverse it.
///
/// The existence condition (HLW section IX.9.3 for one colour, IX.10 for P-series): b(t) s(t)
/// is constant on each class (and b = 0 on superfluous classes). It is equivalent to the
/// symplecticity conditions of symplectic_conditions.hpp; here it can be restricted to the
/// trees whose elementary differentials do not vanish on a class of Hamiltonians
/// (hamiltonian_trees below): separable H = T(p) + V(q), or natural H = |p|^2/2 + V(q) (RKN
/// methods).

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// One free tree: its rooted trees with their signs, and its automorphism count.
struct free_tree {
  int order = 1;
  int representative = -1;        ///< the rooted tree of smallest index in the class (sign +1)
  std::vector<int> rooted;        ///< all rooted trees of the class (tree indices, ascending)
  std::vector<int> sign;          ///< s(t) = +1 or -1 for each entry of `rooted` (0: superfluous)
  std::int64_t sigma = 1;         ///< automorphisms of the free tree
  bool superfluous = false;       ///< reaches a rooted tree with both signs: H(t) = 0
};

/// The free trees of a tree_set (one or two colours), by order.
inline std::vector<free_tree> free_trees(const tree_set& trees) {
  const auto n_trees = static_cast<std::size_t>(trees.size());
  std::vector<int> class_of(n_trees, -1), sign_of(n_trees, 0);
  std::vector<free_tree> out;
  for (int start = 0; start < trees.size(); ++start) {
    if (class_of[static_cast<std::size_t>(start)] >= 0) continue;
    free_tree theta;
    theta.order = trees[start].order;
    theta.representative = start;
    const int id = static_cast<int>(out.size());
    std::vector<int> pending = {start};
    class_of[static_cast<std::size_t>(start)] = id;
    sign_of[static_cast<std::size_t>(start)] = 1;
    const auto reach = [&](int t, int sign) {
      const auto k = static_cast<std::size_t>(t);
      if (class_of[k] < 0) {
        class_of[k] = id;
        sign_of[k] = sign;
        pending.push_back(t);
      } else if (sign_of[k] != sign) {
        theta.superfluous = true;
      }
    };
    while (!pending.empty()) {
      const int t = pending.back();
      pending.pop_back();
      theta.rooted.push_back(t);
      const int sign = sign_of[static_cast<std::size_t>(t)];
      const std::vector<int>& subtrees = trees[t].subtrees;
      if (trees.colours() == 2) reach(trees.find(1 - trees[t].colour, subtrees), sign);  // the root recoloured
      for (std::size_t i = 0; i < subtrees.size(); ++i) {
        std::vector<int> rest = subtrees;
        rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
        // t = u o v with v = subtrees[i]; the root moved to v gives v o u'.
        const int v = subtrees[i];
        const int u_recoloured = trees.find(trees.colours() == 2 ? 1 - trees[v].colour : 0, rest);
        reach(trees.butcher_product(v, u_recoloured), -sign);
      }
    }
    std::sort(theta.rooted.begin(), theta.rooted.end());
    for (int t : theta.rooted) theta.sign.push_back(theta.superfluous ? 0 : sign_of[static_cast<std::size_t>(t)]);
    // sigma(theta) = n / sum 1/sigma(t) over one root colour = n L / sum (L / sigma(t)).
    std::int64_t common = 1;
    for (int t : theta.rooted) common = std::lcm(common, trees[t].sigma);
    std::int64_t sum = 0;
    for (int t : theta.rooted)
      if (trees[t].colour == 0) sum += common / trees[t].sigma;
    theta.sigma = theta.order * common / sum;
    out.push_back(std::move(theta));
  }
  return out;
}

/// Classes of Hamiltonians on which fewer elementary Hamiltonians are needed (two colours).
enum class hamiltonian_class {
  general,    ///< H(p, q): every tree
  separable,  ///< H = T(p) + V(q): colours alternate along every edge
  natural,    ///< H = |p|^2/2 + V(q) (T quadratic; RKN methods on q'' = -grad V(q))
};

/// Whether the elementary differential F(t) of a two-colour tree can be non-zero for the class
/// (position_colour: the colour of q' = H_p; symplectic_conditions.hpp uses 1, the partitioned
/// form of an RKN (partitioned_form.hpp) uses 0):
/// - separable: f = -V'(q) and g = T'(p), so a vertex's children have the other colour;
/// - natural: in addition g = p is linear, so a position-coloured vertex has at most one child.
///   With position_colour 0 these are the Nystrom trees (is_nystrom_tree, velocity_free).
/// For the free trees: a free tree's elementary Hamiltonian vanishes identically on the class iff
/// none of its rooted trees is marked (separable: its vertices cannot be coloured alternately
/// with every edge keeping its orientation; natural: besides, a vertex where T is differentiated
/// three times or more, i.e. a T-vertex of degree >= 3).
inline std::vector<bool> hamiltonian_trees(const tree_set& trees, hamiltonian_class which, int position_colour) {
  if (trees.colours() != 2)
    throw std::invalid_argument("geomint::analysis::bseries::hamiltonian_trees: two-colour trees are needed");
  if (position_colour != 0 && position_colour != 1)
    throw std::invalid_argument("geomint::analysis::bseries::hamiltonian_trees: position_colour must be 0 or 1");
  std::vector<bool> marked(static_cast<std::size_t>(trees.size()), false);
  for (int t = 0; t < trees.size(); ++t) {
    const rooted_tree& tree = trees[t];
    bool ok = which == hamiltonian_class::general ||
              !(which == hamiltonian_class::natural && tree.colour == position_colour && tree.subtrees.size() > 1);
    for (int u : tree.subtrees)
      ok = ok && marked[static_cast<std::size_t>(u)] && (which == hamiltonian_class::general || trees[u].colour != tree.colour);
    marked[static_cast<std::size_t>(t)] = ok;  // subtrees come before the tree
  }
  return marked;
}

/// Per free tree: whether its elementary Hamiltonian can be non-zero on the class that `marked`
/// describes (hamiltonian_trees): it is not superfluous and has a marked rooted tree. The
/// reduced list of free trees for separable or natural H.
inline std::vector<bool> nonvanishing_free_trees(const std::vector<free_tree>& classes, const std::vector<bool>& marked) {
  std::vector<bool> out;
  for (const free_tree& theta : classes)
    out.push_back(!theta.superfluous && std::any_of(theta.rooted.begin(), theta.rooted.end(),
                                                    [&marked](int t) { return marked.at(static_cast<std::size_t>(t)); }));
  return out;
}

/// Verdict of the existence condition of a modified Hamiltonian.
struct hamiltonian_existence {
  bool holds = true;
  int failing_order = 0;   ///< smallest order of a failing free tree (0 if none)
  int t = -1, u = -1;      ///< two marked rooted trees of that free tree with b(t) s(t) != b(u) s(u)
                           ///< (u = -1: t lies on a superfluous free tree and b(t) != 0)
};

/// Checks that b(t) s(t) is constant on the marked rooted trees of every free tree (and zero on
/// superfluous ones), by increasing order; `marked` (one entry per tree, or null for all) as
/// from hamiltonian_trees.
template <class T>
hamiltonian_existence check_modified_hamiltonian_exists(const tree_set& trees, const std::vector<free_tree>& classes,
                                                        const std::vector<T>& b, const std::vector<bool>* marked = nullptr) {
  if (b.size() != static_cast<std::size_t>(trees.size()) || (marked && marked->size() != b.size()))
    throw std::invalid_argument("geomint::analysis::bseries::check_modified_hamiltonian_exists: one coefficient b(t) (and one mark) per tree is needed");
  hamiltonian_existence verdict;
  for (const free_tree& theta : classes) {  // by order
    int first = -1;
    T value(0);
    for (std::size_t i = 0; i < theta.rooted.size(); ++i) {
      const int t = theta.rooted[i];
      if (marked && !(*marked)[static_cast<std::size_t>(t)]) continue;
      const T signed_b = theta.sign[i] < 0 ? T(0) - b[static_cast<std::size_t>(t)] : b[static_cast<std::size_t>(t)];
      const bool fails = theta.superfluous ? b[static_cast<std::size_t>(t)] != T(0) : (first >= 0 && signed_b != value);
      if (fails) {
        verdict = {false, theta.order, t, theta.superfluous ? -1 : first};
        return verdict;
      }
      if (first < 0) {
        first = t;
        value = signed_b;
      }
    }
  }
  return verdict;
}

/// One term h^(order - 1) coefficient H(tree) of the modified Hamiltonian.
template <class T>
struct hamiltonian_term {
  int order = 1;
  int tree = -1;       ///< the rooted tree t whose elementary Hamiltonian H(t) the term uses
  int free = -1;       ///< index of its free tree in free_trees(trees)
  T coefficient{};     ///< b(t)/sigma(theta)
};

/// The modified Hamiltonian's terms with non-zero coefficients, by order, from the modified
/// field b (one or two colours). With `marked` (hamiltonian_trees; for an RKN or Nystrom method
/// its Nystrom trees), only free trees with a marked rooted tree appear, each through its first
/// marked rooted tree, and the existence condition is checked on marked trees only. Throws
/// std::domain_error naming the failing trees if the condition fails (the modified field is not
/// Hamiltonian).
template <class T>
std::vector<hamiltonian_term<T>> modified_hamiltonian(const tree_set& trees, const std::vector<T>& b,
                                                      const std::vector<bool>* marked = nullptr) {
  if (b.size() != static_cast<std::size_t>(trees.size()) || (marked && marked->size() != b.size()))
    throw std::invalid_argument("geomint::analysis::bseries::modified_hamiltonian: one coefficient b(t) (and one mark) per tree is needed");
  const std::vector<free_tree> classes = free_trees(trees);
  const hamiltonian_existence verdict = check_modified_hamiltonian_exists(trees, classes, b, marked);
  if (!verdict.holds)
    throw std::domain_error("geomint::analysis::bseries::modified_hamiltonian: the symplecticity conditions fail at order " +
                            std::to_string(verdict.failing_order) + " (trees " + std::to_string(verdict.t) + " and " +
                            std::to_string(verdict.u) + "): the modified field is not Hamiltonian");
  std::vector<hamiltonian_term<T>> out;
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const free_tree& theta = classes[k];
    if (theta.superfluous) continue;
    for (std::size_t i = 0; i < theta.rooted.size(); ++i) {
      const int t = theta.rooted[i];
      if (marked && !(*marked)[static_cast<std::size_t>(t)]) continue;
      const T coefficient = b[static_cast<std::size_t>(t)] / T(theta.sigma);
      if (coefficient != T(0)) out.push_back({theta.order, t, static_cast<int>(k), coefficient});
      break;
    }
  }
  return out;
}

/// The modified Hamiltonian of a tableau of any kind, with the trees it is expressed on.
template <class K>
struct method_hamiltonian {
  tree_set trees;
  std::vector<bool> marked;                 ///< the trees used (all for rk; see modified_hamiltonian_of)
  int p_colour = 0;                         ///< the colour of p' = -H_q (two colours)
  std::vector<K> field;                     ///< the modified field b, one entry per tree
  std::vector<hamiltonian_term<K>> terms;   ///< H~, terms up to h^(order - 1)
};

/// The modified Hamiltonian of a symplectic method to its h^(order - 1) terms: rk on one-colour
/// trees (every H); prk on two-colour trees with the pair's first tableau on p (colour 0) and
/// the second on q, for every H(p, q) (general) or only for separable H; rkn and nystrom through
/// their partitioned form (partitioned_form.hpp, q on colour 0, p = v on colour 1), for natural
/// H = |p|^2/2 + V(q), on the Nystrom trees, the only trees on which they define a series.
/// std::domain_error if the modified field is not Hamiltonian on these trees.
template <class K>
method_hamiltonian<K> modified_hamiltonian_of(const tableau_data<K>& t, int order,
                                              hamiltonian_class prk_class = hamiltonian_class::general) {
  const bool nystrom = t.kind == methods::method_kind::rkn || t.kind == methods::method_kind::nystrom;
  const int colours = t.kind == methods::method_kind::rk ? 1 : 2;
  method_hamiltonian<K> out{tree_set(order, colours), {}, nystrom ? 1 : 0, {}, {}};
  out.marked = colours == 1 ? std::vector<bool>(static_cast<std::size_t>(out.trees.size()), true)
                            : hamiltonian_trees(out.trees, nystrom ? hamiltonian_class::natural : prk_class, 1 - out.p_colour);
  out.field = modified_field(out.trees, elementary_weights(out.trees, partitioned_form_of(t), &out.marked));
  out.terms = modified_hamiltonian(out.trees, out.field, &out.marked);
  return out;
}

}  // namespace geomint::analysis::bseries
