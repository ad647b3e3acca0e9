/// The step monitor (geomint/solvers/step_monitor.hpp), the validation of newton_options, and the
/// time of a state as t_0 + k tau.
///
/// Expected values:
///  - pendulum (L = qdot^2/2 + cos q), m = 2, tau = 10 from q = 1 at rest: without the monitor
///    the step converges while the energy goes from 1 - cos 1 ... to a value more than ten times
///    larger (the figures: 0.46 -> 44.1); the test measures that jump with the monitor
///    off and requires the monitored step to refuse it and leave the state unchanged;
///  - tau = 1/10 resolves the pendulum (per-step energy change O(tau^3), far below 1/10): 100
///    monitored steps must all pass;
///  - t_k = k tau: the time after k steps equals T(k) * tau exactly (computed, not summed).
#include <limits>
#include <stdexcept>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

using namespace geomint;

TEMPLATE_LIST_TEST_CASE("step monitor: an unresolved step is a failure, the state unchanged", "[monitor]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using I = integrator<lpf<2>, systems::pendulum, T>;
  const vec<T, 1> q0(T(1)), v0(T(0));

  // Unmonitored: the step converges, and the relative energy change is of order one.
  const I free_run(systems::pendulum{}, T(10));
  auto s = free_run.initial_state(q0, v0);
  const T e0 = free_run.energy(s);
  REQUIRE(free_run.try_step(s));
  using std::abs;
  const T relative = abs(T(free_run.energy(s) - e0)) / abs(free_run.energy(s));
  CHECK(relative > T(1) / T(2));

  // Monitored: the same step is refused with left_regime, the state untouched.
  I monitored(systems::pendulum{}, T(10));
  monitored.set_monitor(step_monitor<T>::on());
  auto m = monitored.initial_state(q0, v0);
  const auto before = m;
  const step_status st = monitored.try_step(m);
  CHECK(st.reason == step_failure::left_regime);
  CHECK(st.step == 0);
  CHECK(st.observed > 0.5);
  CHECK(st.message().find("left the scheme's regime") != std::string::npos);
  CHECK(m.q == before.q);
  CHECK(m.p == before.p);
  CHECK(m.step == 0);
  CHECK_THROWS_AS(monitored.step(m), integration_error);

  // A resolved run passes every monitored step.
  I resolved(systems::pendulum{}, T(1) / T(10));
  resolved.set_monitor(step_monitor<T>::on());
  auto r = resolved.initial_state(q0, v0);
  for (int k = 0; k < 100; ++k) REQUIRE(resolved.try_step(r));
}

TEST_CASE("step monitor: invalid bounds are refused where they are set", "[monitor]") {
  using T = double;
  integrator<lpf<2>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(10));
  step_monitor<T> m = step_monitor<T>::on();
  for (const T bad : {T(0), T(-1), T(2), std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
    m.max_relative_energy_change = bad;
    CHECK_THROWS_AS(I.set_monitor(m), std::invalid_argument);
  }
  m.max_relative_energy_change = T(1);
  CHECK_NOTHROW(I.set_monitor(m));
}

TEST_CASE("newton_options: max_iterations and tolerance_ulps must be positive", "[newton]") {
  using T = double;
  for (const int bad : {0, -5, 100001}) {
    newton_options<T> opt;
    opt.max_iterations = bad;
    CHECK_THROWS_AS(opt.validate(), std::invalid_argument);
    CHECK_THROWS_AS((integrator<lpf<2>, systems::pendulum, T>(systems::pendulum{}, T(1) / T(10), opt)), std::invalid_argument);
  }
  newton_options<T> ulps;
  ulps.tolerance_ulps = 0;
  CHECK_THROWS_AS(ulps.validate(), std::invalid_argument);
  // Changed after construction through options(): caught at the next solve, not ignored.
  integrator<lpf<2>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(10));
  I.options().max_iterations = 0;
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  CHECK_THROWS_AS(I.try_step(s), std::invalid_argument);
}

TEMPLATE_LIST_TEST_CASE("time is t0 + k tau, computed from k (not accumulated)", "[integrator]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  const T tau = T(1) / T(10);
  const integrator<midpoint_vi, systems::harmonic, T> I(systems::harmonic{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
  s.t = T(3);  // the start time t_0; commit_step keeps it as the origin of t_0 + k tau
  for (int k = 1; k <= 1000; ++k) {
    I.step(s);
    REQUIRE(s.t == T(3) + T(k) * tau);
  }
}
