/// The verdict of the order study (analysis/order_study.hpp, asymptotic_regime) on one-step maps
/// whose errors are known in closed form, so that the expected verdict follows from exact
/// mathematics:
///  - the midpoint rule on the harmonic oscillator (q, p)' = (p, -q) is the rotation of the
///    (q, p) plane by theta(tau) = 2 atan(tau/2) (its Cayley transform), the flow the rotation
///    by tau: global error at T = |R(N theta) - R(T)| z0, order 2 (theta - tau = -tau^3/12 + ...);
///    at T = 7 and N = 2, 4 the phase errors are 7 - 4 atan(7/4) = 2.8 and 7 - 8 atan(7/8) = 1.2
///    rad: errors as large as the solution (|z| = sqrt 2), no measurement;
///  - a rotation by tau + (tau^3 - 50 tau^4) / T: global error T (tau^2 - 50 tau^3) |z| to
///    leading order, which changes sign at tau = 1/50, so successive orders disagree there.
#include <algorithm>
#include <cmath>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/order_study.hpp"

namespace order_study_test {

using namespace geomint;
using real = double;

/// The rotation of (q, p) by angle a.
void rotate(const analysis::dynamic_vector<real>& q, const analysis::dynamic_vector<real>& p, real a, analysis::dynamic_vector<real>& q1,
            analysis::dynamic_vector<real>& p1) {
  q1 = std::cos(a) * q + std::sin(a) * p;
  p1 = -std::sin(a) * q + std::cos(a) * p;
}

/// The study of the one-step map "rotate by angle(tau)" against the exact rotation by t.
template <class Angle>
analysis::order_result<real> study(const Angle& angle, real t_end, const std::vector<long>& counts) {
  const analysis::dynamic_vector<real> q0 = analysis::dynamic_vector<real>::Constant(1, 1), p0 = q0;
  function_stepper<real> step(1, "rotation", [&](const auto& q, const auto& p, const real& tau, auto& q1, auto& p1) {
    rotate(q, p, angle(tau), q1, p1);
    return true;
  });
  analysis::reference_function<real> reference = [&](const real& t, auto& q, auto& p) { rotate(q0, p0, t, q, p); };
  return analysis::order_study<real>(step, reference, q0, p0, t_end, counts);
}

real midpoint_angle(real tau) { return 2 * std::atan(tau / 2); }

}  // namespace order_study_test

using namespace order_study_test;

TEST_CASE("order study: a short ladder or errors as large as the solution are no measurement", "[order]") {
  // geomint-order --system harmonic --scheme midpoint --t-end 7 --steps 2,4 used to print 1.12, ok.
  const auto short_ladder = study(midpoint_angle, 7, {2, 4});
  REQUIRE(short_ladder.ok);
  CHECK(analysis::asymptotic_regime(short_ladder).find("a ladder of 2 step counts") != std::string::npos);
  const auto coarse = study(midpoint_angle, 7, {2, 4, 8});
  REQUIRE(coarse.ok);
  CHECK(analysis::asymptotic_regime(coarse).find("not well below the solution's size") != std::string::npos);
}

TEST_CASE("order study: the midpoint rule in the asymptotic regime is ok with order 2", "[order]") {
  const auto r = study(midpoint_angle, 1, {16, 32, 64});
  REQUIRE(r.ok);
  CHECK(analysis::asymptotic_regime(r) == "ok");
  CHECK(std::abs(r.global_order - 2) < 0.01);
  // The local error in closed form, |(R(theta(tau)) - R(tau)) z0|_inf, from the two finest steps:
  // 3 + 0.02 (the max norm's direction moves with tau).
  auto local = [](real tau) {
    analysis::dynamic_vector<real> z = analysis::dynamic_vector<real>::Constant(1, 1), qa, pa, qb, pb;
    rotate(z, z, midpoint_angle(tau), qa, pa);
    rotate(z, z, tau, qb, pb);
    return std::max(std::abs(qa[0] - qb[0]), std::abs(pa[0] - pb[0]));
  };
  CHECK(std::abs(r.local_order - std::log(local(real(1) / 32) / local(real(1) / 64)) / std::log(real(2))) < 1e-9);
  REQUIRE(r.global_orders.size() == 2);
  CHECK(std::abs(r.global_orders[0] - 2) < 0.01);
}

TEST_CASE("order study: successive orders that disagree are flagged", "[order]") {
  const auto r = study([](real tau) { return tau + (tau * tau * tau - 50 * tau * tau * tau * tau); }, 1, {16, 32, 64, 128});
  REQUIRE(r.ok);
  CHECK(analysis::asymptotic_regime(r) == "outside: successive global orders disagree");
}
