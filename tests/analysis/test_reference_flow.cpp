/// The Taylor-series reference flow against closed-form solutions and against the library's
/// own Euler-Lagrange acceleration.
#include <boost/math/constants/constants.hpp>

#include "catch.hpp"
#include "geomint/analysis/any_system.hpp"
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

/// |a - b| <= 64 eps * scale * steps.
template <class T>
bool abs_diff_scaled(const T& a, const T& b, const T& scale, const T& steps) {
  return geomint::test::abs_diff(a, b) <= geomint::test::eps_tol<T>(64) * scale * steps;
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
  vec<T, 18> qs, vs;
  zoo::outer_solar::initial_data<T>(qs, vs);
  check_first_coefficient<zoo::outer_solar, T>(qs, vs);
}

TEMPLATE_TEST_CASE("reference flow: the outer solar system keeps energy and both momenta", "[analysis][reference]",
                   double, cpp_bin_float_50) {
  using T = TestType;
  using S = zoo::outer_solar;
  // Independent source: exact mathematics. Energy, total linear and angular momentum are
  // invariants of the N-body flow; a wrong coefficient of any order in the recurrences would
  // change them at the size of that order's term in each Taylor step (steps of some 100 days).
  vec<T, 18> q0, v0;
  S::initial_data<T>(q0, v0);
  const vec<T, 18> p0 = S::mass_matrix<T>() * v0;
  analysis::reference_flow<S, T> flow(q0, p0);
  const T E0 = S::energy_qp<T>(q0, p0);
  const vec<T, 3> P0 = S::linear_momentum<T>(p0), L0 = S::angular_momentum<T>(q0, p0);
  flow.advance_to(T(2000));  // about half an orbit of Jupiter
  const vec<T, 18> p = flow.p();
  CHECK(flow.steps() >= 10);
  // Relative to each invariant's own scale: |E| (the potential's terms are of its size), and
  // for the momenta the largest |p_i| (times |q_i| for L), one rounding per step and term.
  const T steps(flow.steps());
  const T p_scale = p0.cwiseAbs().maxCoeff(), l_scale = p_scale * q0.cwiseAbs().maxCoeff();
  using std::abs;
  CHECK(abs_diff_scaled(S::energy_qp<T>(flow.q(), p), E0, T(abs(E0)), steps));
  CHECK((S::linear_momentum<T>(p) - P0).cwiseAbs().maxCoeff() <= geomint::test::eps_tol<T>(64) * steps * p_scale);
  CHECK((S::angular_momentum<T>(flow.q(), p) - L0).cwiseAbs().maxCoeff() <=
        geomint::test::eps_tol<T>(64) * steps * l_scale);
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

TEST_CASE("reference flow: bounded up front, never a hang", "[analysis][reference][limits]") {
  using T = double;
  // The harmonic oscillator's Taylor steps are about 0.3 to 1 long (order ~20 in double): 1e300
  // needs ~1e300 steps, far beyond any bound. Refused before the first step.
  analysis::reference_flow<systems::harmonic, T> flow(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  CHECK_THROWS_AS(flow.advance_to(T(1e300)), std::length_error);
  CHECK(flow.steps() == 0);
  CHECK(flow.time() == T(0));
  CHECK_THROWS_AS(flow.advance_to(T(100), 10), std::length_error);  // a stated bound of 10 steps
  // advance_toward: at most the given steps, the state valid between calls.
  CHECK_FALSE(flow.advance_toward(T(100), 3));
  CHECK(flow.steps() == 3);
  CHECK(flow.time() > T(0));
  while (!flow.advance_toward(T(100), 50)) {
  }
  CHECK(flow.time() == T(100));
  using std::cos;
  CHECK(geomint::test::abs_diff(flow.q()[0], T(cos(T(100)))) <= geomint::test::eps_tol<T>(1024));
}

TEMPLATE_TEST_CASE("reference flow: a collision stops with t + h == t, not a loop", "[analysis][reference][limits]", double,
                   cpp_bin_float_50) {
  using T = TestType;
  // Radial Kepler fall from rest at r = 1 (mu = 1): collision at t_c = pi / (2 sqrt 2) (the
  // free-fall time, a half period of the degenerate ellipse with a = 1/2). The Taylor steps
  // shrink with the distance to the collision until t + h == t.
  vec<T, 2> q0, p0;
  q0 << T(1), T(0);
  p0 << T(0), T(0);
  analysis::reference_flow<systems::kepler, T> flow(q0, p0);
  CHECK_THROWS_WITH(flow.advance_to(T(2)), Catch::Contains("(t + h == t)"));
  using std::abs;
  using std::sqrt;
  const T t_c = boost::math::constants::pi<T>() / (T(2) * sqrt(T(2)));
  CHECK(abs(T(flow.time() - t_c)) < T(1) / T(1000));  // stopped at the collision
  CHECK(flow.steps() < 100000);
}

TEST_CASE("galerkin_reference: times beyond its step counts are refused, t = 0 is the start", "[analysis][reference][limits]") {
  using T = double;
  const vec<T, 1> q0(T(1)), p0(T(0));
  const auto flow = analysis::galerkin_reference<systems::harmonic, T>(systems::harmonic{}, q0, p0);
  analysis::dynamic_vector<T> q, p;
  // 8 steps per unit time, refined 2^20 times: 1e19 would need 8e19 * 2^20 steps (no long holds them).
  CHECK_THROWS_AS(flow(T(1e19), q, p), std::out_of_range);
  CHECK_THROWS_AS(flow(std::numeric_limits<T>::quiet_NaN(), q, p), std::domain_error);
  CHECK_THROWS_AS(flow(T(-1), q, p), std::domain_error);
  flow(T(0), q, p);
  CHECK(q[0] == T(1));
  CHECK(p[0] == T(0));
}
