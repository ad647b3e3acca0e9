/// Compile-only: stability intervals and verdicts over Q(r) in static_assert
/// (analysis/algebraic_stability.hpp). Independent value: Forest-Ruth (Forest & Ruth 1990; the
/// position Stormer-Verlet steps theta h, (1 - 2 theta) h, theta h, theta = 1/(2 - 2^(1/3))) on
/// y'' = -y has det M = 1 and |tr M(tau)| <= 2 up to tau* = 1.5734019474345400566295794419626...,
/// tau*^2 = 2.4755936881908031514897661643661..., the first crossing of |tr M| = 2 found by a scan
/// in steps of 0.001 and bisection on the product of the nine 2 x 2 kick and drift matrices in
/// 80-digit decimal arithmetic (Python's decimal module), outside the library. (Yoshida's triple
/// jump, with the same tau*, compiles the same way in 14 s more of GCC's time: it is left to the
/// run-time tests, tests/analysis/test_field_stability.cpp.)
#include "geomint/analysis/algebraic_stability.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/composition.hpp"

namespace {

using geomint::exact_number;
using geomint::rational;

template <class Method>
constexpr geomint::algebraic_linear_stability_result stability_of() {
  const auto composed = geomint::methods::tableau_of(Method::tableau());
  if (!(composed.d == 1)) throw "the composition is not consistent";
  return geomint::algebraic_linear_stability(composed.tableau);
}
constexpr auto forest_ruth = stability_of<geomint::methods::forest_ruth>();

static_assert(forest_ruth.determinant_is_one);
static_assert(forest_ruth.interval.kind == geomint::stability_kind::periodic);
static_assert(!forest_ruth.interval.empty && !forest_ruth.interval.unbounded);
// tau*^2 in (2.475593688190803151, 2.475593688190803152).
static_assert(forest_ruth.interval.compare_squared(exact_number(rational(2475593688190803151, 1000000000000000000))) < 0);
static_assert(forest_ruth.interval.compare_squared(exact_number(rational(2475593688190803152, 1000000000000000000))) > 0);
// Order 4, symmetric: R - 2 cos tau = O(tau^6) and the phase lag of order 4 (HLW section V.3).
static_assert(forest_ruth.order == 4 && forest_ruth.phase_lag_order == 4);

// y' = lambda y over Q(sqrt 3): the 2-stage SDIRK method of order 3, (gamma, 0; 1 - 2 gamma,
// gamma), b = (1/2, 1/2), gamma = (3 +- sqrt 3)/6, is A-stable for the + sign only, and not
// L-stable (R(inf) = 1 - sqrt 3); for the - sign |R(iy)| > 1 for every y > 0 (Hairer & Wanner
// II, section IV.6, SDIRK methods).
constexpr geomint::methods::field_polynomial<2> sqrt3_field{{-3, 0, 1}, 1, 2};
using Q3 = geomint::methods::algebraic_number<sqrt3_field>;
constexpr auto sdirk(int sign) {
  const Q3 g = (Q3(3) + Q3(sign) * Q3::generator()) / Q3(6);
  return geomint::methods::make_rk<Q3>({g, Q3(1) - g}, {{g, Q3(0)}, {Q3(1) - g - g, g}}, {Q3(rational(1, 2)), Q3(rational(1, 2))});
}
constexpr auto sdirk_plus = geomint::algebraic_rk_stability(sdirk(1));
constexpr auto sdirk_minus = geomint::algebraic_rk_stability(sdirk(-1));
static_assert(sdirk_plus.a_stable && !sdirk_plus.l_stable);
static_assert(!sdirk_minus.a_stable && sdirk_minus.poles_in_right_half_plane && sdirk_minus.imaginary_axis.empty);

// An explicit method over Q(sqrt 2), a_21 = sqrt 2, b = (1/2, 1/2): R = 1 + z + (sqrt 2 / 2) z^2,
// |R(iy)|^2 = 1 - (sqrt 2 - 1) y^2 + y^4 / 2 <= 1 exactly for y^2 <= 2 sqrt 2 - 2 =
// 0.82842712474619009760... (HW II, section IV.2: the stability function of an explicit method).
constexpr geomint::methods::field_polynomial<2> sqrt2_field{{-2, 0, 1}, 1, 2};
using Q2 = geomint::methods::algebraic_number<sqrt2_field>;
constexpr auto explicit2 = geomint::algebraic_rk_stability(geomint::methods::make_rk<Q2>(
    {Q2(0), Q2::generator()}, {{Q2(0), Q2(0)}, {Q2::generator(), Q2(0)}}, {Q2(rational(1, 2)), Q2(rational(1, 2))}));
static_assert(!explicit2.a_stable && !explicit2.imaginary_axis.empty && !explicit2.imaginary_axis.unbounded);
static_assert(explicit2.imaginary_axis.compare_squared(exact_number(rational(828427124746190097, 1000000000000000000))) < 0);
static_assert(explicit2.imaginary_axis.compare_squared(exact_number(rational(828427124746190098, 1000000000000000000))) > 0);

}  // namespace
