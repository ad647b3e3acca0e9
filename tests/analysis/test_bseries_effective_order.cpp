/// The effective order (include/geomint/analysis/bseries/effective_order.hpp).
///
/// Independent sources: conjugate methods have the same effective order (chi^{-1} o Phi o chi
/// and Phi are processed into each other), so a method conjugated by an explicit Euler step
/// chi (chi^{-1}: implicit Euler with the opposite step), a Runge-Kutta method in its own right
/// of low classical order, keeps the classical order of Phi as an effective order at least; the
/// trapezoidal rule, conjugate to the implicit midpoint rule (HLW: Hairer, Lubich & Wanner,
/// Geometric Numerical Integration, 2nd ed. 2006, section VI.8); a method of order p has
/// effective order >= p. By hand: explicit Euler has effective order 1, since the h term of a
/// modified field, b([tau]) = -1/2 (HLW section IX.1), is unchanged by processing ([z, f] with z
/// on the single vertex is a multiple of [f, f] = 0).
#include <algorithm>
#include <vector>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/effective_order.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/series.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_effective_order_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;

TEST_CASE("bseries effective order: the processor's field brings the processed method to the order found", "[bseries]") {
  const tree_set trees(7, 1);
  for (const tableau& method : {explicit_euler(), implicit_midpoint(), classical_rk4(), radau_iia_2(), lobatto_iiia_3(),
                                conjugated(classical_rk4(), q(1, 3))}) {
    const auto b = modified_field_of(trees, method);
    const auto verdict = effective_order(trees, b);
    // The processed field e^{ad z} b, with the z found, is f on the trees up to the order found.
    const auto processed = processed_field(trees, verdict.processor, b);
    for (int t = 0; t < trees.first(verdict.order + 1); ++t) CHECK(processed[static_cast<std::size_t>(t)] == (trees[t].order == 1 ? q(1) : q(0)));
    CHECK(verdict.order >= series_order(trees, elementary_weights(trees, method)));
    CHECK_FALSE(verdict.processor_not_unique);
  }
}

TEST_CASE("bseries effective order: conjugate methods agree; explicit Euler by hand", "[bseries]") {
  const tree_set trees(7, 1);
  const auto euler = effective_order(trees, modified_field_of(trees, explicit_euler()));
  CHECK(euler.order == 1);
  CHECK_FALSE(euler.order_is_lower_bound);
  for (const tableau& method : {classical_rk4(), radau_iia_2(), implicit_midpoint(), composed_midpoint()}) {
    const auto own = effective_order(trees, modified_field_of(trees, method));
    for (const Q& theta : {q(1, 3), q(-1, 2)}) {
      const tableau other = conjugated(method, theta);
      // Of classical order 2 at most (chi = exp(theta h f - theta^2 h^2/2 f'f + ...), whose h^2
      // part does not commute with f): for RK4 and Radau IIA the verdict is not the classical order.
      const int classical = series_order(trees, elementary_weights(trees, method));
      CHECK(series_order(trees, elementary_weights(trees, other)) == std::min(classical, 2));
      const auto processed = effective_order(trees, modified_field_of(trees, other));
      CHECK(processed.order == own.order);
      CHECK(processed.order_is_lower_bound == own.order_is_lower_bound);
    }
  }
  // Trapezoidal rule and implicit midpoint rule (symmetric, order 2).
  const auto trapezoidal = effective_order(trees, modified_field_of(trees, lobatto_iiia_2()));
  CHECK(trapezoidal.order == effective_order(trees, modified_field_of(trees, implicit_midpoint())).order);
  CHECK(trapezoidal.order >= 2);
  // Two colours: a partitioned pair conjugated on both components alike has the effective
  // order of the pair.
  const tree_set pairs(5, 2);
  const auto own = effective_order(pairs, modified_field_of(pairs, pair_of(lobatto_iiia_3(), lobatto_iiib_3())));
  const auto other = effective_order(pairs, modified_field_of(pairs, pair_of(conjugated(lobatto_iiia_3(), q(1, 3)), conjugated(lobatto_iiib_3(), q(1, 3)))));
  CHECK(own.order >= 4);
  CHECK(other.order == own.order);
}

}  // namespace bseries_effective_order_test
