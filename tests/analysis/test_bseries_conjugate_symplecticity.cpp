/// Conjugate symplecticity up to an order (include/geomint/analysis/bseries/
/// conjugate_symplecticity.hpp).
///
/// Independent sources: symplectic methods conserve their modified Hamiltonian exactly
/// (HLW: Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd ed. 2006, section IX.3);
/// the trapezoidal rule is conjugate to the implicit midpoint rule by half an explicit Euler
/// step (HLW section VI.8: Phi_trap = chi^{-1} o Phi_mid o chi, chi = explicit Euler with step
/// h/2), and in general chi^{-1} o Phi o chi is conjugate symplectic for a symplectic Phi; a
/// method of order p conserves H itself to O(h^(p+1)). Explicit Euler, by hand: its modified
/// field is f - h/2 f'f + O(h^2) (HLW section IX.1); the order-2 free tree is superfluous
/// (H'(f) = 0), so no h-term of H~ can be chosen, and dH/dt along f~ = -h/2 H'(f'f) + O(h^2) =
/// +h/2 H''(f,f) + O(h^2), not zero for the path of three vertices: r = 1, failing at order 3.
#include <vector>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/conjugate_symplecticity.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/bseries/symplectic_conditions.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_conjugate_symplecticity_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;

TEST_CASE("bseries conjugate symplecticity: symplectic and conjugate-symplectic methods to the order checked", "[bseries]") {
  const tree_set trees(8, 1);
  const std::vector<tableau> methods = {implicit_midpoint(), composed_midpoint(), lobatto_iiia_2(),
                                        conjugated(composed_midpoint(), q(1, 3)), conjugated(implicit_midpoint(), q(-2, 5))};
  for (std::size_t k = 0; k < methods.size(); ++k) {
    INFO("method " << k);
    const auto b = modified_field_of(trees, methods[k]);
    const conjugate_symplecticity_verdict v = conjugate_symplecticity(trees, b);
    CHECK(v.order_is_lower_bound);
    CHECK(v.order == 7);
    CHECK(v.checked_order == 7);
    CHECK(v.failing_free_tree == -1);
    // The last three are not symplectic: the verdict is not the symplecticity conditions.
    CHECK(check_symplecticity_conditions(trees, b).holds == (k < 2));
  }
  // The trapezoidal rule is Phi_mid conjugated by chi = half an explicit Euler step: the same
  // series (HLW section VI.8).
  CHECK(elementary_weights(trees, conjugated(implicit_midpoint(), q(1, 2))) == elementary_weights(trees, lobatto_iiia_2()));
  // Two colours: Lobatto IIIA-IIIB (symplectic) and IIIA on both components (the trapezoidal
  // rule, conjugate symplectic, HLW section VI.8).
  const tree_set pairs(6, 2);
  for (const tableau& pair : {pair_of(lobatto_iiia_3(), lobatto_iiib_3()), pair_of(lobatto_iiia_2(), lobatto_iiia_2())}) {
    const conjugate_symplecticity_verdict v = conjugate_symplecticity(pairs, modified_field_of(pairs, pair));
    CHECK(v.order_is_lower_bound);
    CHECK(v.order == 5);
  }
}

TEST_CASE("bseries conjugate symplecticity: RKN methods on the Nystrom trees", "[bseries]") {
  // Stormer-Verlet as an RKN tableau (HLW section I.1.4) is symplectic: on the Nystrom trees of
  // its partitioned form (natural H) a modified energy exists to every order checked. On all
  // trees the conversion's coefficients on the other trees say nothing about the method.
  const tree_set trees(6, 2);
  const tableau verlet = verlet_rkn();
  const auto nystrom = hamiltonian_trees(trees, hamiltonian_class::natural, 0);
  const auto b = modified_field_of(trees, partitioned_form_of(verlet));
  const conjugate_symplecticity_verdict v = conjugate_symplecticity(trees, b, &nystrom);
  CHECK(v.order_is_lower_bound);
  CHECK(v.order == 5);
  const std::vector<bool> too_few(3);
  CHECK_THROWS_AS(conjugate_symplecticity(trees, b, &too_few), std::invalid_argument);
}

TEST_CASE("bseries conjugate symplecticity: explicit Euler stops at 1; a method of order p reaches at least p", "[bseries]") {
  const tree_set trees(8, 1);
  const conjugate_symplecticity_verdict euler = conjugate_symplecticity(trees, modified_field_of(trees, explicit_euler()));
  CHECK_FALSE(euler.order_is_lower_bound);
  CHECK(euler.order == 1);
  const auto classes = free_trees(trees);
  REQUIRE(euler.failing_free_tree >= 0);
  CHECK(classes[static_cast<std::size_t>(euler.failing_free_tree)].order == 3);
  const struct {
    tableau method;
    int order;
  } cases[] = {{classical_rk4(), 4}, {radau_iia_2(), 3}, {lobatto_iiia_3(), 4}, {lobatto_iiib_3(), 4}};
  for (const auto& c : cases) CHECK(conjugate_symplecticity(trees, modified_field_of(trees, c.method)).order >= c.order);
}

}  // namespace bseries_conjugate_symplecticity_test
