/// The one step interface (geomint/solvers/any_stepper.hpp): a user's map behind any_stepper
/// (function_stepper), an integrator erased (geomint::erase, geomint/stepper.hpp), and the
/// analyses that take a stepper (order study, difference Jacobian, energy behaviour).
///
/// Expected values:
///  - exact mathematics: the midpoint rule on the harmonic oscillator L = (qdot^2 - q^2)/2 is the
///    rotation of (q, p) by theta = 2 atan(tau/2) per step (its Cayley transform); a map that adds
///    1/4 to q is a translation, so after 40 steps q = 10 exactly;
///  - the integrator itself for the erased one: the erasure must not change a step, so the
///    erased stepper and the integrator it came from agree bit for bit (same scheme, same
///    starting cache), and they refuse the same steps for the same reason.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "catch.hpp"
#include "geomint/analysis/order_study.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/stepper.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::integrator_scalar_types;

namespace {
template <class T>
using dvec = dynamic_vector<T>;

template <class T>
dvec<T> one(const T& x) {
  return dvec<T>::Constant(1, x);
}

/// The midpoint rule on the harmonic oscillator in closed form: a rotation by 2 atan(tau/2).
template <class T>
function_stepper<T> midpoint_rotation() {
  return function_stepper<T>(
      1, "midpoint rotation",
      [](const dvec<T>& q, const dvec<T>& p, const T& tau, dvec<T>& q1, dvec<T>& p1) {
        using std::atan;
        using std::cos;
        using std::sin;
        const T a = T(2) * atan(tau / T(2));
        q1 = cos(a) * q + sin(a) * p;
        p1 = -sin(a) * q + cos(a) * p;
        return true;
      },
      [](const dvec<T>& q, const dvec<T>& p) { return (q[0] * q[0] + p[0] * p[0]) / T(2); });
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("function_stepper: a user's map, checked as every step", "[any_stepper]", integrator_scalar_types) {
  using T = TestType;
  auto rotation = midpoint_rotation<T>();
  CHECK(rotation.dof() == 1);
  CHECK(rotation.name() == "midpoint rotation");
  dvec<T> q1 = one(T(7)), p1 = one(T(7));
  REQUIRE(rotation.try_step(one(T(1)), one(T(0)), T(1) / T(2), q1, p1));
  using std::atan;
  using std::cos;
  CHECK(test::abs_diff(T(q1[0]), T(cos(T(2) * atan(T(1) / T(4))))) <= test::eps_tol<T>(4));
  CHECK(rotation.energy(one(T(1)), one(T(1))) == T(1));
  // Refused input, untouched output.
  q1 = one(T(7));
  p1 = one(T(7));
  CHECK(rotation.try_step(one(T(1)), one(T(0)), T(0), q1, p1).reason == step_failure::invalid_step_size);
  CHECK(rotation.try_step(one(T(1)), one(T(0)), std::numeric_limits<T>::quiet_NaN(), q1, p1).reason ==
        step_failure::invalid_step_size);
  CHECK(rotation.try_step(one(std::numeric_limits<T>::infinity()), one(T(0)), T(1), q1, p1).reason ==
        step_failure::non_finite_input);
  CHECK((q1[0] == T(7) && p1[0] == T(7)));
  CHECK_THROWS_AS(rotation.try_step(dvec<T>::Zero(2), one(T(0)), T(1), q1, p1), std::invalid_argument);
  // No Lagrangian: no momentum, no monitor, no compensated steps.
  CHECK_THROWS_AS(rotation.momentum(one(T(1)), one(T(1))), std::logic_error);
  CHECK_THROWS_AS(rotation.set_monitor(step_monitor<T>::on()), std::logic_error);
  dvec<T> cq = one(T(0)), cp = one(T(0));
  CHECK_THROWS_AS(rotation.try_step_compensated(one(T(1)), one(T(0)), cq, cp, T(1), q1, p1), std::logic_error);
  // A map that fails, or returns a non-finite or misshapen state, is refused with its reason.
  function_stepper<T> failing(1, "failing", [](const dvec<T>&, const dvec<T>&, const T&, dvec<T>&, dvec<T>&) { return false; });
  const step_status st = failing.try_step(one(T(1)), one(T(0)), T(1), q1, p1);
  CHECK(st.reason == step_failure::map_failed);
  CHECK(st.message().find("the one-step map reported a failure") != std::string::npos);
  CHECK(std::isnan(static_cast<double>(failing.energy(one(T(1)), one(T(0))))));
  function_stepper<T> blowing(1, "nan", [](const dvec<T>& q, const dvec<T>& p, const T&, dvec<T>& a, dvec<T>& b) {
    a = q;
    b = p;
    a[0] = std::numeric_limits<T>::quiet_NaN();
    return true;
  });
  CHECK(blowing.try_step(one(T(1)), one(T(0)), T(1), q1, p1).reason == step_failure::non_finite_iterate);
  function_stepper<T> wide(1, "wide", [](const dvec<T>&, const dvec<T>&, const T&, dvec<T>& a, dvec<T>& b) {
    a = dvec<T>::Zero(2);
    b = dvec<T>::Zero(2);
    return true;
  });
  CHECK(!wide.try_step(one(T(1)), one(T(0)), T(1), q1, p1));
  CHECK((q1[0] == T(7) && p1[0] == T(7)));
  CHECK_THROWS_AS(function_stepper<T>(0, "empty", [](const dvec<T>&, const dvec<T>&, const T&, dvec<T>&, dvec<T>&) {
                    return true;
                  }),
                  std::invalid_argument);
}

TEMPLATE_LIST_TEST_CASE("erase: the integrator, erased, steps as the integrator does", "[any_stepper]", integrator_scalar_types) {
  using T = TestType;
  using I = integrator<lpf<4, gauss_interior>, systems::pendulum, T>;
  I direct(systems::pendulum{}, T(1) / T(4));
  const auto erased = erase(direct);
  CHECK(erased->dof() == 1);
  CHECK(erased->name() == lpf<4, gauss_interior>::name());
  typename I::state s = direct.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  dvec<T> q = s.q, p = s.p, q1, p1;
  for (int k = 0; k < 10; ++k) {
    REQUIRE(direct.try_step(s));
    REQUIRE(erased->try_step(q, p, direct.tau(), q1, p1));
    CHECK((q1[0] == s.q[0] && p1[0] == s.p[0]));
    q = q1;
    p = p1;
  }
  // The Newton options and the monitor go with the erasure: one iteration does not converge,
  // and the midpoint rule at tau = 100 on the harmonic oscillator (tau omega = 100, above its
  // resolution bound 3, schemes/resolution.hpp) is refused by both.
  I starved(systems::pendulum{}, T(1) / T(4));
  starved.options().max_iterations = 1;
  const auto erased_starved = erase(starved);
  typename I::state s0 = starved.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  const step_status direct_status = starved.try_step(s0);
  const step_status erased_status = erased_starved->try_step(one(T(1)), one(T(0)), T(1) / T(4), q1, p1);
  CHECK(direct_status.reason == step_failure::no_convergence);
  CHECK(erased_status.reason == direct_status.reason);
  integrator<midpoint_vi, systems::harmonic, T> monitored(systems::harmonic{}, T(100));
  monitored.set_monitor(step_monitor<T>::on());
  const auto erased_monitored = erase(monitored);
  auto sm = monitored.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
  CHECK(monitored.try_step(sm).reason == step_failure::left_regime);
  CHECK(erased_monitored->try_step(one(T(1)), one(T(1)), T(100), q1, p1).reason == step_failure::left_regime);
}

TEMPLATE_LIST_TEST_CASE("the analyses take a stepper: failures keep their reason", "[any_stepper]", integrator_scalar_types) {
  using T = TestType;
  // The order study of the closed-form midpoint rule: order 2 (theta - tau = -tau^3/12 + ...).
  auto rotation = midpoint_rotation<T>();
  analysis::reference_function<T> exact = [](const T& t, dvec<T>& q, dvec<T>& p) {
    using std::cos;
    using std::sin;
    q = one(T(cos(t)));
    p = one(T(-sin(t)));
  };
  const auto r = analysis::order_study<T>(rotation, exact, one(T(1)), one(T(0)), T(1), {16, 32, 64});
  REQUIRE(r.ok);
  using std::abs;
  CHECK(abs(r.global_order - T(2)) < T(1) / T(20));
  // A map that fails at its third step: the study stops there and says why.
  int calls = 0;
  function_stepper<T> third(1, "fails at the third call", [&calls](const dvec<T>& q, const dvec<T>& p, const T&, dvec<T>& a, dvec<T>& b) {
    a = q;
    b = p;
    return ++calls < 3;
  });
  const auto failed = analysis::order_study<T>(third, exact, one(T(1)), one(T(0)), T(1), {4, 8});
  CHECK(!failed.ok);
  CHECK(failed.failure.find("step 1 failed at tau = T/4") != std::string::npos);
  CHECK(failed.failure.find("the one-step map reported a failure") != std::string::npos);
  // The difference Jacobian names the failed step's reason.
  analysis::phase_vector<T> z(2);
  z << T(1), T(0);
  calls = 0;
  try {
    (void)analysis::one_step_jacobian<T>(third, T(1), z);
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("the map failed at a perturbed state: geomint: step 0: the one-step map") !=
          std::string::npos);
  }
  // Energy behaviour: the rotation conserves q^2 + p^2 to rounding; the last state is returned;
  // a failing map stops the run with its reason.
  const auto e = analysis::energy_behaviour<T>(rotation, z, T(1) / T(4), 40);
  CHECK(e.ok);
  CHECK(e.steps == 40);
  CHECK(e.max_error <= test::eps_tol<T>(64));
  using std::atan;
  using std::cos;
  CHECK(test::abs_diff(T(e.last[0]), T(cos(T(80) * atan(T(1) / T(8))))) <= test::eps_tol<T>(256));
  calls = 0;
  const auto stopped = analysis::energy_behaviour<T>(third, z, T(1) / T(4), 40);
  CHECK(!stopped.ok);
  CHECK(stopped.steps == 2);
  CHECK(stopped.failure.find("the one-step map reported a failure") != std::string::npos);
}
