/// LPF on Gauss-interior nodes in the fixed-point Nystrom form (schemes/gauss_fixed_point.hpp, its stopping
/// rule schemes/fixed_point_stopping.hpp and its multiprecision solve schemes/stages_in_double.hpp),
/// as `lpf_fixed_point<m>` (schemes/lpf_fixed_point.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "geomint/methods/collocation_rkn.hpp"
#include "geomint/methods/symplectic_rounding.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "geomint/stepper.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::eps_tol;

namespace {

/// A binary float wide enough to hold every sum and difference of the stored coefficients of
/// double and cpp_bin_float_50 exactly: they are multiples of a grid of at least 2^-167 below 4,
/// so at most 170 significant bits, and cpp_bin_float_100 has 333.
using wide = geomint::test::cpp_bin_float_100;

/// The largest violation, in exact arithmetic, of the relations that make the stored method
/// symplectic: e_i = 1 - c_i and mu_ji - mu_ij = e_i - e_j.
template <class K>
wide symplecticity_violation(const K& k, int S) {
  using std::abs;
  wide worst(0);
  for (int i = 0; i < S; ++i) {
    const auto I = static_cast<std::size_t>(i);
    const wide d = abs(wide(k.e[I]) - (wide(1) - wide(k.c[I])));
    if (d > worst) worst = d;
    for (int j = 0; j < S; ++j) {
      const auto J = static_cast<std::size_t>(j);
      const wide r = abs((wide(k.mu[J][I]) - wide(k.mu[I][J])) - (wide(k.e[I]) - wide(k.e[J])));
      if (r > worst) worst = r;
    }
  }
  return worst;
}

/// Kepler (e = 1/2) from the pericentre.
template <class T>
std::pair<vec<T, 2>, vec<T, 2>> kepler_start() {
  using std::sqrt;
  const T e = T(1) / T(2);
  return {vec<T, 2>(T(1) - e, T(0)), vec<T, 2>(T(0), T(sqrt((T(1) + e) / (T(1) - e))))};
}

/// 20 steps of lpf_fixed_point<8> on Kepler from the pericentre, tau = 1/8, with the options
/// `configure` sets: the final state and the iterations of all steps.
template <class T, class Configure>
std::tuple<vec<T, 2>, vec<T, 2>, long> kepler_20_steps(Configure configure) {
  const auto start = kepler_start<T>();
  integrator<lpf_fixed_point<8>, systems::kepler, T> I(systems::kepler{}, T(1) / T(8));
  configure(I.options());
  auto s = I.initial_state(start.first, start.second);
  long iterations = 0;
  for (int step = 0; step < 20; ++step) {
    const step_status st = I.try_step(s);
    REQUIRE(st);
    iterations += st.iterations;
  }
  return {s.q, s.p, iterations};
}

template <int M, class T>
void check_coefficients() {
  constexpr int S = M - 1;
  using std::abs;
  const auto k = schemes::detail::gauss_nystrom_coefficients<T, S>::make();
  // Exact mathematics: the stored relations hold with no rounding at all (checked in `wide`,
  // where every difference of them is exact): symplecticity, and the symmetry
  // mu_i'j' = mu_ij + c_j - c_i (i' = S-1-i) that mu_combination relies on.
  CHECK(symplecticity_violation(k, S) == wide(0));
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j) {
      const auto I = static_cast<std::size_t>(i), J = static_cast<std::size_t>(j);
      const auto Im = static_cast<std::size_t>(S - 1 - i), Jm = static_cast<std::size_t>(S - 1 - j);
      CHECK(wide(k.mu[Im][Jm]) - wide(k.mu[I][J]) == wide(k.c[J]) - wide(k.c[I]));
    }
  // A second computation in 100 digits: each stored value is the exact one rounded to the grid
  // (within one grid unit; the grid is a power-of-two multiple of T's epsilon, at most 2^4).
  const auto w = schemes::detail::gauss_nystrom_coefficients<wide, S>::make();
  CHECK(wide(k.grid) <= wide(16) * wide(std::numeric_limits<T>::epsilon()));
  for (int i = 0; i < S; ++i) {
    const auto I = static_cast<std::size_t>(i);
    CHECK(abs(wide(k.c[I]) - w.c[I]) <= wide(k.grid));
    CHECK(abs(wide(k.b[I]) - w.b[I]) <= wide(4) * wide(std::numeric_limits<T>::epsilon()));
    for (int j = 0; j < S; ++j) {
      const auto J = static_cast<std::size_t>(j);
      CHECK(abs(wide(k.mu[I][J]) - w.mu[I][J]) <= wide(2) * wide(k.grid));
    }
  }
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: coefficients exactly symplectic in the scalar", "[lpf_fixed_point]",
                        geomint::test::integrator_scalar_types) {
  check_coefficients<2, TestType>();
  check_coefficients<4, TestType>();
  check_coefficients<8, TestType>();
  check_coefficients<16, TestType>();
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: the coefficients computed once are those computed afresh", "[lpf_fixed_point]",
                        geomint::test::integrator_scalar_types) {
  // make() computes them once per (T, S) and hands out copies: each is bit for bit the direct
  // computation (the Gauss rule, then the symplectic rounding), and a copy changed by its
  // holder leaves the next one alone.
  using T = TestType;
  auto same_as_fresh = []<int S>() {
    const auto fresh = methods::symplecticize(methods::gauss_collocation_rkn<T, S>());
    for (int round = 0; round < 2; ++round) {
      auto k = schemes::detail::gauss_nystrom_coefficients<T, S>::make();
      CHECK(k.grid == fresh.grid);
      CHECK(k.mirrored == fresh.mirrored);
      for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
        CHECK(k.c[i] == fresh.c[i]);
        CHECK(k.e[i] == fresh.e[i]);
        CHECK(k.b[i] == fresh.b[i]);
        for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) CHECK(k.mu[i][j] == fresh.mu[i][j]);
      }
      k.c[0] = T(7);  // the holder's copy only
    }
  };
  same_as_fresh.template operator()<3>();
  same_as_fresh.template operator()<7>();  // (not S = 15: 1.2 s more under the sanitizers, the same code)
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: integrators built one after the other take the steps of one built alone",
                        "[lpf_fixed_point]", geomint::test::integrator_scalar_types) {
  // Two integrators of the same (T, m) built in turn share the computed coefficients and
  // nothing else: stepped alternately, each takes bit for bit the steps of the one built
  // alone (12 steps of Kepler, e = 1/2, tau = 1/8; a continuing step reads its own integrator's
  // cache).
  using T = TestType;
  const auto start = kepler_start<T>();
  const T tau = T(1) / T(8);
  using kepler_integrator = integrator<lpf_fixed_point<8>, systems::kepler, T>;
  std::array<std::pair<vec<T, 2>, vec<T, 2>>, 12> alone;
  {
    kepler_integrator A(systems::kepler{}, tau);
    auto a = A.initial_state(start.first, start.second);
    for (auto& state : alone) {
      REQUIRE(A.try_step(a));
      state = {a.q, a.p};
    }
  }
  kepler_integrator B(systems::kepler{}, tau);
  kepler_integrator C(systems::kepler{}, tau);
  auto b = B.initial_state(start.first, start.second);
  auto c = C.initial_state(start.first, start.second);
  for (const auto& state : alone) {
    REQUIRE(B.try_step(b));
    REQUIRE(C.try_step(c));
    CHECK(b.q == state.first);
    CHECK(b.p == state.second);
    CHECK(c.q == state.first);
    CHECK(c.p == state.second);
  }
}

TEST_CASE("lpf_fixed_point: independently rounded coefficients are not exactly symplectic", "[lpf_fixed_point]") {
  // The check above can fail: the 100-digit coefficients of m = 8 rounded to double one by one
  // (what the Newton form's weights amount to) violate the relations by about an ulp.
  constexpr int S = 7;
  const auto w = schemes::detail::gauss_nystrom_coefficients<wide, S>::make();
  schemes::detail::gauss_nystrom_coefficients<double, S> rounded;
  for (std::size_t i = 0; i < S; ++i) {
    rounded.c[i] = static_cast<double>(w.c[i]);
    rounded.e[i] = static_cast<double>(wide(1) - w.c[i]);
    for (std::size_t j = 0; j < S; ++j) rounded.mu[i][j] = static_cast<double>(w.mu[i][j]);
  }
  const wide v = symplecticity_violation(rounded, S);
  CHECK(v > wide(0));
  CHECK(v <= wide(4) * wide(std::numeric_limits<double>::epsilon()));
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: the same map as lpf<m, gauss_interior> in its Newton form", "[lpf_fixed_point]",
                        geomint::test::integrator_scalar_types) {
  // Second method: the Newton form of the same equations (lpf.hpp, eq. 12). Ten steps of
  // Kepler (e = 1/2) from the pericentre, tau = 1/20: both solve the collocation equations
  // to round-off, so they agree to a small multiple of eps per step (the stage equations'
  // condition and the end update's sums; measured: at most 30 eps over the ten steps).
  using T = TestType;
  const T tau = T(1) / T(20);
  const auto start = kepler_start<T>();  // not a structured binding: Clang 14 cannot capture those
  const vec<T, 2> q0 = start.first, v0 = start.second;
  auto compare = [&]<int M>() {
    integrator<lpf_fixed_point<M>, systems::kepler, T> A(systems::kepler{}, tau);
    integrator<lpf<M, gauss_interior, lagrange, newton_solver>, systems::kepler, T> B(systems::kepler{}, tau);
    auto a = A.initial_state(q0, v0);
    auto b = B.initial_state(q0, v0);
    A.advance(a, 10);
    B.advance(b, 10);
    INFO("m = " << M << ": |q_a - q_b| = " << (a.q - b.q).norm() << ", |p_a - p_b| = " << (a.p - b.p).norm());
    CHECK((a.q - b.q).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(200));
    CHECK((a.p - b.p).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(200));
    CHECK(a.step == 10);
  };
  compare.template operator()<2>();
  compare.template operator()<4>();
  compare.template operator()<8>();
  compare.template operator()<12>();
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: the sweep budget grows with the scalar's digits", "[lpf_fixed_point]",
                        geomint::test::integrator_scalar_types) {
  // Kepler (e = 1/2) at the pericentre with m = 2 and tau = 1/4: the one-stage iteration
  // contracts slowly there and needs more than the 50 sweeps of the default budget to reach 50
  // digits (measured: that budget failed in cpp_bin_float_50). With the budget per 16 digits
  // (sweep_budget) the step converges in every scalar, to the Newton form's step (second
  // method, lpf.hpp) within a few eps.
  using T = TestType;
  const T tau = T(1) / T(4);
  const auto [q0, v0] = kepler_start<T>();
  integrator<lpf_fixed_point<2>, systems::kepler, T> A(systems::kepler{}, tau);
  A.options().double_jacobian = false;  // the sweeps (multiprecision would take Newton steps)
  integrator<lpf<2, gauss_interior, lagrange, newton_solver>, systems::kepler, T> B(systems::kepler{}, tau);
  auto a = A.initial_state(q0, v0);
  auto b = B.initial_state(q0, v0);
  const step_status st = A.try_step(a);
  REQUIRE(st);
  B.step(b);
  INFO("sweeps: " << st.iterations << ", |q_a - q_b| = " << (a.q - b.q).norm());
  // In 50 digits the step needs more sweeps than max_iterations (measured 54 against 50; 18 in
  // double): the case the budget per 16 digits is for.
  if constexpr (std::numeric_limits<T>::digits10 > 16) CHECK(st.iterations > newton_options<T>{}.max_iterations);
  CHECK((a.q - b.q).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(16));
  CHECK((a.p - b.p).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(16));
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: continuing steps and fresh steps solve the same equations",
                        "[lpf_fixed_point]", geomint::test::integrator_scalar_types) {
  // The step cache predicts a continuing step by extrapolating the previous stage forces; a
  // fresh integrator starts from the forces along the straight line. Both iterate to the fixed
  // point, so the results agree to round-off (exact mathematics: the same fixed point).
  using T = TestType;
  const T tau = T(1) / T(10);
  integrator<lpf_fixed_point<6>, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  auto fresh = s;
  for (int k = 0; k < 20; ++k) {
    I.step(s);
    integrator<lpf_fixed_point<6>, systems::pendulum, T> J(systems::pendulum{}, tau);
    J.step(fresh);
  }
  CHECK(abs(T(s.q[0] - fresh.q[0])) <= eps_tol<T>(64));
  CHECK(abs(T(s.p[0] - fresh.p[0])) <= eps_tol<T>(64));
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: stop_on_rate saves sweeps and keeps the fixed point", "[lpf_fixed_point]",
                        geomint::test::integrator_scalar_types) {
  // With stop_on_rate a step ends when the contraction rate bounds the change left below eps,
  // one sweep before the increments stop changing. Both runs reach the same fixed point: each
  // step's iterate is within tolerance_ulps (64) eps of it, so after 20 steps the runs agree to
  // 20 x 2 x 64 eps (exact mathematics: one fixed point), and the rate's stop takes fewer sweeps.
  using T = TestType;
  std::array<long, 2> sweeps{};
  std::array<vec<T, 2>, 2> q, p;
  for (const bool stop_on_rate : {false, true}) {
    const std::size_t k = stop_on_rate ? 1 : 0;
    std::tie(q[k], p[k], sweeps[k]) = kepler_20_steps<T>([&](newton_options<T>& o) {
      o.stop_on_rate = stop_on_rate;
      o.double_jacobian = false;  // the sweeps
    });
  }
  CHECK(T((q[1] - q[0]).cwiseAbs().maxCoeff()) <= eps_tol<T>(2560));
  CHECK(T((p[1] - p[0]).cwiseAbs().maxCoeff()) <= eps_tol<T>(2560));
  CHECK(sweeps[1] < sweeps[0]);
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: a step beyond the iteration's reach fails and leaves the state",
                        "[lpf_fixed_point][errors]", geomint::test::integrator_scalar_types) {
  // The pendulum from theta = 1 with tau = 20 (three periods in one step): the fixed-point map
  // is no contraction there, so the iteration must report failure, not return a step.
  using T = TestType;
  integrator<lpf_fixed_point<8>, systems::pendulum, T> I(systems::pendulum{}, T(20));
  I.options().double_jacobian = false;  // the sweeps, whose reach this is
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  const auto before = s;
  const step_status st = I.try_step(s);
  CHECK(!st);
  CHECK((st.reason == step_failure::no_convergence || st.reason == step_failure::non_finite_iterate));
  CHECK(st.step == 0);
  CHECK(s.q == before.q);
  CHECK(s.p == before.p);
  CHECK(s.step == before.step);
  // The iteration budget is honoured: with one iteration allowed, a step that needs more fails.
  const auto [q0, v0] = kepler_start<T>();
  integrator<lpf_fixed_point<8>, systems::kepler, T> K(systems::kepler{}, T(1) / T(10));
  K.options().max_iterations = 1;
  K.options().double_jacobian = false;
  auto s1 = K.initial_state(q0, v0);
  CHECK(K.try_step(s1).reason == step_failure::no_convergence);
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: Newton steps with the matrix in double reach the sweeps' fixed point",
                        "[lpf_fixed_point]", geomint::test::integrator_scalar_types) {
  // Multiprecision (newton_options::double_jacobian, the default there): simplified Newton on
  // the stage equations with their matrix in double. The equations are the sweeps', so 20 steps
  // of Kepler (e = 1/2, m = 8, tau = 1/8) agree with the sweeps to 20 x 2 x 64 eps (exact
  // mathematics: one solution, each step within 64 eps of it) and with the Newton form of LPF
  // (second method, lpf.hpp) as closely, in fewer iterations than the sweeps take. In double
  // the option changes nothing (the sweeps run either way).
  using T = TestType;
  const auto [q0, v0] = kepler_start<T>();
  std::array<long, 2> iterations{};
  std::array<vec<T, 2>, 2> q, p;
  for (const bool in_double : {false, true}) {
    const std::size_t k = in_double ? 1 : 0;
    std::tie(q[k], p[k], iterations[k]) =
        kepler_20_steps<T>([&](newton_options<T>& o) { o.double_jacobian = in_double; });
  }
  integrator<lpf<8, gauss_interior, lagrange, newton_solver>, systems::kepler, T> N(systems::kepler{}, T(1) / T(8));
  auto n = N.initial_state(q0, v0);
  N.advance(n, 20);
  INFO("iterations: sweeps " << iterations[0] << ", Newton " << iterations[1]);
  CHECK(T((q[1] - q[0]).cwiseAbs().maxCoeff()) <= eps_tol<T>(2560));
  CHECK(T((p[1] - p[0]).cwiseAbs().maxCoeff()) <= eps_tol<T>(2560));
  CHECK(T((q[1] - n.q).cwiseAbs().maxCoeff()) <= eps_tol<T>(2560));
  CHECK(T((p[1] - n.p).cwiseAbs().maxCoeff()) <= eps_tol<T>(2560));
  if constexpr (std::is_floating_point_v<T>) {
    CHECK(iterations[1] == iterations[0]);
  } else {
    CHECK(2 * iterations[1] < iterations[0]);
  }
}

TEST_CASE("lpf_fixed_point: multiprecision steps start from the stage equations solved in double",
          "[lpf_fixed_point]") {
  // The pendulum from theta = 1 with m = 16 and tau = 7/10, near the largest step of the
  // work-precision runs at 1e-30, where the extrapolated predictor is off by about 1e-5. The
  // equations are first solved in double (presolve_in_double), which leaves their matrix
  // factorised at that solution: the iteration in T then starts about 1e-16 from the fixed point
  // and gains about 16 digits per iteration, so 50 digits take three (the third bounds what is
  // left below eps; measured: 3 in every step, 4 or 5 from the predictor before). Each step is
  // the sweeps' fixed point to 2 x 64 eps (exact mathematics: one solution), so 20 steps agree to
  // 20 x 2 x 64 eps with the sweeps (double_jacobian = false) and with LPF's Newton form (second
  // method, lpf.hpp).
  using T = geomint::test::cpp_bin_float_50;
  const T tau = T(7) / T(10);
  integrator<lpf_fixed_point<16>, systems::pendulum, T> A(systems::pendulum{}, tau);
  integrator<lpf_fixed_point<16>, systems::pendulum, T> B(systems::pendulum{}, tau);
  B.options().double_jacobian = false;
  integrator<lpf<16, gauss_interior, lagrange, newton_solver>, systems::pendulum, T> N(systems::pendulum{}, tau);
  auto a = A.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  auto b = a;
  auto c = N.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  int most = 0;
  for (int k = 0; k < 20; ++k) {
    const step_status st = A.try_step(a);
    REQUIRE(st);
    most = std::max(most, st.iterations);
    B.step(b);
    N.step(c);
  }
  CHECK(most <= 3);
  CHECK(abs(T(a.q[0] - b.q[0])) <= eps_tol<T>(2560));
  CHECK(abs(T(a.p[0] - b.p[0])) <= eps_tol<T>(2560));
  CHECK(abs(T(a.q[0] - c.q[0])) <= eps_tol<T>(2560));
  CHECK(abs(T(a.p[0] - c.p[0])) <= eps_tol<T>(2560));
}

TEST_CASE("lpf_fixed_point: beyond double's range the steps fall back to the sweeps", "[lpf_fixed_point][errors]") {
  // The harmonic oscillator at q = p = 2^1400, a state double cannot hold: neither the presolve
  // in double nor the stage matrix in double is possible, so the steps are the sweeps'
  // (Gauss-Seidel in T). The sweeps are homogeneous in the state (a linear force, tests relative
  // to the iterate), and scaling by a power of two is exact in binary floating point, so ten
  // steps from there are exactly 2^1400 times ten sweep steps (double_jacobian = false) from
  // q = p = 1 (exact mathematics).
  using T = geomint::test::cpp_bin_float_50;
  using std::ldexp;
  const int shift = 1400;
  integrator<lpf_fixed_point<6>, systems::harmonic, T> A(systems::harmonic{}, T(1) / T(4));
  integrator<lpf_fixed_point<6>, systems::harmonic, T> B(systems::harmonic{}, T(1) / T(4));
  B.options().double_jacobian = false;
  auto a = A.initial_state(vec<T, 1>(T(ldexp(T(1), shift))), vec<T, 1>(T(ldexp(T(1), shift))));
  auto b = B.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
  for (int k = 0; k < 10; ++k) {
    REQUIRE(A.try_step(a));
    REQUIRE(B.try_step(b));
  }
  CHECK(a.q[0] == T(ldexp(b.q[0], shift)));
  CHECK(a.p[0] == T(ldexp(b.p[0], shift)));
}

TEMPLATE_LIST_TEST_CASE("lpf_fixed_point: the type-erased stepper takes the integrator's steps", "[lpf_fixed_point]",
                        geomint::test::integrator_scalar_types) {
  // The same engine behind both (stepper.hpp): five steps agree bit for bit, plain and with
  // compensated summation (exact mathematics: identical operations).
  using T = TestType;
  const T tau = T(1) / T(10);
  const auto stepper = make_scheme_stepper<lpf_fixed_point<5>, systems::pendulum, T>(systems::pendulum{});
  CHECK(stepper->name() == lpf_fixed_point<5>::name());
  for (bool compensated : {false, true}) {
    integrator<lpf_fixed_point<5>, systems::pendulum, T> I(systems::pendulum{}, tau);
    I.set_compensated_summation(compensated);
    auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    dynamic_vector<T> q(1), p(1), qc(1), pc(1), q1(1), p1(1);
    q[0] = s.q[0];
    p[0] = s.p[0];
    qc[0] = T(0);
    pc[0] = T(0);
    for (int k = 0; k < 5; ++k) {
      I.step(s);
      const step_status st = compensated ? stepper->try_step_compensated(q, p, qc, pc, tau, q1, p1) : stepper->try_step(q, p, tau, q1, p1);
      REQUIRE(st);
      q = q1;
      p = p1;
      CHECK(q[0] == s.q[0]);
      CHECK(p[0] == s.p[0]);
    }
  }
}

namespace {
/// The state after `steps` steps of lpf_fixed_point<M> in double from the system's initial data,
/// with the stage forces on SIMD packs or one by one.
template <class Sys, int M>
phase_state<double, Sys::dof> run_in_double(double tau, int steps, bool simd_forces) {
  integrator<lpf_fixed_point<M>, Sys, double> in(Sys{}, tau);
  in.set_compensated_summation(true);
  in.options().simd_forces = simd_forces;
  vec<double, Sys::dof> q0, v0;
  Sys::initial_data(q0, v0);
  auto s = in.initial_state(q0, v0);
  for (int k = 0; k < steps; ++k) in.step(s);
  return s;
}

/// The two runs take the same map up to the forces' last bits: each step's results differ by a
/// few ulps of the state (the sine's last bit; how a * b + c is contracted), and a difference
/// made at time t grows at most like 1 + (T - t) on these integrable or near-integrable orbits
/// (the period depends on the energy), so after N steps to T they agree within
/// 4 N eps (1 + T / t0) |state| (t0 the system's time unit).
template <class Sys, int M>
void check_simd_forces(double tau, int steps, double time_unit) {
  const auto packed = run_in_double<Sys, M>(tau, steps, true);
  const auto one_by_one = run_in_double<Sys, M>(tau, steps, false);
  const double scale = std::max(one_by_one.q.cwiseAbs().maxCoeff(), one_by_one.p.cwiseAbs().maxCoeff());
  const double tol = 4.0 * steps * std::numeric_limits<double>::epsilon() * (1.0 + tau * steps / time_unit) * scale;
  CHECK((packed.q - one_by_one.q).cwiseAbs().maxCoeff() <= tol);
  CHECK((packed.p - one_by_one.p).cwiseAbs().maxCoeff() <= tol);
}
}  // namespace

TEST_CASE("lpf_fixed_point: stage forces on SIMD packs take the steps of the forces one by one", "[lpf_fixed_point]") {
  STATIC_REQUIRE(stage_parallel_system<systems::pendulum>);
  STATIC_REQUIRE(stage_parallel_system<zoo::outer_solar>);
  check_simd_forces<systems::pendulum, 10>(0.5, 200, 1.0);  // 9 stages: packs with unused lanes
  check_simd_forces<systems::pendulum, 5>(0.25, 200, 1.0);  // 4 stages
  check_simd_forces<systems::pendulum, 3>(0.05, 200, 1.0);  // 2 stages
  check_simd_forces<zoo::outer_solar, 8>(50.0, 100, 4332.0);  // days; Jupiter's period
}
