/// Long-time behaviour: energy without drift, Noether quantities.
#include <cmath>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
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
