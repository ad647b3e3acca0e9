/// Compile-only: the interval of periodicity of a method over Q(2^(1/3)) in static_assert
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

}  // namespace
