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
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/bseries/trees.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_trees_test {

using geomint::analysis::bseries::tree_set;

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

TEST_CASE("bseries trees: bad requests are refused with a reason", "[bseries]") {
  CHECK_THROWS_AS(tree_set(0, 1), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(15, 1), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(10, 2), std::invalid_argument);
  CHECK_THROWS_AS(tree_set(3, 3), std::invalid_argument);
  const tree_set small(2, 1);
  CHECK_THROWS_AS(small.butcher_product(0, small.size()), std::out_of_range);
  CHECK_THROWS_AS(small.butcher_product(-1, 0), std::out_of_range);
}

}  // namespace bseries_trees_test
