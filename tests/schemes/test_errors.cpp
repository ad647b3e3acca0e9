/// Error paths: every failure is reported with its reason and step index, never a silent state.
#include <cmath>
#include <limits>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

using namespace geomint;

namespace {
/// Inverted oscillator L = 1/2 xdot^2 + 4 x^2: for m = 2 the one-step Newton matrix is
/// [[4, -1], [8 - tau^2 V'', -4]] (rows: eq. 9 scaled by tau, eq. 12 scaled by tau^2), with
/// determinant -8 - tau^2 V'' = 0 at V'' = -8, tau = 1 (exactly, in every scalar type).
struct inverted : natural<inverted, 1> {
  template <class S>
  static S potential(const vec<S, 1>& q) { return S(-4) * q[0] * q[0]; }
  template <class T>
  static mat<T, 1> mass_matrix() { return mat<T, 1>::Identity(); }
};
/// V = -4 x^2 + exp(x), tau = 1, x = p = 0: eliminating x^{k+1} leaves exp(eta) = 0, which has
/// no root; Newton walks eta -> eta - 1 forever (divergent).
struct no_root : natural<no_root, 1> {
  template <class S>
  static S potential(const vec<S, 1>& q) {
    using std::exp;
    return S(-4) * q[0] * q[0] + exp(q[0]);
  }
  template <class T>
  static mat<T, 1> mass_matrix() { return mat<T, 1>::Identity(); }
};
}  // namespace

TEMPLATE_LIST_TEST_CASE("tau <= 0 or non-finite tau is rejected with the step index", "[lpf][errors]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  for (const T& tau : {T(0), T(-1), std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
    integrator<scheme16, systems::pendulum, T> I(systems::pendulum{}, tau);
    auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    s.step = 7;
    const auto before = s;
    const step_status st = I.try_step(s);
    CHECK_FALSE(st);
    CHECK(st.reason == step_failure::invalid_step_size);
    CHECK(st.step == 7);
    CHECK(s.q == before.q);
    CHECK(s.step == 7);
    try {
      I.step(s);
      FAIL("no exception");
    } catch (const integration_error& e) {
      CHECK(e.reason() == step_failure::invalid_step_size);
      CHECK(e.step() == 7);
      CHECK(std::string(e.what()).find("step 7") != std::string::npos);
    }
    CHECK_THROWS_AS(I.two_step(vec<T, 1>(T(0)), vec<T, 1>(T(1))), integration_error);
  }
}

TEMPLATE_LIST_TEST_CASE("NaN input is rejected", "[lpf][errors]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  integrator<lpf<3, gauss_interior>, systems::charged, T> I(systems::charged{}, T(1) / T(10));
  auto s = I.initial_state(vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), T(1)));
  s.p[1] = nan;
  step_status st = I.try_step(s);
  CHECK(st.reason == step_failure::non_finite_input);
  CHECK(st.step == 0);
  s.p[1] = T(1);
  s.q[0] = nan;
  CHECK(I.try_step(s).reason == step_failure::non_finite_input);
  try {
    I.two_step(vec<T, 2>(T(1), T(0)), vec<T, 2>(nan, T(0)), 12);
    FAIL("no exception");
  } catch (const integration_error& e) {
    CHECK(e.reason() == step_failure::non_finite_input);
    CHECK(e.step() == 12);
  }
}

TEMPLATE_LIST_TEST_CASE("divergent Newton and singular Jacobian are reported", "[lpf][errors]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  {
    integrator<scheme16, no_root, T> I(no_root{}, T(1));
    I.options().max_iterations = 20;
    phase_state<T, 1> s;
    s.step = 3;
    const step_status st = I.try_step(s);
    INFO(st.message());
    CHECK(st.reason == step_failure::no_convergence);
    CHECK(st.step == 3);
    CHECK(st.iterations == 20);
    CHECK(s.step == 3);
    CHECK(s.q[0] == T(0));
  }
  {
    integrator<scheme16, inverted, T> I(inverted{}, T(1));
    auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    const step_status st = I.try_step(s);
    INFO(st.message());
    CHECK(st.reason == step_failure::singular_jacobian);
    CHECK_THROWS_AS(I.step(s), integration_error);
    I.set_tau(T(1) / T(2));  // away from the singular step size it works
    CHECK(I.try_step(s));
  }
}
