/// The library at the limits of its integer and floating types, with random operands: checked
/// conversions of reals to integers (core/checked_cast.hpp), checked integer arithmetic, the
/// step counter of phase_state at LONG_MAX, huge and tiny t and tau, and the gcd of zero
/// polynomials. Built with -fsanitize=address,undefined in the clang preset, so an overflow or
/// an out-of-range cast anywhere on these paths fails the suite there.
///
/// Expected values come from independent arithmetic: frexp's exponent for the range of a
/// double, exact 128-bit integer arithmetic for sums and products, the definition of the gcd
/// (gcd(0, b) = b up to a unit) with std::gcd on the coefficients.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

#include "catch.hpp"
#include "geomint/core/checked_cast.hpp"
#include "geomint/core/integer_polynomial.hpp"
#include "geomint/core/multiprecision.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_50;

namespace {

constexpr long limits_lmax = std::numeric_limits<long>::max();
constexpr long limits_lmin = std::numeric_limits<long>::min();

std::mt19937_64& limits_rng() {
  static std::mt19937_64 g(20261127);
  return g;
}

/// A random long: uniform, or within 2^20 of one of the limits (half the draws).
long limits_random_long() {
  std::uniform_int_distribution<long> any(limits_lmin, limits_lmax), near(0, 1L << 20);
  switch (limits_rng()() % 4) {
    case 0: return limits_lmax - near(limits_rng());
    case 1: return limits_lmin + near(limits_rng());
    case 2: return near(limits_rng()) - (1L << 19);
    default: return any(limits_rng());
  }
}

/// A random double over the whole exponent range (normal, subnormal, zero, infinity, NaN).
double limits_random_double() {
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(-1080, 1030);
  switch (limits_rng()() % 16) {
    case 0: return std::numeric_limits<double>::infinity();
    case 1: return -std::numeric_limits<double>::infinity();
    case 2: return std::numeric_limits<double>::quiet_NaN();
    case 3: return 0.0;
    case 4: return std::ldexp(limits_rng()() % 2 ? 1.0 : -1.0, 63);  // exactly -+2^63
    default: break;
  }
  const double x = std::ldexp(mantissa(limits_rng()), limits_rng()() % 2 ? exponent(limits_rng()) : 50 + int(limits_rng()() % 20));
  return limits_rng()() % 2 ? x : -x;
}

}  // namespace

TEST_CASE("checked_integer: a double fits a long iff its truncation is in [-2^63, 2^63)", "[core][limits]") {
  for (int trial = 0; trial < 20000; ++trial) {
    const double x = limits_random_double();
    const auto v = checked_integer<long>(x);
    // Independent: x = f 2^e with 0.5 <= |f| < 1; trunc(x) fits 63 value bits iff e <= 63,
    // or x is exactly -2^63 (f = -1/2, e = 64).
    bool fits = false;
    if (std::isfinite(x)) {
      int e = 0;
      const double f = std::frexp(x, &e);
      fits = e <= 63 || (f == -0.5 && e == 64);
    }
    INFO("x = " << x);
    REQUIRE(v.has_value() == fits);
    if (fits) CHECK(*v == static_cast<long>(std::trunc(x)));  // defined: in range by the test above
  }
  CHECK(checked_integer<long>(-0.75) == 0L);
  CHECK(checked_integer<unsigned>(-0.5) == 0u);
  CHECK_FALSE(checked_integer<unsigned>(-1.0));
  CHECK_FALSE(checked_integer<int>(2147483648.0));
  CHECK(checked_integer<int>(2147483647.9) == 2147483647);
  CHECK_THROWS_AS(integer_or_throw<long>(1e19, "steps"), std::out_of_range);
}

TEST_CASE("checked_integer: 50 digits hold 2^63 - 1 exactly, the boundaries are exact", "[core][limits]") {
  using T = cpp_bin_float_50;
  const T two63 = ldexp(T(1), 63);
  std::uniform_int_distribution<long> offset(0, 1L << 30);
  for (int trial = 0; trial < 2000; ++trial) {
    const long r = offset(limits_rng());
    CHECK(checked_integer<long>(T(two63 - T(1) - T(r))) == limits_lmax - r);
    CHECK(checked_integer<long>(T(-two63 + T(r))) == limits_lmin + r);
    CHECK(checked_integer<long>(T(-two63 + T(r) - T(1) / T(2))) == limits_lmin + r);  // truncation toward zero
    CHECK_FALSE(checked_integer<long>(T(two63 + T(r))));
    CHECK_FALSE(checked_integer<long>(T(-two63 - T(1) - T(r))));
  }
  CHECK_FALSE(checked_integer<long>(std::numeric_limits<T>::quiet_NaN()));
  CHECK_FALSE(checked_integer<long>(std::numeric_limits<T>::infinity()));
}

TEST_CASE("checked_add, checked_sub, checked_mul agree with 128-bit arithmetic", "[core][limits]") {
  __extension__ using wide = __int128;
  auto in_range = [](wide w) { return w >= wide(limits_lmin) && w <= wide(limits_lmax); };
  for (int trial = 0; trial < 100000; ++trial) {
    const long a = limits_random_long(), b = limits_random_long();
    const wide sum = wide(a) + wide(b), diff = wide(a) - wide(b), prod = wide(a) * wide(b);
    const auto s = checked_add(a, b), d = checked_sub(a, b), p = checked_mul(a, b);
    REQUIRE(s.has_value() == in_range(sum));
    REQUIRE(d.has_value() == in_range(diff));
    REQUIRE(p.has_value() == in_range(prod));
    if (s) CHECK(wide(*s) == sum);
    if (d) CHECK(wide(*d) == diff);
    if (p) CHECK(wide(*p) == prod);
  }
}

TEST_CASE("phase_state: step indices at the limits, huge and tiny t and tau", "[core][limits]") {
  for (int trial = 0; trial < 20000; ++trial) {
    phase_state<double, 1> s;
    s.step = limits_random_long();
    s.k0 = limits_random_long();
    s.tau0 = limits_rng()() % 2 ? 0.0 : std::ldexp(1.0, int(limits_rng()() % 200) - 100);
    s.t = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(limits_rng()), int(limits_rng()() % 2000) - 1000);
    s.t0 = s.t;
    const double tau = std::ldexp(std::uniform_real_distribution<double>(0.5, 1)(limits_rng()), int(limits_rng()() % 2000) - 1000);
    const vec<double, 1> q1(1.0), p1(2.0);
    const step_status in = check_step_input(s.step, tau, q1, p1);
    if (s.step == limits_lmax) {
      CHECK(in.reason == step_failure::step_index_overflow);
      CHECK_THROWS_AS(s.commit(q1, p1, tau), std::overflow_error);
      CHECK(s.step == limits_lmax);
      continue;
    }
    REQUIRE(in);
    const long k = s.step;
    const double t = s.t;
    const bool same_run = s.tau0 == tau && s.step >= s.k0 && checked_sub(k + 1, s.k0);
    s.commit(q1, p1, tau);
    CHECK(s.step == k + 1);
    // A fresh (k0, t0) at step k: t_{k+1} = t_k + tau rounded once.
    if (!same_run) CHECK(s.t == t + tau);
  }
}

TEST_CASE("integrator: a step from LONG_MAX is refused with a reason, the state unchanged", "[core][limits]") {
  integrator<midpoint_vi, systems::harmonic, double> I(systems::harmonic{}, 0.25);
  auto s = I.initial_state(vec<double, 1>(1.0), vec<double, 1>(0.0));
  s.step = limits_lmax - 1;
  REQUIRE(I.try_step(s));
  CHECK(s.step == limits_lmax);
  const auto before = s.q;
  const step_status st = I.try_step(s);
  CHECK(st.reason == step_failure::step_index_overflow);
  CHECK(st.step == limits_lmax);
  CHECK(s.step == limits_lmax);
  CHECK(s.q == before);
  CHECK_THROWS_AS(I.step(s), integration_error);
  // From the most negative index the counter rises normally.
  s.step = limits_lmin;
  REQUIRE(I.try_step(s));
  CHECK(s.step == limits_lmin + 1);
  CHECK(std::isfinite(s.t));
}

TEST_CASE("polynomial_gcd: zero polynomials, random partners", "[core][limits]") {
  using P = integer_polynomial<4, 6>;
  using B = big_integer<4>;
  std::uniform_int_distribution<long> coeff(-1000, 1000);
  std::uniform_int_distribution<int> degree(0, 6);
  const P zero;
  CHECK(polynomial_gcd(zero, zero).is_zero());
  CHECK_THROWS_AS(zero.lead(), std::domain_error);
  for (int trial = 0; trial < 500; ++trial) {
    P b;
    long raw[7] = {};
    const int d = degree(limits_rng());
    for (int k = 0; k <= d; ++k) {
      raw[k] = coeff(limits_rng());
      b[k] = B(raw[k]);
    }
    b.trim();
    if (b.is_zero()) continue;
    // Independent: gcd(0, b) = b / gcd(coefficients), with a positive leading coefficient.
    long g = 0, lead = 0;
    for (int k = 0; k <= d; ++k) {
      g = std::gcd(g, raw[k]);
      if (raw[k] != 0) lead = raw[k];
    }
    const long sign = lead < 0 ? -1 : 1;
    P expected;
    for (int k = 0; k <= d; ++k) expected[k] = B(sign * raw[k] / g);
    expected.trim();
    CHECK(polynomial_gcd(zero, b) == expected);
    CHECK(polynomial_gcd(b, zero) == expected);
  }
}
