/// The problem zoo (mechanics/zoo.hpp): each system's closed-form energy against the energy the
/// integrators compute from the Lagrangian by automatic differentiation, its Noether momenta
/// conserved by a variational integrator to round-off, and the cited reference data (Arenstorf's
/// periodic orbit, Hairer, Norsett, Wanner, Solving ODEs I, section II.0).
#include <algorithm>
#include <cmath>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::abs_diff;
using geomint::test::eps_tol;

namespace {
/// |a| in the max norm plus one: the scale of relative tolerances.
template <class T, int n>
T scale_of(const vec<T, n>& a) {
  using std::abs;
  T out(1);
  for (int i = 0; i < n; ++i)
    if (abs(a[i]) + T(1) > out) out = abs(a[i]) + T(1);
  return out;
}
/// H from the Lagrangian by AD (qdot . L_qdot - L) against the zoo's closed form.
template <class Sys, class T>
void check_energy_formula(const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& v, const T& closed_form) {
  const T ad = energy_qv<Sys, T>(Sys{}, q, v);
  INFO(Sys::name);
  CHECK(abs_diff(ad, closed_form) <= eps_tol<T>(64) * scale_of<T, 1>(vec<T, 1>(closed_form)));
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("zoo: closed-form energies equal the Lagrangians' energies", "[mechanics][zoo]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  const vec<T, 2> q2(T(3) / T(10), T(-1) / T(5)), v2(T(1) / T(7), T(2) / T(5));
  check_energy_formula<zoo::henon_heiles, T>(q2, v2, zoo::henon_heiles::energy<T>(q2, v2));
  const vec<T, 2> qr(T(11) / T(10), T(1) / T(2));
  check_energy_formula<zoo::spring_pendulum, T>(qr, v2, zoo::spring_pendulum::energy<T>(qr, v2));
  check_energy_formula<zoo::double_pendulum, T>(q2, v2, zoo::double_pendulum::energy<T>(q2, v2));
  vec<T, 2> qa, va;
  zoo::arenstorf::initial_data<T>(qa, va);
  check_energy_formula<zoo::arenstorf, T>(qa, va, zoo::arenstorf::energy<T>(qa, va));
  const vec<T, 3> q3(T(1) / T(3), T(-1) / T(4), T(1) / T(5)), v3(T(1) / T(2), T(-1) / T(3), T(1) / T(9));
  check_energy_formula<zoo::toda3, T>(q3, v3, zoo::toda3::energy<T>(q3, v3));
  vec<T, 18> qs, vs;
  zoo::outer_solar::initial_data<T>(qs, vs);
  const vec<T, 18> ps = zoo::outer_solar::mass_matrix<T>() * vs;
  check_energy_formula<zoo::outer_solar, T>(qs, vs, zoo::outer_solar::energy_qp<T>(qs, ps));
}

TEMPLATE_LIST_TEST_CASE("zoo: Toda lattice keeps its total momentum exactly, H and I3 to the scheme's order",
                        "[mechanics][zoo]", geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::abs;
  // Galerkin VI of degree 2 (order 4): translation invariant, so sum p_i is its Noether momentum.
  const T tau = T(1) / T(10);
  integrator<galerkin_vi<2>, zoo::toda3, T> I(zoo::toda3{}, tau);
  auto s = I.initial_state(vec<T, 3>(T(0), T(1) / T(2), T(-1) / T(2)), vec<T, 3>(T(1), T(-1) / T(3), T(1) / T(5)));
  const T P0 = zoo::toda3::total_momentum<T>(s.p), H0 = zoo::toda3::energy<T>(s.q, s.p);
  const T I0 = zoo::toda3::cubic_integral<T>(s.q, s.p);
  T max_dH(0), max_dI(0);
  const long steps = 200;
  for (long k = 0; k < steps; ++k) {
    I.step(s);
    if (abs(zoo::toda3::energy<T>(s.q, s.p) - H0) > max_dH) max_dH = abs(zoo::toda3::energy<T>(s.q, s.p) - H0);
    if (abs(zoo::toda3::cubic_integral<T>(s.q, s.p) - I0) > max_dI) max_dI = abs(zoo::toda3::cubic_integral<T>(s.q, s.p) - I0);
  }
  CHECK(abs_diff(zoo::toda3::total_momentum<T>(s.p), P0) <= eps_tol<T>(64) * T(steps));
  // Order-4 bound with constant 1: |dH|, |dI3| <= tau^4 = 1e-4 (the errors are O(tau^4), no drift).
  CHECK(max_dH <= tau * tau * tau * tau);
  CHECK(max_dI <= tau * tau * tau * tau);
  CHECK(max_dH > T(0));  // not conserved exactly: the check measures something
}

/// In 50 digits the natural-system Hessian of 18 degrees of freedom is built column by column
/// (the fully nested duals would exceed Eigen's fixed-size stack limit); in double it is the
/// fully nested one. A second computation in higher precision is the reference: one 50-digit
/// step agrees with one double step to the double round-off, and keeps the linear momentum (a
/// Noether quantity of the midpoint map) to the 50-digit round-off.
TEST_CASE("zoo: outer solar system, one step in 50 digits against double", "[mechanics][zoo]") {
  using boost::multiprecision::cpp_bin_float_50;
  using T = cpp_bin_float_50;
  integrator<midpoint_vi, zoo::outer_solar, T> I(zoo::outer_solar{}, T(10));
  integrator<midpoint_vi, zoo::outer_solar, double> D(zoo::outer_solar{}, 10.0);
  vec<T, 18> q0, v0;
  zoo::outer_solar::initial_data<T>(q0, v0);
  vec<double, 18> q0d, v0d;
  zoo::outer_solar::initial_data<double>(q0d, v0d);
  auto s = I.initial_state(q0, v0);
  auto d = D.initial_state(q0d, v0d);
  const vec<T, 3> P0 = zoo::outer_solar::linear_momentum<T>(s.p);
  I.step(s);
  D.step(d);
  // The Newton tolerance (64 ulps) and the rounding of the double data, with a factor 4 of margin.
  const T double_eps(std::numeric_limits<double>::epsilon());
  const T q_scale = s.q.cwiseAbs().maxCoeff(), p_scale = s.p.cwiseAbs().maxCoeff();  // 30 AU; 1e-5 (masses ~1e-3)
  for (int i = 0; i < 18; ++i) {
    CHECK(abs_diff(s.q[i], T(d.q[i])) <= T(256) * double_eps * q_scale);
    CHECK(abs_diff(s.p[i], T(d.p[i])) <= T(256) * double_eps * p_scale);
  }
  const vec<T, 3> P1 = zoo::outer_solar::linear_momentum<T>(s.p);
  for (int i = 0; i < 3; ++i) CHECK(abs_diff(P1[i], P0[i]) <= eps_tol<T>(6400) * scale_of<T, 3>(P0));
}

/// The long-time behaviour in double (50 digits: the single-step test above).
TEST_CASE("zoo: outer solar system keeps linear and angular momentum", "[mechanics][zoo]") {
  using T = double;
  using std::abs;
  // Midpoint VI: invariant under translations and rotations, so both momenta are Noether
  // quantities of the discrete map. 100 steps of 10 days.
  integrator<midpoint_vi, zoo::outer_solar, T> I(zoo::outer_solar{}, T(10));
  vec<T, 18> q0, v0;
  zoo::outer_solar::initial_data<T>(q0, v0);
  auto s = I.initial_state(q0, v0);
  const vec<T, 3> P0 = zoo::outer_solar::linear_momentum<T>(s.p), L0 = zoo::outer_solar::angular_momentum<T>(s.q, s.p);
  const T H0 = zoo::outer_solar::energy_qp<T>(s.q, s.p);
  I.advance(s, 100);
  const vec<T, 3> P1 = zoo::outer_solar::linear_momentum<T>(s.p), L1 = zoo::outer_solar::angular_momentum<T>(s.q, s.p);
  for (int i = 0; i < 3; ++i) {
    CHECK(abs_diff(P1[i], P0[i]) <= eps_tol<T>(6400) * scale_of<T, 3>(P0) * T(1) / T(100));
    CHECK(abs_diff(L1[i], L0[i]) <= eps_tol<T>(6400) * scale_of<T, 3>(L0) * T(1) / T(100));
  }
  // Energy: the midpoint VI is of order 2, so the largest energy error over 1000 days falls by
  // about 4 when the step is halved.
  auto max_energy_error = [&](const T& tau) {
    integrator<midpoint_vi, zoo::outer_solar, T> J(zoo::outer_solar{}, tau);
    auto z = J.initial_state(q0, v0);
    T worst(0);
    for (long k = 0; k < static_cast<long>(T(1000) / tau); ++k) {
      J.step(z);
      worst = std::max(worst, T(abs(zoo::outer_solar::energy_qp<T>(z.q, z.p) - H0)));
    }
    return worst;
  };
  const T ratio = max_energy_error(T(10)) / max_energy_error(T(5));
  INFO("energy error ratio at tau = 10 and 5 days: " << ratio);
  CHECK(ratio > T(7) / T(2));
  CHECK(ratio < T(9) / T(2));
}

TEST_CASE("zoo: Arenstorf orbit closes after its cited period", "[mechanics][zoo]") {
  using T = double;
  using std::abs;
  // Galerkin VI of degree 6 (order 12) with 4000 steps over one period of the periodic orbit of
  // Hairer, Norsett, Wanner (II.0): the orbit returns to its start.
  const long steps = 4000;
  integrator<galerkin_vi<6>, zoo::arenstorf, T> I(zoo::arenstorf{}, zoo::arenstorf::period<T>() / T(steps));
  vec<T, 2> q0, v0;
  zoo::arenstorf::initial_data<T>(q0, v0);
  auto s = I.initial_state(q0, v0);
  const T H0 = I.energy(s);
  I.advance(s, steps);
  INFO("q(T) = (" << s.q[0] << ", " << s.q[1] << ")");
  CHECK(abs(s.q[0] - q0[0]) <= T(1) / T(1000));
  CHECK(abs(s.q[1] - q0[1]) <= T(1) / T(1000));
  CHECK(abs(I.energy(s) - H0) <= T(1) / T(1000000));
}

TEMPLATE_LIST_TEST_CASE("zoo: the tools' initial data have their stated invariants", "[mechanics][zoo]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  // Henon-Heiles: q0 = 0, |qdot0|^2 = 9/100 + 16/100, so H = 1/8 exactly (zoo.hpp).
  vec<T, 2> q, v;
  zoo::henon_heiles::initial_data(q, v);
  CHECK(abs_diff(zoo::henon_heiles::energy<T>(q, v), T(1) / T(8)) <= eps_tol<T>(4));
  // Toda: zero total momentum; spring and double pendulum: released from rest.
  vec<T, 3> q3, v3;
  zoo::toda3::initial_data(q3, v3);
  CHECK(abs_diff(zoo::toda3::total_momentum<T>(v3), T(0)) <= eps_tol<T>(4));
  zoo::spring_pendulum::initial_data(q, v);
  CHECK((v.array() == T(0)).all());
  zoo::double_pendulum::initial_data(q, v);
  CHECK((v.array() == T(0)).all());
}
