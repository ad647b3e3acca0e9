/// The exact symplecticity conditions of a tableau on its irreducible method
/// (analysis/tableau_symplecticity.hpp), against two independent sources: the defects worked out
/// by hand from the printed coefficients, and, for every rk and prk method of the catalogue, the
/// tree conditions on its modified field (analysis/bseries/symplectic_conditions.hpp; HLW
/// section IX.9.3), which decide symplecticity order by order without the algebraic conditions;
/// and, for every method of the catalogue, the numerical defect max |J^T Omega J - Omega| of one
/// step of the method itself through the integrator (analysis/symplecticity.hpp).
#include <algorithm>
#include <limits>
#include <sstream>
#include <string>

#include "catch.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/bseries/symplectic_conditions.hpp"
#include "geomint/analysis/tableau_symplecticity.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "geomint/methods/tableau_stepper.hpp"
#include "scalar_types.hpp"

namespace tableau_symplecticity_test {

using geomint::analysis::symplecticity_conditions;
using geomint::methods::field_element;
using geomint::methods::method_kind;

geomint::methods::tableau_data<field_element> from_text(const std::string& text) {
  std::istringstream in(text);
  return geomint::methods::read_tableau(in, "test.tableau");
}
field_element q(long p, long d) { return field_element(p) / field_element(d); }

TEST_CASE("tableau symplecticity: the defects of printed methods, by hand", "[analysis]") {
  // RK4 (HNW I, Table II.1.2): M_11 = 2 b_1 a_11 - b_1^2 = -1/36.
  const auto rk4 = symplecticity_conditions(from_text(
      "kind rk\nstages 4\nc 0 1/2 1/2 1\na 0 0 0 0  1/2 0 0 0  0 1/2 0 0  0 0 1 0\nb 1/6 1/3 1/3 1/6\n"));
  CHECK_FALSE(rk4.symplectic);
  CHECK(rk4.irreducible_stages == 4);
  CHECK(rk4.defect_i == 0);
  CHECK(rk4.defect_j == 0);
  CHECK(rk4.defect[0][0] == q(-1, 36));
  // The trapezoidal rule as Lobatto IIIA, s = 2: M_11 = -b_1^2 = -1/4, M_12 = b_2 a_21 - b_1 b_2 = 0,
  // M_22 = 2 b_2 a_22 - b_2^2 = 1/4.
  const auto trapezoidal = symplecticity_conditions(from_text("kind rk\nstages 2\nc 0 1\na 0 0 1/2 1/2\nb 1/2 1/2\n"));
  CHECK_FALSE(trapezoidal.symplectic);
  CHECK(trapezoidal.defect[0][0] == q(-1, 4));
  CHECK(trapezoidal.defect[0][1] == field_element(0));
  CHECK(trapezoidal.defect[1][1] == q(1, 4));
  // Lobatto IIIB, s = 2, as printed: M_11 = 2 (1/2)(1/2) - 1/4 = 1/4 != 0; but its irreducible
  // method is the implicit midpoint rule, 2 (1)(1/2) - 1 = 0: symplectic.
  const auto iiib = symplecticity_conditions(from_text("kind rk\nstages 2\nc 0 1\na 1/2 0 1/2 0\nb 1/2 1/2\n"));
  CHECK(iiib.symplectic);
  CHECK(iiib.irreducible_stages == 1);
  // Symplectic Euler as a prk pair (A = 1 implicit, Ahat = 0 explicit; HLW Theorem VI.3.3):
  // b_1 ahat_11 + bhat_1 a_11 - b_1 bhat_1 = 0 + 1 - 1 = 0 and b = bhat.
  const auto euler = symplecticity_conditions(from_text("kind prk\nstages 1\nc 0\na 1\nb 1\nahat 0\nbhat 1\n"));
  CHECK(euler.symplectic);
  CHECK(euler.separable);
  // The same pair with bhat = 2 is not even consistent in p, and b = bhat fails: b_1 - bhat_1 = -1.
  const auto unequal = symplecticity_conditions(from_text("kind prk\nstages 1\nc 0\na 1\nb 1\nahat 0\nbhat 2\n"));
  CHECK_FALSE(unequal.symplectic);
  CHECK(unequal.weight_defect_i == 0);
  CHECK(unequal.weight_defect[0] == field_element(-1));
  // Nystrom's method (HNW I, section II.14) on q'' = f(q): its stages 2 and 3 are equal (c = 1/2,
  // rows (1/8, 0, 0, 0)), so its irreducible method has c = (0, 1/2, 1), a_21 = 1/8, a_32 = 1/2,
  // bbar = (1/6, 1/3, 0), b = (1/6, 2/3, 1/6), and b_1 (bbar_2 - a_12) - b_2 (bbar_1 - a_21)
  // = (1/6)(1/3) - (2/3)(1/6 - 1/8) = 1/18 - 1/36 = 1/36; bbar_i = b_i (1 - c_i) holds.
  const auto nystrom = symplecticity_conditions(from_text(
      "kind rkn\nstages 4\nc 0 1/2 1/2 1\na 0 0 0 0  1/8 0 0 0  1/8 0 0 0  0 0 1/2 0\nbbar 1/6 1/6 1/6 0\nb 1/6 1/3 1/3 1/6\n"));
  CHECK_FALSE(nystrom.symplectic);
  CHECK(nystrom.irreducible_stages == 3);
  CHECK(nystrom.weight_defect_i == -1);
  CHECK(nystrom.defect_i == 0);
  CHECK(nystrom.defect_j == 1);
  CHECK(nystrom.defect[0][1] == q(1, 36));
  // Stormer-Verlet as a nystrom tableau with a velocity matrix: Ap does not enter on q'' = f(q).
  const auto verlet = symplecticity_conditions(from_text(
      "kind nystrom\nstages 2\nc 0 1\na 0 0 1/2 0\nap 0 0 1/2 1/2\nbbar 1/2 0\nb 1/2 1/2\n"));
  CHECK(verlet.symplectic);
  // Zero weights: the step is y1 = y0, symplectic, on no stage at all.
  const auto identity = symplecticity_conditions(from_text("kind rk\nstages 2\nc 0 1\na 0 0 1 0\nb 0 0\n"));
  CHECK(identity.symplectic);
  CHECK(identity.irreducible_stages == 0);
}

TEST_CASE("tableau symplecticity: every rk and prk method of the catalogue agrees with the tree conditions", "[analysis]") {
  using namespace geomint::analysis::bseries;
  // The tree conditions up to an order hold for a symplectic method and, for a method that is
  // not, fail at some order: checked to the orders the catalogue's test uses (one beyond the
  // method's order for coefficients in fields of degree > 2, where a tree costs milliseconds;
  // the non-symplecticity of these methods shows by then).
  for (const geomint::methods::catalogue_entry& e : geomint::methods::catalogue()) {
    if ((e.kind != method_kind::rk && e.kind != method_kind::prk) || !e.tableau) continue;  // Radau s = 5: test_collocation_algebra.cpp
    INFO(e.name);
    const auto t = e.tableau();
    const bool large_field =
        std::any_of(t.c.begin(), t.c.end(), [](const field_element& x) { return x.field() && x.field()->degree() > 2; });
    const int order = e.kind == method_kind::rk ? (large_field ? e.order + 1 : e.order + 2) : std::min(e.order + 1, 7);
    const auto conditions = symplecticity_conditions(t);
    CHECK(conditions.symplectic == e.symplectic);
    if (large_field && order > 8) continue;  // Gauss s = 4, 5: the conditions above, with the source
    const tree_set trees(order, e.kind == method_kind::rk ? 1 : 2);
    CHECK(check_symplecticity_conditions(trees, modified_field(trees, elementary_weights(trees, t))).holds == conditions.symplectic);
  }
}

TEST_CASE("tableau symplecticity: every catalogue verdict agrees with the numerical defect of its step", "[analysis]") {
  // One step of tau = 1/2 on the pendulum from (q, p) = (1, 1/2) in 50 digits, the Jacobian by
  // central differences with one Richardson extrapolation, accurate to about eps^(4/5) (1e-40):
  // a symplectic verdict must give a defect at that noise level, any other one far above it
  // (the defect of a method of order p is O(tau^(p+1)), at least 1e-6 here). The reducible
  // methods run as printed: Lobatto IIIB, s = 2, steps as the implicit midpoint rule it is.
  using T = geomint::test::cpp_bin_float_50;
  using std::pow;
  const T noise = T(1024) * pow(std::numeric_limits<T>::epsilon(), T(4) / T(5));
  geomint::analysis::phase_vector<T> z(2);
  z << T(1), T(1) / T(2);
  int symplectic_count = 0;
  for (const geomint::methods::catalogue_entry& e : geomint::methods::catalogue()) {
    if (!e.tableau) continue;  // Radau s = 5 over its stage algebra: tests/methods/test_collocation_algebra.cpp
    const auto t = e.tableau();
    const auto stepper = geomint::make_tableau_stepper<geomint::systems::pendulum, T>(geomint::methods::nystrom_form_of(t));
    const T defect = geomint::analysis::symplectic_defect(geomint::analysis::one_step_jacobian<T>(*stepper, T(1) / T(2), z));
    const bool symplectic = symplecticity_conditions(t).symplectic;
    INFO(e.name << ": exact verdict " << (symplectic ? "symplectic" : "not symplectic") << ", numerical defect " << defect);
    if (symplectic) {
      ++symplectic_count;
      CHECK(defect <= noise);
    } else {
      CHECK(defect > noise * T(1000000));
    }
  }
  // Gauss 2..5, Lobatto IIIB 2, the IIIA-IIIB pairs 2..5, Stormer-Verlet, Ruth, Forest-Ruth,
  // Yoshida, Suzuki, SB3A 4 and 5 (the sources' verdicts, catalogue.hpp).
  CHECK(symplectic_count == 4 + 1 + 4 + 7);
}

}  // namespace tableau_symplecticity_test
