/// The exact two-step schemes (include/geomint/analysis/exact_scheme.hpp) against the floating
/// integrators, and the run-time side of the big integers (decimal output, overflow).
///
/// Independent source of every expected value here: the integrator (include/geomint/lpf), which
/// solves the LPF equations (eqs. 10-12) numerically by Newton's method in cpp_bin_float_50 and
/// never forms R; its two-step map x^{k+1} = R x^k - x^{k-1} is read off by linearity as in
/// tests/lpf/test_schemes.cpp. The decimal strings are powers of two and ten written by hand.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <stdexcept>
#include <string>

#include "catch.hpp"
#include "geomint/analysis/exact_scheme.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_50;
using geomint::test::eps_tol;

namespace {

using T = cpp_bin_float_50;
using big = big_integer<analysis::detail::exact_limbs>;

/// R and the x^{k-1} coefficient of the integrator's two-step map (linear in its inputs).
template <class Scheme>
std::pair<T, T> two_step_coefficients(const T& tau) {
  integrator<Scheme, systems::harmonic, T> I(systems::harmonic{}, tau);
  const vec<T, 1> zero(T(0)), one(T(1));
  return {I.two_step(zero, one)[0], I.two_step(one, zero)[0]};
}

/// R(tau) from the exact coefficients equals the integrator's, to `ulps` at several tau; and
/// (R - 2 cos tau) / tau^(p+2) at a small tau is the exact leading coefficient c to O(tau^2).
template <class Scheme>
void check_against_integrator(const exact_two_step_scheme& exact, int ulps) {
  using std::abs;
  using std::cos;
  using std::pow;
  for (const T& tau : {T(1) / T(10), T(1) / T(4), T(1) / T(2), T(1)}) {
    const auto [R, back] = two_step_coefficients<Scheme>(tau);
    const T expected = exact.R(tau);
    INFO("m " << exact.m << " tau " << tau << " integrator R " << R << " exact R " << expected);
    CHECK(abs(R - expected) <= eps_tol<T>(ulps));
    CHECK(abs(back + T(1)) <= eps_tol<T>(ulps));
  }
  const T tau = T(1) / T(1000);
  const T R = two_step_coefficients<Scheme>(tau).first;
  const T ratio = (R - T(2) * cos(tau)) / pow(tau, exact.leading_power());
  const T c = T(exact.leading_coefficient.num.str()) / T(exact.leading_coefficient.den().str());
  INFO("m " << exact.m << " (R - 2 cos)/tau^(p+2) " << ratio << " exact c " << exact.leading_coefficient);
  // Round-off: ~ulps eps / tau^(p+2) <= 1e-46 / 1e-30; truncation: O(tau^2) = 1e-6 relative.
  CHECK(abs(ratio / c - T(1)) <= T(1) / T(10000));
}

template <int M>
void check_lpf(int ulps) {
  check_against_integrator<lpf<M, equispaced>>(exact_two_step_v<M>, ulps);
}

}  // namespace

TEST_CASE("exact R(tau) equals the LPF integrator's two-step map, m = 2..8", "[analysis][exact]") {
  check_lpf<2>(16);
  check_lpf<3>(64);
  check_lpf<4>(64);
  check_lpf<5>(128);
  check_lpf<6>(128);
  // m = 7, 8: the integrator's own round-off reaches ~350 ulps (its x^{k-1} coefficient, exactly
  // -1, is off by as much): the equispaced interior systems grow ill-conditioned.
  check_lpf<7>(1024);
  check_lpf<8>(1024);
}

TEST_CASE("exact R(tau) equals the midpoint VI's two-step map (scheme 17)", "[analysis][exact]") {
  check_against_integrator<scheme17>(exact_midpoint_two_step_v, 16);
}

TEST_CASE("big integers print in decimal and throw on overflow", "[analysis][bigint]") {
  big two_100(1);
  for (int i = 0; i < 100; ++i) two_100 = two_100 + two_100;
  CHECK(two_100.str() == "1267650600228229401496703205376");
  CHECK((-two_100).str() == "-1267650600228229401496703205376");
  CHECK(big(0).str() == "0");
  big ten_27(1);
  for (int i = 0; i < 27; ++i) ten_27 *= big(10);
  CHECK(ten_27.str() == "1000000000000000000000000000");  // zero chunks of nine digits
  CHECK((ten_27 + big(7)).str() == "1000000000000000000000000007");
  CHECK(big(-4294967296LL).str() == "-4294967296");
  // 2^400 does not fit the 384-bit integer: an exception at run time (a compile error in a
  // constant expression).
  const big two_200 = two_100 * two_100;
  CHECK_THROWS_AS(two_200 * two_200, std::overflow_error);
  CHECK_THROWS_AS(two_100.to_int64(), std::overflow_error);
  CHECK_THROWS_AS(big(1) / big(0), std::domain_error);
  CHECK_THROWS_AS(exact_quotient(big(7), big(2)), std::domain_error);
}

TEST_CASE("exact leading coefficients print as reduced fractions", "[analysis][exact]") {
  CHECK(exact_two_step_v<2>.leading_coefficient.str() == "1/24");
  CHECK(exact_midpoint_two_step_v.leading_coefficient.str() == "1/6");
  CHECK(exact_two_step_v<4>.leading_coefficient.str() == "-7/7680");
  CHECK(exact_two_step_v<8>.leading_coefficient.str() == "-989/67947724800");
  // The derivation also runs at run time (same code, same result).
  CHECK(exact_two_step<5>() == exact_two_step_v<5>);
}
