/// LPF's solver policies (schemes/lpf.hpp): the default solver takes the fixed-point form's steps
/// on a natural system with Gauss-interior nodes (schemes/gauss_fixed_point.hpp) and Newton's
/// elsewhere, and Newton's for a step beyond the sweeps' reach; dense output and the two-step
/// form work whichever solver took the step. Second method throughout: the Newton form of the
/// same equations (newton_solver), which solves them to round-off.
#include <cmath>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

namespace lpf_solver_test {

using namespace geomint;
using geomint::test::eps_tol;

template <int M>
using lpf_newton = lpf<M, gauss_interior, lagrange, newton_solver>;
template <int M>
using lpf_fixed = lpf<M, gauss_interior, lagrange, fixed_point_solver>;

/// `steps` steps of Scheme on the pendulum from (1, 1/2) with tau.
template <class Scheme, class T>
phase_state<T, 1> pendulum_run(const T& tau, int steps) {
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1) / T(2)));
  I.advance(s, steps);
  return s;
}

TEMPLATE_LIST_TEST_CASE("lpf solvers: the default is the fixed-point form on Gauss-interior nodes of a natural system",
                        "[lpf][solver]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  const T tau = T(1) / T(4);
  // The same code takes the same steps: bit for bit.
  const auto d = pendulum_run<lpf<6, gauss_interior>, T>(tau, 20);
  const auto f = pendulum_run<lpf_fixed<6>, T>(tau, 20);
  CHECK(d.q == f.q);
  CHECK(d.p == f.p);
  // Newton on the same equations: the same map to round-off (20 steps, 64 eps each).
  const auto n = pendulum_run<lpf_newton<6>, T>(tau, 20);
  CHECK(abs(T(d.q[0] - n.q[0])) <= eps_tol<T>(20 * 64));
  CHECK(abs(T(d.p[0] - n.p[0])) <= eps_tol<T>(20 * 64));
  // Elsewhere the default is Newton: other node families, and systems that are not natural.
  const auto e = pendulum_run<lpf<4, equispaced>, T>(tau, 20);
  const auto en = pendulum_run<lpf<4, equispaced, lagrange, newton_solver>, T>(tau, 20);
  CHECK(e.q == en.q);
  CHECK(e.p == en.p);
  integrator<lpf<3, gauss_interior>, systems::charged, T> C(systems::charged{}, tau);
  integrator<lpf_newton<3>, systems::charged, T> CN(systems::charged{}, tau);
  auto c = C.initial_state(vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), T(1)));
  auto cn = c;
  C.advance(c, 10);
  CN.advance(cn, 10);
  CHECK(c.q == cn.q);
  CHECK(c.p == cn.p);
}

TEMPLATE_LIST_TEST_CASE("lpf solvers: a step beyond the sweeps' reach is Newton's", "[lpf][solver]",
                        geomint::test::integrator_scalar_types) {
  // The pendulum from theta = 1 with m = 4 and tau = 5 (about three quarters of a period in one
  // step): the fixed-point map is no contraction there (fixed_point_solver fails), Newton
  // converges, and the default solver returns Newton's step.
  using T = TestType;
  const T tau(5);
  integrator<lpf_fixed<4>, systems::pendulum, T> F(systems::pendulum{}, tau);
  integrator<lpf<4, gauss_interior>, systems::pendulum, T> D(systems::pendulum{}, tau);
  integrator<lpf_newton<4>, systems::pendulum, T> N(systems::pendulum{}, tau);
  // The sweeps, whose reach this is (multiprecision would presolve in double), and the same
  // Newton options in both Newton runs.
  for (newton_options<T>* o : {&F.options(), &D.options(), &N.options()}) o->double_jacobian = false;
  auto f = F.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  auto d = f, n = f;
  CHECK_FALSE(F.try_step(f));
  REQUIRE(N.try_step(n));
  REQUIRE(D.try_step(d));
  CHECK(d.q == n.q);
  CHECK(d.p == n.p);
}

TEMPLATE_LIST_TEST_CASE("lpf solvers: dense output and the two-step form with the fixed-point form",
                        "[lpf][solver][step_path]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  const T tau = T(1) / T(4);
  integrator<lpf<5, gauss_interior>, systems::pendulum, T> D(systems::pendulum{}, tau);
  integrator<lpf_newton<5>, systems::pendulum, T> N(systems::pendulum{}, tau);
  for (const bool compensated : {false, true}) {
    D.set_compensated_summation(compensated);
    N.set_compensated_summation(compensated);
    auto d = D.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1) / T(2)));
    auto n = d;
    for (int k = 0; k < 4; ++k) {
      const auto pd = D.step_with_path(d);
      const auto pn = N.step_with_path(n);
      // The path of the fixed-point step is the collocation polynomial Newton fits: the same to
      // round-off at nine points of the step. Its node values agree to the solvers' tolerance
      // (64 eps |x| per step, accumulated over the steps), its velocity to that amplified by the
      // differentiation weights, sum_j |l_j'(s)| / tau (as tests/schemes/test_step_path.cpp).
      const T nodes_tol = T(pn.control_points().cwiseAbs().maxCoeff()) * eps_tol<T>(64 * (k + 1));
      for (int j = 0; j <= 8; ++j) {
        const T s = T(j) / T(8), t = pd.t_begin() + s * pd.tau();
        T amplification(0);
        for (const T& w : basis_derivatives<1, lagrange, gauss_interior, 5, T>(s)) amplification += abs(w);
        CHECK(abs(T(pd.position(t)[0] - pn.position(t)[0])) <= T(4) * nodes_tol);
        CHECK(abs(T(pd.velocity(t)[0] - pn.velocity(t)[0])) <= T(4) * nodes_tol * amplification / tau);
      }
    }
  }
  // The two-step form (Newton on the end momentum, eq. 10-12) reproduces the default solver's
  // one-step trajectory (exact mathematics: the same map).
  D.set_compensated_summation(false);
  auto s = D.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  auto [xm, x] = D.start(s.q, vec<T, 1>(T(0)));
  D.step(s);
  for (int k = 1; k < 20; ++k) {
    const vec<T, 1> next = D.two_step(xm, x, k);
    xm = x;
    x = next;
    D.step(s);
  }
  CHECK(abs(T(x[0] - s.q[0])) <= eps_tol<T>(4000));
}

TEST_CASE("lpf solvers: a solver chosen explicitly is named", "[lpf][solver]") {
  CHECK(lpf<4, gauss_interior>::name() == "lpf(m=4, gauss-interior, lagrange)");
  CHECK(lpf_newton<4>::name() == "lpf(m=4, gauss-interior, lagrange, newton)");
  CHECK(lpf_fixed<4>::name() == "lpf(m=4, gauss-interior, lagrange, fixed-point)");
}

}  // namespace lpf_solver_test
