#pragma once
/// Rooted trees (one colour, for B-series of Runge-Kutta methods) and bi-coloured rooted trees
/// (two colours, for P-series of partitioned Runge-Kutta methods), generated up to an order.
///
/// Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006 (HLW),
/// sections III.1.1-III.1.2 (trees T, order |t|, symmetry sigma, density gamma) and III.2.1
/// (P-trees TP: the colour of a vertex says which component, y' = f(y,z) (colour 0, "black") or
/// z' = g(y,z) (colour 1, "white"), its elementary differential differentiates).
///
/// A tree is stored canonically as its root colour and the sorted multiset of the indices of the
/// root's subtrees (t = [t_1, ..., t_m] with a coloured root), so equal trees have equal records.
///   |t| = 1 + sum |t_i|,   gamma(t) = |t| prod gamma(t_i),
///   sigma(t) = prod over distinct subtrees u of (multiplicity of u)! sigma(u)^(multiplicity)
/// (HLW section III.1.2: sigma and gamma as in the B-series of the exact flow, B(e, y) with
/// e(t) = 1/gamma(t)). Colours enter only through equality of subtrees.
///
/// For the substitution and Lie-derivative laws the table also holds, per tree, its edge cuts:
/// removing one edge splits t into the part containing the root and the cut-off subtree; the
/// pairs (root part, cut part) are listed with the number of edges giving them (their
/// multiplicities sum to |t| - 1). In the 1/sigma normalisation of B-series, grafting a tree
/// onto every vertex of another (the derivative F(u)'F(v) summed over vertices) corresponds
/// exactly to this sum over edges.
///
/// Counts per order n = 1, 2, ...: one colour 1, 1, 2, 4, 9, 20, 48, 115, 286, 719 (OEIS
/// A000081); two colours, per root colour, 1, 2, 7, 26, 107, 458, 2058, 9498 (OEIS A000151; the
/// total is twice that). Both checked in tests/analysis/test_bseries_trees.cpp.
///
/// Two colours can also be restricted to the trees whose elementary differentials can be
/// nonzero for a second-order system written as q' = v (colour 0), v' = F(q, v) (colour 1):
/// f = v is linear in v and constant in q, so a colour-0 vertex has no child or one child of
/// colour 1; for F = F(q) (Runge-Kutta-Nystrom, velocity-free) a colour-1 vertex has colour-0
/// children only (tree_class::rkn), for F(q, v) (Nystrom) children of either colour
/// (tree_class::nystrom). These are the Nystrom trees of Hairer, Norsett, Wanner, Solving ODEs I,
/// 2nd ed., section II.14 (a colour-1 vertex is fat, a colour-0 vertex meagre), the trees
/// is_nystrom_tree (partitioned_form.hpp) selects in the full set. Each class is closed under
/// taking subtrees and under edge cuts (both parts of a cut stay in it), so find() and cuts()
/// work within it; the generator skips the other trees before appending them. Counts per order,
/// root colour 1: rkn 1, 1, 2, 3, 6, 10, 20, 36, 72, 137, ... (the special Nystrom trees of
/// analysis/nystrom_trees.hpp), nystrom 1, 2, 6, 18, 60, 204, 730, 2664, ...; root colour 0: one
/// at order 1, then the root-colour-1 count of the order below. Checked against their generating
/// functions in tests/analysis/test_bseries_trees.cpp.
///
/// Everything here is constexpr (C++20 transient allocation): a tree_set built inside a constant
/// expression gives its counts, sigma, gamma and cuts to static_assert
/// (tests/analysis/test_bseries_static.cpp). Lookups are binary searches in the table itself:
/// within an order the trees are sorted by root colour and then lexicographically by their
/// subtree lists (the order for_each_sons generates them in).

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace geomint::analysis::bseries {

/// Largest orders the generator accepts (one colour: 32 973 trees of order 14; two colours:
/// 2 x 216 598 trees of order 10, 547 404 in all, the P-series of an order-8 partitioned method
/// to p + 2; docs/results/modified.md gives the time and memory of that analysis).
inline constexpr int max_tree_order_one_colour = 14;
inline constexpr int max_tree_order_two_colours = 10;

/// Which trees a tree_set holds (see the top of the file): all, or only those with possibly
/// nonzero elementary differentials for q' = v, v' = f(q) (rkn) or v' = F(q, v) (nystrom).
enum class tree_class { all, rkn, nystrom };

/// Largest orders of the two-colour classes (rkn: 9 240 + 4 521 trees of order 16, 27 103 in
/// all; nystrom: 37 955 + 9 975 of order 10, 65 276 in all). Building the set at the cap takes
/// 0.08 s and 0.13 s at -Og (nystrom at order 11 has 249 864 trees).
inline constexpr int max_tree_order_rkn = 16;
inline constexpr int max_tree_order_nystrom = 10;

/// One tree of a tree_set.
struct rooted_tree {
  int order = 1;              ///< |t|, number of vertices
  int colour = 0;             ///< colour of the root: 0 (y, f) or 1 (z, g)
  std::vector<int> subtrees;  ///< indices of the root's subtrees, ascending (with repetition)
  std::int64_t sigma = 1;     ///< symmetry coefficient
  std::int64_t gamma = 1;     ///< density
};

/// One way of cutting an edge of a tree: the part holding the root, the cut-off subtree, and
/// how many edges of the tree give this pair.
struct edge_cut {
  int root_part = -1;
  int cut_part = -1;
  int multiplicity = 0;
};

namespace detail {
/// Whether a series coefficient is zero by its representation: a zero field_element (Q(r)) is
/// the empty polynomial, other types compare with 0. The series loops skip such terms, which
/// is what makes high orders affordable: a method of order p has b(t) = 0 for 2 <= |t| <= p
/// (and a symmetric one at every even order), so most edge cuts of the modified field's
/// recursion contribute nothing. A false "not zero" only costs time.
template <class T>
constexpr bool known_zero(const T& x) {
  if constexpr (requires { x.coefficients().empty(); }) return x.coefficients().empty();
  else return x == T(0);
}

/// gamma(t) = |t| prod gamma(u) and sigma(t) = prod over distinct sons u of (multiplicity)!
/// sigma(u)^(multiplicity), for a tree t of order n whose root has the sons `sons` (ascending
/// indices into `trees`).
template <class Tree>
constexpr void set_symmetry_and_density(Tree& t, int n, const std::vector<int>& sons, const std::vector<Tree>& trees) {
  t.gamma = n;
  t.sigma = 1;
  std::int64_t run = 0;
  for (std::size_t i = 0; i < sons.size(); ++i) {
    const Tree& u = trees[static_cast<std::size_t>(sons[i])];
    t.gamma *= u.gamma;
    run = (i > 0 && sons[i] == sons[i - 1]) ? run + 1 : 1;
    t.sigma *= run * u.sigma;  // (multiplicity)! built up one factor per repeat
  }
}

/// The sons of a new root: calls emit(sons) for every list of indices into `trees` (a list by
/// order), ascending with repetition, below `end`, from `from` on, whose orders sum to
/// `remaining` and which `admissible(tree)` accepts; `sons` holds the list built so far. emit
/// may append to `trees` (only indices below `end` are read).
template <class Tree, class Admissible, class Emit>
constexpr void for_each_sons(const std::vector<Tree>& trees, int end, int remaining, int from, std::vector<int>& sons,
                             const Admissible& admissible, const Emit& emit) {
  if (remaining == 0) {
    emit(sons);
    return;
  }
  for (int u = from; u < end; ++u) {
    const int order = trees[static_cast<std::size_t>(u)].order;
    if (order > remaining) break;  // trees are by order
    if (!admissible(trees[static_cast<std::size_t>(u)])) continue;
    sons.push_back(u);
    for_each_sons(trees, end, remaining - order, u, sons, admissible, emit);
    sons.pop_back();
  }
}
}  // namespace detail

/// All (one- or two-coloured) rooted trees up to an order, by order; within an order, by root
/// colour and then by subtree indices.
class tree_set {
 public:
  /// colours: 1 for B-series (Runge-Kutta), 2 for P-series (partitioned Runge-Kutta).
  constexpr tree_set(int max_order, int colours) : tree_set(max_order, colours, tree_class::all) {}
  /// The two-coloured trees of a class (tree_class::all: the same as tree_set(max_order, 2)).
  constexpr tree_set(int max_order, tree_class kind) : tree_set(max_order, 2, kind) {}

  constexpr int max_order() const { return max_order_; }
  constexpr int colours() const { return colours_; }
  constexpr tree_class kind() const { return kind_; }
  constexpr int size() const { return static_cast<int>(trees_.size()); }
  constexpr const rooted_tree& operator[](int t) const { return trees_.at(static_cast<std::size_t>(t)); }
  constexpr const std::vector<rooted_tree>& trees() const { return trees_; }
  /// Index of the first tree of order n (n = max_order + 1 gives size()).
  constexpr int first(int n) const { return first_.at(static_cast<std::size_t>(n)); }
  /// Number of trees of order n.
  constexpr int count(int n) const { return first(n + 1) - first(n); }
  /// Number of trees of order n whose root has the given colour.
  constexpr int count(int n, int colour) const {
    int k = 0;
    for (int t = first(n); t < first(n + 1); ++t) k += trees_[static_cast<std::size_t>(t)].colour == colour;
    return k;
  }
  /// The edge cuts of tree t (empty for a single vertex).
  constexpr const std::vector<edge_cut>& cuts(int t) const { return cuts_.at(static_cast<std::size_t>(t)); }

  /// Index of the tree with this root colour and these subtrees (any order), -1 if its order
  /// exceeds max_order (or a subtree index is not a tree of the set).
  constexpr int find(int colour, std::vector<int> subtrees) const {
    std::sort(subtrees.begin(), subtrees.end());
    int order = 1;
    for (int u : subtrees) {
      if (u < 0 || u >= size()) return -1;
      order += trees_[static_cast<std::size_t>(u)].order;
    }
    if (order > max_order_) return -1;
    // Binary search among the trees of this order, sorted by (colour, subtrees).
    const auto begin = trees_.begin() + first(order), end = trees_.begin() + first(order + 1);
    const auto it = std::lower_bound(begin, end, subtrees, [colour](const rooted_tree& t, const std::vector<int>& key) {
      return t.colour != colour ? t.colour < colour : t.subtrees < key;
    });
    return it != end && it->colour == colour && it->subtrees == subtrees ? static_cast<int>(it - trees_.begin()) : -1;
  }
  /// The single vertex of a colour.
  constexpr int leaf(int colour) const { return find(colour, {}); }
  /// The Butcher product u o v: v grafted as a new subtree onto the root of u (HLW section III.1;
  /// the product of the symplecticity conditions, HLW section IX.9); -1 if |u| + |v| exceeds max_order.
  constexpr int butcher_product(int u, int v) const {
    if (v < 0 || v >= size()) throw std::out_of_range("geomint::analysis::bseries::tree_set::butcher_product: no tree " + std::to_string(v));
    std::vector<int> subtrees = (*this)[u].subtrees;
    subtrees.push_back(v);
    return find((*this)[u].colour, std::move(subtrees));
  }

 private:
  constexpr tree_set(int max_order, int colours, tree_class kind) : max_order_(max_order), colours_(colours), kind_(kind) {
    if (colours != 1 && colours != 2)
      throw std::invalid_argument("geomint::analysis::bseries::tree_set: colours must be 1 or 2");
    const int limit = colours == 1                  ? max_tree_order_one_colour
                      : kind == tree_class::rkn     ? max_tree_order_rkn
                      : kind == tree_class::nystrom ? max_tree_order_nystrom
                                                    : max_tree_order_two_colours;
    if (max_order < 1 || max_order > limit)
      throw std::invalid_argument("geomint::analysis::bseries::tree_set: max_order must be in 1.." +
                                  std::to_string(limit) + " for " + std::to_string(colours) + " colour(s)" +
                                  (kind == tree_class::rkn       ? " (rkn class)"
                                   : kind == tree_class::nystrom ? " (nystrom class)"
                                                                 : ""));
    first_.assign(static_cast<std::size_t>(max_order) + 2, 0);
    for (int n = 1; n <= max_order; ++n) {
      first_[static_cast<std::size_t>(n)] = size();
      for (int colour = 0; colour < colours; ++colour) {
        std::vector<int> subtrees;
        if (kind != tree_class::all && colour == 0) {
          // q' = v: the root alone or over one colour-1 tree (those of order n - 1 are in the set).
          if (n == 1) append(n, colour, subtrees);
          else
            for (int u = first(n - 1); u < first(n); ++u)
              if (trees_[static_cast<std::size_t>(u)].colour == 1) append(n, colour, {u});
          continue;
        }
        const bool colour_0_sons_only = kind == tree_class::rkn && colour == 1;  // f(q): no v-argument
        detail::for_each_sons(
            trees_, first(n), n - 1, 0, subtrees,
            [&](const rooted_tree& u) { return !colour_0_sons_only || u.colour == 0; },
            [&](const std::vector<int>& sons) { append(n, colour, sons); });
      }
      first_[static_cast<std::size_t>(n) + 1] = size();
    }
  }

  constexpr void append(int n, int colour, const std::vector<int>& subtrees) {
    rooted_tree t;
    t.order = n;
    t.colour = colour;
    t.subtrees = subtrees;
    detail::set_symmetry_and_density(t, n, subtrees, trees_);
    const int id = size();
    trees_.push_back(std::move(t));
    cuts_.push_back(make_cuts(id));
  }

  /// The edge cuts of tree id: the edges from the root to each subtree, and the edges inside
  /// each subtree (from that subtree's cuts); sorted by (root part, cut part).
  constexpr std::vector<edge_cut> make_cuts(int id) const {
    const rooted_tree& t = trees_[static_cast<std::size_t>(id)];
    std::vector<edge_cut> out;
    const auto add = [&out](int root_part, int cut_part, int multiplicity) {
      for (edge_cut& c : out)
        if (c.root_part == root_part && c.cut_part == cut_part) {
          c.multiplicity += multiplicity;
          return;
        }
      out.push_back({root_part, cut_part, multiplicity});
    };
    for (std::size_t i = 0; i < t.subtrees.size(); ++i) {
      if (i > 0 && t.subtrees[i] == t.subtrees[i - 1]) continue;
      const int u = t.subtrees[i];
      const int copies = static_cast<int>(std::count(t.subtrees.begin(), t.subtrees.end(), u));
      std::vector<int> rest = t.subtrees;
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
      add(find(t.colour, rest), u, copies);
      for (const edge_cut& inner : cuts_[static_cast<std::size_t>(u)]) {
        std::vector<int> replaced = rest;
        replaced.push_back(inner.root_part);
        add(find(t.colour, replaced), inner.cut_part, copies * inner.multiplicity);
      }
    }
    std::sort(out.begin(), out.end(), [](const edge_cut& x, const edge_cut& y) {
      return x.root_part != y.root_part ? x.root_part < y.root_part : x.cut_part < y.cut_part;
    });
    return out;
  }

  int max_order_;
  int colours_;
  tree_class kind_;
  std::vector<rooted_tree> trees_;
  std::vector<std::vector<edge_cut>> cuts_;
  std::vector<int> first_;
};

/// For each tree of `part` (a class set) up to all.max_order(), the index of the same tree in
/// `all` (a two-colour set of tree_class::all): subtrees come first, so one find() per tree.
constexpr std::vector<int> indices_in(const tree_set& part, const tree_set& all) {
  std::vector<int> out;
  for (int t = 0; t < part.first(std::min(part.max_order(), all.max_order()) + 1); ++t) {
    std::vector<int> sons;
    for (int u : part[t].subtrees) sons.push_back(out[static_cast<std::size_t>(u)]);
    out.push_back(all.find(part[t].colour, std::move(sons)));
  }
  return out;
}

}  // namespace geomint::analysis::bseries
