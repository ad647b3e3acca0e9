/// The P-series of LPF as the collocation Nystrom method on q'' = F(q, q') (rkn_series.hpp,
/// collocation_nystrom_weights): the velocity-dependent Nystrom trees, by two independent routes.
///
/// - Against series.hpp on the partitioned form (partitioned_form.hpp) of the same Nystrom
///   method written as a tableau: LPF m = 3 on Gauss-interior nodes is the collocation method on
///   the two Gauss points; its c, a, bbar, b are those of examples/tableaux/gauss2.tableau
///   (Hairer, Norsett & Wanner, Solving ODEs I, section II.14) and its velocity stages
///   ap_ij = int_0^{c_i} l_j(u) du are the 2-stage Gauss Runge-Kutta matrix (1/4, 1/4 - sqrt3/6;
///   1/4 + sqrt3/6, 1/4) (Hairer, Lubich & Wanner, Geometric Numerical Integration, 2006,
///   Table II.1.1), written out below.
/// - The order conditions a(t) = 1/gamma(t) (exact flow, series.hpp): the collocation Nystrom
///   method on the s Gauss points has order 2s on q'' = F(q, q') (HNW section II.14, the
///   superconvergence of collocation), so every velocity-dependent Nystrom tree up to order 2s
///   satisfies them and some tree of order 2s + 1 does not.
#include <algorithm>
#include <sstream>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/rkn_series.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/methods/tableau_file.hpp"

namespace bseries_rkn_series_test {

using namespace geomint::analysis::bseries;
using geomint::methods::exact_rational;
using geomint::methods::field_element;

TEST_CASE("rkn series: LPF on F(q, q') against the partitioned form of its Nystrom tableau", "[bseries]") {
  std::istringstream text(
      "kind nystrom\nstages 2\nname lpf-gauss-interior-3\nfield r^2 - 3\n"
      "c    1/2-r/6   1/2+r/6\n"
      "a    1/36      5/36-r/12   5/36+r/12   1/36\n"
      "ap   1/4       1/4-r/6     1/4+r/6     1/4\n"
      "bbar 1/4+r/12  1/4-r/12\n"
      "b    1/2       1/2\n");
  const auto tableau = geomint::methods::read_tableau(text, "test");
  const tree_set trees(6, 2);
  const std::vector<bool> wanted = nystrom_trees(trees, false);
  const auto a = collocation_nystrom_weights(trees, geomint::lpf_tableau<3, geomint::gauss_interior>());
  const auto b = elementary_weights(trees, partitioned_form_of(tableau), &wanted);
  int compared = 0, velocity_dependent = 0;
  for (int t = 0; t < trees.size(); ++t) {
    const auto i = static_cast<std::size_t>(t);
    if (!wanted[i]) {
      CHECK(a[i] == exact_rational(0));
      continue;
    }
    INFO("tree " << t);
    CHECK(field_element(a[i]) == b[i]);
    ++compared;
    if (!is_nystrom_tree(trees, t, true)) ++velocity_dependent;
  }
  CHECK(velocity_dependent > 30);
  CHECK(compared > velocity_dependent);
}

template <int M>
void check_gauss_order() {
  constexpr int order = 2 * (M - 1);
  const tree_set trees(order + 1, 2);
  const std::vector<bool> wanted = nystrom_trees(trees, false);
  const auto a = collocation_nystrom_weights(trees, geomint::lpf_tableau<M, geomint::gauss_interior>());
  const auto exact = exact_flow_coefficients<exact_rational>(trees);
  bool defect_above = false;
  for (int t = 0; t < trees.size(); ++t) {
    const auto i = static_cast<std::size_t>(t);
    if (!wanted[i]) continue;
    INFO("m " << M << ", tree " << t << " of order " << trees[t].order);
    if (trees[t].order <= order) CHECK(a[i] == exact[i]);
    else defect_above = defect_above || a[i] != exact[i];
  }
  CHECK(defect_above);
}

TEST_CASE("rkn series: LPF on Gauss-interior nodes has order 2m - 2 on F(q, q')", "[bseries]") {
  check_gauss_order<2>();
  check_gauss_order<3>();
  check_gauss_order<4>();
}

TEST_CASE("rkn series: the velocity stages need a collocation tableau", "[bseries]") {
  CHECK_THROWS_AS(collocation_nystrom_weights(tree_set(3, 2), geomint::trapezoidal_tableau()), std::invalid_argument);
}

TEST_CASE("rkn series: the modified field on the rkn tree class equals the full set's on its Nystrom trees", "[bseries]") {
  // The same weights (rkn_series.hpp) and modified_field on two tree sets: all two-colour trees
  // masked by is_nystrom_tree, and tree_class::rkn generated directly. Only the tree generation
  // differs; the published values through the class set are checked by the CLI test
  // geomint_cli_modified_scheme_hamiltonian (Stormer-Verlet's modified Hamiltonian, HLW IX.3).
  const int order = 7;
  const tree_set all(order, 2), part(order, tree_class::rkn);
  const std::vector<bool> wanted = nystrom_trees(all);
  const std::vector<int> same = indices_in(part, all);
  REQUIRE(static_cast<int>(same.size()) == part.size());
  CHECK(part.size() == static_cast<int>(std::count(wanted.begin(), wanted.end(), true)));
  const auto check = [&](const geomint::exact_rkn_tableau& method) {
    const auto b_all = modified_field(all, elementary_weights(all, method));
    const auto b_part = modified_field(part, elementary_weights(part, method));
    int nonzero = 0;
    for (int t = 0; t < part.size(); ++t) {
      const auto u = static_cast<std::size_t>(same[static_cast<std::size_t>(t)]);
      REQUIRE(wanted[u]);
      CHECK(b_part[static_cast<std::size_t>(t)] == b_all[u]);
      nonzero += part[t].order > 1 && !(b_part[static_cast<std::size_t>(t)] == exact_rational(0));
    }
    CHECK(nonzero > 0);
  };
  check(geomint::trapezoidal_tableau());                          // Stormer-Verlet
  check(geomint::lpf_tableau<3, geomint::gauss_interior>());
}

}  // namespace bseries_rkn_series_test
