/// The series of a run-time tableau on the fastest exact type (bseries/exact_series.hpp), against
/// exact mathematics and published values, on each of its three paths:
/// - 64-bit rationals throughout: Stormer-Verlet as the Lobatto IIIA-IIIB pair, whose modified
///   field at h^2 HLW section IX.3 prints (Hairer, Lubich & Wanner, Geometric Numerical
///   Integration, 2nd ed. 2006; the values of tests/analysis/test_bseries_static.cpp);
/// - rational entries whose series leaves 64 bits (the fallback to field_element): the one-stage
///   method a = x, b = 1 with x = 1/1000003. By hand, every stage value is x^(|t|-1), so
///   a(t) = x^(|t|-1); on y' = lambda y its step is R(z) = (1 + (1 - x) z)/(1 - x z), and the
///   modified field of the tall tree of order n (the only trees whose F is not zero there,
///   sigma = 1) is the z^n coefficient of log R(z) = log(1 + (1 - x) z) - log(1 - x z):
///   ((-1)^(n+1) (1 - x)^n + x^n) / n. x^4 and (1 - x)^4 have 80-bit denominators;
/// - irrational entries: Gauss s = 2 over Q(sqrt 3), of order 4 (Butcher 1964), so
///   a(t) = 1/gamma(t) for |t| <= 4 and the modified field is f up to h^4; its first term is
///   the local error (the recursion of modified_equation.hpp with b = 0 at orders 2..4), by hand:
///   the bushy tree [t, t, t, t] has a = sum b_i c_i^4, the two-point Gauss-Legendre rule on x^4,
///   7/36, so b = 7/36 - 1/5 = -1/180; the tall tree of order 5 has a = the z^5 coefficient of
///   the step R(z) = (1 + z/2 + z^2/12)/(1 - z/2 + z^2/12), the (2,2) Pade approximant of e^z,
///   whose error is e^z - R(z) = z^5/720 + O(z^6) (Hairer & Wanner, Solving ODEs II, section
///   IV.3, Theorem 3.11), so b = -1/720.
#include <vector>

#include "catch.hpp"
#include "field_numbers.hpp"
#include "geomint/analysis/bseries/exact_series.hpp"
#include "geomint/methods/catalogue.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_exact_series_test {

using geomint::methods::field_element;
using geomint::test::field_numbers::q;
using namespace geomint::analysis::bseries;
using tableau = geomint::methods::tableau_data<field_element>;

TEST_CASE("exact series: Stormer-Verlet as a Lobatto IIIA-IIIB pair on 64-bit rationals (HLW IX.3)", "[bseries]") {
  tableau kdk;  // kick-drift-kick: q by IIIA (colour 0), p by IIIB (colour 1)
  kdk.kind = geomint::methods::method_kind::prk;
  kdk.stages = 2;
  kdk.c = {q(0), q(1)};
  kdk.a = {{q(0), q(0)}, {q(1, 2), q(1, 2)}};
  kdk.b = {q(1, 2), q(1, 2)};
  kdk.ahat = {{q(1, 2), q(0)}, {q(1, 2), q(0)}};
  kdk.bhat = {q(1, 2), q(1, 2)};
  const tree_set t(3, 2);
  const exact_series s = exact_series_of(t, kdk);
  const int f = t.leaf(0), g = t.leaf(1);
  const auto over_sigma = [&](int tree) { return s.b[static_cast<std::size_t>(tree)] / q(static_cast<long>(t[tree].sigma)); };
  CHECK(over_sigma(t.find(0, {g, g})) == q(-1, 24));        // f''(g, g)
  CHECK(over_sigma(t.find(0, {t.find(1, {f})})) == q(-1, 6)); // f'g'f
  CHECK(over_sigma(t.find(1, {f, f})) == q(1, 12));         // g''(f, f)
  CHECK(over_sigma(t.find(1, {t.find(0, {g})})) == q(1, 12)); // g'f'g
}

TEST_CASE("exact series: a series beyond 64 bits falls back to exact field arithmetic", "[bseries]") {
  const field_element x = q(1, 1000003);
  tableau one_stage;
  one_stage.kind = geomint::methods::method_kind::rk;
  one_stage.stages = 1;
  one_stage.c = {x};
  one_stage.a = {{x}};
  one_stage.b = {q(1)};
  const int order = 6;
  const tree_set t(order, 1);
  const exact_series s = exact_series_of(t, one_stage);
  for (int k = 0; k < t.size(); ++k) {
    field_element power = q(1);
    for (int j = 1; j < t[k].order; ++j) power *= x;
    CHECK(s.a[static_cast<std::size_t>(k)] == power);
  }
  int tall = t.leaf(0);
  field_element one_minus_x_n = q(1), x_n = q(1);
  for (int n = 1; n <= order; ++n) {
    if (n > 1) tall = t.find(0, {tall});
    one_minus_x_n *= q(1) - x;
    x_n *= x;
    const field_element expected = ((n % 2 == 1 ? one_minus_x_n : q(0) - one_minus_x_n) + x_n) / q(n);
    INFO("n = " << n);
    CHECK(s.b[static_cast<std::size_t>(tall)] == expected);
  }
}

TEST_CASE("exact series: irrational entries (Gauss s = 2 over Q(sqrt 3)): order 4 and its h^4 terms", "[bseries]") {
  const geomint::methods::catalogue_entry* gauss = geomint::methods::find_in_catalogue("gauss-2");
  REQUIRE(gauss != nullptr);
  const tree_set t(5, 1);
  const exact_series s = exact_series_of(t, gauss->tableau());
  for (int k = 0; k < t.size(); ++k) {
    if (t[k].order > 4) continue;
    CHECK(s.a[static_cast<std::size_t>(k)] == q(1, static_cast<long>(t[k].gamma)));
    CHECK(s.b[static_cast<std::size_t>(k)] == (t[k].order == 1 ? q(1) : q(0)));
  }
  const int leaf = t.leaf(0);
  int tall = leaf;
  for (int n = 2; n <= 5; ++n) tall = t.find(0, {tall});
  CHECK(s.b[static_cast<std::size_t>(t.find(0, {leaf, leaf, leaf, leaf}))] == q(-1, 180));
  CHECK(s.b[static_cast<std::size_t>(tall)] == q(-1, 720));
}

}  // namespace bseries_exact_series_test
