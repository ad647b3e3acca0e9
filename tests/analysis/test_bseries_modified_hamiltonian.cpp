/// Free trees and the modified Hamiltonian of a symplectic B-series method
/// (include/geomint/analysis/bseries/modified_hamiltonian.hpp).
///
/// Independent sources: the number of free trees per order (OEIS A000055: 1, 1, 1, 2, 3, 6, 11,
/// 23, 47, 106 for n = 1..10); the superfluous ones u o u exist only for even n and are one per
/// rooted tree u of order n/2 (the edge joining the halves is the tree's central edge, which is
/// unique, so u and the free tree determine each other): A000081(n/2) of them; automorphism
/// counts of paths (2) and stars ((n-1)!). The modified Hamiltonian of the implicit midpoint
/// rule to h^2, derived by hand from its printed modified equation (Hairer, Lubich, Wanner,
/// Geometric Numerical Integration, 2nd ed. 2006 (HLW), section IX.1)
///   f~ = f + h^2 (1/12 f'f'f - 1/24 f''(f,f)) + O(h^4),   f = J^{-1} grad H:
/// grad (H''(f,f)) = H'''(f,f) + 2 f'^T H'' f and f'^T = -H'' J^{-1}, so
/// J^{-1} grad (H''(f,f)) = f''(f,f) - 2 f'f'f, and f~ = J^{-1} grad H~ with
///   H~ = H - h^2/24 H''(f,f) + O(h^4)   (H''(f,f) = H([tau,tau]) = -H([[tau]])).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/modified_hamiltonian.hpp"
#include "geomint/analysis/bseries/series.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_modified_hamiltonian_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;

TEST_CASE("bseries modified Hamiltonian: free trees per order (OEIS A000055), superfluous ones, automorphisms", "[bseries]") {
  const tree_set trees(10, 1);
  const auto classes = free_trees(trees);
  const std::vector<int> free_count = {1, 1, 1, 2, 3, 6, 11, 23, 47, 106};
  const std::vector<int> rooted_count = {1, 1, 2, 4, 9};  // A000081, n = 1..5
  std::vector<int> found(11, 0), superfluous(11, 0), rooted_members(11, 0);
  for (const free_tree& theta : classes) {
    ++found[static_cast<std::size_t>(theta.order)];
    superfluous[static_cast<std::size_t>(theta.order)] += theta.superfluous;
    rooted_members[static_cast<std::size_t>(theta.order)] += static_cast<int>(theta.rooted.size());
    // n = sum over rooted trees of sigma(theta)/sigma(t), exactly.
    std::int64_t vertices_times_lcm = 0, lcm = 1;
    for (int t : theta.rooted) lcm = std::lcm(lcm, trees[t].sigma);
    for (int t : theta.rooted) vertices_times_lcm += theta.sigma * (lcm / trees[t].sigma);
    CHECK(vertices_times_lcm == theta.order * lcm);
  }
  for (int n = 1; n <= 10; ++n) {
    CHECK(found[static_cast<std::size_t>(n)] == free_count[static_cast<std::size_t>(n - 1)]);
    CHECK(superfluous[static_cast<std::size_t>(n)] == (n % 2 == 0 ? rooted_count[static_cast<std::size_t>(n / 2 - 1)] : 0));
    CHECK(rooted_members[static_cast<std::size_t>(n)] == trees.count(n));  // every rooted tree in one class
  }
  // Paths and stars.
  int path = trees.leaf(0), star_subtrees = 0;
  std::vector<int> leaves;
  std::int64_t factorial = 1;
  for (int n = 2; n <= 10; ++n) {
    path = trees.find(0, {path});
    leaves.push_back(trees.leaf(0));
    factorial *= ++star_subtrees;
    const int star = trees.find(0, leaves);
    for (const free_tree& theta : classes) {
      if (std::find(theta.rooted.begin(), theta.rooted.end(), path) != theta.rooted.end()) CHECK(theta.sigma == 2);
      if (n > 2 && std::find(theta.rooted.begin(), theta.rooted.end(), star) != theta.rooted.end()) CHECK(theta.sigma == factorial);
    }
  }
}

TEST_CASE("bseries modified Hamiltonian: implicit midpoint rule to h^2 (HLW IX.1)", "[bseries]") {
  const tree_set trees(7, 1);
  const auto terms = modified_hamiltonian(trees, modified_field(trees, elementary_weights(trees, implicit_midpoint())));
  const int tau = trees.leaf(0), cherry = trees.find(0, {tau, tau}), tall = trees.find(0, {trees.find(0, {tau})});
  REQUIRE(terms.size() >= 2);
  CHECK(terms[0].order == 1);
  CHECK(terms[0].tree == tau);
  CHECK(terms[0].coefficient == q(1));
  CHECK(terms[1].order == 3);
  // -1/24 H([tau,tau]) = +1/24 H([[tau]]).
  REQUIRE((terms[1].tree == cherry || terms[1].tree == tall));
  CHECK(terms[1].coefficient == (terms[1].tree == cherry ? q(-1, 24) : q(1, 24)));
  // Symmetric method: only even powers of h (HLW section IX.2), so only odd orders.
  for (const auto& term : terms) CHECK(term.order % 2 == 1);
  for (std::size_t i = 2; i < terms.size(); ++i) CHECK(terms[i].order >= 5);
}

TEST_CASE("bseries modified Hamiltonian: exists for a symplectic method, refused for explicit Euler", "[bseries]") {
  const tree_set trees(7, 1);
  // Two midpoint steps of sizes h/3 and 2h/3 (symplectic, HLW section VI.4; see
  // test_bseries_symplectic_conditions.cpp): an h^3 term (order 4) appears.
  const tableau composed = composed_midpoint();
  const auto b = modified_field(trees, elementary_weights(trees, composed));
  const auto terms = modified_hamiltonian(trees, b);
  // The h^3 term by hand: the order-4 free trees are the path (superfluous, [tau] o [tau]) and
  // the star, rooted as [tau,tau,tau] (sigma 6) or [[tau,tau]] (sigma 2). For H~ = ... +
  // h^3 c H'''(f,f,f): grad (H'''(f,f,f)) = H''''(f,f,f) + 3 f'^T H'''(f,f), f'^T = -H'' J^{-1},
  // so J^{-1} grad = f'''(f,f,f) - 3 f'f''(f,f): the field's coefficients are
  // b([tau,tau,tau])/6 = c and b([[tau,tau]])/2 = -3c.
  const int tau = trees.leaf(0);
  const int star_at_centre = trees.find(0, {tau, tau, tau}), star_at_leaf = trees.find(0, {trees.find(0, {tau, tau})});
  const Q c = b[static_cast<std::size_t>(star_at_centre)] / 6;
  CHECK(c != q(0));
  CHECK(b[static_cast<std::size_t>(star_at_leaf)] / 2 == -3 * c);
  int order_four = 0;
  for (const auto& term : terms) {
    if (term.order != 4) continue;
    ++order_four;
    REQUIRE((term.tree == star_at_centre || term.tree == star_at_leaf));
    // H([[tau,tau]]) = H'(f''(f,f)) = -H'''(f,f,f) (f = J^{-1} grad H, J^{-1} skew).
    CHECK(term.coefficient == (term.tree == star_at_centre ? c : -c));
  }
  CHECK(order_four == 1);
  CHECK_THROWS_AS(modified_hamiltonian(trees, modified_field(trees, elementary_weights(trees, explicit_euler()))), std::domain_error);
  CHECK_THROWS_AS(free_trees(tree_set(3, 2)), std::invalid_argument);
  const tree_set two(3, 2);
  CHECK_THROWS_AS(modified_hamiltonian(two, std::vector<Q>(static_cast<std::size_t>(two.size()))), std::invalid_argument);
}

}  // namespace bseries_modified_hamiltonian_test
