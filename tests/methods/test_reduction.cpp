/// The irreducible form of a tableau (methods/reduction.hpp): DJ- and S-reduction (Hairer &
/// Wanner, Solving ODEs II, section IV.12). Expected values by hand from the definitions: the
/// stages a reduction drops or merges are equal on every problem, so the reduced tableau is the
/// one written out below, and a method with no equal stages is returned as it is.
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/methods/reduction.hpp"
#include "geomint/methods/tableau_file.hpp"

namespace reduction_test {

using geomint::methods::field_element;
using geomint::methods::irreducible_form;
using geomint::methods::method_kind;
using geomint::methods::tableau_data;

tableau_data<field_element> from_text(const std::string& text) {
  std::istringstream in(text);
  return geomint::methods::read_tableau(in, "test.tableau");
}
field_element q(long p, long d) { return field_element(p) / field_element(d); }

TEST_CASE("reduction: Lobatto IIIB, s = 2, is the implicit midpoint rule", "[methods]") {
  // Both rows of A are (1/2, 0): the stages are equal (S-reduction); merged, a = 1/2, b = 1
  // and c = 1/2 (the published c = 0, 1 differ, so the merged stage takes its row sum).
  const auto r = irreducible_form(from_text("kind rk\nstages 2\nc 0 1\na 1/2 0 1/2 0\nb 1/2 1/2\n"));
  REQUIRE(r.method.stages == 1);
  CHECK(r.method.kind == method_kind::rk);
  CHECK(r.method.a[0][0] == q(1, 2));
  CHECK(r.method.b[0] == field_element(1));
  CHECK(r.method.c[0] == q(1, 2));
  CHECK(r.stage_of == std::vector<int>{0, 0});
}

TEST_CASE("reduction: an unused stage is dropped, weights that cancel on merging too", "[methods]") {
  // Heun's method with a third stage that nothing uses (b_3 = 0, column 3 zero): DJ-reducible.
  const auto heun = irreducible_form(from_text("kind rk\nstages 3\nc 0 1 1/2\na 0 0 0  1 0 0  1/2 0 0\nb 1/2 1/2 0\n"));
  REQUIRE(heun.method.stages == 2);
  CHECK(heun.method.a[1][0] == field_element(1));
  CHECK(heun.method.b == std::vector<field_element>{q(1, 2), q(1, 2)});
  CHECK(heun.stage_of == std::vector<int>{0, 1, -1});
  // Stages 1 and 2 are equal (zero rows, weights 1/2 and -1/2): merged, their weight is 0 and
  // stage 3 (a_33 = 1/2) does not use them, so they go: the implicit midpoint rule.
  const auto cancel = irreducible_form(from_text("kind rk\nstages 3\nc 0 0 1/2\na 0 0 0  0 0 0  0 0 1/2\nb 1/2 -1/2 1\n"));
  REQUIRE(cancel.method.stages == 1);
  CHECK(cancel.method.a[0][0] == q(1, 2));
  CHECK(cancel.method.b[0] == field_element(1));
  CHECK(cancel.stage_of == std::vector<int>{-1, -1, 0});
}

TEST_CASE("reduction: rkn stages merge only with equal nodes", "[methods]") {
  // Stormer-Verlet with its second stage written twice (c = 1, the same row, weights 1/4 + 1/4).
  const auto verlet = irreducible_form(from_text(
      "kind rkn\nstages 3\nc 0 1 1\na 0 0 0  1/2 0 0  1/2 0 0\nbbar 1/2 0 0\nb 1/2 1/4 1/4\n"));
  REQUIRE(verlet.method.stages == 2);
  CHECK(verlet.method.c == std::vector<field_element>{field_element(0), field_element(1)});
  CHECK(verlet.method.a[1][0] == q(1, 2));
  CHECK(verlet.method.bbar == std::vector<field_element>{q(1, 2), field_element(0)});
  CHECK(verlet.method.b == std::vector<field_element>{q(1, 2), q(1, 2)});
  CHECK(verlet.stage_of == std::vector<int>{0, 1, 1});
  // Equal (zero) rows but c = 0 and 1: Q_1 = q and Q_2 = q + h v differ, nothing merges.
  const auto apart = irreducible_form(from_text("kind rkn\nstages 2\nc 0 1\na 0 0 0 0\nbbar 1/2 0\nb 1/2 1/2\n"));
  CHECK(apart.method.stages == 2);
}

TEST_CASE("reduction: a prk pair merges only stages equal in both tableaux", "[methods]") {
  // Lobatto IIIA-IIIB, s = 2: IIIB's rows are equal, IIIA's are not (row sums 0 and 1).
  const auto pair = irreducible_form(from_text(
      "kind prk\nstages 2\nc 0 1\na 0 0 1/2 1/2\nb 1/2 1/2\nahat 1/2 0 1/2 0\nbhat 1/2 1/2\n"));
  CHECK(pair.method.stages == 2);
  CHECK(pair.stage_of == std::vector<int>{0, 1});
  // Gauss s = 2 (c = 1/2 -+ sqrt 3 / 6; HLW section II.1.3) is irreducible: returned as it is.
  const auto gauss = from_text(
      "kind rk\nstages 2\nfield r^2 - 3\nc 1/2-r/6 1/2+r/6\na 1/4 1/4-r/6 1/4+r/6 1/4\nb 1/2 1/2\n");
  const auto same = irreducible_form(gauss);
  CHECK(same.method.stages == 2);
  CHECK(same.method.a == gauss.a);
  CHECK(same.method.b == gauss.b);
  CHECK(same.method.c == gauss.c);
}

TEST_CASE("reduction: inconsistent arrays are errors; a method without weights has no stage", "[methods]") {
  auto t = from_text("kind rk\nstages 2\nc 0 1\na 0 0 1 0\nb 1/2 1/2\n");
  t.b.pop_back();
  CHECK_THROWS_AS(irreducible_form(t), std::invalid_argument);
  // b = 0: y1 = y0 whatever the stages are, so every stage goes.
  const auto none = irreducible_form(from_text("kind rk\nstages 2\nc 0 1\na 0 0 1 0\nb 0 0\n"));
  CHECK(none.method.stages == 0);
  CHECK(none.stage_of == std::vector<int>{-1, -1});
}

TEST_CASE("reduction: a reducible method is symmetric when its irreducible method is", "[methods]") {
  // An rkn tableau with zero weights is the free drift q1 = q + h v, v1 = v, whose adjoint is
  // itself; its one printed stage (c = 0) has no mirror (c* = 1), so only the reduction shows it.
  const auto drift = from_text("kind rkn\nstages 1\nc 0\na 0\nbbar 0\nb 0\n");
  CHECK_FALSE(geomint::is_symmetric(drift));
  CHECK(geomint::verdicts(drift).symmetric);
  // Heun's method with an unused third stage is as unsymmetric as Heun's method.
  CHECK_FALSE(geomint::verdicts(from_text("kind rk\nstages 3\nc 0 1 1/2\na 0 0 0  1 0 0  1/2 0 0\nb 1/2 1/2 0\n")).symmetric);
}

}  // namespace reduction_test
