/// Principal error constants of tableaux of every kind (analysis/bseries/error_constants.hpp):
/// against the Taylor expansion of one step done by hand, against the library's Nystrom-tree
/// constants (analysis/order_conditions.hpp, an independent constexpr code path) on the rational
/// RKN methods of the catalogue, and Gauss s = 2 over Q(sqrt 3) against the Galerkin VI m = 2,
/// after checking that the two are one map.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <sstream>
#include <string>

#include "catch.hpp"
#include "geomint/analysis/bseries/error_constants.hpp"
#include "geomint/analysis/order_conditions.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "field_numbers.hpp"

// A named namespace: the suites of a folder are compiled as one unit (UNITY_BUILD).
namespace error_constants_test {

using namespace geomint;
using methods::exact_rational;
using methods::field_element;
using geomint::test::field_numbers::q;
using T = boost::multiprecision::cpp_bin_float_50;

field_element from_exact(const exact_number& x) { return field_element(exact_rational(x.num.str()) / exact_rational(x.den().str())); }

template <class Method>
exact_rkn_tableau library_tableau() {
  const auto t = Method::tableau();
  return rational_rkn_tableau(t.c, t.a, t.bbar, t.b);
}
methods::tableau_data<field_element> catalogue_tableau(const char* name) {
  const methods::catalogue_entry* e = methods::find_in_catalogue(name);
  REQUIRE(e != nullptr);
  return e->tableau();
}

TEST_CASE("Error constants of Stormer-Verlet and the implicit midpoint rule from their Taylor expansions", "[error_constants]") {
  // Stormer-Verlet, q1 = q + h v + h^2/2 f(q), v1 = v + h/2 (f(q) + f(q1)), against the exact
  // q(h), v(h) with q''' = f'(q) v, v''' = f''(q)(v, v) + f'(q) f(q). Position: the method has no
  // h^3 term, the error is -h^3/6 f' v: C_q = 1/6. Velocity: f(q1) = f + f'(h v + h^2/2 f) +
  // f''(h v, h v)/2 + O(h^3), so h/2 f(q1) gives h^3/4 (f' f + f''(v, v)) against the exact
  // h^3/6 (f' f + f''(v, v)): the coefficients of both differentials are 1/12, C_p^2 = 2/144.
  // C^2 = C_q^2 + C_p^2 = 1/24 (the library's trapezoidal VI, the same map, has these three).
  const auto verlet = analysis::bseries::principal_error_constants(catalogue_tableau("stormer-verlet"), 2);
  CHECK(verlet.components == 2);
  CHECK(verlet.first_squared == q(1, 36));
  CHECK(verlet.second_squared == q(1, 72));
  CHECK(verlet.squared == q(1, 24));
  // The implicit midpoint rule as rk (A = 1/2, b = 1, c = 1/2), order 2, on y' = f(y): the trees
  // of order 3 (HLW section III.1) are [[tau]] (Phi = b A c = 1/4, gamma = 6, sigma = 1) and
  // [tau, tau] (Phi = b c^2 = 1/4, gamma = 3, sigma = 2): T = 1/12 and -1/24, C^2 = 5/576.
  std::istringstream in("kind rk\nstages 1\nc 1/2\na 1/2\nb 1\n");
  const auto midpoint = analysis::bseries::principal_error_constants(methods::read_tableau(in, "midpoint"), 2);
  CHECK(midpoint.components == 1);
  CHECK(midpoint.squared == q(5, 576));
  CHECK(midpoint.first_squared == q(5, 576));
}

TEST_CASE("Error constants of the rational RKN methods of the catalogue agree with the library's Nystrom trees", "[error_constants]") {
  struct method {
    const char* name;
    exact_rkn_tableau tableau;
  };
  for (const method& m : {method{"stormer-verlet", library_tableau<methods::stormer_verlet>()},
                          method{"ruth-3", library_tableau<methods::ruth3>()},
                          method{"demp-rkn43", library_tableau<methods::demp_rkn43>()},
                          method{"demp-rkn43-embedded", library_tableau<methods::demp_rkn43_embedded>()},
                          method{"demp-rkn64", library_tableau<methods::demp_rkn64>()},
                          method{"demp-rkn64-embedded", library_tableau<methods::demp_rkn64_embedded>()}}) {
    INFO(m.name);
    const order_summary library = order_analysis(m.tableau);
    REQUIRE_FALSE(library.order_is_lower_bound);
    const auto c = analysis::bseries::principal_error_constants(catalogue_tableau(m.name), library.order);
    CHECK(c.squared == from_exact(library.error_constant_squared));
    CHECK(c.first_squared == from_exact(library.position_error_constant_squared));
    CHECK(c.second_squared == from_exact(library.velocity_error_constant_squared));
  }
}

TEST_CASE("Gauss s = 2 over Q(sqrt 3) is the Galerkin VI m = 2 on natural systems, with the same error constants", "[error_constants]") {
  // The map: the Nystrom form of Gauss s = 2 (A A, b^T A, b) against the Galerkin VI's RKN
  // tableau in 50 digits on the Gauss points 1/2 -+ sqrt 3/6 (both in ascending nodes).
  // On q'' = f(q) the velocity stages (ap = A) do not enter: the special Nystrom trees.
  auto gauss = methods::nystrom_form_of(catalogue_tableau("gauss-2"));
  gauss.has_velocity_stages = false;
  const exact_rkn_tableau galerkin = galerkin_tableau<2>();
  using std::sqrt;
  const T nodes[2] = {T(1) / 2 - sqrt(T(3)) / 6, T(1) / 2 + sqrt(T(3)) / 6};
  const methods::tableau_data<T> g = numeric_tableau<T>(galerkin, nodes);
  REQUIRE(gauss.stages == 2);
  using std::abs;
  const T tolerance = T(1) / T("1e45");
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(abs(gauss.c[i].to<T>() - g.c[i]) < tolerance);
    CHECK(abs(gauss.bbar[i].to<T>() - g.bbar[i]) < tolerance);
    CHECK(abs(gauss.b[i].to<T>() - g.b[i]) < tolerance);
    for (std::size_t j = 0; j < 2; ++j) CHECK(abs(gauss.a[i][j].to<T>() - g.a[i][j]) < tolerance);
  }
  // The constants: exact, over Q(sqrt 3) against the library's over Q.
  const order_summary library = order_analysis(galerkin);
  REQUIRE(library.order == 4);
  const auto c = analysis::bseries::principal_error_constants(gauss, 4);
  CHECK(c.squared == from_exact(library.error_constant_squared));
  CHECK(c.first_squared == from_exact(library.position_error_constant_squared));
  CHECK(c.second_squared == from_exact(library.velocity_error_constant_squared));
}

}  // namespace error_constants_test
