/// A user's tableau through the one integrator (methods/tableau_method.hpp): the same maps as
/// the library's schemes where the literature says they are the same method, and the published
/// orders against closed-form solutions.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <stdexcept>

#include "catch.hpp"
#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "geomint/methods/collocation_families.hpp"
#include "geomint/methods/collocation_rkn.hpp"
#include "geomint/methods/tableau_method.hpp"
#include "field_numbers.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using methods::exact_rational;
using methods::field_element;
using geomint::test::cpp_bin_float_50;

namespace {

using R = rational;
using F = field_element;
using geomint::test::field_numbers::q;
F generator(std::vector<exact_rational> poly) { return F::generator(methods::algebraic_field::make(std::move(poly))); }

/// Stormer-Verlet as an RKN tableau: c = (0, 1), a_21 = 1/2, bbar = (1/2, 0), b = (1/2, 1/2),
/// i.e. q1 = q + h v + h^2/2 f(q), v1 = v + h/2 (f(q) + f(q1)) (Hairer, Lubich & Wanner 2006,
/// section I.1.4).
struct verlet {
  static auto tableau() { return methods::make_rkn<R>({0, 1}, {{0, 0}, {R(1, 2), 0}}, {R(1, 2), 0}, {R(1, 2), R(1, 2)}); }
};

/// The s-stage Gauss Nystrom collocation methods (Hairer, Norsett & Wanner I, section II.14;
/// Hairer, Lubich & Wanner 2006, section II.1.4): c the Gauss points, b the Gauss weights,
/// abar_ij = int_0^{c_i} (c_i - u) l_j(u) du and bbar_j = int_0^1 (1 - u) l_j(u) du, the
/// integrals evaluated exactly by hand (sympy), not by geomint.
struct gauss2 {
  static auto tableau() {
    const F r = generator({-3, 0, 1});  // sqrt 3
    return methods::make_rkn<F>({q(1, 2) - r / 6, q(1, 2) + r / 6}, {{q(1, 36), q(5, 36) - r / 12}, {q(5, 36) + r / 12, q(1, 36)}},
                                {q(1, 4) + r / 12, q(1, 4) - r / 12}, {q(1, 2), q(1, 2)});
  }
};
struct gauss3 {
  static auto tableau() {
    const F r = generator({-15, 0, 1});  // sqrt 15
    return methods::make_rkn<F>({q(1, 2) - r / 10, q(1, 2), q(1, 2) + r / 10},
                                {{q(1, 120), q(1, 12) - r / 45, q(13, 120) - r / 36},
                                 {q(5, 96) + r / 72, q(1, 48), q(5, 96) - r / 72},
                                 {q(13, 120) + r / 36, q(1, 12) + r / 45, q(1, 120)}},
                                {q(5, 36) + r / 36, q(2, 9), q(5, 36) - r / 36}, {q(5, 18), q(4, 9), q(5, 18)});
  }
};

/// The 2-stage Gauss Nystrom collocation method for q'' = F(q, q'): the RKN coefficients of
/// gauss2 and ap = the Gauss Runge-Kutta matrix, ap_ij = int_0^{c_i} l_j(u) du
/// = (1/4, 1/4 - sqrt 3/6; 1/4 + sqrt 3/6, 1/4), the Gauss method of order 4 (Hammer &
/// Hollingsworth; Hairer, Norsett & Wanner I, section II.7).
struct gauss2_nystrom {
  static auto tableau() {
    const auto rkn = gauss2::tableau();
    const F r = generator({-3, 0, 1});  // sqrt 3
    return methods::make_nystrom<F>({rkn.c[0], rkn.c[1]}, {{rkn.a[0][0], rkn.a[0][1]}, {rkn.a[1][0], rkn.a[1][1]}},
                                    {{q(1, 4), q(1, 4) - r / 6}, {q(1, 4) + r / 6, q(1, 4)}}, {rkn.bbar[0], rkn.bbar[1]},
                                    {rkn.b[0], rkn.b[1]});
  }
};

/// The implicit midpoint rule as a 1-stage rk tableau (c = 1/2, a = 1/2, b = 1): on a natural
/// system in (q, p) the map q1 = q + h M^{-1} (p + p1)/2, p1 = p - h grad V((q + q1)/2), which is
/// the midpoint variational integrator (its discrete Euler-Lagrange equations; Marsden & West
/// 2001, docs/references.md).
struct implicit_midpoint {
  static auto tableau() { return methods::make_rk<R>({R(1, 2)}, {{R(1, 2)}}, {1}); }
};

/// Stormer-Verlet as the 2-stage Lobatto IIIA-IIIB pair (Hairer, Lubich & Wanner 2006, section II.2.2).
struct lobatto_pair {
  static auto tableau() {
    return methods::make_prk<R>({0, 1}, {{0, 0}, {R(1, 2), R(1, 2)}}, {R(1, 2), R(1, 2)}, {{R(1, 2), 0}, {R(1, 2), 0}},
                                {R(1, 2), R(1, 2)});
  }
};

/// The classical Runge-Kutta method of order 4 (Kutta 1901, as printed in Hairer, Norsett &
/// Wanner I, section II.1; docs/references.md).
struct rk4 {
  static auto tableau() {
    return methods::make_rk<R>({0, R(1, 2), R(1, 2), 1}, {{0, 0, 0, 0}, {R(1, 2), 0, 0, 0}, {0, R(1, 2), 0, 0}, {0, 0, 1, 0}},
                               {R(1, 6), R(1, 3), R(1, 3), R(1, 6)});
  }
};

/// Nystrom's classical method of order 4 for q'' = F(q, q') (Nystrom 1925, as printed in
/// Hairer, Norsett & Wanner I, section II.14; docs/references.md).
struct nystrom4 {
  static auto tableau() {
    return methods::make_nystrom<R>({0, R(1, 2), R(1, 2), 1}, {{0, 0, 0, 0}, {R(1, 8), 0, 0, 0}, {R(1, 8), 0, 0, 0}, {0, 0, R(1, 2), 0}},
                                    {{0, 0, 0, 0}, {R(1, 2), 0, 0, 0}, {0, R(1, 2), 0, 0}, {0, 0, 1, 0}},
                                    {R(1, 6), R(1, 6), R(1, 6), 0}, {R(1, 6), R(1, 3), R(1, 3), R(1, 6)});
  }
};

/// The triple jump of Stormer-Verlet, gamma = (1, -2^(1/3), 1) / (2 - 2^(1/3)), order 4
/// (Yoshida 1990, Phys. Lett. A 150, 262-268; Forest & Ruth 1990; docs/references.md).
struct triple_jump {
  static auto tableau() {
    const F r = generator({-2, 0, 0, 1});  // 2^(1/3)
    const auto base = methods::make_rkn<F>({0, 1}, {{0, 0}, {q(1, 2), 0}}, {q(1, 2), 0}, {q(1, 2), q(1, 2)});
    const F g1 = F(1) / (F(2) - r), g2 = -r / (F(2) - r);
    return methods::composition<decltype(base), 3>{base, {g1, g2, g1}};
  }
};

/// A unit charge in the uniform magnetic field B = 1: L = |v|^2/2 + (x v_y - y v_x)/2, a
/// Lagrangian that is not natural, with x'' = y', y'' = -x': the velocity turns at unit rate,
/// v(t) = R(-t) v0, q(t) = q0 + (vx0 sin t + vy0 (1 - cos t), vx0 (cos t - 1) + vy0 sin t).
struct uniform_field {
  static constexpr int dof = 2;
  template <class S>
  S operator()(const vec<S, 2>& x, const vec<S, 2>& v) const {
    return (v[0] * v[0] + v[1] * v[1]) / S(2) + (x[0] * v[1] - x[1] * v[0]) / S(2);
  }
  template <class T>
  static void exact(const T& t, vec<T, 2>& x, vec<T, 2>& p) {
    using std::cos;
    using std::sin;
    const T vx0(0), vy0(1), c = cos(t), s = sin(t);
    x << T(1) + vx0 * s + vy0 * (T(1) - c), vx0 * (c - T(1)) + vy0 * s;
    const vec<T, 2> v(vx0 * c + vy0 * s, -vx0 * s + vy0 * c);
    p << v[0] - x[1] / T(2), v[1] + x[0] / T(2);
  }
};

/// The tolerance of comparing two implicit maps: each solver stops within its Newton tolerance
/// (newton_options::tolerance_ulps, 64 eps relative by default) of the same stage solution.
template <class T>
T newton_tolerance() {
  return T(newton_options<T>{}.tolerance_ulps) * std::numeric_limits<T>::epsilon();
}

/// The largest relative difference max |x_a - x_b| / max(1, |x_b|) over the positions and momenta
/// of two states.
template <class T, class State>
T state_difference(const State& sa, const State& sb) {
  using std::abs;
  T worst(0);
  for (Eigen::Index i = 0; i < sb.q.size(); ++i) {
    worst = std::max<T>(worst, T(abs(T(sa.q[i] - sb.q[i])) / std::max<T>(T(1), T(abs(sb.q[i])))));
    worst = std::max<T>(worst, T(abs(T(sa.p[i] - sb.p[i])) / std::max<T>(T(1), T(abs(sb.p[i])))));
  }
  return worst;
}

/// The largest relative difference between two states after `steps` steps of each integrator.
template <class A, class B, class Sys, class T>
T map_difference(const Sys& sys, const vec<T, Sys::dof>& q0, const vec<T, Sys::dof>& v0, const T& tau, int steps) {
  integrator<A, Sys, T> a(sys, tau);
  integrator<B, Sys, T> b(sys, tau);
  auto sa = a.initial_state(q0, v0);
  auto sb = b.initial_state(q0, v0);
  for (int k = 0; k < steps; ++k) {
    a.step(sa);
    b.step(sb);
  }
  return state_difference<T>(sa, sb);
}

/// The largest relative difference between one step of A and one of B from the same state, over
/// the states of `steps` steps of B: the maps themselves, without the accumulation of a run.
template <class A, class B, class Sys, class T>
T step_difference(const Sys& sys, const vec<T, Sys::dof>& q0, const vec<T, Sys::dof>& v0, const T& tau, int steps) {
  integrator<A, Sys, T> a(sys, tau);
  integrator<B, Sys, T> b(sys, tau);
  auto sb = b.initial_state(q0, v0);
  T worst(0);
  for (int k = 0; k < steps; ++k) {
    auto sa = sb;
    a.step(sa);
    b.step(sb);
    worst = std::max<T>(worst, state_difference<T>(sa, sb));
  }
  return worst;
}

/// Observed order from the global errors at t = 1 with tau and tau/2 (log2 of their ratio).
template <class Scheme, class Sys, class T, class Exact>
double observed_order(const Sys& sys, const vec<T, Sys::dof>& q0, const vec<T, Sys::dof>& v0, int steps, Exact exact) {
  using std::abs;
  auto error = [&](int count) {
    integrator<Scheme, Sys, T> I(sys, T(1) / T(count));
    auto s = I.initial_state(q0, v0);
    I.advance(s, count);
    vec<T, Sys::dof> q, p;
    exact(T(1), q, p);
    T e(0);
    for (int i = 0; i < Sys::dof; ++i) e = std::max<T>(e, std::max<T>(T(abs(T(s.q[i] - q[i]))), T(abs(T(s.p[i] - p[i])))));
    return e;
  };
  const T coarse = error(steps), fine = error(2 * steps);
  using std::log2;
  return static_cast<double>(log2(coarse / fine));
}

}  // namespace

TEMPLATE_TEST_CASE("tableau_method: the Stormer-Verlet RKN tableau is trapezoidal_vi", "[methods]", double, cpp_bin_float_50) {
  // trapezoidal_vi solves its step by Newton's method (to its tolerance); the tableau is explicit.
  using T = TestType;
  const T tau = T(1) / T(10);
  vec<T, 1> q1(T(1)), v1(T(0));
  CHECK(map_difference<methods::tableau_method<verlet>, trapezoidal_vi>(systems::pendulum{}, q1, v1, tau, 20) <= newton_tolerance<T>());
  vec<T, 2> q2(T(1) / T(2), T(0)), v2(T(0), T(3) / T(2));
  CHECK(map_difference<methods::tableau_method<verlet>, trapezoidal_vi>(systems::kepler{}, q2, v2, tau, 20) <= newton_tolerance<T>());
}

TEMPLATE_TEST_CASE("tableau_method: the Gauss RKN tableaux over Q(sqrt 3) and Q(sqrt 15) are lpf on Gauss-interior nodes",
                   "[methods]", double, cpp_bin_float_50) {
  using T = TestType;
  const T tau = T(1) / T(4);
  vec<T, 2> q2(T(1) / T(2), T(0)), v2(T(0), T(3) / T(2));
  CHECK(map_difference<methods::tableau_method<gauss2>, lpf<3, gauss_interior>>(systems::kepler{}, q2, v2, tau, 10) <=
        newton_tolerance<T>());
  CHECK(map_difference<methods::tableau_method<gauss3>, lpf<4, gauss_interior>>(systems::kepler{}, q2, v2, tau, 10) <=
        newton_tolerance<T>());
  vec<T, 1> q1(T(2)), v1(T(0));
  CHECK(map_difference<methods::tableau_method<gauss3>, lpf<4, gauss_interior>>(systems::pendulum{}, q1, v1, tau, 10) <=
        newton_tolerance<T>());
}

TEMPLATE_TEST_CASE("tableau_method: a prk and an implicit rk tableau are the Stormer-Verlet and midpoint maps",
                   "[methods]", double, cpp_bin_float_50) {
  using T = TestType;
  const T tau = T(1) / T(10);
  vec<T, 2> q2(T(1) / T(2), T(0)), v2(T(0), T(3) / T(2));
  CHECK(map_difference<methods::tableau_method<lobatto_pair>, trapezoidal_vi>(systems::kepler{}, q2, v2, tau, 20) <=
        newton_tolerance<T>());
  CHECK(map_difference<methods::tableau_method<implicit_midpoint>, midpoint_vi>(systems::kepler{}, q2, v2, tau, 20) <=
        newton_tolerance<T>());
}

TEMPLATE_TEST_CASE("tableau_method: the Gauss Nystrom tableau on a Lagrangian that is not natural is lpf on Gauss-interior nodes",
                   "[methods]", double, cpp_bin_float_50) {
  using T = TestType;
  const T tau = T(1) / T(10);
  vec<T, 2> q2(T(1), T(0)), v2(T(0), T(1));
  CHECK(map_difference<methods::tableau_method<gauss2_nystrom>, lpf<3, gauss_interior>>(systems::charged{}, q2, v2, tau, 10) <=
        newton_tolerance<T>());
}

namespace {
/// LPF of degree M on Family's nodes as data: the collocation Nystrom tableau on its M - 1
/// interior nodes in T (methods/collocation_rkn.hpp).
template <class Family, int M, class T>
struct lpf_as_nystrom {
  static auto tableau() {
    const auto all = nodes<Family, M, T>();
    methods::stage_vector<T, M - 1> c;
    for (std::size_t i = 0; i + 1 < static_cast<std::size_t>(M); ++i) c[i] = all[i + 1];
    return methods::collocation_nystrom<T, M - 1>(c);
  }
};

template <class Family, int M, class T>
void check_lpf_is_nystrom_collocation() {
  // docs/results/schemes.md, "LPF as a Nystrom method": LPF's path satisfies the Euler-Lagrange
  // equations at the interior nodes, which is the collocation Nystrom method there for
  // q'' = F(q, q') with p <-> v by the Legendre maps. Both integrators solve their implicit
  // equations to their Newton tolerance, so one step of each from the same state agrees to it.
  INFO(Family::name << ", m = " << M);
  const T tau = T(1) / T(10);
  vec<T, 2> q(T(1), T(0)), v(T(0), T(1));
  CHECK(step_difference<methods::tableau_method<lpf_as_nystrom<Family, M, T>>, lpf<M, Family>>(systems::charged{}, q, v, tau, 10) <=
        newton_tolerance<T>());
  vec<T, 2> qs(T(11) / T(10), T(1) / T(2)), vs(T(0), T(0));
  CHECK(step_difference<methods::tableau_method<lpf_as_nystrom<Family, M, T>>, lpf<M, Family>>(zoo::spring_pendulum{}, qs, vs, tau, 10) <=
        newton_tolerance<T>());
}
}  // namespace

TEMPLATE_TEST_CASE("tableau_method: LPF on a Lagrangian that is not natural is the collocation Nystrom method on its interior nodes",
                   "[methods]", double, cpp_bin_float_50) {
  using T = TestType;
  check_lpf_is_nystrom_collocation<equispaced, 3, T>();
  check_lpf_is_nystrom_collocation<equispaced, 4, T>();
  check_lpf_is_nystrom_collocation<gauss_lobatto, 4, T>();
  check_lpf_is_nystrom_collocation<chebyshev_lobatto, 5, T>();
  check_lpf_is_nystrom_collocation<gauss_interior, 4, T>();
  check_lpf_is_nystrom_collocation<radau_right, 3, T>();
  check_lpf_is_nystrom_collocation<radau_left, 3, T>();
}

TEMPLATE_TEST_CASE("tableau_method: galerkin on a natural system is the Gauss Runge-Kutta method of the catalogue", "[methods]",
                   double, cpp_bin_float_50) {
  // The Galerkin VI of degree m with m-point Gauss quadrature is the Gauss RK method applied to
  // H(q, p) (Hairer, Lubich & Wanner 2006, Theorem VI.6.4); on a natural system with M = I the
  // Legendre map is linear (p = v) and the method runs on (q, p) as it does on (q, v). One step
  // of each from the same state agrees to the Newton tolerance.
  using T = TestType;
  const T tau = T(1) / T(4);
  vec<T, 2> q2(T(1) / T(2), T(0)), v2(T(0), T(3) / T(2));
  vec<T, 1> q1(T(2)), v1(T(0));
  CHECK(step_difference<methods::tableau_method<methods::gauss<2>>, galerkin_vi<2>>(systems::kepler{}, q2, v2, tau, 10) <= newton_tolerance<T>());
  CHECK(step_difference<methods::tableau_method<methods::gauss<3>>, galerkin_vi<3>>(systems::kepler{}, q2, v2, tau, 10) <= newton_tolerance<T>());
  CHECK(step_difference<methods::tableau_method<methods::gauss<4>>, galerkin_vi<4>>(systems::pendulum{}, q1, v1, tau, 10) <=
        newton_tolerance<T>());
  CHECK(step_difference<methods::tableau_method<methods::gauss<5>>, galerkin_vi<5>>(systems::pendulum{}, q1, v1, tau, 10) <=
        newton_tolerance<T>());
}

TEST_CASE("tableau_method: classical RK4 and Nystrom's method have order 4 in 50 digits", "[methods]") {
  using T = cpp_bin_float_50;
  vec<T, 1> q0(T(1)), v0(T(0));
  auto harmonic_exact = [](const T& t, vec<T, 1>& q, vec<T, 1>& p) {
    using std::cos;
    using std::sin;
    q[0] = cos(t);
    p[0] = -sin(t);
  };
  CHECK(std::lround(observed_order<methods::tableau_method<rk4>>(systems::harmonic{}, q0, v0, 16, harmonic_exact)) == 4);
  CHECK(std::lround(observed_order<methods::tableau_method<nystrom4>>(systems::harmonic{}, q0, v0, 16, harmonic_exact)) == 4);
  // On a Lagrangian that is not natural the velocity stages (ap) and the Legendre maps matter.
  vec<T, 2> x0(T(1), T(0)), u0(T(0), T(1));
  auto field_exact = [](const T& t, vec<T, 2>& q, vec<T, 2>& p) { uniform_field::exact(t, q, p); };
  CHECK(std::lround(observed_order<methods::tableau_method<nystrom4>>(uniform_field{}, x0, u0, 16, field_exact)) == 4);
  CHECK(std::lround(observed_order<methods::tableau_method<rk4>>(uniform_field{}, x0, u0, 16, field_exact)) == 4);
}

TEST_CASE("tableau_method: the triple jump of Stormer-Verlet over Q(2^(1/3)) has order 4 in 50 digits", "[methods]") {
  using T = cpp_bin_float_50;
  vec<T, 1> q0(T(1)), v0(T(0));
  auto pendulum_exact = [](const T& t, vec<T, 1>& q, vec<T, 1>& p) {
    const auto s = analysis::pendulum_from_rest(T(1), t);
    q[0] = s.q[0];
    p[0] = s.p[0];
  };
  CHECK(std::lround(observed_order<methods::tableau_method<triple_jump>>(systems::pendulum{}, q0, v0, 16, pendulum_exact)) == 4);
  CHECK(std::lround(observed_order<methods::tableau_method<verlet>>(systems::pendulum{}, q0, v0, 16, pendulum_exact)) == 2);
}

TEST_CASE("tableau_method: failures are reported through step_status", "[methods]") {
  // An implicit tableau with one Newton iteration allowed: no convergence, the state unchanged.
  integrator<methods::tableau_method<gauss2>, systems::pendulum, double> I(systems::pendulum{}, 1.0);
  I.options().max_iterations = 1;
  auto s = I.initial_state(vec<double, 1>(2.0), vec<double, 1>(0.0));
  const auto before = s.q;
  CHECK(I.try_step(s).reason == step_failure::no_convergence);
  CHECK(s.q == before);
  // The same on a Lagrangian that is not natural (stage accelerations, Euler-Lagrange residual).
  integrator<methods::tableau_method<gauss2_nystrom>, uniform_field, double> G(uniform_field{}, 1.0);
  G.options().max_iterations = 1;
  auto g = G.initial_state(vec<double, 2>(1.0, 0.0), vec<double, 2>(0.0, 1.0));
  CHECK(G.try_step(g).reason == step_failure::no_convergence);
  // An explicit tableau whose force is not finite at a stage (Kepler at the origin).
  integrator<methods::tableau_method<verlet>, systems::kepler, double> K(systems::kepler{}, 0.1);
  auto at_origin = K.initial_state(vec<double, 2>(0.0, 0.0), vec<double, 2>(1.0, 0.0));
  CHECK(K.try_step(at_origin).reason == step_failure::non_finite_iterate);
  // A non-finite state is refused before the step.
  auto bad = I.initial_state(vec<double, 1>(std::numeric_limits<double>::quiet_NaN()), vec<double, 1>(0.0));
  CHECK(I.try_step(bad).reason == step_failure::non_finite_input);
  // An rkn tableau on a Lagrangian that is not natural: refused (a static_assert in the scheme
  // type; at run time, by the engine).
  using engine = methods::detail::tableau_engine<uniform_field, double>;
  CHECK_THROWS_AS(engine(uniform_field{}, methods::to_scalar<double>(methods::nystrom_form_of(verlet::tableau()))),
                  std::invalid_argument);
}
