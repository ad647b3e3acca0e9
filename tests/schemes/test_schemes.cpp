/// Schemes (16)-(19) recovered from the integrators, closed-form harmonic solutions, and the
/// interchangeability of the Lagrange and Bernstein bases.
#include <cmath>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::eps_tol;
using boost::multiprecision::cpp_bin_float_50;

namespace {

/// The paper's two-step coefficients R(tau) of x^{k+1} = R x^k - x^{k-1} for
/// L = 1/2 xdot^2 - 1/2 x^2: eq. (16), (17), (18), (19) (independent source: the paper).
template <class T>
T paper_R(int scheme, const T& tau) {
  const T t2 = tau * tau, t4 = t2 * t2, t6 = t4 * t2;
  switch (scheme) {
    case 16: return (T(16) - T(6) * t2) / (T(8) + t2);
    case 17: return (T(8) - T(2) * t2) / (T(4) + t2);
    case 18: return (T(22) * t4 - T(468) * t2 + T(972)) / (T(2) * t4 + T(9) * t2 + T(486));
    default: return (T(-150) * t6 + T(9616) * t4 - T(142848) * t2 + T(294912)) /
                    (T(9) * t6 - T(184) * t4 + T(2304) * t2 + T(147456));
  }
}

/// R and the x^{k-1} coefficient read off the integrator's two-step map (linear in its inputs).
template <class Scheme, class Sys, class T>
std::pair<T, T> two_step_coefficients(const T& tau) {
  integrator<Scheme, Sys, T> I(Sys{}, tau);
  const vec<T, 1> zero(T(0)), one(T(1));
  return {I.two_step(zero, one)[0], I.two_step(one, zero)[0]};
}

template <class Scheme, class Sys, class T>
void check_scheme(int scheme, int ulps) {
  for (const T& tau : {T(1) / T(10), T(1) / T(4), T(1) / T(2), T(1)}) {
    const auto [R, back] = two_step_coefficients<Scheme, Sys, T>(tau);
    const T expected = paper_R<T>(scheme, tau);
    INFO("scheme " << scheme << " tau " << tau << " R " << R << " paper " << expected);
    using std::abs;
    CHECK(abs(R - expected) <= eps_tol<T>(ulps));
    CHECK(abs(back + T(1)) <= eps_tol<T>(ulps));  // the x^{k-1} coefficient is exactly -1
  }
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("schemes 16, 17, 18, 19 are the integrators' two-step maps", "[lpf][paper]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using H = systems::harmonic;
  check_scheme<scheme16, H, T>(16, 16);
  check_scheme<scheme17, H, T>(17, 16);
  check_scheme<scheme18, H, T>(18, 64);
  check_scheme<scheme19, H, T>(19, 64);
  // The general (AD on L, third derivatives) path gives the same schemes.
  check_scheme<scheme16, general<H>, T>(16, 16);
  check_scheme<scheme17, general<H>, T>(17, 16);
  check_scheme<scheme19, general<H>, T>(19, 64);
  // Remark after table 2: Bernstein interpolation (13) gives the same schemes.
  check_scheme<lpf<2, equispaced, bernstein>, H, T>(16, 16);
  check_scheme<lpf<3, equispaced, bernstein>, H, T>(18, 256);
  check_scheme<lpf<4, equispaced, bernstein>, general<H>, T>(19, 256);
  // The degree-1 Galerkin VI with 1-point Gauss quadrature is the midpoint VI (17).
  check_scheme<galerkin_vi<1>, H, T>(17, 16);
}

TEST_CASE("scheme coefficients in 50 digits at several tau", "[lpf][paper]") {
  using T = cpp_bin_float_50;
  // 50-digit agreement means the coefficient is the formula, not an approximation of it.
  check_scheme<scheme16, systems::harmonic, T>(16, 8);
  check_scheme<scheme18, systems::harmonic, T>(18, 32);
  check_scheme<scheme19, systems::harmonic, T>(19, 32);
  const T R = two_step_coefficients<scheme16, systems::harmonic, T>(T(1) / T(10)).first;
  // Eq. (16) at tau = 1/10 by hand: (16 - 6/100) / (8 + 1/100) = 1594/801.
  CHECK(abs(R - T(1594) / T(801)) <= eps_tol<T>(8));
}

TEMPLATE_LIST_TEST_CASE("harmonic oscillator: one-step trajectory equals the closed form of the recurrence",
                        "[lpf][harmonic]", geomint::test::integrator_scalar_types) {
  // x^k = x0 cos(k theta) + (x1 - x0 cos theta) sin(k theta) / sin theta with cos theta = R/2
  // solves x^{k+1} = R x^k - x^{k-1} exactly (R from the paper's formula).
  using T = TestType;
  using std::acos;
  using std::cos;
  using std::sin;
  using std::abs;
  const T tau = T(1) / T(10);
  auto run = [&](auto scheme_tag, int scheme) {
    using Scheme = decltype(scheme_tag);
    integrator<Scheme, systems::harmonic, T> I(systems::harmonic{}, tau);
    auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
    const T x0 = s.q[0];
    I.step(s);
    const T x1 = s.q[0];
    const T theta = acos(paper_R<T>(scheme, tau) / T(2));
    T worst(0);
    for (int k = 2; k <= 500; ++k) {
      I.step(s);
      const T closed = x0 * cos(T(k) * theta) + (x1 - x0 * cos(theta)) * sin(T(k) * theta) / sin(theta);
      worst = std::max<T>(worst, T(abs(s.q[0] - closed)));
    }
    INFO("scheme " << scheme << " worst deviation " << worst);
    // Round-off grows linearly with k for a neutrally stable linear recurrence.
    CHECK(worst <= eps_tol<T>(500 * 64));
  };
  run(scheme16{}, 16);
  run(scheme17{}, 17);
  run(scheme18{}, 18);
  run(scheme19{}, 19);
}

TEMPLATE_LIST_TEST_CASE("harmonic oscillator: global order against x = cos t + sin t", "[lpf][harmonic]",
                        geomint::test::integrator_scalar_types) {
  // Error at t = 2 for tau = 1/40 and 1/80; log2 of the ratio is the order. Expected orders
  // from R(tau) - 2 cos(tau) = O(tau^(p+2)): 2 for (16), (17), (18); 4 for (19); 2(m-1) = 6
  // for m = 4 on Gauss interior nodes; 2m = 6 for the 3-point Galerkin VI.
  using T = TestType;
  auto error_at_2 = [](auto scheme_tag, int steps) {
    using Scheme = decltype(scheme_tag);
    using std::abs;
    using std::cos;
    using std::sin;
    const T tau = T(2) / T(steps);
    integrator<Scheme, systems::harmonic, T> I(systems::harmonic{}, tau);
    auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1)));
    I.advance(s, steps);
    return T(abs(s.q[0] - (cos(T(2)) + sin(T(2)))));
  };
  auto order = [&](auto tag) {
    using std::log2;
    return T(log2(error_at_2(tag, 80) / error_at_2(tag, 160)));
  };
  const T tol = T(1) / T(20);
  using std::abs;
  CHECK(abs(order(scheme16{}) - T(2)) < tol);
  CHECK(abs(order(scheme17{}) - T(2)) < tol);
  CHECK(abs(order(scheme18{}) - T(2)) < tol);
  CHECK(abs(order(trapezoidal_vi{}) - T(2)) < tol);
  if constexpr (std::numeric_limits<T>::digits10 > 30) {  // errors near or below double round-off
    CHECK(abs(order(scheme19{}) - T(4)) < tol);
    CHECK(abs(order(lpf<4, gauss_interior>{}) - T(6)) < tol);
    CHECK(abs(order(galerkin_vi<3>{}) - T(6)) < tol);
  }
}

TEMPLATE_LIST_TEST_CASE("two-step form started consistently reproduces the one-step trajectory", "[lpf]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  integrator<lpf<3, gauss_lobatto>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(10));
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  auto [xm, x] = I.start(s.q, vec<T, 1>(T(0)));
  I.step(s);
  CHECK(abs(x[0] - s.q[0]) == T(0));
  for (int k = 1; k < 40; ++k) {
    const vec<T, 1> next = I.two_step(xm, x, k);
    xm = x;
    x = next;
    I.step(s);
  }
  INFO("two-step " << x[0] << " one-step " << s.q[0]);
  CHECK(abs(x[0] - s.q[0]) <= eps_tol<T>(4000));
}

TEMPLATE_LIST_TEST_CASE("Lagrange and Bernstein bases give the same map (schemes 21 and 22)", "[lpf][basis]",
                        geomint::test::integrator_scalar_types) {
  // Same polynomial space, same collocation conditions (eq. 12 at the nodes, eq. 11 at the
  // ends): the discrete map is identical; only the unknowns (node values eta vs control
  // points) and the round-off differ.
  using T = TestType;
  using std::abs;
  const T tau = T(1) / T(10);
  integrator<scheme21, systems::pendulum, T> L(systems::pendulum{}, tau);
  integrator<scheme22, systems::pendulum, T> B(systems::pendulum{}, tau);
  integrator<lpf<4, gauss_interior, bernstein>, general<systems::charged>, T> CB(general<systems::charged>{}, tau);
  integrator<lpf<4, gauss_interior, lagrange>, systems::charged, T> CL(systems::charged{}, tau);
  auto a = L.initial_state(vec<T, 1>(T(2)), vec<T, 1>(T(0)));
  auto b = a;
  T worst(0);
  for (int k = 0; k < 300; ++k) {
    L.step(a);
    B.step(b);
    worst = std::max<T>(worst, T(abs(a.q[0] - b.q[0]) + abs(a.p[0] - b.p[0])));
  }
  INFO("pendulum Lagrange vs Bernstein " << worst);
  CHECK(worst <= eps_tol<T>(300 * 64));
  auto c = CL.initial_state(vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), T(1)));
  auto d = c;
  worst = T(0);
  for (int k = 0; k < 50; ++k) {
    CL.step(c);
    CB.step(d);
    worst = std::max<T>(worst, T((c.q - d.q).norm() + (c.p - d.p).norm()));
  }
  INFO("charged Lagrange vs Bernstein " << worst);
  CHECK(worst <= eps_tol<T>(50 * 256));
}

TEMPLATE_LIST_TEST_CASE("natural fast path equals the general AD path", "[lpf][ad]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  const T tau = T(1) / T(8);
  integrator<lpf<3, chebyshev_lobatto>, systems::kepler, T> fast(systems::kepler{}, tau);
  integrator<lpf<3, chebyshev_lobatto>, general<systems::kepler>, T> slow(general<systems::kepler>{}, tau);
  auto a = fast.initial_state(vec<T, 2>(T(1) / T(2), T(0)), vec<T, 2>(T(0), T(3) / T(2)));
  auto b = a;
  for (int k = 0; k < 30; ++k) {
    fast.step(a);
    slow.step(b);
  }
  INFO("difference " << (a.q - b.q).norm());
  CHECK((a.q - b.q).norm() + (a.p - b.p).norm() <= eps_tol<T>(30 * 256));
}
