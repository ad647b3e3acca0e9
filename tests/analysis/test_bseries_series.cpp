/// Exact B- and P-series of one step (include/geomint/analysis/bseries/series.hpp).
///
/// Independent sources: the published orders of the methods (Hairer, Norsett, Wanner, Solving
/// Ordinary Differential Equations I, 2nd ed. 1993 (HNW I), section II.1 (explicit Euler,
/// classical Runge-Kutta, order 1 and 4); Hairer, Wanner, Solving ODEs II, 2nd ed. 1996,
/// section IV.5 (Radau IIA s = 2, order 3; Lobatto IIIA s = 3, order 4; implicit midpoint =
/// Gauss s = 1, order 2); Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006
/// (HLW), section II.2 (the Lobatto IIIA-IIIB pairs: Stormer-Verlet for s = 2 (order 2),
/// order 4 for s = 3; symplectic Euler, order 1)), and elementary weights computed by hand
/// from the tableau (HLW section III.1: Phi(t) = b^T (prod of A g(subtrees))).
#include <stdexcept>
#include <vector>

#include "catch.hpp"
#include "bseries_methods.hpp"
#include "geomint/analysis/bseries/series.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_series_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;

TEST_CASE("bseries series: orders of Runge-Kutta methods from their elementary weights", "[bseries]") {
  const tree_set trees(6, 1);
  CHECK(series_order(trees, elementary_weights(trees, explicit_euler())) == 1);
  CHECK(series_order(trees, elementary_weights(trees, implicit_midpoint())) == 2);
  CHECK(series_order(trees, elementary_weights(trees, radau_iia_2())) == 3);
  CHECK(series_order(trees, elementary_weights(trees, lobatto_iiia_3())) == 4);
  CHECK(series_order(trees, elementary_weights(trees, classical_rk4())) == 4);
  CHECK(series_order(trees, exact_flow_coefficients<Q>(trees)) == 6);
}

TEST_CASE("bseries series: elementary weights and local errors by hand", "[bseries]") {
  const tree_set trees(4, 1);
  const int tau = trees.leaf(0), t2 = trees.find(0, {tau});
  const int cherry = trees.find(0, {tau, tau}), tall = trees.find(0, {t2});
  // Implicit midpoint, one stage a = c = 1/2, b = 1: Phi([tau]) = c = 1/2,
  // Phi([tau, tau]) = c^2 = 1/4, Phi([[tau]]) = a c = 1/4, Phi([[[tau]]]) = 1/8.
  const auto a = elementary_weights(trees, implicit_midpoint());
  CHECK(a[static_cast<std::size_t>(tau)] == q(1));
  CHECK(a[static_cast<std::size_t>(t2)] == q(1, 2));
  CHECK(a[static_cast<std::size_t>(cherry)] == q(1, 4));
  CHECK(a[static_cast<std::size_t>(tall)] == q(1, 4));
  CHECK(a[static_cast<std::size_t>(trees.find(0, {tall}))] == q(1, 8));
  // Local error of the midpoint rule: a - 1/gamma = 1/4 - 1/3 and 1/4 - 1/6.
  const auto err = local_error_coefficients(trees, a);
  CHECK(err[static_cast<std::size_t>(t2)] == q(0));
  CHECK(err[static_cast<std::size_t>(cherry)] == q(-1, 12));
  CHECK(err[static_cast<std::size_t>(tall)] == q(1, 12));
  // Explicit Euler: a(tau) = 1, a(t) = 0 for |t| >= 2.
  const auto euler = elementary_weights(trees, explicit_euler());
  for (int t = 1; t < trees.size(); ++t) CHECK(euler[static_cast<std::size_t>(t)] == q(0));
}

TEST_CASE("bseries series: orders of partitioned pairs from their P-series", "[bseries]") {
  const tree_set trees(5, 2);
  // Stormer-Verlet as the Lobatto IIIA-IIIB pair with s = 2, in both assignments of the
  // colours: order 2 exactly.
  CHECK(series_order(trees, elementary_weights(trees, pair_of(lobatto_iiib_2(), lobatto_iiia_2()))) == 2);
  CHECK(series_order(trees, elementary_weights(trees, pair_of(lobatto_iiia_2(), lobatto_iiib_2()))) == 2);
  // Lobatto IIIA-IIIB with s = 3: order 4 (each method alone is of order 4 on its own trees
  // too, but the pair mixes them on bi-coloured trees).
  CHECK(series_order(trees, elementary_weights(trees, pair_of(lobatto_iiia_3(), lobatto_iiib_3()))) == 4);
  // Symplectic Euler: implicit Euler for one component, explicit Euler for the other.
  const tableau implicit_euler = rk({q(1)}, {{q(1)}}, {q(1)});
  CHECK(series_order(trees, elementary_weights(trees, pair_of(implicit_euler, explicit_euler()))) == 1);
  // The same method on both components is the Runge-Kutta method: its P-series is its
  // B-series with the colours forgotten, so the order is that of the method.
  CHECK(series_order(trees, elementary_weights(trees, pair_of(radau_iia_2(), radau_iia_2()))) == 3);
}

TEST_CASE("bseries series: P-series weights by hand for Stormer-Verlet", "[bseries]") {
  // Colour 0 = p (Lobatto IIIB, A = [[1/2, 0], [1/2, 0]]), colour 1 = q (Lobatto IIIA,
  // A = [[0, 0], [1/2, 1/2]]), b = (1/2, 1/2). A p-rooted tree with one q-leaf:
  // b^T (Ahat 1) = 1/2 (0) + 1/2 (1) = 1/2; a q-rooted tree with one p-leaf: b^T (A 1) = 1/2;
  // a p-root over a q-vertex over a p-leaf: b^T (Ahat (A 1)) = 1/2 (1/2 (1/2) + 1/2 (1/2)) = 1/4.
  const tree_set trees(3, 2);
  const auto a = elementary_weights(trees, pair_of(lobatto_iiib_2(), lobatto_iiia_2()));
  const int p = trees.leaf(0), qq = trees.leaf(1);
  CHECK(a[static_cast<std::size_t>(trees.find(0, {qq}))] == q(1, 2));
  CHECK(a[static_cast<std::size_t>(trees.find(1, {p}))] == q(1, 2));
  CHECK(a[static_cast<std::size_t>(trees.find(0, {trees.find(1, {p})}))] == q(1, 4));
  // p-root over two q-leaves: b^T (Ahat 1)^2 = 1/2 (0) + 1/2 (1) = 1/2 (1/gamma = 1/3).
  CHECK(a[static_cast<std::size_t>(trees.find(0, {qq, qq}))] == q(1, 2));
}

TEST_CASE("bseries series: bad tableaux and tree sets are refused with a reason", "[bseries]") {
  const tree_set one(3, 1), two(3, 2);
  CHECK_THROWS_AS(elementary_weights(two, explicit_euler()), std::invalid_argument);
  CHECK_THROWS_AS(elementary_weights(one, pair_of(explicit_euler(), explicit_euler())), std::invalid_argument);
  tableau ragged = classical_rk4();
  ragged.a[2].pop_back();
  CHECK_THROWS_AS(elementary_weights(one, ragged), std::invalid_argument);
  CHECK_THROWS_AS(elementary_weights(two, pair_of(lobatto_iiia_2(), explicit_euler())), std::invalid_argument);
  CHECK_THROWS_AS(local_error_coefficients(one, std::vector<Q>(2)), std::invalid_argument);
}

}  // namespace bseries_series_test
