/// Long-time behaviour: energy without drift, Noether quantities.
#include <cmath>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "geomint/stepper.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::eps_tol;

TEST_CASE("pendulum, m = 2: energy error bounded over 10^6 steps (no drift)", "[lpf][pendulum][long]") {
  // Scheme (21), theta(0) = 1, thetadot(0) = 0, tau = 1/10, double, natural fast path.
  // Expected: the energy error of a symplectic order-2 method oscillates with amplitude
  // O(tau^2) and does not grow; we compare the largest error in the last 10^5 steps with the
  // largest in the first 10^5 (a drift of even 1% of the amplitude would fail).
  using T = double;
  const T tau = T(1) / T(10);
  integrator<scheme21, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  const T E0 = I.energy(s);
  T first(0), last(0);
  const long steps = 1000000;
  for (long k = 0; k < steps; ++k) {
    I.step(s);
    const T err = std::abs(I.energy(s) - E0);
    if (k < steps / 10) first = std::max(first, err);
    if (k >= steps - steps / 10) last = std::max(last, err);
  }
  INFO("max energy error: first 10% " << first << ", last 10% " << last);
  CHECK(first <= tau * tau);
  CHECK(last <= first * (T(101) / T(100)));
  CHECK(s.step == steps);
}

TEMPLATE_LIST_TEST_CASE("Kepler (e = 0.5): angular momentum conserved to round-off", "[lpf][kepler]",
                        geomint::test::integrator_scalar_types) {
  // q0 = (1 - e, 0), qdot0 = (0, sqrt((1 + e)/(1 - e))): pericentre of the orbit with a = 1.
  // L is rotation invariant; the Noether quantity q x p changes over a step by the integral
  // of x(t) x xddot(t), a polynomial of degree 2m - 3 (the t^(2m-2) term is a_m x a_m = 0)
  // vanishing at the interior nodes: zero exactly when the m - 1 interior nodes are Gauss
  // points (exact for degree 2m - 3), i.e. gauss_interior for any m and every family for m = 2.
  using T = TestType;
  using std::abs;
  using std::sqrt;
  const T tau = T(1) / T(20);
  const long steps = std::numeric_limits<T>::digits10 > 20 ? 150 : 2000;
  auto run = [&](auto scheme_tag) {
    using Scheme = decltype(scheme_tag);
    integrator<Scheme, systems::kepler, T> I(systems::kepler{}, tau);
    auto s = I.initial_state(vec<T, 2>(T(1) / T(2), T(0)), vec<T, 2>(T(0), sqrt(T(3))));
    const T J0 = systems::kepler::conserved<T>(s.q, s.p);
    T worst(0);
    for (long k = 0; k < steps; ++k) {
      I.step(s);
      worst = std::max<T>(worst, T(abs(systems::kepler::conserved<T>(s.q, s.p) - J0)));
    }
    return worst;
  };
  const T bound = eps_tol<T>(static_cast<int>(32 * steps));  // round-off, linear in steps
  CHECK(run(scheme21{}) <= bound);
  CHECK(run(scheme22{}) <= bound);
  CHECK(run(lpf<3, gauss_interior>{}) <= bound);
  CHECK(run(lpf<4, gauss_interior, bernstein>{}) <= bound);
  CHECK(run(midpoint_vi{}) <= bound);
  CHECK(run(galerkin_vi<2>{}) <= bound);
  // Equispaced m = 3 (nodes 1/3, 2/3 are not Gauss points): not conserved exactly.
  CHECK(run(lpf<3, equispaced>{}) > T(1) / T(1000000));
}

TEMPLATE_LIST_TEST_CASE("charged particle in B_z = 1 + r^2: conserved quantities", "[lpf][charged]",
                        geomint::test::integrator_scalar_types) {
  // L = 1/2|qdot|^2 + A(q).qdot, A = (1 + r^2/2)/2 (-y, x): rotation invariant, so the
  // canonical angular momentum J = x p_y - y p_x is conserved (Noether); the energy is
  // 1/2|qdot|^2 (the magnetic force does no work).
  // - Galerkin / midpoint VI: L_d is rotation invariant, so J is conserved to round-off
  //   (discrete Noether theorem).
  // - LPF on Gauss interior nodes: d/dt 1/2|xdot|^2 = xdot . xddot has degree 2m - 3 and
  //   vanishes at the nodes (xddot = xdot x B there), so the energy is conserved to round-off;
  //   J is not exactly invariant (A is nonlinear) but its error stays bounded, O(tau^(2m-2)).
  using T = TestType;
  using std::abs;
  const T tau = T(1) / T(10);
  const long steps = std::numeric_limits<T>::digits10 > 20 ? 60 : 1000;
  const vec<T, 2> q0(T(1), T(0)), v0(T(0), T(1));
  const T bound = eps_tol<T>(static_cast<int>(16 * steps));
  auto run = [&](auto scheme_tag, T& dJ, T& dE, T& dJ_first, T& dJ_last) {
    using Scheme = decltype(scheme_tag);
    integrator<Scheme, systems::charged, T> I(systems::charged{}, tau);
    auto s = I.initial_state(q0, v0);
    const T J0 = systems::charged::conserved<T>(s.q, s.p), E0 = I.energy(s);
    dJ = dE = dJ_first = dJ_last = T(0);
    for (long k = 0; k < steps; ++k) {
      I.step(s);
      const T j = abs(systems::charged::conserved<T>(s.q, s.p) - J0);
      dJ = std::max<T>(dJ, j);
      dE = std::max<T>(dE, T(abs(I.energy(s) - E0)));
      if (k < steps / 4) dJ_first = std::max<T>(dJ_first, j);
      if (k >= steps - steps / 4) dJ_last = std::max<T>(dJ_last, j);
    }
  };
  T dJ, dE, f, l;
  run(galerkin_vi<2>{}, dJ, dE, f, l);
  INFO("galerkin 2: dJ " << dJ << " dE " << dE);
  CHECK(dJ <= bound);
  run(midpoint_vi{}, dJ, dE, f, l);
  CHECK(dJ <= bound);
  run(lpf<3, gauss_interior>{}, dJ, dE, f, l);
  INFO("lpf 3 gauss: dJ " << dJ << " dE " << dE << " first " << f << " last " << l);
  CHECK(dE <= bound);
  CHECK(dJ <= tau * tau * tau * tau);  // O(tau^4) for m = 3
  if (steps >= 1000) CHECK(l <= f * T(2));  // bounded, no drift
  run(lpf<2, equispaced>{}, dJ, dE, f, l);
  CHECK(dE <= bound);  // m = 2: the midpoint node is the Gauss point
  CHECK(dJ <= tau * tau);
}

// ---------------------------------------------------------------------------------------------
// Compensated summation of the end update (integrator::set_compensated_summation,
// solvers/phase_state.hpp add_compensated).

TEMPLATE_LIST_TEST_CASE("add_compensated is exact where plain summation loses every increment", "[compensated]",
                        geomint::test::integrator_scalar_types) {
  // Expected values by exact arithmetic in cpp_bin_float_100 (332 bits: the sums below need at
  // most the scalar's bits plus 20, so they are exact there).
  using T = TestType;
  using R = geomint::test::cpp_bin_float_100;
  const T eps = std::numeric_limits<T>::epsilon();
  const long count = 100000;
  // 1) 10^5 increments d = eps/3 onto x = 1: each rounds away in plain summation (1 + d = 1).
  {
    const T d = eps / T(3);
    vec<T, 1> x(T(1)), carry(T(0)), plain(T(1));
    for (long k = 0; k < count; ++k) {
      add_compensated(x, carry, vec<T, 1>(d));
      plain[0] += d;
    }
    const R exact = R(1) + R(count) * R(d);
    const R plain_error = abs(R(plain[0]) - exact);
    const R comp_error = abs(R(x[0]) + R(carry[0]) - exact);
    INFO("plain error " << static_cast<double>(plain_error) << ", compensated " << static_cast<double>(comp_error));
    CHECK(plain_error == R(count) * R(d));  // plain summation lost all of them
    // Each step rounds only y = d + carry (error <= eps |y| / 2, |y| <= 2 d): in all < count eps d.
    CHECK(comp_error <= R(count) * R(eps) * R(d));
    // and x itself is the exact sum rounded to the scalar (to one unit in the last place).
    CHECK(abs(R(x[0]) - exact) <= R(eps));
  }
  // 2) Increments larger than the value itself (a momentum crossing zero), where Kahan's
  //    fast two-sum would not be exact: each addition makes the new x + carry equal to the old
  //    x plus y exactly (y = dx + carry rounded, the only rounding of a step), so the sum
  //    is off the exact one by at most sum_k eps |y_k| / 2.
  {
    vec<T, 1> x(eps / T(3)), carry(T(0));
    R exact = R(x[0]), bound(0);
    bool every_step_exact = true;
    for (long k = 0; k < 1000; ++k) {
      const T d = (k % 2 == 0 ? T(1) : T(-1)) * (T(1) + T(k) / T(7));
      const T y = d + carry[0];
      const R x_before = R(x[0]);
      add_compensated(x, carry, vec<T, 1>(d));
      every_step_exact = every_step_exact && R(x[0]) + R(carry[0]) == x_before + R(y);
      exact += R(d);
      bound += R(eps) * abs(R(y)) / R(2);
    }
    CHECK(every_step_exact);
    const R error = abs(R(x[0]) + R(carry[0]) - exact);
    INFO("compensated error " << static_cast<double>(error) << ", bound " << static_cast<double>(bound));
    CHECK(error <= bound);
  }
}

TEMPLATE_LIST_TEST_CASE("two_sum and the double-length add_compensated keep every bit", "[compensated]",
                        geomint::test::integrator_scalar_types) {
  // Expected values by arithmetic in cpp_bin_float_100: exact for double; for cpp_bin_float_50
  // exact for two_sum and within 2^-320 |x| for the long sum, far below its bound.
  using T = TestType;
  using R = geomint::test::cpp_bin_float_100;
  const T eps = std::numeric_limits<T>::epsilon();
  // two_sum: s + e = a + b exactly, s the rounded sum, for magnitudes far apart and crossing.
  for (const auto& [a, b] : {std::pair<T, T>(T(1), eps / T(3)), std::pair<T, T>(T(1) / T(3), T(-2) / T(7)),
                             std::pair<T, T>(eps / T(5), T(-7) / T(3)), std::pair<T, T>(T(3), T(-3))}) {
    T s, e;
    two_sum(a, b, s, e);
    CHECK(R(s) + R(e) == R(a) + R(b));
    CHECK(s == T(a + b));
  }
  // add_compensated(x, carry, dx, dx_lo): 10^4 increments known to twice the precision
  // (dx + dx_lo = 1/10 + 1/7 in about 2 p bits) onto x = 1. The exact sum is off by the small
  // terms' roundings alone, each below eps^2 |x| (here |x| < 2500): in all under 10^4 eps^2 2500.
  const T tenth = T(1) / T(10);
  const T dx_lo = T(T(1) / T(7)) * eps;  // a part below the last bit of dx
  vec<T, 1> x(T(1)), carry(T(0));
  R exact = R(1);
  const long count = 10000;
  for (long k = 0; k < count; ++k) {
    add_compensated(x, carry, vec<T, 1>(tenth), vec<T, 1>(dx_lo));
    exact += R(tenth) + R(dx_lo);
  }
  const R error = abs(R(x[0]) + R(carry[0]) - exact);
  INFO("error " << static_cast<double>(error));
  CHECK(error <= R(count) * R(eps) * R(eps) * R(2500));
  CHECK(abs(R(x[0]) - exact) <= R(eps) * R(2500));  // x is the sum to the last bit or so
  // The single-length add_compensated cannot keep dx_lo: it loses about count |dx_lo|.
  vec<T, 1> y(T(1)), carry_y(T(0));
  for (long k = 0; k < count; ++k) add_compensated(y, carry_y, vec<T, 1>(T(tenth + dx_lo)));
  CHECK(abs(R(y[0]) + R(carry_y[0]) - exact) > R(count) * R(eps) * R(eps) * R(2500));
}

TEMPLATE_LIST_TEST_CASE("compensated and plain steps agree to rounding", "[compensated]",
                        geomint::test::integrator_scalar_types) {
  // The two runs solve the same equations and differ only in how the increments are added, so
  // after k steps they agree to about k eps |q| (the plain run's round-off; the pendulum's flow
  // from theta = 1 does not amplify it by more than a small factor over these times). Whether
  // compensation pays is a long-run statistic, measured by geomint-run --growth
  // (docs/results/long_runs.md), not a property of one short run.
  using T = TestType;
  using std::abs;
  const long steps = std::numeric_limits<T>::digits10 > 20 ? 100 : 2000;
  auto check_scheme = [&](auto scheme_tag) {
    using Scheme = decltype(scheme_tag);
    const T tau = T(1) / T(10);
    integrator<Scheme, systems::pendulum, T> plain(systems::pendulum{}, tau), comp(systems::pendulum{}, tau);
    comp.set_compensated_summation(true);
    CHECK(comp.compensated_summation());
    CHECK_FALSE(plain.compensated_summation());
    auto a = plain.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    auto b = comp.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    plain.advance(a, steps);
    comp.advance(b, steps);
    INFO(Scheme::name() << ": q " << a.q[0] << " vs " << b.q[0] << ", p " << a.p[0] << " vs " << b.p[0]);
    CHECK(abs(a.q[0] - b.q[0]) <= eps_tol<T>(static_cast<int>(4 * steps)));
    CHECK(abs(a.p[0] - b.p[0]) <= eps_tol<T>(static_cast<int>(4 * steps)));
    CHECK(b.step == steps);
    CHECK(b.t == a.t);
    CHECK((a.q[0] != b.q[0] || a.p[0] != b.p[0]));  // the compensation did change the rounding
  };
  check_scheme(lpf<4, gauss_interior>{});
  check_scheme(lpf_fixed_point<4>{});
  check_scheme(galerkin_vi<3>{});
  check_scheme(midpoint_vi{});
}

namespace {
/// One compensated double step of Scheme on Sys from its initial data with the carries (cq, cp)
/// against the same scheme in 50 digits from the exact sums q + cq, p + cp (the second method):
/// the largest difference of q + carry.q and of p + carry.p after the step.
template <class Scheme, class Sys>
std::pair<test::cpp_bin_float_50, test::cpp_bin_float_50> compensated_step_gap(const vec<double, Sys::dof>& cq,
                                                                              const vec<double, Sys::dof>& cp) {
  using R = test::cpp_bin_float_50;
  using std::abs;
  constexpr int n = Sys::dof;
  vec<double, n> q0, v0;
  Sys::initial_data(q0, v0);
  integrator<Scheme, Sys, double> I(Sys{}, 1.0 / 20);
  I.set_compensated_summation(true);
  auto s = I.initial_state(q0, v0);
  s.carry.q = cq;
  s.carry.p = cp;
  integrator<Scheme, Sys, R> J(Sys{}, R(1) / R(20));
  auto r = J.initial_state(q0.template cast<R>(), v0.template cast<R>());
  for (int i = 0; i < n; ++i) {
    r.q[i] = R(s.q[i]) + R(cq[i]);
    r.p[i] = R(s.p[i]) + R(cp[i]);
  }
  REQUIRE(I.try_step(s));
  REQUIRE(J.try_step(r));
  R gap_q(0), gap_p(0);
  for (int i = 0; i < n; ++i) {
    gap_q = std::max(gap_q, R(abs(R(R(s.q[i]) + R(s.carry.q[i])) - r.q[i])));
    gap_p = std::max(gap_p, R(abs(R(R(s.p[i]) + R(s.carry.p[i])) - r.p[i])));
  }
  return {gap_q, gap_p};
}
}  // namespace

TEST_CASE("a compensated step from q and its carry is the step from their sum", "[compensated]") {
  // Compensated summation: the state is q + carry.q, p + carry.p (phase_state::carry), so every
  // scheme's path, momentum rows and end update must see the carried parts. Second method: the
  // same scheme in 50 digits from the exact sums. Carries of 2^-30 and 2^-31, far above the
  // round-off, so that a step taken from the rounded parts alone misses by about tau |carry|
  // (1e-11) while the double step from the whole state is good to a few eps. Kepler (natural:
  // p = qdot) and the charged particle (general: p = qdot + A(q)) from their initial data, tau =
  // 1/20.
  // (Measured with the carries left out of the stages: 3e-11 to 4e-11 in q, 3e-11 to 7e-10
  // in p, for every scheme here.) LPF on a general system takes p_{k+1} = dL/dqdot at the
  // path's end (eq. 10), where the derivative weights D1(m, j) / tau amplify the round-off of
  // the increments: there p gets 64 eps (measured 4.3e-15 = 19 eps for m = 4).
  using R = test::cpp_bin_float_50;
  const R eps = R(std::numeric_limits<double>::epsilon());
  const vec<double, 2> cq(std::ldexp(1.0, -30), -std::ldexp(1.0, -30));
  const vec<double, 2> cp(std::ldexp(1.0, -31), std::ldexp(1.0, -31));
  auto check = [&]<class Scheme, class Sys>(int p_ulps) {
    const auto [gap_q, gap_p] = compensated_step_gap<Scheme, Sys>(cq, cp);
    INFO(Scheme::name() << " on " << Sys::name << ": |q - q_50| = " << gap_q << ", |p - p_50| = " << gap_p);
    CHECK(gap_q <= R(16) * eps);
    CHECK(gap_p <= R(p_ulps) * eps);
  };
  check.template operator()<lpf<4, gauss_interior>, systems::kepler>(16);
  check.template operator()<lpf<4, gauss_interior>, systems::charged>(64);
  check.template operator()<lpf<3, equispaced, bernstein>, systems::kepler>(16);
  check.template operator()<lpf<3, equispaced, bernstein>, systems::charged>(64);
  check.template operator()<galerkin_vi<3>, systems::kepler>(16);
  check.template operator()<galerkin_vi<3>, systems::charged>(16);
  check.template operator()<midpoint_vi, systems::charged>(16);
  check.template operator()<trapezoidal_vi, systems::kepler>(16);
  check.template operator()<lpf_fixed_point<4>, systems::kepler>(16);
}

TEMPLATE_LIST_TEST_CASE("a failed compensated step leaves the state and its compensation terms unchanged",
                        "[compensated]", geomint::test::integrator_scalar_types) {
  // The step is solved and its new compensation terms computed, then the step monitor rejects
  // it (energy change above a bound set far below the scheme's error at tau = 1).
  using T = TestType;
  integrator<lpf<2, gauss_interior>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(10));
  I.set_compensated_summation(true);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  I.advance(s, 25);
  REQUIRE(((s.carry.q.array() != T(0)).any() || (s.carry.p.array() != T(0)).any()));  // something to keep
  const auto before = s;
  step_monitor<T> m = step_monitor<T>::on();
  m.max_energy_change_ratio = std::numeric_limits<T>::epsilon();
  I.set_monitor(m);
  I.set_tau(T(1));
  const step_status st = I.try_step(s);
  CHECK_FALSE(st);
  CHECK(st.reason == step_failure::left_regime);
  CHECK(s.q == before.q);
  CHECK(s.p == before.p);
  CHECK(s.carry.q == before.carry.q);
  CHECK(s.carry.p == before.carry.p);
  CHECK(s.step == before.step);
  CHECK(s.t == before.t);
  // The same through the type-erased stepper: on failure its carries are untouched too.
  const std::unique_ptr<any_stepper<T>> stepper =
      std::make_unique<scheme_stepper<lpf<2, gauss_interior>, systems::pendulum, T>>();
  stepper->set_monitor(m);
  dynamic_vector<T> q = before.q, p = before.p, cq = before.carry.q, cp = before.carry.p, q1 = q, p1 = p;
  CHECK_FALSE(stepper->try_step_compensated(q, p, cq, cp, T(1), q1, p1));
  CHECK(cq == dynamic_vector<T>(before.carry.q));
  CHECK(cp == dynamic_vector<T>(before.carry.p));
  // and on success it takes the integrator's step, bit for bit.
  integrator<lpf<2, gauss_interior>, systems::pendulum, T> J(systems::pendulum{}, T(1) / T(10));
  J.set_compensated_summation(true);
  auto r = before;
  REQUIRE(J.try_step(r));
  stepper->set_monitor(step_monitor<T>{});
  REQUIRE(stepper->try_step_compensated(q, p, cq, cp, T(1) / T(10), q1, p1));
  CHECK(q1 == dynamic_vector<T>(r.q));
  CHECK(p1 == dynamic_vector<T>(r.p));
  CHECK(cq == dynamic_vector<T>(r.carry.q));
  CHECK(cp == dynamic_vector<T>(r.carry.p));
}
