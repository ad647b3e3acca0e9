/// Dense output (schemes/step_path.hpp): the path of each step, evaluated anywhere in the step,
/// against the closed-form pendulum (Jacobi elliptic functions: an independent reference), its
/// measured order against the order derived in docs/guide/your_own_system.md, and its errors.
#include <cmath>

#include "catch.hpp"
#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::eps_tol;
using boost::multiprecision::cpp_bin_float_50;

namespace {

template <class T>
struct dense_errors {
  T position = T(0), velocity = T(0), nodes = T(0);
};

/// Max errors over [0, 1] of the dense output (9 points per step, ends included) and of the
/// nodes, pendulum released from rest at theta0 = 1 with `steps` steps of tau = 1 / steps.
template <class Scheme, class T>
dense_errors<T> pendulum_dense_errors(int steps) {
  using std::abs;
  const T tau = T(1) / T(steps), theta0(1);
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto s = I.initial_state(vec<T, 1>::Constant(theta0), vec<T, 1>::Zero());
  dense_errors<T> e;
  for (int k = 0; k < steps; ++k) {
    const auto path = I.step_with_path(s);
    for (int j = 0; j <= 8; ++j) {
      const T t = path.t_begin() + T(j) * path.tau() / T(8);
      const auto ref = analysis::pendulum_from_rest(theta0, t);
      const T dq = abs(T(path.position(t)[0] - ref.q[0])), dv = abs(T(path.velocity(t)[0] - ref.p[0]));
      if (dq > e.position) e.position = dq;
      if (dv > e.velocity) e.velocity = dv;
    }
    const T dn = abs(T(s.q[0] - analysis::pendulum_from_rest(theta0, s.t).q[0]));
    if (dn > e.nodes) e.nodes = dn;
  }
  return e;
}

/// log2 of the error ratio between tau and tau / 2.
template <class T>
double slope(const T& coarse, const T& fine) {
  using std::log2;
  return static_cast<double>(T(log2(T(coarse / fine))));
}

/// Observed orders from tau = 1/8 to 1/16 against the theory: position min(m+1, p), velocity
/// min(m, p), nodes p (p: the order of the scheme at the nodes).
template <class Scheme, class T>
void check_dense_order(int position_order, int velocity_order, int node_order) {
  const auto coarse = pendulum_dense_errors<Scheme, T>(8);
  const auto fine = pendulum_dense_errors<Scheme, T>(16);
  const double sp = slope(coarse.position, fine.position), sv = slope(coarse.velocity, fine.velocity),
               sn = slope(coarse.nodes, fine.nodes);
  INFO(Scheme::name() << ": position slope " << sp << ", velocity slope " << sv << ", node slope " << sn);
  CHECK(std::abs(sp - position_order) < 0.35);
  CHECK(std::abs(sv - velocity_order) < 0.35);
  CHECK(std::abs(sn - node_order) < 0.35);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("dense output: the path interpolates the step's ends", "[step_path]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  integrator<lpf_gauss<4>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(4));
  auto s = I.initial_state(vec<T, 1>::Constant(T(1)), vec<T, 1>::Constant(T(1) / T(2)));
  for (int k = 0; k < 3; ++k) {
    const vec<T, 1> q0 = s.q, p0 = s.p;
    const auto path = I.step_with_path(s);
    REQUIRE(path.t_begin() == T(k) / T(4));
    REQUIRE(path.t_end() == s.t);
    // Unit mass: the momentum is the velocity. x(t_k) = X_0 = q_k up to the rounding of the
    // basis values; x(t_{k+1}) = X_m = q_{k+1}. The velocities hold up to the Newton tolerance of
    // the increments (64 eps |q|) amplified by the derivative weights: sum_j |phi_j'(s)| / tau.
    const T newton = T(path.control_points().cwiseAbs().maxCoeff()) * eps_tol<T>(I.options().tolerance_ulps);
    T amplification(0);
    for (const T& w : basis_derivatives<1, lagrange, gauss_interior, 4, T>(T(1))) amplification += abs(w);
    const T velocity_tol = T(4) * newton * amplification / I.tau();
    CHECK(abs(T(path.position(path.t_begin())[0] - q0[0])) <= eps_tol<T>(16));
    CHECK(abs(T(path.position(path.t_end())[0] - s.q[0])) <= T(4) * newton);
    CHECK(abs(T(path.velocity(path.t_begin())[0] - p0[0])) <= velocity_tol);
    CHECK(abs(T(path.velocity(path.t_end())[0] - s.p[0])) <= velocity_tol);
  }
}

TEMPLATE_LIST_TEST_CASE("dense output: evaluation outside the step is an error", "[step_path]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  integrator<galerkin_vi<3>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(4));
  typename decltype(I)::path empty;
  CHECK(empty.empty());
  CHECK_THROWS_AS(empty.position(T(0)), std::logic_error);
  auto s = I.initial_state(vec<T, 1>::Constant(T(1)), vec<T, 1>::Zero());
  I.step(s);
  const auto path = I.step_with_path(s);  // [1/4, 1/2]
  CHECK_NOTHROW(path.position(T(1) / T(4)));
  CHECK_NOTHROW(path.velocity(T(1) / T(2)));
  CHECK_THROWS_AS(path.position(T(1) / T(5)), std::out_of_range);
  CHECK_THROWS_AS(path.velocity(T(3) / T(5)), std::out_of_range);
  CHECK_THROWS_AS(path.position(std::numeric_limits<T>::quiet_NaN()), std::out_of_range);
  // A failed step leaves the state and the path unchanged.
  auto bad = s;
  bad.q[0] = std::numeric_limits<T>::infinity();
  auto kept = path;
  CHECK(!I.try_step_with_path(bad, kept));
  CHECK(kept.t_begin() == path.t_begin());
  CHECK(bad.step == s.step);
}

TEMPLATE_LIST_TEST_CASE("dense output: measured order against the derived one", "[step_path]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  // LPF on Gauss nodes, m = 4: nodes 2(m-1) = 6; path position min(m+1, 6) = 5, velocity 4.
  check_dense_order<lpf_gauss<4>, T>(5, 4, 6);
  // LPF on Gauss nodes, m = 2: nodes 2; position min(3, 2) = 2, velocity min(2, 2) = 2.
  check_dense_order<lpf_gauss<2>, T>(2, 2, 2);
  // The same path in the Bernstein basis (Bezier control points, eq. 13), m = 2 equispaced.
  check_dense_order<lpf<2, equispaced, bernstein>, T>(2, 2, 2);
  // Galerkin m = 3 (order 2m = 6 at the nodes): position 4, velocity 3.
  check_dense_order<galerkin_vi<3>, T>(4, 3, 6);
  // Midpoint: linear interpolation of order-2 nodes: position 2, the secant velocity 1.
  check_dense_order<midpoint_vi, T>(2, 1, 2);
}
