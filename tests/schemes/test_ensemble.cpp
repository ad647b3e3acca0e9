/// Ensembles (geomint/ensemble.hpp) against independent oracles: the pendulum's exact flow
/// (Jacobi elliptic functions in 50 digits, analysis/closed_form_flows.hpp), and the scalar
/// integrator stepping each trajectory alone, a separate implementation of the same map (its
/// own tests check it against exact flows). Where no compiler contraction differs (no FMA in the
/// target) and the forces use the same functions (SLEEF's sine of the same width, Henon-Heiles'
/// polynomial), every trajectory is the scalar integrator's bit for bit: the ensemble does each
/// lane's operations in the same order. With FMA, the compiler may contract the two codes'
/// multiply-adds differently: then within 64 N eps (N steps, entries of size at most 3).
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "catch.hpp"
#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/ensemble.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"

namespace {

template <int n>
using states = std::vector<geomint::phase_state<double, n>>;

/// Random initial data: the pendulum released from rest at 0.1..2.5 rad, Henon-Heiles from the
/// origin with energies 1/24..1/12 in random directions (bounded motion).
template <class Sys>
states<Sys::dof> random_states(int count, unsigned seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  states<Sys::dof> s(static_cast<std::size_t>(count));
  for (auto& x : s) {
    if constexpr (Sys::dof == 1) {
      x.q[0] = 0.1 + 2.4 * u(g);
    } else {
      const double energy = (1 + u(g)) / 24, phi = 6.283185307179586 * u(g);
      x.p << std::sqrt(2 * energy) * std::cos(phi), std::sqrt(2 * energy) * std::sin(phi);
    }
  }
  return s;
}

/// The scalar integrator with compensated summation, one trajectory alone: its steps until
/// `steps` or its first failure (then `failed`).
template <int M, class Sys>
void step_alone(geomint::phase_state<double, Sys::dof>& x, double tau, long steps, const geomint::newton_options<double>& opt,
                bool* failed = nullptr) {
  geomint::integrator<geomint::lpf_fixed_point<M>, Sys, double> I(Sys{}, tau, opt);
  I.set_compensated_summation(true);
  for (long k = 0; k < steps; ++k) {
    const geomint::step_status st = I.try_step(x);
    if (!st) {
      if (failed) *failed = true;
      return;
    }
  }
}

template <int n>
void require_same(const geomint::phase_state<double, n>& a, const geomint::phase_state<double, n>& b, long steps) {
  REQUIRE(a.step == b.step);
  REQUIRE(a.t == b.t);
#if defined(__FMA__)
  const double tol = 64 * static_cast<double>(steps) * std::numeric_limits<double>::epsilon() * 3;
  for (int r = 0; r < n; ++r) {
    CHECK(std::abs((a.q[r] + a.carry.q[r]) - (b.q[r] + b.carry.q[r])) <= tol);
    CHECK(std::abs((a.p[r] + a.carry.p[r]) - (b.p[r] + b.carry.p[r])) <= tol);
  }
#else
  (void)steps;
  CHECK(a.q == b.q);
  CHECK(a.p == b.p);
  CHECK(a.carry.q == b.carry.q);
  CHECK(a.carry.p == b.carry.p);
#endif
}

template <int M, class Sys, int W>
void check_against_alone(double tau, long steps, bool stop_on_rate) {
  geomint::newton_options<double> opt;
  opt.stop_on_rate = stop_on_rate;
  // 2W + 1 trajectories: two full blocks and one of a single trajectory (the padded lanes).
  const auto start = random_states<Sys>(2 * W + 1, 7);
  auto together = start;
  const geomint::ensemble_integrator<M, Sys, W> E(tau, opt);
  E.integrate(together, steps);
  for (std::size_t k = 0; k < start.size(); ++k) {
    auto alone = start[k];
    step_alone<M, Sys>(alone, tau, steps, opt);
    INFO("trajectory " << k);
    require_same<Sys::dof>(together[k], alone, steps);
  }
}

}  // namespace

TEST_CASE("ensemble: every trajectory is the scalar integrator's on it", "[schemes][ensemble]") {
  SECTION("pendulum, m = 10, the default lanes") { check_against_alone<10, geomint::systems::pendulum, geomint::ensemble_width>(0.9, 300, false); }
  SECTION("pendulum, m = 6, 2 lanes, stopping on the rate") { check_against_alone<6, geomint::systems::pendulum, 2>(0.5, 300, true); }
  SECTION("Henon-Heiles, m = 8, the default lanes") { check_against_alone<8, geomint::zoo::henon_heiles, geomint::ensemble_width>(0.7, 300, false); }
}

TEST_CASE("ensemble: the pendulum follows its exact flow", "[schemes][ensemble]") {
  // LPF m = 12 (order 22) with tau = 1/4: the method's error is far below 1e-11 at T = 100; the
  // round-off of 400 compensated steps is about 1e-15.
  using R = boost::multiprecision::cpp_bin_float_50;
  auto s = random_states<geomint::systems::pendulum>(5, 3);
  const auto start = s;
  geomint::ensemble_integrator<12, geomint::systems::pendulum> E(0.25);
  E.integrate(s, 400);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const auto exact = geomint::analysis::pendulum_from_rest<R>(R(start[k].q[0]), R(100));
    INFO("trajectory " << k << ", theta0 = " << start[k].q[0]);
    CHECK(s[k].t == 100);
    CHECK(std::abs(s[k].q[0] - static_cast<double>(exact.q[0])) < 1e-11);
    CHECK(std::abs(s[k].p[0] - static_cast<double>(exact.p[0])) < 1e-11);
  }
}

TEST_CASE("ensemble: bad input and failing steps are reported with the trajectory", "[schemes][ensemble]") {
  using sys = geomint::zoo::henon_heiles;
  REQUIRE_THROWS_AS((geomint::ensemble_integrator<8, sys>(0.0)), std::invalid_argument);
  REQUIRE_THROWS_AS((geomint::ensemble_integrator<8, sys>(std::numeric_limits<double>::infinity())), std::invalid_argument);
  const geomint::ensemble_integrator<8, sys, 2> E(0.5);
  REQUIRE_THROWS_AS(E.integrate(std::span<geomint::phase_state<double, 2>>(), -1), std::invalid_argument);

  SECTION("non-finite data: refused before any step, naming the trajectory") {
    auto s = random_states<sys>(5, 11);
    s[3].p[1] = std::numeric_limits<double>::quiet_NaN();
    const auto before = s;
    REQUIRE_THROWS_WITH(E.integrate(s, 10), Catch::Matchers::Contains("trajectory 3"));
    for (std::size_t k = 0; k < s.size(); ++k) CHECK(s[k].step == before[k].step);
  }
  SECTION("an escaping trajectory: its block stops before the failing step, the blocks before are complete") {
    // Energy 1/2 > 1/6: trajectory 3 leaves the potential well and its sweeps stop converging.
    auto s = random_states<sys>(6, 13);
    s[3].p << 1.0, 0.0;
    const auto start = s;
    bool thrown = false;
    try {
      E.integrate(s, 400);
    } catch (const geomint::integration_error& e) {
      thrown = true;
      CHECK_THAT(e.what(), Catch::Matchers::Contains("trajectory 3"));
    }
    REQUIRE(thrown);
    // Trajectories 0, 1 (the block before) are complete; 2, 3 are where the scalar integrator's
    // steps of trajectory 3 ended (at its first failure); 4, 5 untouched.
    geomint::newton_options<double> opt;
    for (std::size_t k : {0u, 1u}) {
      auto alone = start[k];
      step_alone<8, sys>(alone, 0.5, 400, opt);
      require_same<2>(s[k], alone, 400);
    }
    auto alone = start[3];
    bool failed = false;
    step_alone<8, sys>(alone, 0.5, 400, opt, &failed);
    REQUIRE(failed);
    require_same<2>(s[3], alone, alone.step);
    CHECK(s[2].step == s[3].step);
    CHECK(s[4].step == 0);
    CHECK(s[5].step == 0);
  }
}
