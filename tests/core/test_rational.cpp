/// geomint::rational against boost::multiprecision::cpp_rational (arbitrary precision, exact):
/// every result that fits in 64 bits must equal Boost's exactly (same reduced numerator and
/// denominator), and every result that does not fit must throw std::overflow_error, never
/// return a wrong value. Operands are drawn at random (fixed seed) from small values, 32-bit
/// values and values within a few units of the 64-bit limits.
///
/// Expected values: cpp_rational for the randomized part; for the named cases, exact
/// arithmetic by hand (e.g. 2 / INT64_MIN = -1 / 2^62) and the IEEE 754 binary64 encoding
/// (0.1 = 3602879701896397 / 2^55).
#include <geomint/core/rational.hpp>

#include <boost/multiprecision/cpp_int.hpp>
#include <cstdint>
#include <limits>
#include <random>

#include "catch.hpp"

using geomint::rational;
using boost::multiprecision::cpp_int;
using boost::multiprecision::cpp_rational;

namespace {

constexpr std::int64_t max64 = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t min64 = std::numeric_limits<std::int64_t>::min();

/// Operand pairs per run: 2^19 in optimised builds (about 10^6 operands, each combined by
/// +, -, *, / and <=>), 2^15 in unoptimised builds (the clang preset at -O0, where
/// Boost's cpp_rational alone takes about 33 s for 2^19 pairs; the gcc preset runs all 2^19).
#ifdef __OPTIMIZE__
constexpr long pairs = 1L << 19;
#else
constexpr long pairs = 1L << 15;
#endif

/// A random 64-bit value from one of four regimes (never INT64_MIN, which no rational holds).
std::int64_t draw(std::mt19937_64& rng, bool nonzero) {
  for (;;) {
    std::int64_t v = 0;
    switch (rng() % 4) {
      case 0: v = static_cast<std::int64_t>(rng() % 201) - 100; break;                     // small
      case 1: v = static_cast<std::int32_t>(rng()); break;                                  // 32-bit
      case 2: v = max64 - static_cast<std::int64_t>(rng() % 16); break;                     // near the top
      default: v = static_cast<std::int64_t>(rng() >> 1) * (rng() % 2 ? 1 : -1); break;   // 63-bit
    }
    if (rng() % 2 == 0 && v > 0) v = -v;
    if (v == min64 || (nonzero && v == 0)) continue;
    return v;
  }
}

/// n / d in cpp_rational (Boost's two-argument constructor refuses a negative denominator).
cpp_rational exact_fraction(std::int64_t n, std::int64_t d) { return cpp_rational(cpp_int(n)) / cpp_rational(cpp_int(d)); }

cpp_rational to_boost(const rational& r) { return exact_fraction(r.num, r.den); }

/// Whether an exact result fits a rational (numerator and denominator within +-(2^63 - 1)).
bool fits(const cpp_rational& x) {
  const cpp_int n = boost::multiprecision::numerator(x), d = boost::multiprecision::denominator(x);
  return abs(n) <= cpp_int(max64) && d <= cpp_int(max64);
}

/// Checks one result: exactly Boost's value when it fits, std::overflow_error otherwise.
template <class Op>
void check_op(const char* name, Op op, const cpp_rational& exact, long& exact_count, long& overflow_count) {
  if (fits(exact)) {
    rational r;
    try {
      r = op();
    } catch (const std::overflow_error&) {
      FAIL(name << ": overflow reported for a representable result " << exact);
    }
    if (to_boost(r) != exact || r.den <= 0) FAIL(name << ": got " << r.str() << ", exact " << exact);
    ++exact_count;
  } else {
    try {
      const rational r = op();
      FAIL(name << ": no overflow reported; got " << r.str() << " for " << exact);
    } catch (const std::overflow_error&) {
      ++overflow_count;
    }
  }
}

}  // namespace

TEST_CASE("rational: constructors check their range", "[rational]") {
  CHECK_THROWS_AS(rational(min64), std::overflow_error);
  CHECK_THROWS_AS(rational(min64, 1), std::overflow_error);
  CHECK_THROWS_AS(rational(1, min64), std::overflow_error);       // -1 / 2^63: 2^63 does not fit
  CHECK_THROWS_AS(rational(min64, -1), std::overflow_error);      // 2^63
  CHECK_THROWS_AS(rational(std::numeric_limits<std::uint64_t>::max()), std::overflow_error);
  CHECK_THROWS_AS(rational(std::uint64_t{1} << 63), std::overflow_error);
  CHECK_THROWS_AS(rational(1, 0), std::domain_error);
  CHECK(rational(2, min64) == rational(-1, std::int64_t{1} << 62));  // 2 / -2^63 = -1 / 2^62
  CHECK(rational(min64, min64) == rational(1));
  CHECK(rational(min64, 2) == rational(-(std::int64_t{1} << 62)));
  CHECK(rational(std::uint64_t{max64}) == rational(max64));
  const rational top(-max64);
  CHECK((-top).num == max64);
  CHECK(abs(top).num == max64);
  const rational inverse = rational(1) / top;
  CHECK(inverse.num == -1);
  CHECK(inverse.den == max64);
  // Unsigned, char and short arguments convert exactly.
  CHECK(rational(static_cast<unsigned char>(200), static_cast<short>(-8)) == rational(-25));
}

TEST_CASE("rational: the exact value of a double", "[rational]") {
  CHECK(rational::from_double(0.5) == rational(1, 2));
  CHECK(rational::from_double(-3.0) == rational(-3));
  CHECK(rational::from_double(0.0) == rational(0));
  // 0.1 is 3602879701896397 * 2^-55 in binary64; cpp_rational converts doubles exactly.
  CHECK(rational::from_double(0.1) == rational(3602879701896397, std::int64_t{1} << 55));
  for (const double x : {0.1, -0.75, 1.0 / 3.0, 12345.678, 9007199254740993.0, 4611686018427387904.0})
    CHECK(to_boost(rational::from_double(x)) == cpp_rational(x));
  CHECK_THROWS_AS(rational::from_double(1e300), std::overflow_error);
  CHECK_THROWS_AS(rational::from_double(std::ldexp(1.0, -70)), std::overflow_error);
  CHECK_THROWS_AS(rational::from_double(std::numeric_limits<double>::quiet_NaN()), std::domain_error);
  CHECK_THROWS_AS(rational::from_double(std::numeric_limits<double>::infinity()), std::domain_error);
}

TEST_CASE("rational: randomized cross-check against cpp_rational", "[rational]") {
  std::mt19937_64 rng(20251123);
  long exact_count = 0, overflow_count = 0;
  for (long i = 0; i < pairs; ++i) {
    const std::int64_t an = draw(rng, false), ad = draw(rng, true), bn = draw(rng, false), bd = draw(rng, true);
    // Reduction: rational(n, d) against Boost's reduced n/d (always representable here, since
    // reduction only shrinks |n| and |d|, and neither operand is INT64_MIN).
    const cpp_rational A = exact_fraction(an, ad), B = exact_fraction(bn, bd);
    const rational a(an, ad), b(bn, bd);
    REQUIRE(to_boost(a) == A);
    REQUIRE(to_boost(b) == B);
    REQUIRE(a.den > 0);
    check_op("+", [&] { return a + b; }, A + B, exact_count, overflow_count);
    check_op("-", [&] { return a - b; }, A - B, exact_count, overflow_count);
    check_op("*", [&] { return a * b; }, A * B, exact_count, overflow_count);
    if (bn != 0) check_op("/", [&] { return a / b; }, A / B, exact_count, overflow_count);
    // Comparison never overflows (128-bit cross products) and must agree with Boost.
    REQUIRE((a < b) == (A < B));
    REQUIRE((a == b) == (A == B));
    REQUIRE((a > b) == (A > B));
  }
  // Both outcomes must have been exercised in quantity, or the test proves little.
  CHECK(exact_count > pairs / 4);
  CHECK(overflow_count > pairs / 4);
}
