/// Short versions of the order and symplecticity studies (the full tables: geomint-order and
/// geomint-symplectic, docs/results/analysis.md).
#include "catch.hpp"
#include "geomint/analysis/exact_scheme.hpp"
#include "geomint/analysis/order_study.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/integrator.hpp"
#include "geomint/stepper.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using T = boost::multiprecision::cpp_bin_float_50;
using Pendulum = systems::pendulum;

namespace {

/// Observed global order of Scheme on the pendulum from theta = 1 at rest, T = 1, N = 8..64,
/// against the Taylor reference flow in 100 digits.
template <class Scheme>
analysis::order_result<T> pendulum_orders(const std::vector<long>& counts) {
  using R = boost::multiprecision::cpp_bin_float_100;
  const auto stepper = erase(integrator<Scheme, Pendulum, T>());
  analysis::reference_function<T> reference = [](const T& t, analysis::dynamic_vector<T>& q,
                                                 analysis::dynamic_vector<T>& p) {
    analysis::reference_flow<Pendulum, R> flow(vec<R, 1>(R(1)), vec<R, 1>(R(0)));
    flow.advance_to(R(t));
    q = analysis::dynamic_vector<T>::Constant(1, T(flow.q()[0]));
    p = analysis::dynamic_vector<T>::Constant(1, T(flow.p()[0]));
  };
  const analysis::dynamic_vector<T> q0 = analysis::dynamic_vector<T>::Constant(1, T(1)),
                                    p0 = analysis::dynamic_vector<T>::Constant(1, T(0));
  return analysis::order_study<T>(*stepper, reference, q0, p0, T(1), counts);
}

template <class Scheme>
void check_orders(int expected_global) {
  const auto r = pendulum_orders<Scheme>({8, 16, 32});
  INFO(Scheme::name() << ": local " << r.local_order << ", global " << r.global_order);
  REQUIRE(r.ok);
  using std::abs;
  // Observed slopes within 0.25 of the integers: the asymptotic regime at tau = 1/32.
  CHECK(abs(r.global_order - T(expected_global)) < T(1) / T(4));
  CHECK(abs(r.local_order - T(expected_global + 1)) < T(1) / T(4));
}

/// The symplecticity defect of Scheme's one-step map on the pendulum at (q, p) = (1, 1/2), tau = 1/4.
template <class Scheme>
T pendulum_defect() {
  const auto stepper = erase(integrator<Scheme, Pendulum, T>());
  analysis::phase_vector<T> z0(2);
  z0 << T(1), T(1) / T(2);
  return analysis::symplectic_defect<T>(analysis::one_step_jacobian<T>(*stepper, T(1) / T(4), z0));
}

}  // namespace

TEST_CASE("symplectic defect of known matrices", "[analysis][symplectic]") {
  // Exact mathematics: rotations and shears are symplectic; diag(2, 1) has J^T Omega J = 2 Omega.
  using std::cos;
  using std::sin;
  analysis::phase_matrix<T> rotation(2, 2), stretch(2, 2), shear4(4, 4);
  const T c = cos(T(3) / T(10)), s = sin(T(3) / T(10));
  rotation << c, s, -s, c;
  stretch << T(2), T(0), T(0), T(1);
  shear4.setIdentity();
  shear4.block(2, 0, 2, 2) << T(3), T(1), T(1), T(5);  // p += S q with S symmetric
  CHECK(analysis::symplectic_defect<T>(rotation) <= geomint::test::eps_tol<T>(8));
  CHECK(analysis::symplectic_defect<T>(shear4) == T(0));
  CHECK(analysis::symplectic_defect<T>(stretch) == T(1));
  // The difference Jacobian of a linear map is the matrix itself (to round-off over delta).
  function_stepper<T> linear(2, "shear", [&](const dynamic_vector<T>& q, const dynamic_vector<T>& p, const T&,
                                               dynamic_vector<T>& q1, dynamic_vector<T>& p1) {
    analysis::phase_vector<T> z(4);
    z << q, p;
    const analysis::phase_vector<T> z1 = shear4 * z;
    q1 = z1.head(2);
    p1 = z1.tail(2);
    return true;
  });
  analysis::phase_vector<T> z(4);
  z << T(1), T(2), T(3), T(4);
  using std::pow;
  const T J_error = (analysis::one_step_jacobian<T>(linear, T(1), z) - shear4).cwiseAbs().maxCoeff();
  CHECK(J_error <= T(64) * pow(std::numeric_limits<T>::epsilon(), T(4) / T(5)));
}

TEST_CASE("variational schemes are symplectic to working precision; LPF on equispaced m = 3 is not",
          "[analysis][symplectic]") {
  using std::pow;
  // The difference Jacobian is accurate to about eps^(4/5) (1e-40 in 50 digits).
  const T floor_level = T(1024) * pow(std::numeric_limits<T>::epsilon(), T(4) / T(5));
  const T midpoint = pendulum_defect<midpoint_vi>(), trapezoidal = pendulum_defect<trapezoidal_vi>(),
          galerkin = pendulum_defect<galerkin_vi<3>>(), lpf_m2 = pendulum_defect<lpf<2, equispaced>>(),
          lpf_m3 = pendulum_defect<lpf<3, equispaced>>();
  INFO("midpoint " << midpoint << ", trapezoidal " << trapezoidal << ", galerkin(3) " << galerkin << ", lpf(2) "
                   << lpf_m2 << ", lpf(3, equispaced) " << lpf_m3);
  CHECK(midpoint <= floor_level);
  CHECK(trapezoidal <= floor_level);
  CHECK(galerkin <= floor_level);
  CHECK(lpf_m2 <= floor_level);
  // A non-variational map stands out by many orders of magnitude.
  CHECK(lpf_m3 > pow(std::numeric_limits<T>::epsilon(), T(1) / T(5)));
}

TEST_CASE("observed orders on the pendulum", "[analysis][order]") {
  // Expected orders from independent sources: midpoint 2 (its exact R(tau), eq. 17); Galerkin with
  // m-point Gauss quadrature 2m (variational error analysis of Galerkin VIs); LPF on equispaced
  // nodes the order of the exact two-step scheme of the harmonic oscillator (exact_scheme.hpp);
  // LPF on the m - 1 Gauss interior nodes 2(m - 1), the order of (m - 1)-stage Gauss collocation.
  check_orders<midpoint_vi>(exact_midpoint_two_step().order);
  check_orders<galerkin_vi<2>>(4);
  check_orders<lpf<2, equispaced>>(exact_two_step<2>().order);
  check_orders<lpf<3, equispaced>>(exact_two_step<3>().order);
  check_orders<lpf<4, equispaced>>(exact_two_step<4>().order);
  check_orders<lpf<3, gauss_interior>>(4);
  check_orders<lpf<4, gauss_interior>>(6);
}

TEST_CASE("energy behaviour: slope and maximum", "[analysis][symplectic]") {
  // Exact mathematics: a map that adds tau to the "energy" z[0] each step drifts with slope 1.
  function_stepper<T> drift(
      1, "drift",
      [](const dynamic_vector<T>& q, const dynamic_vector<T>& p, const T&, dynamic_vector<T>& q1, dynamic_vector<T>& p1) {
        q1 = q;
        q1[0] += T(1) / T(4);
        p1 = p;
        return true;
      },
      [](const dynamic_vector<T>& q, const dynamic_vector<T>&) { return q[0]; });
  analysis::phase_vector<T> z0 = analysis::phase_vector<T>::Zero(2);
  const auto r = analysis::energy_behaviour<T>(drift, z0, T(1) / T(4), 40);
  CHECK(r.ok);
  CHECK(r.steps == 40);
  CHECK(geomint::test::abs_diff(r.max_error, T(10)) <= geomint::test::eps_tol<T>(16));
  CHECK(geomint::test::abs_diff(r.drift, T(1)) <= geomint::test::eps_tol<T>(64));
}
