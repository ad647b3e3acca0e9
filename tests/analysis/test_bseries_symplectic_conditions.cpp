/// The symplecticity conditions on the modified field's trees (include/geomint/analysis/
/// bseries/symplectic_conditions.hpp).
///
/// Independent sources: which Runge-Kutta methods are symplectic, from their tableaux: an RK
/// method is symplectic iff b_i a_ij + b_j a_ji = b_i b_j for all i, j (Hairer, Lubich, Wanner,
/// Geometric Numerical Integration, 2nd ed. 2006 (HLW), section VI.4), and then its modified
/// equation is Hamiltonian, b(u o v) + b(v o u) = 0 (HLW section IX.9.3). Explicit Euler is not:
/// its modified field has b([tau]) = -1/2 (HLW section IX.1), so the condition with
/// u = v = tau reads 2 b([tau]) = -1 != 0.
#include <vector>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/bseries/symplectic_conditions.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_symplectic_conditions_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;

symplecticity_verdict verdict_of(const tree_set& trees, const rk_tableau<Q>& method) {
  return check_symplecticity_conditions(trees, modified_field(trees, elementary_weights(trees, method)));
}

TEST_CASE("bseries symplectic conditions: symplectic methods satisfy them up to order 8", "[bseries]") {
  const tree_set trees(8, 1);
  // Implicit midpoint (Gauss s = 1): b a + b a = 1/2 + 1/2 = 1 = b^2.
  const symplecticity_verdict midpoint = verdict_of(trees, implicit_midpoint());
  CHECK(midpoint.holds);
  CHECK(midpoint.checked_order == 8);
  CHECK(midpoint.failing_order == 0);
  // Two midpoint steps of sizes h/3 and 2h/3: A = [[1/6, 0], [1/3, 1/3]], b = (1/3, 2/3);
  // 2 b1 a11 = 1/9 = b1^2, b1 a12 + b2 a21 = 2/9 = b1 b2, 2 b2 a22 = 4/9 = b2^2. It has
  // order 2 but is not symmetric (its adjoint takes the steps in the other order), so its
  // modified field has an h^3 term (a method is symmetric iff its modified field has only even
  // powers of h, HLW section IX.2): the conditions are not met trivially by zeros.
  const rk_tableau<Q> composed = composed_midpoint();
  CHECK(verdict_of(trees, composed).holds);
  const auto b = modified_field(trees, elementary_weights(trees, composed));
  bool odd_power_term = false;
  for (int t = trees.first(4); t < trees.first(5); ++t) odd_power_term = odd_power_term || b[static_cast<std::size_t>(t)] != q(0);
  CHECK(odd_power_term);
}

TEST_CASE("bseries symplectic conditions: explicit Euler fails at order 2", "[bseries]") {
  const tree_set trees(6, 1);
  const symplecticity_verdict euler = verdict_of(trees, explicit_euler());
  CHECK_FALSE(euler.holds);
  CHECK(euler.failing_order == 2);
  CHECK(euler.u == trees.leaf(0));
  CHECK(euler.v == trees.leaf(0));
}

TEST_CASE("bseries symplectic conditions: bad input is refused with a reason", "[bseries]") {
  const tree_set one(3, 1), two(3, 2);
  CHECK_THROWS_AS(check_symplecticity_conditions(two, std::vector<Q>(static_cast<std::size_t>(two.size()))), std::invalid_argument);
  CHECK_THROWS_AS(check_symplecticity_conditions(one, std::vector<Q>(1)), std::invalid_argument);
}

}  // namespace bseries_symplectic_conditions_test
