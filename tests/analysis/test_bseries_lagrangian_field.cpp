/// The first-order field (q, v) -> (v, F(q, v)) of a Lagrangian that is not natural
/// (analysis/bseries/lagrangian_field.hpp) against the Euler-Lagrange equations derived by hand.
///
/// - L = m(q) qdot^2 / 2 - V(q), m = 1 + q^2, V = q^4 / 4 (one degree of freedom): d/dt (m qdot)
///   = m' qdot^2 / 2 - V' gives qddot = -(q qdot^2 + q^3) / (1 + q^2); its derivatives
///   dF/dv = -2 q v / (1 + q^2), dF/dq = -((v^2 + 3 q^2)(1 + q^2) - 2 q (q v^2 + q^3)) / (1 + q^2)^2;
///   E = m qdot^2 / 2 + V, grad E = (q v^2 + q^3, (1 + q^2) v).
/// - The charged particle (systems::charged, L = |qdot|^2/2 + A . qdot with B_z = 1 + r^2): the
///   Lorentz force qddot = B (ydot, -xdot), E = |qdot|^2 / 2.
/// The field's first derivative goes through the jet scalar of elementary_differentials.hpp (the
/// duals of L's derivatives nest over it).
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "bseries_lagrangians.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/elementary_differentials.hpp"
#include "geomint/analysis/bseries/lagrangian_field.hpp"
#include "geomint/mechanics/systems.hpp"

namespace bseries_lagrangian_field_test {

using namespace geomint::analysis::bseries;
using geomint::vec;
using bseries_lagrangians::check_close;
using bseries_lagrangians::variable_mass;

/// L = qdot^2 / 2 for qdot > 0, L_vv = 0 at qdot = 0: degenerate there.
struct degenerate {
  static constexpr int dof = 1;
  template <class S>
  S operator()(const vec<S, 1>&, const vec<S, 1>& v) const { return S(v[0] * v[0] * v[0] / S(6)); }
};

TEMPLATE_TEST_CASE("lagrangian field: a position-dependent mass", "[bseries]", double, boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  const lagrangian_field<variable_mass> field{};
  const T q = T(7) / T(10), v = T(-13) / T(10), m = T(1) + q * q;
  const vec<T, 2> y(q, v);
  const vec<T, 2> f = field(y);
  check_close(f[0], v);
  check_close(f[1], T(-(q * v * v + q * q * q) / m));
  check_close(field.energy(y), T(m * v * v / T(2) + q * q * q * q / T(4)));
  const vec<T, 2> g = field.energy_gradient(y);
  check_close(g[0], T(q * v * v + q * q * q));
  check_close(g[1], T(m * v));
  // f'(y)[u] with u = (1, 0) and (0, 1): the columns of the Jacobian.
  const vec<T, 2> eq(T(1), T(0)), ev(T(0), T(1));
  const vec<T, 2> dq = directional_derivative(field, y, {&eq});
  const vec<T, 2> dv = directional_derivative(field, y, {&ev});
  check_close(dq[0], T(0));
  check_close(dv[0], T(1));
  check_close(dq[1], T(-((v * v + T(3) * q * q) * m - T(2) * q * (q * v * v + q * q * q)) / (m * m)));
  check_close(dv[1], T(-T(2) * q * v / m));
}

TEMPLATE_TEST_CASE("lagrangian field: the charged particle's Lorentz force", "[bseries]", double,
                   boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  const lagrangian_field<geomint::systems::charged> field{};
  const vec<T, 4> y(T(3) / T(10), T(-1) / T(2), T(2) / T(5), T(9) / T(10));
  const T B = T(1) + y[0] * y[0] + y[1] * y[1];
  const vec<T, 4> f = field(y);
  check_close(f[0], y[2]);
  check_close(f[1], y[3]);
  check_close(f[2], T(B * y[3]));
  check_close(f[3], T(-B * y[2]));
  check_close(field.energy(y), T((y[2] * y[2] + y[3] * y[3]) / T(2)));
  const vec<T, 4> g = field.energy_gradient(y);
  for (int i = 0; i < 4; ++i) check_close(g[i], i < 2 ? T(0) : y[i]);
}

TEST_CASE("lagrangian field: a singular L_vv is an error", "[bseries]") {
  const lagrangian_field<degenerate> field{};
  CHECK_THROWS_AS(field(vec<double, 2>(0.5, 0.0)), std::domain_error);
}

}  // namespace bseries_lagrangian_field_test
