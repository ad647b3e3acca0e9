/// The exact order and symplecticity of tableaux of every kind (analysis/bseries/
/// method_analysis.hpp, partitioned_form.hpp), from the same data the integrator runs: the
/// example tableau files, RK4 and Nystrom's method written as files, against their published
/// orders; the partitioned form of Stormer-Verlet against Lobatto IIIA-IIIB; and the order of
/// the library's schemes against the independent RKN analysis (analysis/order_conditions.hpp).
#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/method_analysis.hpp"
#include "geomint/analysis/order_conditions.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/analysis/scheme_structure.hpp"
#include "geomint/methods/tableau_file.hpp"

namespace bseries_method_analysis_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;
using geomint::methods::field_element;

geomint::methods::tableau_data<field_element> example(const std::string& file) {
  return geomint::methods::read_tableau_file(std::string(GEOMINT_SOURCE_DIR) + "/examples/tableaux/" + file);
}
geomint::methods::tableau_data<field_element> from_text(const std::string& text) {
  std::istringstream in(text);
  return geomint::methods::read_tableau(in, "test.tableau");
}

TEST_CASE("bseries method analysis: the example tableau files", "[bseries]") {
  // Published orders and symplecticity (the files' headers): Stormer-Verlet order 2 (HLW
  // section I.1.4), Gauss s = 2 order 4 (HLW section II.1.4), Forest-Ruth order 4 (Forest &
  // Ruth, Physica D 43 (1990) 105-117); all three symplectic (HLW Theorem VI.4.10 and VI.4).
  const struct {
    const char* file;
    int order;
  } cases[] = {{"stormer_verlet.tableau", 2}, {"gauss2.tableau", 4}, {"forest_ruth.tableau", 4}};
  for (const auto& c : cases) {
    INFO(c.file);
    const method_analysis r = analyse_method(example(c.file));
    CHECK(r.order == c.order);
    CHECK_FALSE(r.order_is_lower_bound);
    CHECK(r.colours == 2);
    CHECK(r.tree_order == 8);
    CHECK(r.symplectic);
  }
}

TEST_CASE("bseries method analysis: RK4, Gauss RK and Nystrom's method written as files", "[bseries]") {
  // Classical RK4: order 4 (HNW I, section II.1, Table 1.2), not symplectic (b_i a_ij + b_j a_ji
  // = b_i b_j fails at i = j = 1: 0 != 1/36; HLW Theorem VI.4.3).
  const method_analysis rk4 = analyse_method(from_text(
      "kind rk\nstages 4\nc 0 1/2 1/2 1\n"
      "a 0 0 0 0  1/2 0 0 0  0 1/2 0 0  0 0 1 0\nb 1/6 1/3 1/3 1/6\n"));
  CHECK(rk4.order == 4);
  CHECK(rk4.colours == 1);
  CHECK(rk4.tree_order == 10);
  CHECK_FALSE(rk4.symplectic);
  // Gauss RK s = 2 over Q(sqrt 3): order 4 (HLW section II.1.4), symplectic (HLW Theorem VI.4.3).
  const method_analysis gauss = analyse_method(from_text(
      "kind rk\nstages 2\nfield r^2 - 3\nc 1/2-r/6 1/2+r/6\n"
      "a 1/4 1/4-r/6  1/4+r/6 1/4\nb 1/2 1/2\n"));
  CHECK(gauss.order == 4);
  CHECK(gauss.symplectic);
  // Nystrom's method (Nystrom 1925; HNW I, section II.14): order 4; not symplectic
  // (b_1 (bbar_2 - a_12) = 1/36 != b_2 (bbar_1 - a_21) = 1/72).
  const method_analysis nystrom = analyse_method(from_text(
      "kind rkn\nstages 4\nc 0 1/2 1/2 1\n"
      "a 0 0 0 0  1/8 0 0 0  1/8 0 0 0  0 0 1/2 0\nbbar 1/6 1/6 1/6 0\nb 1/6 1/3 1/3 1/6\n"));
  CHECK(nystrom.order == 4);
  CHECK_FALSE(nystrom.symplectic);
  // Lobatto IIIA-IIIB s = 3 as a prk pair: order 4, symplectic (HLW sections II.2.2, VI.4);
  // P-trees up to order 6 (the modified field on all P-trees of order 8 takes seconds).
  const method_analysis pair = analyse_method(pair_of(lobatto_iiia_3(), lobatto_iiib_3()), 10, 6);
  CHECK(pair.order == 4);
  CHECK(pair.symplectic);
}

TEST_CASE("bseries method analysis: the order of each component", "[bseries]") {
  // One-stage RKN methods, expanded by hand against q(h) = q + h v + h^2/2 f + h^3/6 f'v + ...,
  // v(h) = v + h f + h^2/2 f'v + h^3/6 (f''(v, v) + f'f) + ...:
  // c = 0, bbar = 1/2, b = 1: q1 = q + h v + h^2/2 f (error h^3/6 f'v: position order 2),
  // v1 = v + h f (error h^2/2 f'v: velocity order 1); the method's order is 1.
  const method_analysis kick = analyse_method(from_text("kind rkn\nstages 1\nc 0\na 0\nbbar 1/2\nb 1\n"));
  CHECK(kick.component_order == std::array<int, 2>{2, 1});
  CHECK(kick.component_order_is_lower_bound == std::array<bool, 2>{false, false});
  CHECK(kick.order == 1);
  // c = 1/2: v1 = v + h f(q + h/2 v) = v + h f + h^2/2 f'v + h^3/8 f''(v, v) (velocity order 2),
  // q1 = q + h v + h^2/2 f + h^3/4 f'v (position order 2).
  const method_analysis mid = analyse_method(from_text("kind rkn\nstages 1\nc 1/2\na 0\nbbar 1/2\nb 1\n"));
  CHECK(mid.component_order == std::array<int, 2>{2, 2});
  CHECK(mid.order == 2);
  // One component for rk: RK4 (order 4, HNW I, Table II.1.2) in both entries.
  const method_analysis rk4 = analyse_method(from_text(
      "kind rk\nstages 4\nc 0 1/2 1/2 1\n"
      "a 0 0 0 0  1/2 0 0 0  0 1/2 0 0  0 0 1 0\nb 1/6 1/3 1/3 1/6\n"));
  CHECK(rk4.component_order == std::array<int, 2>{4, 4});
  // A prk pair whose stages are Heun's on both components, with Euler's update on q (b = (1, 0))
  // and Heun's on p: q1 = q + h f(q, p) is first order, p1 = p + h/2 (g(q, p) + g(q + h f, p + h g))
  // is Heun's method on (q, p), second order (HNW I, section II.1); the method's order is 1.
  const method_analysis coupled = analyse_method(from_text(
      "kind prk\nstages 2\nc 0 1\na 0 0 1 0\nb 1 0\nahat 0 0 1 0\nbhat 1/2 1/2\n"));
  CHECK(coupled.component_order == std::array<int, 2>{1, 2});
  CHECK(coupled.order == 1);
}

TEST_CASE("bseries series: the fixed-size methods:: tableaux give the series of their run-time data", "[bseries]") {
  // The implicit midpoint rule (HLW section II.1.1) as methods::rk<Q, 1> and as tableau_data;
  // a one-stage prk pair of it on both components.
  const geomint::methods::rk<Q, 1> midpoint{{q(1, 2)}, {{{q(1, 2)}}}, {q(1)}};
  const tree_set one(5, 1), two(4, 2);
  CHECK(elementary_weights(one, midpoint) == elementary_weights(one, implicit_midpoint()));
  const geomint::methods::prk<Q, 1> pair{{q(1, 2)}, {{{q(1, 2)}}}, {q(1)}, {{{q(1, 2)}}}, {q(1)}};
  CHECK(elementary_weights(two, pair) == elementary_weights(two, pair_of(implicit_midpoint(), implicit_midpoint())));
  CHECK_THROWS_AS(elementary_weights(two, geomint::methods::data_of(midpoint)), std::invalid_argument);
}

TEST_CASE("bseries method analysis: a composition through its Nystrom form", "[bseries]") {
  // Yoshida's triple jump of Stormer-Verlet over Q(2^(1/3)), gamma = (1, -r, 1)/(2 - r): order 4
  // (Yoshida, Phys. Lett. A 150 (1990) 262-268; HLW section II.4), symplectic (a composition of
  // symplectic maps); two half steps of Stormer-Verlet: order 2, symplectic.
  using geomint::methods::algebraic_field;
  const auto verlet = example("stormer_verlet.tableau");
  const auto base = geomint::methods::nystrom_form_of(verlet);
  const field_element r = field_element::generator(algebraic_field::make({-2, 0, 0, 1}));
  const field_element one(1), two(2);
  const method_analysis jump = analyse_method(geomint::methods::compose(base, {one / (two - r), -r / (two - r), one / (two - r)}));
  CHECK(jump.order == 4);
  CHECK(jump.symplectic);
  const method_analysis halves = analyse_method(geomint::methods::compose(base, {one / two, one / two}));
  CHECK(halves.order == 2);
  CHECK(halves.symplectic);
}

TEST_CASE("bseries partitioned form: Stormer-Verlet as an RKN is Lobatto IIIA-IIIB on the Nystrom trees", "[bseries]") {
  // Stormer-Verlet as an RKN (HLW section I.1.4) and as the pair Lobatto IIIA (q) - IIIB (v)
  // (HLW section II.2.2) are the same map on q' = v, v' = f(q): their P-series agree on every
  // tree whose elementary differential does not vanish there.
  const tableau verlet = verlet_rkn();
  const tree_set trees(7, 2);  // 2 x 2 659 P-trees (to order 8: 2 x 12 157, the cost of this check x 4.6)
  const auto converted = elementary_weights(trees, partitioned_form_of(verlet));
  const auto lobatto = elementary_weights(trees, pair_of(lobatto_iiia_2(), lobatto_iiib_2()));
  int compared = 0, differing_elsewhere = 0;
  for (int t = 0; t < trees.size(); ++t) {
    const auto k = static_cast<std::size_t>(t);
    if (is_nystrom_tree(trees, t, true)) {
      ++compared;
      CHECK(converted[k] == lobatto[k]);
    } else {
      differing_elsewhere += converted[k] != lobatto[k];
    }
  }
  // The Nystrom trees up to order 7 with both root colours; the remaining trees carry
  // coefficients of the conversion, not of the method (some differ).
  CHECK(compared > 2 * 7);
  CHECK(differing_elsewhere > 0);
  // The one-vertex trees and the tree q[v] (the q-component of h^2/2 f) are Nystrom trees; q[q]
  // (f_q f, zero for f = v) is not.
  CHECK(is_nystrom_tree(trees, trees.find(0, {trees.leaf(1)}), true));
  CHECK_FALSE(is_nystrom_tree(trees, trees.find(0, {trees.leaf(0)}), true));
  CHECK_FALSE(is_nystrom_tree(trees, trees.find(1, {trees.leaf(1)}), true));
  CHECK(is_nystrom_tree(trees, trees.find(1, {trees.leaf(1)}), false));
}

TEST_CASE("bseries method analysis: library schemes agree with the RKN order conditions", "[bseries]") {
  using namespace geomint;
  // Equispaced LPF: interior nodes a/m (the LPF paper's eq. 8); midpoint and trapezoidal keep
  // their stage values.
  const struct {
    const char* name;
    exact_rkn_tableau t;
    std::vector<Q> nodes;
  } schemes[] = {{"midpoint", midpoint_tableau(), {}},
                 {"trapezoidal", trapezoidal_tableau(), {}},
                 {"lpf m=2 equispaced", lpf_tableau<2, equispaced>(), {q(1, 2)}},
                 {"lpf m=3 equispaced", lpf_tableau<3, equispaced>(), {q(1, 3), q(2, 3)}},
                 {"lpf m=4 equispaced", lpf_tableau<4, equispaced>(), {q(1, 4), q(1, 2), q(3, 4)}}};
  for (const auto& s : schemes) {
    INFO(s.name);
    const order_summary independent = order_analysis(s.t);
    REQUIRE_FALSE(independent.order_is_lower_bound);
    REQUIRE((s.t.basis == stage_basis::values || static_cast<int>(s.nodes.size()) == s.t.stages));
    const method_analysis r = analyse_method(numeric_tableau<Q>(s.t, s.nodes.data()));
    CHECK(r.order == independent.order);
    CHECK(r.symplectic == symplecticity(s.t).symplectic);
  }
}

}  // namespace bseries_method_analysis_test
