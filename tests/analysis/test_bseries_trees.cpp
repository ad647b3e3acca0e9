/// Rooted and bi-coloured rooted trees (include/geomint/analysis/bseries/trees.hpp).
///
/// Independent sources: the numbers of rooted trees per order (OEIS A000081, listed in Hairer,
/// Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006, section III.1) and of
/// bi-coloured rooted trees with a root of a given colour (OEIS A000151; HLW section III.2);
/// sigma and gamma of the trees of order <= 4 as printed in the table of HLW section III.1; and
/// the count of increasing labellings: a tree t with n vertices has n!/(sigma(t) gamma(t))
/// labellings by 1..n increasing away from the root, up to its symmetries, and the increasing
/// (recursive) trees with n vertices number (n-1)! (vertex k + 1 hangs from one of the k
/// before it); with two colours, the n - 1 non-root vertices are coloured freely, 2^(n-1) ways.
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/trees.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_trees_test {

using geomint::analysis::bseries::tree_class;
using geomint::analysis::bseries::tree_set;

/// Coefficients 1..n_max of R(x) = x prod_k (1 - x^k)^(-c_k), c(k) given for k < the order
/// asked (Euler transform: m a_m = sum_{k=1}^m (sum_{d | k} d c_d) a_{m-k}, a = R / x).
template <class Weights>
std::vector<std::int64_t> rooted_counts(int n_max, const Weights& c) {
  std::vector<std::int64_t> r(static_cast<std::size_t>(n_max) + 1, 0), a(static_cast<std::size_t>(n_max), 0);
  a[0] = 1;
  r[1] = 1;
  for (int m = 1; m < n_max; ++m) {
    std::int64_t sum = 0;
    for (int k = 1; k <= m; ++k) {
      std::int64_t divisor_sum = 0;
      for (int d = 1; d <= k; ++d)
        if (k % d == 0) divisor_sum += d * c(d, r);
      sum += divisor_sum * a[static_cast<std::size_t>(m - k)];
    }
    a[static_cast<std::size_t>(m)] = sum / m;
    r[static_cast<std::size_t>(m) + 1] = a[static_cast<std::size_t>(m)];
  }
  return r;
}

TEST_CASE("bseries trees: counts per order match OEIS A000081 and A000151", "[bseries]") {
  const std::vector<int> rooted = {1, 1, 2, 4, 9, 20, 48, 115, 286, 719};  // A000081, n = 1..10
  const tree_set one(10, 1);
  for (int n = 1; n <= 10; ++n) CHECK(one.count(n) == rooted[static_cast<std::size_t>(n - 1)]);

  const std::vector<int> coloured = {1, 2, 7, 26, 107, 458, 2058, 9498};  // A000151, n = 1..8
  const tree_set two(8, 2);
  for (int n = 1; n <= 8; ++n) {
    CHECK(two.count(n, 0) == coloured[static_cast<std::size_t>(n - 1)]);
    CHECK(two.count(n, 1) == coloured[static_cast<std::size_t>(n - 1)]);
    CHECK(two.count(n) == 2 * coloured[static_cast<std::size_t>(n - 1)]);
  }
}

TEST_CASE("bseries trees: sigma and gamma of the trees of order <= 4 (HLW III.1)", "[bseries]") {
  const tree_set trees(4, 1);
  const int tau = trees.leaf(0);
  const int t2 = trees.find(0, {tau});              // [tau]
  const int cherry = trees.find(0, {tau, tau});     // [tau, tau]
  const int tall = trees.find(0, {t2});             // [[tau]]
  struct expected { int t; int order; std::int64_t sigma, gamma; };
  const std::vector<expected> table = {
      {tau, 1, 1, 1},
      {t2, 2, 1, 2},
      {cherry, 3, 2, 3},
      {tall, 3, 1, 6},
      {trees.find(0, {tau, tau, tau}), 4, 6, 4},
      {trees.find(0, {t2, tau}), 4, 1, 8},
      {trees.find(0, {cherry}), 4, 2, 12},
      {trees.find(0, {tall}), 4, 1, 24},
  };
  for (const expected& e : table) {
    REQUIRE(e.t >= 0);
    CHECK(trees[e.t].order == e.order);
    CHECK(trees[e.t].sigma == e.sigma);
    CHECK(trees[e.t].gamma == e.gamma);
  }
  CHECK(trees.butcher_product(tau, tau) == t2);
  CHECK(trees.butcher_product(tau, t2) == tall);
  CHECK(trees.butcher_product(t2, tau) == cherry);
  CHECK(trees.butcher_product(tall, t2) == -1);  // order 5 > 4
}

TEST_CASE("bseries trees: increasing labellings n!/(sigma gamma) sum to (n-1)! (x 2^(n-1) for two colours)", "[bseries]") {
  for (int colours = 1; colours <= 2; ++colours) {
    const tree_set trees(colours == 1 ? 10 : 8, colours);
    std::int64_t factorial = 1;  // (n-1)!
    std::int64_t colourings = 1;  // colours^(n-1)
    for (int n = 1; n <= trees.max_order(); ++n) {
      if (n > 1) {
        factorial *= n - 1;
        colourings *= colours;
      }
      for (int root = 0; root < colours; ++root) {
        std::int64_t labellings = 0;
        for (int t = trees.first(n); t < trees.first(n + 1); ++t) {
          if (trees[t].colour != root) continue;
          std::int64_t n_factorial = 1;
          for (int k = 2; k <= n; ++k) n_factorial *= k;
          REQUIRE(n_factorial % (trees[t].sigma * trees[t].gamma) == 0);
          labellings += n_factorial / (trees[t].sigma * trees[t].gamma);
        }
        CHECK(labellings == factorial * colourings);
      }
    }
  }
}

TEST_CASE("bseries trees: edge cuts split each tree into two parts, one cut per edge", "[bseries]") {
  for (int colours = 1; colours <= 2; ++colours) {
    const tree_set trees(colours == 1 ? 8 : 6, colours);
    for (int t = 0; t < trees.size(); ++t) {
      int edges = 0;
      for (const auto& cut : trees.cuts(t)) {
        REQUIRE(cut.root_part >= 0);
        REQUIRE(cut.cut_part >= 0);
        CHECK(trees[cut.root_part].order + trees[cut.cut_part].order == trees[t].order);
        CHECK(trees[cut.root_part].colour == trees[t].colour);
        edges += cut.multiplicity;
      }
      CHECK(edges == trees[t].order - 1);
    }
  }
  // [tau, [tau]]: cutting the lone leaf gives ([[tau]], tau), the top of [tau] gives
  // ([tau, tau], tau), the edge to [tau] gives ([tau], [tau]).
  const tree_set trees(4, 1);
  const int tau = trees.leaf(0), t2 = trees.find(0, {tau});
  const auto& cuts = trees.cuts(trees.find(0, {tau, t2}));
  REQUIRE(cuts.size() == 3);
  int found = 0;
  for (const auto& cut : cuts) {
    CHECK(cut.multiplicity == 1);
    found += (cut.root_part == trees.find(0, {t2}) && cut.cut_part == tau) +
             (cut.root_part == trees.find(0, {tau, tau}) && cut.cut_part == tau) +
             (cut.root_part == t2 && cut.cut_part == t2);
  }
  CHECK(found == 3);
}

TEST_CASE("bseries trees: the rkn and nystrom classes count as their generating functions", "[bseries]") {
  // Colour-1 roots (fat, HNW II.14): special Nystrom trees S(x) = x prod_k (1 - x^k)^(-B_k),
  // B(x) = x + x S(x) (a son is a colour-0 leaf or a colour-0 vertex over an S-tree); general
  // Nystrom trees F(x) = x prod_k (1 - x^k)^(-(F_k + M_k)), M(x) = x (1 + F(x)). A colour-0
  // root is alone (order 1) or over one colour-1 tree of the order below.
  const auto special = rooted_counts(16, [](int k, const std::vector<std::int64_t>& r) {
    return (k == 1 ? 1 : 0) + r[static_cast<std::size_t>(k - 1)];
  });
  const auto general = rooted_counts(9, [](int k, const std::vector<std::int64_t>& r) {
    return r[static_cast<std::size_t>(k)] + (k == 1 ? 1 : r[static_cast<std::size_t>(k - 1)]);
  });
  // The first counts as listed in analysis/nystrom_trees.hpp and bseries/nystrom_tree_set.hpp.
  CHECK(std::vector<std::int64_t>(special.begin() + 1, special.begin() + 9) == std::vector<std::int64_t>{1, 1, 2, 3, 6, 10, 20, 36});
  CHECK(std::vector<std::int64_t>(general.begin() + 1, general.begin() + 6) == std::vector<std::int64_t>{1, 2, 6, 18, 60});
  for (const auto& [kind, counts] : {std::pair{tree_class::rkn, special}, std::pair{tree_class::nystrom, general}}) {
    const tree_set trees(static_cast<int>(counts.size()) - 1, kind);
    CHECK(trees.kind() == kind);
    for (int n = 1; n <= trees.max_order(); ++n) {
      CHECK(trees.count(n, 1) == counts[static_cast<std::size_t>(n)]);
      CHECK(trees.count(n, 0) == (n == 1 ? 1 : counts[static_cast<std::size_t>(n) - 1]));
    }
  }
}

TEST_CASE("bseries trees: a class holds the trees is_nystrom_tree selects, with their sigma, gamma and cuts", "[bseries]") {
  const int order = 7;
  const tree_set all(order, 2);
  for (const tree_class kind : {tree_class::rkn, tree_class::nystrom}) {
    const bool velocity_free = kind == tree_class::rkn;
    const tree_set part(order, kind);
    // The tree of the full set equal to each tree of the class (subtrees come first).
    std::vector<int> in_all(static_cast<std::size_t>(part.size()), -1);
    for (int t = 0; t < part.size(); ++t) {
      std::vector<int> sons;
      for (int u : part[t].subtrees) sons.push_back(in_all[static_cast<std::size_t>(u)]);
      const int a = all.find(part[t].colour, sons);
      REQUIRE(a >= 0);
      in_all[static_cast<std::size_t>(t)] = a;
      CHECK(geomint::analysis::bseries::is_nystrom_tree(all, a, velocity_free));
      CHECK(all[a].order == part[t].order);
      CHECK(all[a].sigma == part[t].sigma);
      CHECK(all[a].gamma == part[t].gamma);
      // The same cuts: both parts in the class, mapped onto the full set's cuts of the tree.
      std::vector<std::pair<std::pair<int, int>, int>> mapped, expected;
      for (const auto& cut : part.cuts(t)) {
        REQUIRE(cut.root_part >= 0);
        REQUIRE(cut.cut_part >= 0);
        mapped.push_back({{in_all[static_cast<std::size_t>(cut.root_part)], in_all[static_cast<std::size_t>(cut.cut_part)]}, cut.multiplicity});
      }
      for (const auto& cut : all.cuts(a)) expected.push_back({{cut.root_part, cut.cut_part}, cut.multiplicity});
      std::sort(mapped.begin(), mapped.end());
      std::sort(expected.begin(), expected.end());
      CHECK(mapped == expected);
    }
    // Distinct trees, and every tree is_nystrom_tree selects is one of them.
    std::vector<int> sorted = in_all;
    std::sort(sorted.begin(), sorted.end());
    CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    int selected = 0;
    for (int a = 0; a < all.size(); ++a) selected += geomint::analysis::bseries::is_nystrom_tree(all, a, velocity_free);
    CHECK(selected == part.size());
  }
}

TEST_CASE("bseries trees: bad requests are refused with a reason", "[bseries]") {
  CHECK_THROWS_AS(tree_set(0, 1), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(15, 1), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(11, 2), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(3, 3), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(17, tree_class::rkn), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(11, tree_class::nystrom), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(11, tree_class::all), std::invalid_argument);
  const tree_set small(2, 1);
  CHECK_THROWS_AS(small.butcher_product(0, small.size()), std::out_of_range);
  CHECK_THROWS_AS(small.butcher_product(-1, 0), std::out_of_range);
}

}  // namespace bseries_trees_test
