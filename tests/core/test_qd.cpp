/// libqd's dd_real and qd_real as geomint scalars (core/qd.hpp), against independent oracles:
/// exact rational arithmetic (cpp_rational) for the conversions, Boost's cpp_bin_float_100 and
/// 150-digit functions (an independent implementation) for the elementary functions, and the
/// exact flow and the exact stability function for the integrator.
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <random>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include "catch.hpp"
#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/analysis/composition.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/core/checked_cast.hpp"
#include "geomint/core/elementary.hpp"
#include "geomint/core/qd.hpp"
#include "geomint/integrator.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/methods/number_field.hpp"
#include "scalar_types.hpp"

namespace {
using boost::multiprecision::cpp_bin_float_100;
using boost::multiprecision::cpp_rational;
using H150 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<150>>;

/// The exact value of a sum of doubles.
template <class T>
cpp_rational exact_value(const T& x) {
  cpp_rational sum(0);
  for (int k = 0; k < geomint::double_expansion<T>::terms; ++k) sum += cpp_rational(geomint::double_expansion<T>::term(x, k));
  return sum;
}

/// 2^-(digits) as a rational: half a unit in the last of T's `digits` bits, relative.
template <class T>
cpp_rational half_unit() {
  // (a copy: libqd declares digits without defining it, so it must not be bound to a reference)
  const unsigned digits = std::numeric_limits<T>::digits;
  return cpp_rational(1, boost::multiprecision::cpp_int(1) << digits);
}
}  // namespace

TEMPLATE_TEST_CASE("qd: exact rationals convert within half a unit of the last place", "[core][qd]", dd_real, qd_real) {
  using T = TestType;
  // Exact mathematics: |x - rational_to(x)| <= 2^-p |x|, p = digits (104 and 209 bits: libqd's
  // declared precision; the term-by-term rounding reaches 106 and 212).
  const cpp_rational values[] = {cpp_rational(1, 3), cpp_rational(-2, 7), cpp_rational(1, 10),
                                 cpp_rational(boost::multiprecision::cpp_int("123456789012345678901234567890123"), 7),
                                 cpp_rational(1, boost::multiprecision::cpp_int("340282366920938463463374607431768211457"))};
  for (const cpp_rational& x : values) {
    const T got = geomint::methods::rational_to<T>(x);
    INFO("x = " << x);
    CHECK(abs(exact_value(got) - x) <= half_unit<T>() * abs(x));
    CHECK(geomint::to_double(got) == x.template convert_to<double>());  // the leading term: x's nearest double
  }
  // Through geomint::rational: its int64 numerator and denominator exact, then one division in T
  // (libqd's, within a few units of its last bit).
  const cpp_rational big(std::numeric_limits<std::int64_t>::max(), 3);
  const geomint::rational r(std::numeric_limits<std::int64_t>::max(), 3);
  CHECK(abs(exact_value(r.to<T>()) - big) <= 4 * half_unit<T>() * big);
}

TEMPLATE_TEST_CASE("qd: 64-bit integers, frexp and round are exact", "[core][qd]", dd_real, qd_real) {
  using T = TestType;
  for (const std::int64_t v : {std::int64_t(0), std::int64_t(-1), (std::int64_t(1) << 53) + 1, -((std::int64_t(1) << 62) + 12345),
                               std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min()}) {
    CHECK(exact_value(geomint::from_int64<T>(v)) == cpp_rational(v));
  }
  // frexp: x = m 2^e with |m| in [1/2, 1), also for 1/2 - 2^-80 (leading term 1/2, the rest negative).
  const T below_half = T(0.5) - ldexp(T(1), -80);
  for (const T& x : {T(3), T(-0.75), below_half, T(ldexp(T(1), 300)), T(T(1) / T(3))}) {
    int e = 0;
    const T m = frexp(x, &e);
    CHECK(abs(m) >= T(0.5));
    CHECK(abs(m) < T(1));
    CHECK(exact_value(T(ldexp(m, e))) == exact_value(x));
  }
  int e = 0;
  frexp(below_half, &e);
  CHECK(e == -1);
  // checked_integer (core/checked_cast.hpp): the exact integer, also 2^63 - 1 = 2^63 + (-1),
  // and nothing past the range.
  CHECK(geomint::checked_integer<std::int64_t>(geomint::from_int64<T>(std::numeric_limits<std::int64_t>::max())) ==
        std::numeric_limits<std::int64_t>::max());
  CHECK(geomint::checked_integer<std::int64_t>(T(T(-7) / T(2))) == -3);
  CHECK(!geomint::checked_integer<std::int64_t>(T(ldexp(T(1), 63))));
  CHECK(trunc(T(T(-7) / T(2))) == T(-3));
  // round: half away from zero, as std::round.
  CHECK(round(T(2.5)) == T(3));
  CHECK(round(T(-2.5)) == T(-3));
  CHECK(round(T(T(2.5) - ldexp(T(1), -90))) == T(2));
  CHECK(round(T(T(-7) / T(3))) == T(-2));
}

TEMPLATE_TEST_CASE("qd: the elementary functions geomint uses, against Boost in 150 digits", "[core][qd]", dd_real, qd_real) {
  using T = TestType;
  const T eps = T(std::numeric_limits<T>::epsilon());
  std::mt19937 engine(7);
  std::uniform_real_distribution<double> uniform(-4.0, 4.0);
  for (int i = 0; i < 200; ++i) {
    const T x = T(uniform(engine)) + T(uniform(engine)) * eps * T(1 << 20);
    const H150 X = geomint::widen<H150>(x);
    INFO("x = " << X);
    // geomint's own (core/elementary.hpp): within 4 eps relative of sin and cos on |x| < 9/8,
    // within 4 eps absolute beyond (its error bounds, test_elementary.cpp), 2 eps for 1/sqrt.
    const auto [s, c] = geomint::sin_cos(x);
    CHECK(abs(geomint::widen<H150>(s) - sin(X)) <= H150(4) * geomint::widen<H150>(eps) * H150(1));
    CHECK(abs(geomint::widen<H150>(c) - cos(X)) <= H150(4) * geomint::widen<H150>(eps) * H150(1));
    const T a = abs(x) + T(1) / T(8);
    CHECK(abs(geomint::widen<H150>(geomint::inverse_sqrt(a)) - H150(1) / sqrt(geomint::widen<H150>(a))) <=
          H150(2) * geomint::widen<H150>(eps) / sqrt(geomint::widen<H150>(a)));
    // libqd's own, which the systems call through argument-dependent lookup.
    CHECK(abs(geomint::widen<H150>(T(exp(x))) - exp(X)) <= H150(8) * geomint::widen<H150>(eps) * exp(X));
    CHECK(abs(geomint::widen<H150>(T(log(a))) - log(geomint::widen<H150>(a))) <= H150(8) * geomint::widen<H150>(eps));
    CHECK(abs(geomint::widen<H150>(T(sqrt(a))) - sqrt(geomint::widen<H150>(a))) <=
          H150(2) * geomint::widen<H150>(eps) * sqrt(geomint::widen<H150>(a)));
  }
}

TEST_CASE("qd: the pendulum in dd_real follows the exact flow to dd_real's round-off", "[core][qd]") {
  // The closed form (analysis/closed_form_flows.hpp, Jacobi elliptic functions in 50 digits)
  // against LPF's fixed-point form m = 16 (order 30) over T = 10 in 20 steps, where its
  // truncation error is far below dd_real's epsilon of 5e-32 (a qd_real run with this step over
  // T = 100 is within 5e-35 of the exact flow): what remains is round-off, within one unit of
  // epsilon per step (compensated summation: each step's rounding enters the state once).
  using T = dd_real;
  using R = boost::multiprecision::cpp_bin_float_50;
  using I = geomint::integrator<geomint::lpf_fixed_point<16>, geomint::systems::pendulum, T>;
  I integ(geomint::systems::pendulum{}, T(T(10) / T(20)));
  I::state s;
  s.q[0] = T(1);
  s.p[0] = T(0);
  for (int k = 0; k < 20; ++k) REQUIRE(integ.try_step(s));
  const auto exact = geomint::analysis::pendulum_from_rest<R>(R(1), R(10));
  const R eps = geomint::widen<R>(T(std::numeric_limits<T>::epsilon()));
  CHECK(abs(geomint::widen<R>(s.q[0]) - exact.q[0]) <= R(20) * eps);
  CHECK(abs(geomint::widen<R>(s.p[0]) - exact.p[0]) <= R(20) * eps);
  CHECK(abs(geomint::widen<R>(s.q[0]) - exact.q[0]) > R(0));  // it ran in dd_real, not exactly
}

TEMPLATE_TEST_CASE("qd: the compositions' coefficients satisfy their order conditions in T", "[core][qd]", dd_real, qd_real) {
  // Refined in 100 digits and rounded to T (analysis/composition.hpp); the order conditions of
  // the published orders (Yoshida 6, Kahan & Li 8, Sofroniou & Spaletta 10; words of the free
  // algebra) evaluated in T hold to T's round-off, those of two orders more do not.
  using T = TestType;
  using C = geomint::analysis::symmetric_composition<T>;
  const T eps = T(std::numeric_limits<T>::epsilon());
  for (const C& c : {C::yoshida6(), C::kahan_li8(), C::sofroniou_spaletta10()}) {
    INFO(c.name());
    CHECK(c.order_defect() <= T(64) * eps);
    CHECK(c.next_order_defect() > T(1 << 20) * eps);
    T sum(0);
    for (const T& g : c.gamma()) sum += g;
    CHECK(abs(sum - T(1)) <= T(c.stages()) * eps);
  }
}

TEST_CASE("qd: the Taylor-series flow in dd_real follows the pendulum's exact flow", "[core][qd]") {
  // analysis/reference_flow.hpp in dd_real (its Taylor coefficients take their integers through
  // from_int64) against the closed form in 50 digits at t = 10; its steps are chosen for a
  // truncation below dd_real's epsilon, so what remains is round-off: a few units of epsilon
  // (64 leaves room for its growth over the steps to t = 10).
  using T = dd_real;
  using R = boost::multiprecision::cpp_bin_float_50;
  geomint::vec<T, 1> q, p;
  q[0] = T(1);
  p[0] = T(0);
  geomint::analysis::reference_flow<geomint::systems::pendulum, T> flow(q, p);
  flow.advance_to(T(10));
  const auto exact = geomint::analysis::pendulum_from_rest<R>(R(1), R(10));
  const R eps = geomint::widen<R>(T(std::numeric_limits<T>::epsilon()));
  CHECK(abs(geomint::widen<R>(flow.q()[0]) - exact.q[0]) <= R(64) * eps);
  CHECK(abs(geomint::widen<R>(flow.qdot()[0]) - exact.p[0]) <= R(64) * eps);
}

TEMPLATE_TEST_CASE("qd: the harmonic oscillator follows its exact flow to the scalar's round-off", "[core][qd]", dd_real,
                   qd_real) {
  // Exact mathematics: q'' = -q maps q + i p to exp(-i t) (q + i p). LPF's fixed-point form
  // m = 16 is a collocation method with 15 Gauss nodes, of order 30: with tau = 1/8 its error
  // per step is of order tau^31 (s!)^4 / ((2s+1) ((2s)!)^3) = 5e-79 for s = 15 (the Gauss
  // methods' error constant, Hairer, Norsett & Wanner I, Theorem II.7.9; the collocation form
  // for q'' = f has one of that size), far below qd_real's epsilon of 1.2e-63: what remains over
  // 80 steps is round-off.
  using T = TestType;
  using I = geomint::integrator<geomint::lpf_fixed_point<16>, geomint::systems::harmonic, T>;
  I integ(geomint::systems::harmonic{}, T(1) / T(8));
  typename I::state st;
  st.q[0] = T(1);
  st.p[0] = T(1);
  constexpr int steps = 80;
  for (int k = 0; k < steps; ++k) REQUIRE(integ.try_step(st));
  const H150 t(10);  // 80 steps of 1/8
  const std::complex<H150> y = std::complex<H150>(cos(t), -sin(t)) * std::complex<H150>(H150(1), H150(1));
  const H150 eps = geomint::widen<H150>(T(std::numeric_limits<T>::epsilon()));
  // Within one unit of epsilon per step: the increments are added with compensated summation,
  // so each step's rounding enters the state once.
  CHECK(abs(geomint::widen<H150>(st.q[0]) - y.real()) <= H150(steps) * eps);
  CHECK(abs(geomint::widen<H150>(st.p[0]) - y.imag()) <= H150(steps) * eps);
}
