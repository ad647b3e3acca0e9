/// The N-trees of Nystrom methods (include/geomint/analysis/bseries/nystrom_tree_set.hpp).
///
/// Independent sources: the counts per order from the generating function of the N-trees (HNW:
/// Hairer, Norsett & Wanner, Solving ODEs I, section II.14: a fat root with a multiset of sons,
/// each fat or meagre; a meagre vertex alone or over one fat tree), evaluated here by its own
/// recurrence (Euler transform); the special counts of analysis/nystrom_trees.hpp (another
/// generator); the bi-coloured trees of trees.hpp (a third generator) that is_nystrom_tree
/// selects, tree by tree with their sigma and gamma; and the elementary weights of the partitioned
/// form of partitioned_form.hpp on those trees, for Nystrom's method and RK4 written as Nystrom
/// methods (HNW section II.14) and for Stormer-Verlet as an rkn method.
#include <cstdint>
#include <vector>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/nystrom_tree_set.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/nystrom_trees.hpp"
#include "geomint/methods/nystrom_form.hpp"

namespace bseries_nystrom_tree_set_test {

using namespace bseries_test_methods;
using geomint::analysis::bseries::nystrom_tree_set;
using geomint::analysis::bseries::tree_set;

/// Coefficients 1..n of the fat-rooted N-trees F(x) = x prod_k (1 - x^k)^(-(F_k + M_k)), with
/// M(x) = x (1 + F(x)) (general) or M(x) = x and F free of fat sons (velocity_free).
std::vector<std::int64_t> fat_counts(int n, bool velocity_free) {
  std::vector<std::int64_t> f(static_cast<std::size_t>(n) + 1, 0), m(static_cast<std::size_t>(n) + 1, 0);
  for (int k = 1; k <= n; ++k) {
    // Multisets of total order k - 1 of sons of kinds g_j = (fat?) f_j + m_j.
    std::vector<std::int64_t> ways(static_cast<std::size_t>(k), 0);
    ways[0] = 1;
    for (int j = 1; j < k; ++j) {
      const std::int64_t kinds = (velocity_free ? 0 : f[static_cast<std::size_t>(j)]) + m[static_cast<std::size_t>(j)];
      std::vector<std::int64_t> next(ways.size(), 0);
      for (int total = 0; total < k; ++total) {
        // choose r sons of order j among `kinds` kinds with repetition: C(kinds + r - 1, r)
        std::int64_t choose = 1;
        for (int r = 0; total + r * j < k; ++r) {
          if (r > 0) choose = choose * (kinds + r - 1) / r;
          next[static_cast<std::size_t>(total + r * j)] += ways[static_cast<std::size_t>(total)] * choose;
        }
      }
      ways = next;
    }
    f[static_cast<std::size_t>(k)] = ways[static_cast<std::size_t>(k - 1)];
    m[static_cast<std::size_t>(k)] = k == 1 ? 1 : f[static_cast<std::size_t>(k - 1)];
  }
  return f;
}

TEST_CASE("nystrom tree set: counts per order, general and special, against the generating functions", "[bseries]") {
  const nystrom_tree_set general(8, false), special(8, true);
  const std::vector<std::int64_t> f = fat_counts(8, false), fs = fat_counts(8, true);
  // The coefficients themselves, as a guard on the recurrence above.
  const std::vector<std::int64_t> expected_general = {1, 2, 6, 18, 60, 204, 730, 2664};
  const std::vector<std::int64_t> expected_special = {1, 1, 2, 3, 6, 10, 20, 36};
  for (int n = 1; n <= 8; ++n) {
    const auto k = static_cast<std::size_t>(n);
    CHECK(f[k] == expected_general[k - 1]);
    CHECK(fs[k] == expected_special[k - 1]);
    CHECK(general.count(n, true) == f[k]);
    CHECK(general.count(n, false) == (n == 1 ? 1 : f[k - 1]));
    CHECK(special.count(n, true) == fs[k]);
    CHECK(special.count(n, false) == (n == 1 ? 1 : fs[k - 1]));
    CHECK(special.count(n, true) == geomint::nystrom_tree_count(n));  // the special trees' own generator
  }
  CHECK_THROWS_AS(nystrom_tree_set(0, false), std::invalid_argument);
  CHECK_THROWS_AS(nystrom_tree_set(geomint::analysis::bseries::max_nystrom_tree_order + 1, false), std::invalid_argument);
}

/// The bi-coloured tree of trees.hpp (colour 1 fat, colour 0 meagre) of every N-tree.
std::vector<int> as_bicoloured(const nystrom_tree_set& n, const tree_set& two) {
  std::vector<int> map;
  for (int t = 0; t < n.size(); ++t) {
    std::vector<int> sons;
    for (int u : n[t].sons) sons.push_back(map[static_cast<std::size_t>(u)]);
    map.push_back(two.find(n[t].fat ? 1 : 0, sons));
  }
  return map;
}

TEST_CASE("nystrom tree set: the N-trees are the bi-coloured trees is_nystrom_tree selects, with their sigma and gamma", "[bseries]") {
  const tree_set two(7, 2);
  for (const bool velocity_free : {false, true}) {
    const nystrom_tree_set n(7, velocity_free);
    const std::vector<int> map = as_bicoloured(n, two);
    std::vector<int> hits(static_cast<std::size_t>(two.size()), 0);
    for (int t = 0; t < n.size(); ++t) {
      const int u = map[static_cast<std::size_t>(t)];
      REQUIRE(u >= 0);
      ++hits[static_cast<std::size_t>(u)];
      CHECK(two[u].order == n[t].order);
      CHECK(two[u].sigma == n[t].sigma);
      CHECK(two[u].gamma == n[t].gamma);
    }
    for (int u = 0; u < two.size(); ++u)
      CHECK(hits[static_cast<std::size_t>(u)] == (geomint::analysis::bseries::is_nystrom_tree(two, u, velocity_free) ? 1 : 0));
  }
}

TEST_CASE("nystrom tree set: elementary weights are those of the partitioned form on the same trees", "[bseries]") {
  using geomint::analysis::bseries::elementary_weights;
  using geomint::analysis::bseries::is_nystrom_tree;
  using geomint::analysis::bseries::partitioned_form_of;
  // Nystrom's method of order 4 (HNW section II.14), RK4 as a Nystrom method (order 4 on the
  // first-order form, methods/nystrom_form.hpp) and velocity Stormer-Verlet as an rkn (order 2).
  tableau nystrom4;
  nystrom4.kind = geomint::methods::method_kind::nystrom;
  nystrom4.stages = 4;
  nystrom4.c = {q(0), q(1, 2), q(1, 2), q(1)};
  nystrom4.a = {{q(0), q(0), q(0), q(0)}, {q(1, 8), q(0), q(0), q(0)}, {q(1, 8), q(0), q(0), q(0)}, {q(0), q(0), q(1, 2), q(0)}};
  nystrom4.ap = {{q(0), q(0), q(0), q(0)}, {q(1, 2), q(0), q(0), q(0)}, {q(0), q(1, 2), q(0), q(0)}, {q(0), q(0), q(1), q(0)}};
  nystrom4.bbar = {q(1, 6), q(1, 6), q(1, 6), q(0)};
  nystrom4.b = {q(1, 6), q(1, 3), q(1, 3), q(1, 6)};
  const tableau verlet = verlet_rkn();
  const struct {
    tableau method;
    int order;
  } cases[] = {{nystrom4, 4}, {classical_rk4(), 4}, {verlet, 2}};
  const tree_set two(6, 2);
  for (const auto& c : cases) {
    const auto form = geomint::methods::nystrom_form_of(c.method);
    const bool velocity_free = !form.has_velocity_stages;
    const nystrom_tree_set n(6, velocity_free);
    const std::vector<int> map = as_bicoloured(n, two);
    std::vector<bool> wanted(static_cast<std::size_t>(two.size()));
    for (int u = 0; u < two.size(); ++u) wanted[static_cast<std::size_t>(u)] = is_nystrom_tree(two, u, velocity_free);
    const auto reference = elementary_weights(two, partitioned_form_of(form), &wanted);
    const auto phi = elementary_weights(n, form);
    int order = n.max_order();
    for (int t = 0; t < n.size(); ++t) {
      CHECK(phi[static_cast<std::size_t>(t)] == reference[static_cast<std::size_t>(map[static_cast<std::size_t>(t)])]);
      if (order == n.max_order() && phi[static_cast<std::size_t>(t)] != Q(1) / Q(n[t].gamma)) order = n[t].order - 1;
    }
    CHECK(order == c.order);
  }
  // An rkn method has no weights on the general trees.
  CHECK_THROWS_AS(elementary_weights(nystrom_tree_set(3, false), geomint::methods::nystrom_form_of(verlet)), std::invalid_argument);
}

}  // namespace bseries_nystrom_tree_set_test
