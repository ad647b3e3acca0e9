/// The step monitor (geomint/solvers/step_monitor.hpp), the validation of newton_options, and the
/// time of a state as t_0 + k tau.
///
/// Expected values, all from exact mathematics:
///  - harmonic oscillator L = (qdot^2 - q^2)/2: omega_max = 1; the midpoint rule advances
///    (q, p) by a rotation of theta = 2 atan(tau/2) per step (its Cayley transform), so from
///    (1, 1) q_k = cos(k theta) + sin(k theta); the exact flow gives q(t) = cos t + sin t,
///    q(1000) = 1.389 (the midpoint rule at tau = 100 gives 0.532: refused);
///  - pendulum L = qdot^2/2 + cos q: omega_max = sqrt|cos q|; Kepler L = |qdot|^2/2 + 1/|q|:
///    Hess V = (I - 3 r r^T / r^2) / r^3, omega_max = sqrt(2 / r^3); charged particle at rest
///    (A = (1 + r^2/2)/2 (-y, x), B = curl A = 1 + r^2): qddot = B J qdot, omega_max = B;
///  - a parabolic Kepler orbit (q = (1, 0), qdot = (0, sqrt 2)) has E = 0, a spring pendulum
///    released at rest at the pivot's height (r = 1, phi = pi/2) has E = 0: both are resolved
///    and conserve the energy, so every monitored step must pass;
///  - adding a constant to L (the potential's zero) changes no verdict and no observed ratio;
///  - the resolution bound of the midpoint rule, 3: its phase error per step is
///    3 - 2 atan(3/2) = 1.034 rad (schemes/resolution.hpp).
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/tableau_method.hpp"
#include "geomint/stepper.hpp"
#include "scalar_types.hpp"

using namespace geomint;

namespace {
/// The pendulum with its potential's zero moved by `shift`: L = qdot^2/2 + cos q - shift.
template <int shift>
struct shifted_pendulum : natural<shifted_pendulum<shift>, 1> {
  template <class S>
  static S potential(const vec<S, 1>& q) {
    using std::cos;
    return S(S(shift) - cos(q[0]));
  }
  template <class S>
  static mat<S, 1> mass_matrix() {
    return mat<S, 1>::Identity();
  }
};
}  // namespace

TEMPLATE_LIST_TEST_CASE("step monitor: omega_max of the linearised flow, against closed forms", "[monitor]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  using std::cos;
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  // Lower bound: the estimate is an upper bound of the spectral radius (up to rounding); upper:
  // within (32 kappa)^(1/32) of it, here below 1/20 (two distinct eigenvalue moduli at most).
  auto close = [&](const T& estimate, const T& exact) {
    CHECK(estimate >= exact * (T(1) - T(100) * eps));
    CHECK(estimate <= exact * (T(1) + T(1) / T(20)));
  };
  close(fastest_local_rate<systems::harmonic, T>({}, vec<T, 1>(T(1)), vec<T, 1>(T(1))), T(1));
  close(fastest_local_rate<systems::pendulum, T>({}, vec<T, 1>(T(1)), vec<T, 1>(T(0))), T(sqrt(cos(T(1)))));
  close(fastest_local_rate<systems::pendulum, T>({}, vec<T, 1>(T(3)), vec<T, 1>(T(2))), T(sqrt(abs(cos(T(3))))));
  const T r = T(1) / T(2);
  close(fastest_local_rate<systems::kepler, T>({}, vec<T, 2>(r, T(0)), vec<T, 2>(T(0), T(1))), T(sqrt(T(2) / (r * r * r))));
  close(fastest_local_rate<systems::charged, T>({}, vec<T, 2>(T(10), T(0)), vec<T, 2>(T(0), T(0))), T(101));
}

TEMPLATE_LIST_TEST_CASE("step monitor: an unresolved step is refused, the state unchanged", "[monitor]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using I = integrator<lpf<2>, systems::pendulum, T>;
  const vec<T, 1> q0(T(1)), v0(T(0));

  // Unmonitored: the step converges, and the energy changes by more than half its new value.
  I free_run(systems::pendulum{}, T(10));
  auto s = free_run.initial_state(q0, v0);
  const T e0 = free_run.energy(s);
  REQUIRE(free_run.try_step(s));
  using std::abs;
  CHECK(abs(T(free_run.energy(s) - e0)) > abs(free_run.energy(s)) / T(2));

  // Monitored: refused by the resolution check (tau omega = 10 sqrt(cos 1) = 7.35 > 3, the
  // bound of lpf<2>), the state untouched.
  I monitored(systems::pendulum{}, T(10));
  monitored.set_monitor(step_monitor<T>::on());
  CHECK(monitored.monitor().max_tau_omega == T(3));
  auto m = monitored.initial_state(q0, v0);
  const auto before = m;
  const step_status st = monitored.try_step(m);
  CHECK(st.reason == step_failure::left_regime);
  CHECK(st.regime_check == monitor_check::resolution);
  CHECK(st.step == 0);
  CHECK(st.observed > 7.3);
  CHECK(st.observed < 7.4);
  CHECK(st.message().find("tau * omega_max") != std::string::npos);
  CHECK(m.q == before.q);
  CHECK(m.p == before.p);
  CHECK(m.step == 0);
  CHECK_THROWS_AS(monitored.step(m), integration_error);

  // Without the resolution check the energy check refuses the same step.
  step_monitor<T> energy_only = step_monitor<T>::on();
  energy_only.max_tau_omega = std::numeric_limits<T>::infinity();
  monitored.set_monitor(energy_only);
  const step_status by_energy = monitored.try_step(m);
  CHECK(by_energy.regime_check == monitor_check::energy);
  CHECK(by_energy.observed > 0.1);
  CHECK(m.step == 0);

  // A resolved run passes every monitored step.
  I resolved(systems::pendulum{}, T(1) / T(10));
  resolved.set_monitor(step_monitor<T>::on());
  auto r = resolved.initial_state(q0, v0);
  for (int k = 0; k < 100; ++k) REQUIRE(resolved.try_step(r));
}

TEMPLATE_LIST_TEST_CASE("step monitor: the energy check does not depend on the potential's zero", "[monitor]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  step_monitor<T> energy_only = step_monitor<T>::on();
  energy_only.max_tau_omega = std::numeric_limits<T>::infinity();
  auto first_step = [&]<class Sys>(Sys) {
    integrator<lpf<2>, Sys, T> I(Sys{}, T(10));
    I.set_monitor(energy_only);
    auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    return I.try_step(s);
  };
  const step_status a = first_step(shifted_pendulum<0>{}), b = first_step(shifted_pendulum<-1000>{}),
                    c = first_step(shifted_pendulum<1000>{});
  CHECK(a.regime_check == monitor_check::energy);
  CHECK(b.regime_check == monitor_check::energy);
  CHECK(c.regime_check == monitor_check::energy);
  // The same ratio up to the rounding of L + 1000 (about 1000 eps relative).
  CHECK(std::abs(b.observed - a.observed) <= 1e-9 * a.observed);
  CHECK(std::abs(c.observed - a.observed) <= 1e-9 * a.observed);
}

TEMPLATE_LIST_TEST_CASE("step monitor: resolved runs through extrema of the kinetic energy are never refused",
                        "[monitor]", geomint::test::integrator_scalar_types) {
  // Each run is resolved (tau omega_max <= 1/10 against bounds of 3 and more) and its energy
  // error, measured here without the monitor, stays below 1/100 of the energy: correct runs.
  // Their steps cross extrema of the kinetic energy, where the exchange |Delta(p . qdot)| + |Delta L|
  // of a step vanishes to first order while its energy error does not (a turning point of the
  // pendulum; for Henon-Heiles, extrema of the total kinetic energy while the two degrees of
  // freedom still exchange energy). Against the exchange alone these steps were refused:
  // Henon-Heiles trapezoidal step 250, midpoint step 146; the pendulum with Ruth's method
  // (Ruth 1983; methods/catalogue.hpp) step 33.
  using T = TestType;
  using std::abs;
  using std::max;
  auto worst_error = [&]<class Scheme, class Sys>(Scheme, Sys, const vec<T, Sys::dof>& q0, const vec<T, Sys::dof>& v0,
                                                  const T& tau, int steps, bool monitored) {
    integrator<Scheme, Sys, T> I(Sys{}, tau);
    if (monitored) I.set_monitor(step_monitor<T>::on());
    auto s = I.initial_state(q0, v0);
    const T e0 = I.energy(s);
    T worst(0);
    for (int k = 0; k < steps; ++k) {
      const step_status st = I.try_step(s);
      INFO("step " << k << ": " << st.message());
      REQUIRE(st);
      worst = max(worst, T(abs(T(I.energy(s) - e0))));
    }
    return worst;
  };
  vec<T, 2> q0, v0;
  zoo::henon_heiles::initial_data<T>(q0, v0);  // E = 1/8
  const T tenth = T(1) / T(10);
  for (const bool monitored : {false, true}) {
    CHECK(worst_error(trapezoidal_vi{}, zoo::henon_heiles{}, q0, v0, tenth, 400, monitored) < T(1) / T(800));
    CHECK(worst_error(midpoint_vi{}, zoo::henon_heiles{}, q0, v0, tenth, 400, monitored) < T(1) / T(800));
    // The pendulum from rest at q = 1: E = -cos 1, |E| = 0.54; turning points every half period.
    for (const T& tau : {tenth, T(2) * tenth})
      CHECK(worst_error(methods::tableau_method<methods::ruth3>{}, systems::pendulum{}, vec<T, 1>(T(1)),
                        vec<T, 1>(T(0)), tau, 400, monitored) < T(1) / T(200));
  }
}

TEMPLATE_LIST_TEST_CASE("step monitor: runs with energy 0 that conserve it are never refused", "[monitor]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  // Parabolic Kepler orbit, E = 0, at every step size from 1e-2 to 1e-6.
  for (const T& tau : {T(1) / T(100), T(1) / T(1000000)}) {
    integrator<galerkin_vi<4>, systems::kepler, T> I(systems::kepler{}, tau);
    I.set_monitor(step_monitor<T>::on());
    auto s = I.initial_state(vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), T(sqrt(T(2)))));
    CHECK(abs(I.energy(s)) <= T(4) * eps);
    for (int k = 0; k < 50; ++k) REQUIRE(I.try_step(s));
  }
  // Spring pendulum released at rest at the pivot's height (E = 0).
  {
    integrator<lpf<3, gauss_interior>, zoo::spring_pendulum, T> I(zoo::spring_pendulum{}, T(1) / T(100));
    I.set_monitor(step_monitor<T>::on());
    const T pi = boost::math::constants::pi<T>();
    auto s = I.initial_state(vec<T, 2>(T(1), pi / T(2)), vec<T, 2>(T(0), T(0)));
    CHECK(abs(I.energy(s)) <= T(4) * eps);
    for (int k = 0; k < 50; ++k) REQUIRE(I.try_step(s));
  }
  // At rest at the equilibrium: nothing changes, nothing is refused.
  {
    integrator<midpoint_vi, systems::harmonic, T> I(systems::harmonic{}, T(1) / T(10));
    I.set_monitor(step_monitor<T>::on());
    auto s = I.initial_state(vec<T, 1>(T(0)), vec<T, 1>(T(0)));
    for (int k = 0; k < 10; ++k) REQUIRE(I.try_step(s));
  }
}

TEMPLATE_LIST_TEST_CASE("step monitor: the midpoint rule at tau = 100 is refused, at tau <= 3 it follows its closed form",
                        "[monitor]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  using std::atan;
  using std::cos;
  using std::sin;
  const T eps = std::numeric_limits<T>::epsilon();
  using I = integrator<midpoint_vi, systems::harmonic, T>;
  // tau = 100, 10 steps: the scheme's q(1000) is cos(10 theta) + sin(10 theta) with theta =
  // 2 atan 50, far from the flow's cos 1000 + sin 1000; the monitor refuses the first step.
  {
    I free_run(systems::harmonic{}, T(100));
    auto s = free_run.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
    free_run.advance(s, 10);
    const T theta = T(2) * atan(T(50));
    CHECK(abs(T(s.q[0] - (cos(T(10) * theta) + sin(T(10) * theta)))) <= T(1000) * eps);
    CHECK(abs(T(s.q[0] - (cos(T(1000)) + sin(T(1000))))) > T(1) / T(2));
    I monitored(systems::harmonic{}, T(100));
    monitored.set_monitor(step_monitor<T>::on());
    auto m = monitored.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
    const step_status st = monitored.try_step(m);
    CHECK(st.regime_check == monitor_check::resolution);
    CHECK(std::abs(st.observed - 100) < 1e-9);
    CHECK(st.bound == 3);
  }
  // The bound: its phase error per step is 3 - 2 atan(3/2) = 1.034 rad.
  CHECK(T(3) - T(2) * atan(T(3) / T(2)) > T(1));
  CHECK(T(3) - T(2) * atan(T(3) / T(2)) < T(11) / T(10));
  // tau = 3 (tau omega = 3 exactly) is accepted, and the run follows the closed form.
  for (const T& tau : {T(3), T(1) / T(10)}) {
    I monitored(systems::harmonic{}, tau);
    monitored.set_monitor(step_monitor<T>::on());
    auto m = monitored.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
    const T theta = T(2) * atan(tau / T(2));
    for (int k = 1; k <= 20; ++k) {
      REQUIRE(monitored.try_step(m));
      CHECK(abs(T(m.q[0] - (cos(T(k) * theta) + sin(T(k) * theta)))) <= T(1000) * eps);
    }
  }
  I too_coarse(systems::harmonic{}, T(31) / T(10));
  too_coarse.set_monitor(step_monitor<T>::on());
  auto c = too_coarse.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
  CHECK(too_coarse.try_step(c).regime_check == monitor_check::resolution);
}

TEMPLATE_LIST_TEST_CASE("step monitor: the charged particle's gyration must be resolved", "[monitor]",
                        geomint::test::integrator_scalar_types) {
  // At q = (10, 0), B = 101: galerkin m = 2 (bound 5) resolves tau = 1/40 (tau B = 2.5) and
  // refuses tau = 1/10 (tau B = 10.1), through the type-erased stepper as the tools use it.
  using T = TestType;
  const auto stepper = make_stepper<systems::charged, T>(scheme_spec{"galerkin", "equispaced", "lagrange", 2});
  stepper->set_monitor(step_monitor<T>::on());
  CHECK(stepper->monitor().max_tau_omega == T(5));
  dynamic_vector<T> q(2), v(2), q1, p1;
  q << T(10), T(0);
  v << T(0), T(1);
  const dynamic_vector<T> p = stepper->momentum(q, v);
  CHECK(stepper->try_step(q, p, T(1) / T(40), q1, p1));
  const step_status st = stepper->try_step(q, p, T(1) / T(10), q1, p1);
  CHECK(st.regime_check == monitor_check::resolution);
  CHECK(st.observed > 10.1);
}

TEST_CASE("step monitor: invalid bounds are refused where they are set", "[monitor]") {
  using T = double;
  integrator<lpf<2>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(10));
  step_monitor<T> m = step_monitor<T>::on();
  for (const T bad : {T(0), T(-1), T(2), std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
    m.max_energy_change_ratio = bad;
    CHECK_THROWS_AS(I.set_monitor(m), std::invalid_argument);
  }
  m.max_energy_change_ratio = T(1);
  CHECK_NOTHROW(I.set_monitor(m));
  for (const T bad : {T(-1), std::numeric_limits<T>::quiet_NaN()}) {
    m.max_tau_omega = bad;
    CHECK_THROWS_AS(I.set_monitor(m), std::invalid_argument);
  }
  m.max_tau_omega = T(7);  // an explicit bound is kept
  I.set_monitor(m);
  CHECK(I.monitor().max_tau_omega == T(7));
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
  integrator<midpoint_vi, systems::harmonic, T> I(systems::harmonic{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
  s.t = T(3);  // the start time t_0; commit_step keeps it as the origin of t_0 + k tau
  for (int k = 1; k <= 1000; ++k) {
    I.step(s);
    REQUIRE(s.t == T(3) + T(k) * tau);
  }
}
