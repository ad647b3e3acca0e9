/// The Taylor-series reference flow against closed-form solutions and against the library's
/// own Euler-Lagrange acceleration.
#include "catch.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_50;

TEMPLATE_TEST_CASE("reference flow: harmonic oscillator equals cos/sin", "[analysis][reference]", double,
                   cpp_bin_float_50) {
  using T = TestType;
  using std::cos;
  using std::sin;
  // Independent source: x(t) = cos t + sin t for x(0) = xdot(0) = 1 (closed form).
  analysis::reference_flow<systems::harmonic, T> flow(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
  for (int k = 1; k <= 5; ++k) {
    const T t = T(k) * T(7) / T(5);
    flow.advance_to(t);
    CHECK(geomint::test::abs_diff(flow.q()[0], T(cos(t) + sin(t))) <= geomint::test::eps_tol<T>(64));
    CHECK(geomint::test::abs_diff(flow.p()[0], T(cos(t) - sin(t))) <= geomint::test::eps_tol<T>(64));
  }
  CHECK(flow.steps() >= 5);  // at least one Taylor step per interval
}

TEMPLATE_TEST_CASE("reference flow: Kepler orbit equals Kepler's equation", "[analysis][reference]", double,
                   cpp_bin_float_50) {
  using T = TestType;
  using std::cos;
  using std::sin;
  using std::sqrt;
  // Independent source: e = 1/2, a = 1 from pericentre: M = t = E - e sin E (solved by Newton),
  // x = cos E - e, y = sqrt(1 - e^2) sin E, xdot = -sin E / (1 - e cos E), ydot = sqrt(1 - e^2) cos E / (1 - e cos E).
  const T e = T(1) / T(2);
  vec<T, 2> q0, p0;
  q0 << e, T(0);
  p0 << T(0), sqrt(T(3));
  analysis::reference_flow<systems::kepler, T> flow(q0, p0);
  for (int k = 1; k <= 4; ++k) {
    const T t = T(k) * T(3) / T(2);
    flow.advance_to(t);
    T E = t;
    for (int it = 0; it < 200; ++it) E -= (E - e * sin(E) - t) / (T(1) - e * cos(E));
    const T d = T(1) - e * cos(E), b = sqrt(T(1) - e * e);
    const T tol = geomint::test::eps_tol<T>(1024);
    CHECK(geomint::test::abs_diff(flow.q()[0], T(cos(E) - e)) <= tol);
    CHECK(geomint::test::abs_diff(flow.q()[1], T(b * sin(E))) <= tol);
    CHECK(geomint::test::abs_diff(flow.qdot()[0], T(-sin(E) / d)) <= tol);
    CHECK(geomint::test::abs_diff(flow.qdot()[1], T(b * cos(E) / d)) <= tol);
  }
}

template <class Sys, class T>
void check_first_coefficient(const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& v) {
  std::vector<vec<T, Sys::dof>> qc, vc;
  analysis::detail::taylor_coefficients<Sys, T>(q, v, 4, qc, vc);
  // v_1 = a(q, v): the closed-form field against the Euler-Lagrange acceleration of the
  // Lagrangian by automatic differentiation (two independent derivations).
  const vec<T, Sys::dof> a = geomint::lagrangian_derivatives<Sys, T>::acceleration(Sys{}, q, v);
  for (int i = 0; i < Sys::dof; ++i) CHECK(geomint::test::abs_diff(vc[1][i], a[i]) <= geomint::test::eps_tol<T>(16));
}

TEMPLATE_TEST_CASE("reference flow: closed-form fields equal the Lagrangians' accelerations", "[analysis][reference]",
                   double, cpp_bin_float_50) {
  using T = TestType;
  check_first_coefficient<systems::pendulum, T>(vec<T, 1>(T(7) / T(10)), vec<T, 1>(T(-3) / T(10)));
  vec<T, 2> q, v;
  q << T(3) / T(5), T(-2) / T(5);
  v << T(1) / T(3), T(5) / T(4);
  check_first_coefficient<systems::kepler, T>(q, v);
  check_first_coefficient<systems::charged, T>(q, v);
}

TEST_CASE("reference flow: energy is conserved to working precision", "[analysis][reference]") {
  using T = cpp_bin_float_50;
  vec<T, 2> q0, p0;
  q0 << T(1), T(0);
  p0 << T(0), T(1) + T(3) / T(4);  // p = v + A(q): v = (0, 1), A = (0, 3/4)
  analysis::reference_flow<systems::charged, T> flow(q0, p0);
  const T E0 = energy_qv<systems::charged, T>(systems::charged{}, flow.q(), flow.qdot());
  flow.advance_to(T(3));
  const T E1 = energy_qv<systems::charged, T>(systems::charged{}, flow.q(), flow.qdot());
  CHECK(geomint::test::abs_diff(E0, E1) <= geomint::test::eps_tol<T>(1024));
  CHECK_THROWS_AS(flow.advance_to(T(1)), std::invalid_argument);  // backwards
}
