/// H(q, p) = p . v - L(q, v) of a Lagrangian that is not natural
/// (analysis/bseries/lagrangian_hamiltonian.hpp) against Hamiltonians derived by hand, and the
/// identification it is used for: one step of the Galerkin variational integrator is the Gauss
/// Runge-Kutta step on H (Hairer, Lubich & Wanner, Geometric Numerical Integration, 2006,
/// Theorem VI.6.4), checked against the Gauss stage equations solved here independently.
///
/// - L = (1 + q^2) qdot^2 / 2 - q^4 / 4: p = (1 + q^2) v, H = p^2 / (2 (1 + q^2)) + q^4 / 4,
///   H_q = -q p^2 / (1 + q^2)^2 + q^3, H_p = p / (1 + q^2).
/// - The charged particle (systems::charged, L = |v|^2/2 + A . v, A = a(r) (-y, x),
///   a = (1 + r^2/2)/2): p = v + A, H = |p - A|^2 / 2, H_p = p - A.
/// - L = v^2/2 + v^4/12 - q^2/2 (Newton needs several steps): p = v + v^3/3, so
///   dv/dp = 1 / (1 + v^2) and d^2v/dp^2 = -2 v / (1 + v^2)^3 (the derivatives of the implicit v
///   carried by the dual scalar through the iteration).
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>

#include "bseries_lagrangians.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/elementary_differentials.hpp"
#include "geomint/analysis/bseries/lagrangian_hamiltonian.hpp"
#include "geomint/analysis/bseries/rkn_series.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/schemes/classical.hpp"

namespace bseries_lagrangian_hamiltonian_test {

using namespace geomint::analysis::bseries;
using geomint::dual;
using geomint::vec;
using bseries_lagrangians::check_close;
using bseries_lagrangians::variable_mass;

/// L = v^2/2 + v^4/12 - q^2/2.
struct quartic_kinetic {
  static constexpr int dof = 1;
  template <class S>
  S operator()(const vec<S, 1>& q, const vec<S, 1>& v) const {
    const S v2 = v[0] * v[0];
    return S(v2 / S(2) + v2 * v2 / S(12) - q[0] * q[0] / S(2));
  }
};

TEMPLATE_TEST_CASE("lagrangian hamiltonian: a position-dependent mass", "[bseries]", double, boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  const lagrangian_hamiltonian<variable_mass> H{};
  const T q = T(7) / T(10), p = T(-13) / T(10), m = T(1) + q * q;
  const vec<T, 2> y(q, p);
  check_close(H(y), T(p * p / (T(2) * m) + q * q * q * q / T(4)));
  const vec<T, 2> g = H.gradient(y);
  check_close(g[0], T(-q * p * p / (m * m) + q * q * q));
  check_close(g[1], T(p / m));
  // The field J^{-1} grad H through hamiltonian_field, and its derivative in the jet scalar:
  // d/dq of H_p = p / m is -2 q p / m^2.
  const hamiltonian_field<lagrangian_hamiltonian<variable_mass>, 1> f{};
  const vec<T, 2> fy = f(y);
  check_close(fy[0], T(p / m));
  check_close(fy[1], T(q * p * p / (m * m) - q * q * q));
  const vec<T, 2> dq(T(1), T(0));
  const vec<T, 2> d = directional_derivative(f, y, {&dq});
  check_close(d[0], T(-T(2) * q * p / (m * m)));
}

TEMPLATE_TEST_CASE("lagrangian hamiltonian: the charged particle", "[bseries]", double, boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  const lagrangian_hamiltonian<geomint::systems::charged> H{};
  const T x = T(3) / T(5), z = T(-2) / T(5), px = T(1) / T(3), pz = T(6) / T(5);
  const T a = (T(1) + (x * x + z * z) / T(2)) / T(2);
  const T vx = px + a * z, vz = pz - a * x;  // p - A, A = a (-z, x)
  const vec<T, 4> y(x, z, px, pz);
  check_close(H(y), T((vx * vx + vz * vz) / T(2)));
  const vec<T, 4> g = H.gradient(y);
  check_close(g[2], vx);
  check_close(g[3], vz);
  // H_q = -(dA/dq)^T (p - A): A_x = -a z, A_y = a x, da/dq = q / 2.
  check_close(g[0], T(-(-x / T(2) * z * vx + (a + x * x / T(2)) * vz)));
  check_close(g[1], T(-(-(a + z * z / T(2)) * vx + z / T(2) * x * vz)));
}

TEMPLATE_TEST_CASE("lagrangian hamiltonian: the implicit velocity's derivatives converge with its value", "[bseries]", double,
                   boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  using D1 = dual<T, 1>;
  using D2 = dual<D1, 1>;
  const lagrangian_hamiltonian<quartic_kinetic> H{};
  const T q = T(1) / T(2), p = T(5) / T(2);
  // p along both dual levels: v.v = v, v.d = dv/dp, v.d.d = d^2 v / dp^2.
  D2 pd;
  pd.v = D1::variable(p, 0);
  pd.d[0] = D1(T(1));
  const vec<D2, 1> v = H.velocity<D2>(vec<D2, 1>(D2(D1(q))), vec<D2, 1>(pd));
  const T v0 = v[0].v.v;
  check_close(T(v0 + v0 * v0 * v0 / T(3)), p);
  check_close(v[0].v.d[0], T(T(1) / (T(1) + v0 * v0)));
  check_close(v[0].d[0].d[0], T(-T(2) * v0 / ((T(1) + v0 * v0) * (T(1) + v0 * v0) * (T(1) + v0 * v0))));
}

TEST_CASE("collocation_rk_weights: the Gauss methods' B-series", "[bseries]") {
  using Q = geomint::methods::exact_rational;
  const geomint::analysis::bseries::tree_set trees(7, 1);
  // s = 1 on Gauss nodes: the midpoint rule a = 1/2, b = 1, c = 1/2, by series.hpp from its tableau.
  geomint::methods::tableau_data<Q> midpoint;
  midpoint.kind = geomint::methods::method_kind::rk;
  midpoint.stages = 1;
  midpoint.a = {{Q(1, 2)}};
  midpoint.b = {Q(1)};
  midpoint.c = {Q(1, 2)};
  CHECK(collocation_rk_weights(trees, geomint::galerkin_tableau<1>()) == elementary_weights(trees, midpoint));
  // The s-stage Gauss method has order 2s exactly (HLW section II.1.3).
  CHECK(series_order(trees, collocation_rk_weights(trees, geomint::galerkin_tableau<2>())) == 4);
  CHECK(series_order(trees, collocation_rk_weights(trees, geomint::galerkin_tableau<3>())) == 6);
}

/// One step of the 2-stage Gauss method (HLW Table II.1.1: c = 1/2 -+ sqrt(3)/6,
/// a = [[1/4, 1/4 - sqrt(3)/6], [1/4 + sqrt(3)/6, 1/4]], b = (1/2, 1/2); s = 1 the midpoint rule
/// a = 1/2, b = 1) on q' = H_p, p' = -H_q of H = p^2 / (2 (1 + q^2)) + q^4/4, the stage
/// equations solved by fixed-point iteration.
template <class T, int s>
vec<T, 2> gauss_step(const vec<T, 2>& y, const T& h, const T (&a)[s][s], const T (&b)[s]) {
  const auto f = [](const vec<T, 2>& z) {
    const T m = T(1) + z[0] * z[0];
    return vec<T, 2>(z[1] / m, T(z[0] * z[1] * z[1] / (m * m) - z[0] * z[0] * z[0]));
  };
  vec<T, 2> k[s];
  for (auto& ki : k) ki = f(y);
  for (int it = 0; it < 400; ++it) {
    vec<T, 2> next[s];
    for (int i = 0; i < s; ++i) {
      vec<T, 2> z = y;
      for (int j = 0; j < s; ++j) z += h * a[i][j] * k[j];
      next[i] = f(z);
    }
    for (int i = 0; i < s; ++i) k[i] = next[i];
  }
  vec<T, 2> out = y;
  for (int i = 0; i < s; ++i) out += h * b[i] * k[i];
  return out;
}

TEST_CASE("galerkin m = 2 and midpoint on a Lagrangian that is not natural are the Gauss RK methods on H(q, p)", "[bseries]") {
  using T = boost::multiprecision::cpp_bin_float_50;
  using std::abs;
  using std::sqrt;
  const T h = T(1) / T(5), q0 = T(7) / T(10), v0 = T(-13) / T(10);
  const vec<T, 1> q(q0), v(v0);
  const vec<T, 2> y(q0, T((T(1) + q0 * q0) * v0));
  const T r = sqrt(T(3)) / T(6);
  const T a2[2][2] = {{T(1) / T(4), T(1) / T(4) - r}, {T(1) / T(4) + r, T(1) / T(4)}};
  const T b2[2] = {T(1) / T(2), T(1) / T(2)};
  const T a1[1][1] = {{T(1) / T(2)}};
  const T b1[1] = {T(1)};
  const T tolerance = T(1) / T("1e40");
  {
    geomint::integrator<geomint::galerkin_vi<2>, variable_mass, T> I(variable_mass{}, h);
    auto st = I.initial_state(q, v);
    I.step(st);
    const vec<T, 2> expected = gauss_step<T, 2>(y, h, a2, b2);
    INFO("galerkin " << st.q[0] << ", " << st.p[0] << " Gauss " << expected[0] << ", " << expected[1]);
    CHECK(T(abs(T(st.q[0] - expected[0]))) < tolerance);
    CHECK(T(abs(T(st.p[0] - expected[1]))) < tolerance);
    // The 1-stage method is another map: the comparison can tell them apart.
    CHECK(T(abs(T(st.q[0] - gauss_step<T, 1>(y, h, a1, b1)[0]))) > T(1) / T(1000000));
  }
  {
    geomint::integrator<geomint::midpoint_vi, variable_mass, T> I(variable_mass{}, h);
    auto st = I.initial_state(q, v);
    I.step(st);
    const vec<T, 2> expected = gauss_step<T, 1>(y, h, a1, b1);
    CHECK(T(abs(T(st.q[0] - expected[0]))) < tolerance);
    CHECK(T(abs(T(st.p[0] - expected[1]))) < tolerance);
  }
}

}  // namespace bseries_lagrangian_hamiltonian_test
