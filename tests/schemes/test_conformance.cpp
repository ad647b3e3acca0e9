/// The integrator contract, checked the same way for every scheme over double and
/// cpp_bin_float_50: consistency, failure reporting that leaves the state unchanged, exact time
/// bookkeeping, symplecticity exactly where the scheme claims it, and reversibility (every
/// scheme here is symmetric: symmetric node families, symmetric quadratures).
///
/// Independent sources of the expected values: the exact flow of y'' = -y, (cos tau, -sin tau)
/// from (1, 0) (consistency); the time reversibility of the pendulum, (q, p) -> (q, -p)
/// (reversibility); J^T Omega J = Omega for a symplectic map (symplecticity; J by differences
/// in 50 digits, accurate to about 1e-40, analysis/symplecticity.hpp).
#include <cmath>
#include <limits>
#include <tuple>

#include <boost/math/constants/constants.hpp>

#include "catch.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/integrator.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "geomint/stepper.hpp"
#include "geomint/mechanics/constrained_systems.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/constrained_integrator.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using namespace geomint::analysis;
using boost::multiprecision::cpp_bin_float_50;

namespace {

/// One representative of every scheme kind, on every node family and both bases (and LPF's
/// fixed-point form, schemes/lpf_fixed_point.hpp).
using conformance_schemes = std::tuple<lpf<2>, lpf<3, gauss_lobatto>, lpf<4, gauss_interior>, lpf<4, chebyshev_lobatto, bernstein>,
                           galerkin_vi<3>, midpoint_vi, trapezoidal_vi, lpf_fixed_point<4>>;

/// Every scheme x {double, cpp_bin_float_50}.
using cases = std::tuple<std::pair<lpf<2>, double>, std::pair<lpf<2>, cpp_bin_float_50>,
                         std::pair<lpf<3, gauss_lobatto>, double>, std::pair<lpf<3, gauss_lobatto>, cpp_bin_float_50>,
                         std::pair<lpf<4, gauss_interior>, double>, std::pair<lpf<4, gauss_interior>, cpp_bin_float_50>,
                         std::pair<lpf<4, chebyshev_lobatto, bernstein>, double>,
                         std::pair<lpf<4, chebyshev_lobatto, bernstein>, cpp_bin_float_50>,
                         std::pair<galerkin_vi<3>, double>, std::pair<galerkin_vi<3>, cpp_bin_float_50>,
                         std::pair<midpoint_vi, double>, std::pair<midpoint_vi, cpp_bin_float_50>,
                         std::pair<trapezoidal_vi, double>, std::pair<trapezoidal_vi, cpp_bin_float_50>,
                         std::pair<lpf_fixed_point<4>, double>, std::pair<lpf_fixed_point<4>, cpp_bin_float_50>>;

template <class T>
T abs_of(const T& x) {
  using std::abs;
  return T(abs(x));
}

/// Local error of one step of y'' = -y from (1, 0) against the exact flow.
template <class Scheme, class T>
T local_error(const T& tau) {
  integrator<Scheme, systems::harmonic, T> I(systems::harmonic{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  I.step(s);
  using std::cos;
  using std::sin;
  const T eq = abs_of(T(s.q[0] - cos(tau))), ep = abs_of(T(s.p[0] + sin(tau)));
  return eq > ep ? eq : ep;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("conformance: consistency of order >= 2 against the exact flow", "[conformance]", cases) {
  using Scheme = typename TestType::first_type;
  using T = typename TestType::second_type;
  // Every scheme here has order >= 2, so the local error is O(tau^3): halving tau divides it
  // by about 8 (at least 6 allows for the next term at tau = 1/8).
  const T coarse = local_error<Scheme, T>(T(1) / T(8)), fine = local_error<Scheme, T>(T(1) / T(16));
  INFO(Scheme::name() << ": local errors " << coarse << ", " << fine);
  CHECK(coarse > T(0));
  CHECK(coarse / fine > T(6));
}

TEMPLATE_LIST_TEST_CASE("conformance: a failed step reports reason and index and leaves the state unchanged",
                        "[conformance]", cases) {
  using Scheme = typename TestType::first_type;
  using T = typename TestType::second_type;
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(10));
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  I.advance(s, 3);
  s.q[0] = std::numeric_limits<T>::quiet_NaN();
  const auto before = s;
  const step_status st = I.try_step(s);
  CHECK(st.reason == step_failure::non_finite_input);
  CHECK(st.step == 3);
  CHECK(s.step == before.step);
  CHECK(s.p == before.p);
  CHECK(s.t == before.t);
  bool thrown = false;
  try {
    I.step(s);
  } catch (const integration_error& e) {
    thrown = true;
    CHECK(e.step() == 3);
    CHECK(e.reason() == step_failure::non_finite_input);
  }
  CHECK(thrown);
  I.set_tau(T(0));
  auto good = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  CHECK(I.try_step(good).reason == step_failure::invalid_step_size);
  CHECK(good.step == 0);
  CHECK(good.q[0] == T(1));
}

TEMPLATE_LIST_TEST_CASE("conformance: continuing steps and fresh steps solve the same equations", "[conformance]",
                        cases) {
  // A continuing step starts from the previous step's solution (extrapolated) and, while it
  // contracts well, its factorised Newton matrix (the fixed-point form: the previous stage
  // forces); a fresh integrator per step starts from its fresh predictor (and a fresh matrix),
  // and in multiprecision both may stop on the contraction rate (stop_on_rate). Both solve
  // the same equations to tolerance_ulps (64) eps relative, so after 30 steps the two runs
  // agree to 30 x 2 x 64 eps, with room to spare (exact mathematics: one solution).
  using Scheme = typename TestType::first_type;
  using T = typename TestType::second_type;
  const T tau = T(1) / T(2);
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  auto fresh = s;
  for (int k = 0; k < 30; ++k) {
    I.step(s);
    integrator<Scheme, systems::pendulum, T> J(systems::pendulum{}, tau);
    J.step(fresh);
  }
  INFO(Scheme::name() << ": q " << s.q[0] << " and " << fresh.q[0]);
  CHECK(abs_of(T(s.q[0] - fresh.q[0])) <= T(3840) * std::numeric_limits<T>::epsilon());
  CHECK(abs_of(T(s.p[0] - fresh.p[0])) <= T(3840) * std::numeric_limits<T>::epsilon());
}

TEMPLATE_LIST_TEST_CASE("conformance: t_k = t0 + k tau exactly, also after a change of tau", "[conformance]", cases) {
  using Scheme = typename TestType::first_type;
  using T = typename TestType::second_type;
  const T tau = T(1) / T(10);
  integrator<Scheme, systems::harmonic, T> I(systems::harmonic{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  s.t = T(5);
  I.advance(s, 1000);
  CHECK(s.step == 1000);
  CHECK(s.t == T(5) + T(1000) * tau);  // accumulating t += tau would miss this in binary arithmetic
  I.set_tau(tau / T(2));
  I.advance(s, 10);
  CHECK(s.t == (T(5) + T(1000) * tau) + T(10) * (tau / T(2)));
}

TEMPLATE_LIST_TEST_CASE("conformance: reversibility of the symmetric schemes", "[conformance]", cases) {
  using Scheme = typename TestType::first_type;
  using T = typename TestType::second_type;
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(4));
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1) / T(2)));
  const auto start = s;
  I.advance(s, 5);
  s.p = -s.p;
  I.advance(s, 5);
  // Back at (q0, -p0) to the Newton tolerance, amplified by at most a few steps.
  const T tol = geomint::test::eps_tol<T>(4096);
  CHECK(geomint::test::abs_diff(s.q[0], start.q[0]) <= tol);
  CHECK(geomint::test::abs_diff(T(-s.p[0]), start.p[0]) <= tol);
}

/// Which schemes are symplectic for natural systems (constant mass matrix): the variational
/// ones, and LPF when its interior nodes are Gauss points or m = 2 (docs/results/analysis.md).
template <class Scheme>
inline constexpr bool is_lpf = false;
template <int M, class Family, class Basis>
inline constexpr bool is_lpf<lpf<M, Family, Basis>> = true;
template <class Scheme>
constexpr bool claims_symplectic() {
  if constexpr (is_lpf<Scheme>)
    return Scheme::m == 2 || std::is_same_v<typename Scheme::family, gauss_interior>;
  else
    return true;
}

TEMPLATE_LIST_TEST_CASE("conformance: symplectic exactly where claimed (pendulum, 50 digits)", "[conformance]", conformance_schemes) {
  using Scheme = TestType;
  using T = cpp_bin_float_50;
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(4));
  const auto stepper = erase(I);
  phase_vector<T> z(2);
  z[0] = T(1);
  z[1] = T(1) / T(2);
  const T defect = symplectic_defect<T>(one_step_jacobian<T>(*stepper, I.tau(), z));
  INFO(Scheme::name() << ": defect " << defect);
  using std::cbrt;
  const T eps = std::numeric_limits<T>::epsilon();
  if constexpr (claims_symplectic<Scheme>())
    CHECK(defect < cbrt(eps * eps));  // eps^(2/3), about 1e-33: the difference Jacobian is good to 1e-40
  else
    CHECK(defect > cbrt(eps));  // eps^(1/3), about 1e-17: a structural defect, far above the noise
}

TEMPLATE_LIST_TEST_CASE("conformance: the constrained integrator follows the same contract", "[conformance]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  const T tau = T(1) / T(10);
  constrained_integrator<constrained_lpf<3, gauss_interior>, systems::free_particle_2d, systems::unit_circle, T> I(
      {}, {}, tau);
  auto s = I.initial_state(vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), T(1)));
  I.advance(s, 100);
  CHECK(s.step == 100);
  CHECK(s.t == T(100) * tau);
  // Unit speed on the unit circle: the exact angle is t = 10, i.e. 10 - 4 pi in (-pi, pi].
  using std::atan2;
  CHECK(geomint::test::abs_diff(T(atan2(s.q[1], s.q[0])), T(T(100) * tau - T(4) * boost::math::constants::pi<T>())) <
        T(1) / T(1000));
  s.p[1] = std::numeric_limits<T>::infinity();
  const auto before = s;
  const step_status st = I.try_step(s);
  CHECK(st.reason == step_failure::non_finite_input);
  CHECK(st.step == 100);
  CHECK(s.q == before.q);
  CHECK(s.step == before.step);
}
