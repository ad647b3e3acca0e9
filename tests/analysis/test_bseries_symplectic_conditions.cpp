/// The symplecticity conditions on the modified field's trees (include/geomint/analysis/
/// bseries/symplectic_conditions.hpp).
///
/// Independent sources: which Runge-Kutta methods are symplectic, from their tableaux: an RK
/// method is symplectic iff b_i a_ij + b_j a_ji = b_i b_j for all i, j (Hairer, Lubich, Wanner,
/// Geometric Numerical Integration, 2nd ed. 2006 (HLW), section VI.4), and then its modified
/// equation is Hamiltonian, b(u o v) + b(v o u) = 0 (HLW section IX.9.3). Explicit Euler is not:
/// its modified field has b([tau]) = -1/2 (HLW section IX.1), so the condition with
/// u = v = tau reads 2 b([tau]) = -1 != 0. For partitioned pairs, the symplectic ones of HLW
/// section VI.4 against non-symplectic pairs.
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

symplecticity_verdict verdict_of(const tree_set& trees, const tableau& method) {
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
  const tableau composed = composed_midpoint();
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
  CHECK(euler.failed == symplecticity_condition::butcher_products);
  CHECK(euler.u == trees.leaf(0));
  CHECK(euler.v == trees.leaf(0));
}

TEST_CASE("bseries symplectic conditions: partitioned pairs on P-trees", "[bseries]") {
  const tree_set trees(6, 2);
  const tableau implicit_euler = rk({q(1)}, {{q(1)}}, {q(1)});
  // Symplectic for every partitioned H (HLW section VI.4: b_i = bhat_i and
  // b_i ahat_ij + bhat_j a_ji = b_i bhat_j): Stormer-Verlet in both variants, Lobatto
  // IIIA-IIIB with s = 3, both symplectic Euler methods, and a symplectic RK method on both.
  const std::vector<tableau> symplectic = {
      pair_of(lobatto_iiib_2(), lobatto_iiia_2()), pair_of(lobatto_iiia_2(), lobatto_iiib_2()),
      pair_of(lobatto_iiia_3(), lobatto_iiib_3()), pair_of(implicit_euler, explicit_euler()),
      pair_of(explicit_euler(), implicit_euler),   pair_of(composed_midpoint(), composed_midpoint())};
  for (const auto& pair : symplectic) {
    const symplecticity_verdict verdict = verdict_of(trees, pair);
    CHECK(verdict.holds);
    CHECK(verdict.failed == symplecticity_condition::none);
  }
  // Not symplectic: Lobatto IIIA with s = 3 on both components (2 b_1 a_11 = 0 != b_1^2), so
  // some condition fails; explicit Euler on both: b(p[q]) = b(q[p]) = -1/2 (the one-colour
  // b([tau]) on either colouring), so b(p o q) + b(q o p) = -1 at order 2.
  CHECK_FALSE(verdict_of(trees, pair_of(lobatto_iiia_3(), lobatto_iiia_3())).holds);
  const symplecticity_verdict euler = verdict_of(trees, pair_of(explicit_euler(), explicit_euler()));
  CHECK_FALSE(euler.holds);
  CHECK(euler.failing_order == 2);
  CHECK(euler.failed == symplecticity_condition::butcher_products);
  // Weights that differ between the components: b = (1/2, 1/2) with A of Lobatto IIIA for p,
  // bhat = (1, 0) with Ahat = [[1/2, 0], [1/2, 0]] for q. Then a(p[p]) = b^T A 1 = 1/2 and
  // a(q[p]) = bhat^T A 1 = 0, so b(p[p]) = 1/2 - 1/2 = 0 != b(q[p]) = 0 - 1/2: the root-colour
  // condition fails at order 2.
  const tableau other_weights = rk({q(0), q(1)}, {{q(1, 2), q(0)}, {q(1, 2), q(0)}}, {q(1), q(0)});
  const symplecticity_verdict mixed = verdict_of(trees, pair_of(lobatto_iiia_2(), other_weights));
  CHECK_FALSE(mixed.holds);
  CHECK(mixed.failing_order == 2);
  CHECK(mixed.failed == symplecticity_condition::root_colour);
  CHECK(mixed.u == trees.find(0, {trees.leaf(0)}));
  CHECK(mixed.v == trees.find(1, {trees.leaf(0)}));
}

TEST_CASE("bseries symplectic conditions: bad input is refused with a reason", "[bseries]") {
  const tree_set one(3, 1);
  CHECK_THROWS_AS(check_symplecticity_conditions(one, std::vector<Q>(1)), std::invalid_argument);
}

}  // namespace bseries_symplectic_conditions_test
