/// The step skeleton on a large system: the outer solar system (18 dof, mechanics/zoo.hpp) in
/// 50 digits with LPF of degree 8 on Gauss interior nodes, 144 unknowns per step, whose Newton
/// matrix (144^2 entries of 64 bytes) lives on the heap (linalg/types.hpp, square_matrix) and
/// not in the engine or on the default 8 MiB stack of the test process. Expected values come
/// from exact mechanics and the method's published order, not from the code in another type:
/// - total linear momentum: the pair forces cancel (Newton's third law), and the LPF end update
///   p_{k+1} = p_k + tau sum_i b_i L_q(x_i) adds their sum, so sum p_i is kept to round-off;
/// - accuracy: LPF on the m - 1 Gauss interior nodes has the order 2(m - 1) = 14 of (m - 1)-stage
///   Gauss collocation (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed.,
///   Springer 2006, section II.1.3; docs/results/analysis.md), so halving the step divides the
///   error by about 2^14; each run's error is measured against a run at a quarter of its step.
/// The test process runs on the default 8 MiB stack.
///
/// The step cache (integrator::cache_type): the caller's, so that a const integrator serves
/// several trajectories at once. Expected values: (1) an integrator is a function of its
/// construction and of the cache a step is given, so steps with a cache of their own per
/// trajectory are bit for bit those of an integrator used for that trajectory alone; (2) a cache
/// only changes the start of the solve, so steps that never continue their cache's last step
/// solve the same equations and agree to the solver's tolerance (exact mathematics: one
/// solution).
#include <array>
#include <cmath>
#include <tuple>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::abs_diff;
using geomint::test::eps_tol;

namespace step_skeleton_test {
using T = boost::multiprecision::cpp_bin_float_50;
using solar = zoo::outer_solar;
using scheme = lpf<8, gauss_interior, lagrange, newton_solver>;  // the step skeleton's Newton form
using solar_integrator = integrator<scheme, solar, T>;
using solar_state = typename solar_integrator::state;

// The Newton matrix is on the heap, and so neither in the integrator (held by value here) nor
// on the stack: the integrator is a few step vectors, not 144^2 entries (1.3 MiB).
static_assert(heap_matrix<T, 8 * solar::dof>, "the outer solar system's Newton matrix at m = 8 is a heap matrix");
static_assert(sizeof(solar_integrator) < stack_matrix_bytes, "the integrator holds no fixed-size Newton matrix");

/// The state after `steps` steps of tau from Table 2.1's initial data, and the largest change of
/// the total linear momentum along the way (max over steps and components).
solar_state run(const T& tau, int steps, T& momentum_drift) {
  solar_integrator I(solar{}, tau);
  vec<T, 18> q0, v0;
  solar::initial_data<T>(q0, v0);
  solar_state s = I.initial_state(q0, v0);
  const vec<T, 3> P0 = solar::linear_momentum<T>(s.p);
  momentum_drift = T(0);
  for (int k = 0; k < steps; ++k) {
    const step_status st = I.try_step(s);
    REQUIRE(st);
    const vec<T, 3> P = solar::linear_momentum<T>(s.p);
    for (int i = 0; i < 3; ++i)
      if (abs_diff(P[i], P0[i]) > momentum_drift) momentum_drift = abs_diff(P[i], P0[i]);
  }
  return s;
}

/// max_i |a_i - b_i| over positions (AU) and momenta scaled by 1 / the largest |p| of b.
T distance(const solar_state& a, const solar_state& b) {
  const T p_scale = b.p.cwiseAbs().maxCoeff();
  T out(0);
  for (int i = 0; i < 18; ++i) {
    if (abs_diff(a.q[i], b.q[i]) > out) out = abs_diff(a.q[i], b.q[i]);
    if (abs_diff(a.p[i], b.p[i]) / p_scale > out) out = abs_diff(a.p[i], b.p[i]) / p_scale;
  }
  return out;
}

TEST_CASE("step skeleton: outer solar system, lpf m = 8 in 50 digits, Newton matrix on the heap", "[schemes][zoo]") {
  using std::abs;
  using std::log2;
  // 400 days (a tenth of Jupiter's period) in steps of 100, 50 and 25 days.
  const T tau(100);
  const int steps = 4;
  T drift_coarse, drift_half, drift_fine;
  const solar_state coarse = run(tau, steps, drift_coarse);
  const solar_state half = run(tau / T(2), 2 * steps, drift_half);
  const solar_state fine = run(tau / T(4), 4 * steps, drift_fine);

  // Linear momentum: sum p_i ~ 1e-5 (solar masses AU/day); round-off of a few ulps per step.
  vec<T, 18> q0, v0;
  solar::initial_data<T>(q0, v0);
  const T p_scale = (solar::mass_matrix<T>() * v0).cwiseAbs().maxCoeff();
  for (const T& drift : {drift_coarse, drift_half, drift_fine}) CHECK(drift <= eps_tol<T>(64) * T(4 * steps) * p_scale);

  // Order 14: e(tau) / e(tau / 2) = 2^14 asymptotically; e(tau) ~ |coarse - fine| (the fine run's
  // own error is 2^-28 of it), e(tau / 2) ~ |half - fine| (1 + 2^-14). Accept orders 12..16.
  const T e_coarse = distance(coarse, fine), e_half = distance(half, fine);
  INFO("errors at tau = 100, 50 days: " << e_coarse << ", " << e_half);
  REQUIRE(e_half > T(1000) * std::numeric_limits<T>::epsilon());  // above round-off: the order is measurable
  const T order = log2(T(e_coarse / e_half));
  INFO("observed order " << order);
  CHECK(order >= T(12));
  CHECK(order <= T(16));

  // Energy: its errors fall by the same order (the scheme is not energy-conserving, so they
  // are not zero: the check measures something).
  const T H0 = solar::energy_qp<T>(q0, vec<T, 18>(solar::mass_matrix<T>() * v0));
  const T dH_coarse = abs_diff(solar::energy_qp<T>(coarse.q, coarse.p), H0);
  const T dH_half = abs_diff(solar::energy_qp<T>(half.q, half.p), H0);
  INFO("energy errors at tau = 100, 50 days: " << dH_coarse << ", " << dH_half << " (H0 = " << H0 << ")");
  REQUIRE(dH_half > T(1000) * std::numeric_limits<T>::epsilon() * abs(H0));
  const T energy_order = log2(T(dH_coarse / dH_half));
  INFO("observed order of the energy error " << energy_order);
  CHECK(energy_order >= T(12));
  CHECK(energy_order <= T(16));
}

/// The fixed-point form with the Newton form behind it (lpf on a natural system, Gauss-interior
/// nodes) and the step skeleton alone (Newton on equispaced nodes), in double and 50 digits.
template <class Scheme, class S>
struct cache_case {
  using scheme = Scheme;
  using scalar = S;
};
using cache_cases = std::tuple<cache_case<lpf<4, gauss_interior>, double>,
                               cache_case<lpf<4, gauss_interior>, boost::multiprecision::cpp_bin_float_50>,
                               cache_case<lpf<3, equispaced>, double>,
                               cache_case<lpf<3, equispaced>, boost::multiprecision::cpp_bin_float_50>>;

TEMPLATE_LIST_TEST_CASE("step cache: one const integrator, a cache per trajectory", "[schemes][cache]", cache_cases) {
  using S = typename TestType::scalar;
  using pendulum_integrator = integrator<typename TestType::scheme, systems::pendulum, S>;
  using state = typename pendulum_integrator::state;
  const S tau = S(1) / S(8);
  const std::array<S, 2> angles{S(1), S(1) / S(2)};
  constexpr int steps = 12;

  // Each trajectory alone, with the integrator's own cache.
  std::array<std::array<state, steps>, 2> alone;
  for (std::size_t k = 0; k < 2; ++k) {
    pendulum_integrator I(systems::pendulum{}, tau);
    state s = I.initial_state(vec<S, 1>(angles[k]), vec<S, 1>(S(0)));
    for (state& out : alone[k]) {
      REQUIRE(I.try_step(s));
      out = s;
    }
  }

  // Both at once through one const integrator: a cache each, then one cache shared (each step
  // then starts fresh: its cache's last step is the other trajectory's).
  const pendulum_integrator C(systems::pendulum{}, tau);
  std::array<typename pendulum_integrator::cache_type, 2> own;
  typename pendulum_integrator::cache_type shared;
  std::array<state, 2> a, b;
  for (std::size_t k = 0; k < 2; ++k) a[k] = b[k] = C.initial_state(vec<S, 1>(angles[k]), vec<S, 1>(S(0)));
  S largest(0);
  for (int i = 0; i < steps; ++i)
    for (std::size_t k = 0; k < 2; ++k) {
      REQUIRE(C.try_step(a[k], own[k]));
      CHECK(a[k].q == alone[k][static_cast<std::size_t>(i)].q);
      CHECK(a[k].p == alone[k][static_cast<std::size_t>(i)].p);
      REQUIRE(C.try_step(b[k], shared));
      using std::max;
      largest = max(largest, max(abs_diff(b[k].q[0], a[k].q[0]), abs_diff(b[k].p[0], a[k].p[0])));
    }
  // Within 64 eps (|q|, |p| <= 1, 12 steps: the Newton tolerance is 64 eps per step, and the
  // sweeps stop at the eps level).
  INFO("largest difference, fresh against continuing steps: " << largest);
  CHECK(largest <= eps_tol<S>(64) * S(steps));
}

}  // namespace step_skeleton_test
