/// The constrained LPF integrator and the paper's scheme (23). Expected values:
/// - the paper's printed formula (23) (its residual, evaluated independently of the integrator);
/// - exact mathematics: f = 0 and G qdot = 0 on the constraint manifold; uniform circular motion
///   q(t) = (cos t, sin t) for the free particle on the unit circle; Noether's theorem for the
///   vertical angular momentum of the spherical pendulum (the scheme is rotation-equivariant);
/// - a second method: the double pendulum in angle coordinates integrated by the unconstrained
///   LPF integrator, compared at the order of the method.
#include <geomint/constrained_integrator.hpp>
#include <geomint/integrator.hpp>
#include <geomint/mechanics/constrained_systems.hpp>
#include <geomint/schemes/paper23.hpp>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "catch.hpp"
#include "scalar_types.hpp"

using geomint::vec;
using geomint::test::eps_tol;

namespace {
template <class T>
vec<T, 2> on_circle(const T& angle) {
  using std::cos;
  using std::sin;
  return vec<T, 2>(T(cos(angle)), T(sin(angle)));
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("the general machinery without eq. (5)'s end terms is the paper's scheme (23)",
                        "[constraints][paper23]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  using geomint::systems::free_particle_2d;
  using geomint::systems::unit_circle;
  const T tau = T(1) / T(10);
  geomint::constrained_integrator<geomint::constrained_lpf<2>, free_particle_2d, unit_circle, T> integrator(
      {}, {}, tau);
  // Two points on the circle and one slightly off it: (23) is a map of the plane.
  const vec<T, 2> x0 = on_circle(T(0)), x1 = on_circle(tau);
  const vec<T, 2> x1_off = T(T(101) / T(100)) * on_circle(T(T(3) / T(2) * tau));
  for (const auto& [prev, curr] : {std::pair{x0, x1}, std::pair{x1, x1_off}}) {
    const vec<T, 2> general = integrator.two_step(prev, curr, geomint::endpoint_terms::drop);
    const vec<T, 2> printed = geomint::paper23_step<T>(prev, curr);
    // The printed residual at the general machinery's x^{k+1} vanishes to round-off
    // (terms of size 8, so 64 eps covers the rounding of the Newton solution).
    CHECK(geomint::paper23_residual<T>(prev, curr, general).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(64));
    CHECK((general - printed).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(64));
  }
  // With eq. (5)'s terms kept, x^{k+1} lies on the circle; as printed, (23) drifts off it.
  const vec<T, 2> kept = integrator.two_step(x0, x1, geomint::endpoint_terms::keep);
  CHECK(geomint::constraint_violation<unit_circle, T, 2>({}, kept) <= eps_tol<T>(16));
}

TEMPLATE_LIST_TEST_CASE("constrained LPF: particle on the circle stays on it, energy bounded, solution converges",
                        "[constraints][circle]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  using geomint::systems::free_particle_2d;
  using geomint::systems::unit_circle;
  const T tau = T(1) / T(10);
  geomint::constrained_integrator<geomint::constrained_lpf<3, geomint::gauss_lobatto>, free_particle_2d,
                                        unit_circle, T>
      integrator({}, {}, tau);
  auto s = integrator.initial_state(on_circle(T(0)), vec<T, 2>(T(0), T(1)));
  const T energy0 = integrator.energy(s);
  const long steps = std::is_same_v<T, double> ? 20000 : 200;
  T worst_f(0), worst_v(0), worst_energy(0);
  using std::abs;
  using std::max;
  for (long k = 0; k < steps; ++k) {
    integrator.step(s);
    worst_f = max(worst_f, integrator.violation(s));
    worst_v = max(worst_v, integrator.velocity_violation(s));
    worst_energy = max(worst_energy, T(abs(T(integrator.energy(s) - energy0))));
  }
  // f(q) = |q|^2 - 1 is held by Newton at every step to round-off (its terms are of size 1).
  CHECK(worst_f <= eps_tol<T>(16));
  CHECK(worst_v <= eps_tol<T>(16));
  // Uniform motion: the kinetic energy 1/2 |qdot|^2 is conserved by the projection; its error
  // is round-off, accumulated at most linearly (sqrt(steps) for random rounding).
  CHECK(worst_energy <= eps_tol<T>(16) * T(steps));
}

/// Global error at t = 4 against q(t) = (cos t, sin t) for tau and tau/2 in 50 digits (so that
/// round-off does not bend the slope): the observed order of the constrained scheme.
template <class Scheme>
double circle_observed_order() {
  using T = geomint::test::cpp_bin_float_50;
  using geomint::systems::free_particle_2d;
  using geomint::systems::unit_circle;
  auto error = [](const T& tau, long steps) {
    geomint::constrained_integrator<Scheme, free_particle_2d, unit_circle, T> integrator({}, {}, tau);
    auto s = integrator.initial_state(on_circle(T(0)), vec<T, 2>(T(0), T(1)));
    for (long k = 0; k < steps; ++k) integrator.step(s);
    return T((s.q - on_circle(T(T(steps) * tau))).template lpNorm<Eigen::Infinity>());
  };
  using std::log2;
  return static_cast<double>(log2(T(error(T(1) / T(5), 20) / error(T(1) / T(10), 40))));
}

TEST_CASE("constrained LPF on the circle converges at the order of the free scheme", "[constraints][order]") {
  // Expected orders: 2 for m = 2 (scheme 16's order, the constraint does not change it) and
  // 4 for m = 3 on Gauss-Lobatto nodes (the free scheme's order there). The leading error
  // term dominates at these steps, so the slopes are integers to within 0.05.
  const double order2 = circle_observed_order<geomint::constrained_lpf<2>>();
  const double order3 = circle_observed_order<geomint::constrained_lpf<3, geomint::gauss_lobatto>>();
  INFO("observed orders " << order2 << " (m = 2), " << order3 << " (m = 3 Lobatto)");
  CHECK(std::abs(order2 - 2) < 0.05);
  CHECK(std::abs(order3 - 4) < 0.05);
}

/// Dense output of the constrained integrator (schemes/step_path.hpp): max error of the path over
/// [0, 4] (9 points per step) against q(t) = (cos t, sin t), in 50 digits. Expected order
/// min(m + 1, p) = 4 for m = 3 on Gauss-Lobatto nodes (p = 4 at the nodes, the test above).
TEST_CASE("constrained LPF: dense output on the circle", "[constraints][step_path]") {
  using T = geomint::test::cpp_bin_float_50;
  using geomint::systems::free_particle_2d;
  using geomint::systems::unit_circle;
  using Scheme = geomint::constrained_lpf<3, geomint::gauss_lobatto>;
  auto error = [](const T& tau, long steps) {
    geomint::constrained_integrator<Scheme, free_particle_2d, unit_circle, T> integrator({}, {}, tau);
    auto s = integrator.initial_state(on_circle(T(0)), vec<T, 2>(T(0), T(1)));
    T worst(0);
    for (long k = 0; k < steps; ++k) {
      const auto path = integrator.step_with_path(s);
      for (int j = 0; j <= 8; ++j) {
        const T t = path.t_begin() + T(j) * tau / T(8);
        const T e = (path.position(t) - on_circle(t)).template lpNorm<Eigen::Infinity>();
        if (e > worst) worst = e;
      }
      if (k == 0) CHECK_THROWS_AS(path.position(T(2) * tau), std::out_of_range);
    }
    return worst;
  };
  using std::log2;
  const double order = static_cast<double>(log2(T(error(T(1) / T(5), 20) / error(T(1) / T(10), 40))));
  INFO("observed dense-output order " << order);
  CHECK(std::abs(order - 4) < 0.35);
}

TEMPLATE_LIST_TEST_CASE("constrained LPF: spherical pendulum conserves vertical angular momentum (Noether)",
                        "[constraints][spherical]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  using geomint::systems::spherical_pendulum;
  using geomint::systems::unit_sphere;
  const T tau = T(1) / T(20);
  geomint::constrained_integrator<geomint::constrained_lpf<2>, spherical_pendulum, unit_sphere, T> integrator(
      {}, {}, tau);
  using std::sqrt;
  const T r = sqrt(T(T(1) / T(2)));
  auto s = integrator.initial_state(vec<T, 3>(r, T(0), -r), vec<T, 3>(T(0), T(T(4) / T(5)), T(0)));
  const T momentum0 = spherical_pendulum::conserved<T>(s.q, s.p);
  const T energy0 = integrator.energy(s);
  const long steps = std::is_same_v<T, double> ? 20000 : 200;
  T worst_momentum(0), worst_energy(0), worst_f(0);
  using std::abs;
  using std::max;
  for (long k = 0; k < steps; ++k) {
    integrator.step(s);
    worst_momentum = max(worst_momentum, T(abs(T(spherical_pendulum::conserved<T>(s.q, s.p) - momentum0))));
    worst_energy = max(worst_energy, T(abs(T(integrator.energy(s) - energy0))));
    worst_f = max(worst_f, integrator.violation(s));
  }
  // Round-off only: each step adds a few eps, accumulated at most linearly.
  CHECK(worst_momentum <= eps_tol<T>(16) * T(steps));
  CHECK(worst_f <= eps_tol<T>(16));
  // Energy error of a symplectic order-2 scheme: O(tau^2), bounded (no drift) over the run.
  CHECK(worst_energy <= tau * tau);
}

TEST_CASE("double pendulum: Cartesian with two rods agrees with angle coordinates at the method's order",
          "[constraints][double]") {
  using T = double;
  using geomint::systems::double_pendulum_angles;
  using geomint::systems::double_pendulum_cartesian;
  using geomint::systems::double_pendulum_rods;
  const T final_time = 2;
  // Initial angles (1, 1/2) at rest; Cartesian: q1 = (sin a, -cos a), q2 = q1 + (sin b, -cos b).
  const T a = 1, b = 0.5;
  const vec<T, 2> angles0(a, b);
  const vec<T, 4> cart0(std::sin(a), -std::cos(a), std::sin(a) + std::sin(b), -std::cos(a) - std::cos(b));
  auto difference = [&](const T& tau) {
    const long steps = std::lround(final_time / tau);
    geomint::constrained_integrator<geomint::constrained_lpf<2>, double_pendulum_cartesian, double_pendulum_rods, T>
        cartesian({}, {}, tau);
    auto sc = cartesian.initial_state(cart0, vec<T, 4>::Zero());
    geomint::integrator<geomint::lpf<2>, double_pendulum_angles, T> angular({}, tau);
    auto sa = angular.initial_state(angles0, vec<T, 2>::Zero());
    for (long k = 0; k < steps; ++k) {
      cartesian.step(sc);
      angular.step(sa);
    }
    const vec<T, 4> from_angles(std::sin(sa.q[0]), -std::cos(sa.q[0]), std::sin(sa.q[0]) + std::sin(sa.q[1]),
                                -std::cos(sa.q[0]) - std::cos(sa.q[1]));
    return (sc.q - from_angles).lpNorm<Eigen::Infinity>();
  };
  const T coarse = difference(T(1) / 40), fine = difference(T(1) / 80);
  const T observed_order = std::log2(coarse / fine);
  INFO("difference at tau = 1/40: " << coarse << ", at 1/80: " << fine << ", observed order " << observed_order);
  // Both are second-order discretisations of the same motion: their difference is O(tau^2).
  CHECK(observed_order > 1.8);
  CHECK(observed_order < 2.2);
}

TEMPLATE_LIST_TEST_CASE("constrained LPF: bad input gets a clear error", "[constraints][errors]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using geomint::systems::free_particle_2d;
  using geomint::systems::unit_circle;
  using I = geomint::constrained_integrator<geomint::constrained_lpf<2>, free_particle_2d, unit_circle, T>;
  I integrator({}, {}, T(1) / T(10));
  // Off the circle, or a velocity with a radial part: rejected with the size of the defect.
  CHECK_THROWS_AS(integrator.initial_state(vec<T, 2>(T(2), T(0)), vec<T, 2>(T(0), T(1))), std::invalid_argument);
  CHECK_THROWS_AS(integrator.initial_state(vec<T, 2>(T(1), T(0)), vec<T, 2>(T(1), T(1))), std::invalid_argument);
  // ... or projected explicitly: onto the circle, velocity tangent.
  const auto projected = integrator.project_initial_state(vec<T, 2>(T(2), T(0)), vec<T, 2>(T(1), T(1)));
  CHECK(integrator.violation(projected) <= eps_tol<T>(4));
  CHECK(integrator.velocity_violation(projected) <= eps_tol<T>(4));
  CHECK(projected.p[0] == T(0));
  // Non-finite data: named as such (it used to be reported as a singular constraint Jacobian).
  const T nan = std::numeric_limits<T>::quiet_NaN();
  for (const auto& [q, v] : {std::pair{vec<T, 2>(nan, T(0)), vec<T, 2>(T(0), T(1))},
                             std::pair{vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), nan)}}) {
    try {
      (void)integrator.project_initial_state(q, v);
      FAIL("no error for a non-finite initial state");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).find("not finite") != std::string::npos);
    }
  }
  // Newton options are checked where they are set.
  geomint::newton_options<T> zero_iterations;
  zero_iterations.max_iterations = 0;
  CHECK_THROWS_AS(I({}, {}, T(1) / T(10), zero_iterations), std::invalid_argument);
  // tau <= 0 and NaN state: integration_error naming the reason and the step.
  I zero_step({}, {}, T(0));
  auto s = integrator.initial_state(vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), T(1)));
  try {
    zero_step.step(s);
    FAIL("no error for tau = 0");
  } catch (const geomint::integration_error& e) {
    CHECK(e.reason() == geomint::step_failure::invalid_step_size);
    CHECK(e.step() == 0);
  }
  s.p[0] = std::numeric_limits<T>::quiet_NaN();
  CHECK_THROWS_AS(integrator.step(s), geomint::integration_error);
}

TEST_CASE("scheme (23) as printed amplifies radial defects by 3 + 2 sqrt 2 per step", "[constraints][paper23]") {
  // Linearising (23) about the circle, the normalisations remove the radial component r of a
  // perturbation, leaving r_{k-1} + 6 r_k + r_{k+1} = 0: roots -3 -+ 2 sqrt(2). The dominant
  // one, -(3 + 2 sqrt 2), is the expected ratio of successive radial defects (exact
  // mathematics). 50 digits and tau = 1/1000 keep the defects in the linear regime: the
  // truncation error that seeds them is O(tau^4) = 1e-12, far above round-off.
  using T = geomint::test::cpp_bin_float_50;
  const T tau = T(1) / T(1000);
  vec<T, 2> prev = on_circle(T(0)), curr = on_circle(tau);
  std::vector<T> radial;
  for (long k = 1; k <= 10; ++k) {
    const vec<T, 2> next = geomint::paper23_step<T>(prev, curr, k);
    prev = curr;
    curr = next;
    radial.push_back(T(curr.norm() - T(1)));
  }
  using std::sqrt;
  const T expected = -(T(3) + T(2) * sqrt(T(2)));
  for (std::size_t k = 6; k < radial.size(); ++k) {
    const T ratio = radial[k] / radial[k - 1];
    INFO("step " << k << ": radial defect " << radial[k] << ", ratio " << ratio);
    using std::abs;
    CHECK(abs(T(ratio / expected - T(1))) < T(1) / T(100));
  }
}

TEST_CASE("constrained LPF: a compensated step from q and its carry is the step from their sum", "[constraints][compensated]") {
  // Compensated summation (phase_state::carry): the state is q + carry.q, p + carry.p, so the
  // path, the momentum row and the constraint rows of the step must see the carried parts.
  // Second method: the same scheme in 50 digits from the exact sums (as for the free schemes,
  // tests/schemes/test_conservation.cpp). The spherical pendulum from (sin, 0, -cos)(pi/4) with
  // the velocity (0, 4/5, 0), tau = 1/20; carries of 2^-30 and 2^-31, far above the round-off, so
  // that a step from the rounded parts alone misses by about |carry| (1e-9). The carry leaves
  // the constraint: q + carry.q is off the sphere by about 2^-30, and the step's end condition
  // f(q_{k+1}) = 0 puts the new point back on it, in both runs alike.
  using R = geomint::test::cpp_bin_float_50;
  using geomint::systems::spherical_pendulum;
  using geomint::systems::unit_sphere;
  using std::abs;
  const double r = std::sqrt(0.5);
  const vec<double, 3> q0(r, 0.0, -r), v0(0.0, 0.8, 0.0);
  const vec<double, 3> cq(std::ldexp(1.0, -30), -std::ldexp(1.0, -30), std::ldexp(1.0, -31));
  const vec<double, 3> cp(std::ldexp(1.0, -31), std::ldexp(1.0, -31), -std::ldexp(1.0, -30));
  auto check = [&]<class Scheme>() {
    geomint::constrained_integrator<Scheme, spherical_pendulum, unit_sphere, double> I({}, {}, 1.0 / 20);
    I.set_compensated_summation(true);
    CHECK(I.compensated_summation());
    auto s = I.initial_state(q0, v0);
    s.carry.q = cq;
    s.carry.p = cp;
    geomint::constrained_integrator<Scheme, spherical_pendulum, unit_sphere, R> J({}, {}, R(1) / R(20));
    geomint::phase_state<R, 3> t;
    for (int i = 0; i < 3; ++i) {
      t.q[i] = R(s.q[i]) + R(cq[i]);
      t.p[i] = R(s.p[i]) + R(cp[i]);
    }
    REQUIRE(I.try_step(s));
    REQUIRE(J.try_step(t));
    R gap_q(0), gap_p(0);
    for (int i = 0; i < 3; ++i) {
      gap_q = std::max(gap_q, R(abs(R(R(s.q[i]) + R(s.carry.q[i])) - t.q[i])));
      gap_p = std::max(gap_p, R(abs(R(R(s.p[i]) + R(s.carry.p[i])) - t.p[i])));
    }
    const R eps = R(std::numeric_limits<double>::epsilon());
    INFO(Scheme::name() << ": |q - q_50| = " << gap_q << ", |p - p_50| = " << gap_p);
    CHECK(gap_q <= R(16) * eps);
    CHECK(gap_p <= R(64) * eps);  // p = dL/dqdot at the path's end, projected (as for general LPF)
    CHECK((s.carry.p.array() == 0.0).all());  // the projected momentum is a value
  };
  check.template operator()<geomint::constrained_lpf<2>>();
  check.template operator()<geomint::constrained_lpf<3, geomint::gauss_interior>>();
}
