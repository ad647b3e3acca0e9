/// Closed-form pendulum and Kepler solutions against the Taylor-series reference flow (an
/// independent derivation: recurrences of the closed-form accelerations).
#include "catch.hpp"
#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_50;

TEMPLATE_TEST_CASE("closed-form pendulum equals the Taylor-series flow", "[analysis][closed_form]", double,
                   cpp_bin_float_50) {
  using T = TestType;
  analysis::reference_flow<systems::pendulum, T> flow(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  for (int k = 1; k <= 4; ++k) {
    const T t = T(k) * T(17) / T(10);
    flow.advance_to(t);
    const auto exact = analysis::pendulum_from_rest<T>(T(1), t);
    CHECK(geomint::test::abs_diff(flow.q()[0], exact.q[0]) <= geomint::test::eps_tol<T>(256));
    CHECK(geomint::test::abs_diff(flow.p()[0], exact.p[0]) <= geomint::test::eps_tol<T>(256));
  }
  CHECK_THROWS_AS(analysis::pendulum_from_rest<T>(T(4), T(1)), std::invalid_argument);
}

TEMPLATE_TEST_CASE("closed-form Kepler orbit equals the Taylor-series flow", "[analysis][closed_form]", double,
                   cpp_bin_float_50) {
  using T = TestType;
  using std::sqrt;
  vec<T, 2> q0, p0;
  q0 << T(1) / T(2), T(0);
  p0 << T(0), sqrt(T(3));
  analysis::reference_flow<systems::kepler, T> flow(q0, p0);
  for (int k = 1; k <= 4; ++k) {
    const T t = T(k) * T(23) / T(10);
    flow.advance_to(t);
    const auto exact = analysis::kepler_from_pericentre<T>(T(1) / T(2), t);
    const vec<T, 2> p = flow.p();
    for (int i = 0; i < 2; ++i) {
      CHECK(geomint::test::abs_diff(flow.q()[i], exact.q[std::size_t(i)]) <= geomint::test::eps_tol<T>(2048));
      CHECK(geomint::test::abs_diff(p[i], exact.p[std::size_t(i)]) <= geomint::test::eps_tol<T>(2048));
    }
  }
  CHECK_THROWS_AS(analysis::kepler_from_pericentre<T>(T(1), T(1)), std::invalid_argument);
}
