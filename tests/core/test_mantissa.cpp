/// multiply_into, add_into, subtract_into and to_double (core/mantissa.hpp): for cpp_bin_float
/// formed on the mantissas and rounded once.
///
/// Independent expected values: the same operations in a 1200-bit binary float, where every
/// product and every sum of these data is exact (exact mathematics: products need 2p bits, and
/// the sums' operands are at most about p + 40 binary places apart, below 1200 - p), rounded
/// by the scalar's own conversion (to nearest, ties to even); hand-made ties; the double that
/// is nearest by IEEE 754's rule for to_double; and the operators for the cases left to Boost.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "catch.hpp"
#include "geomint/core/multiprecision.hpp"
#include "geomint/core/mantissa.hpp"

namespace {
using exact_float = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<1200, boost::multiprecision::backends::digit_base_2>>;

bool same(const auto& x, const auto& y) {
  using std::signbit;
  return x == y && signbit(x) == signbit(y);
}

/// Operands built to reach every path: far apart (the smaller below half an ulp of the larger,
/// or at the tie), cancelling to a few bits, equal, opposite, powers of two.
template <class T>
void check_against_exact() {
  using std::ldexp;
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> shift(-3, 3), pick(0, 9), spread(-200, 200);
  const int p = std::numeric_limits<T>::digits;
  int far_below = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    T a = T(unit(engine)) + ldexp(T(unit(engine)), -50) + ldexp(T(unit(engine)), -100) + ldexp(T(unit(engine)), -150) +
          ldexp(T(unit(engine)), -250);
    T b;
    switch (pick(engine)) {
      case 0: b = T(-a + ldexp(T(unit(engine)), -p + 5 * shift(engine))); break;  // cancellation
      case 1: b = ldexp(a, -p - shift(engine)); break;                             // near half an ulp
      case 2: b = ldexp(T(1), spread(engine) % (p + 10)) * (unit(engine) < 0 ? -1 : 1); break;
      case 3: b = T(-a); break;
      case 4: b = a; break;
      case 5: b = T(ldexp(T(unit(engine)), -p + shift(engine)) + ldexp(T(1), -p - 1 + shift(engine))); break;
      default: b = ldexp(T(T(unit(engine)) + ldexp(T(unit(engine)), -60)), 20 * shift(engine) + spread(engine) % 8);
    }
    a = ldexp(a, shift(engine));
    if (b != T(0) && abs(b) * ldexp(T(1), p) < abs(a)) ++far_below;
    const exact_float A(a), B(b);
    INFO("trial " << trial << ": a = " << a.str(0, std::ios::scientific) << ", b = " << b.str(0, std::ios::scientific));
    T out;
    geomint::add_into(out, a, b);
    CHECK(same(out, T(A + B)));
    geomint::subtract_into(out, a, b);
    CHECK(same(out, T(A - B)));
    geomint::multiply_into(out, a, b);
    CHECK(same(out, T(A * B)));
    // The destination may be an operand.
    T c = a;
    geomint::add_into(c, c, b);
    CHECK(same(c, T(A + B)));
    c = b;
    geomint::multiply_into(c, a, c);
    CHECK(same(c, T(A * B)));
  }
  REQUIRE(far_below > 1000);
}

/// 1 + 2^-p is halfway between 1 and its successor and rounds to the even 1; 1 + 3 2^-p rounds
/// to the even 1 + 2^(2-p); (1 + 2^(1-p))^2 = 1 + 2^(2-p) + 2^(2-2p) rounds down; a difference
/// below half an ulp of the result rounds back to the minuend, also for the pair on which
/// Boost 1.74's operator- returns the neighbour below (docs/results/performance.md).
template <class T>
void check_hand_made() {
  using std::ldexp;
  const int p = std::numeric_limits<T>::digits;
  const T half_ulp = ldexp(T(1), -p);
  CHECK(same(geomint::fast_sum(T(1), half_ulp), T(1)));
  CHECK(same(geomint::fast_sum(T(1), T(3 * half_ulp)), T(T(1) + ldexp(T(1), 2 - p))));
  CHECK(same(geomint::fast_difference(T(-1), T(3 * half_ulp)), T(-T(1) - ldexp(T(1), 2 - p))));
  const T next = T(1) + ldexp(T(1), 1 - p);
  CHECK(same(geomint::fast_product(next, next), T(T(1) + ldexp(T(1), 2 - p))));
  const T three(3);
  CHECK(same(geomint::fast_difference(three, ldexp(T(3), -p - 2)), three));
  if constexpr (std::numeric_limits<T>::digits == 168) {
    const T minuend("3.03774352864845624303443772922655767692055013164410144");
    const T subtrahend("4.05958685084126728489730307561355118141208533471518263e-51");
    CHECK(same(geomint::fast_difference(minuend, subtrahend), minuend));  // 0.38 ulp below it
  }
  // Left to Boost: zeros, exact cancellation (+0), infinities, NaN.
  CHECK(same(geomint::fast_difference(three, three), T(three - three)));
  CHECK(same(geomint::fast_sum(T(0), three), three));
  CHECK(same(geomint::fast_product(T(-0.0), three), T(T(-0.0) * three)));
  const T inf = std::numeric_limits<T>::infinity();
  CHECK(same(geomint::fast_sum(inf, three), inf));
  CHECK(geomint::fast_product(inf, T(0)) != geomint::fast_product(inf, T(0)));
  // Products beyond the exponent range: as the operator.
  const T huge = ldexp(T(1), std::numeric_limits<T>::max_exponent - 2);
  CHECK(same(geomint::fast_product(huge, T(16)), T(huge * T(16))));
  const T tiny = ldexp(T(1), std::numeric_limits<T>::min_exponent + 2);
  CHECK(same(geomint::fast_product(tiny, ldexp(T(1), -16)), T(tiny * ldexp(T(1), -16))));
}

/// to_double: the nearest double, ties to even (IEEE 754 rounding of the exact value, checked
/// by its distance to the neighbours), where that is a normal double; else the cast.
template <class T>
void check_to_double() {
  using std::ldexp;
  std::mt19937_64 engine(9);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> spread(-1080, 1080), pick(0, 3);
  for (int trial = 0; trial < 20000; ++trial) {
    T x = T(unit(engine)) + ldexp(T(unit(engine)), -53 - pick(engine)) + ldexp(T(unit(engine)), -120);
    if (pick(engine) == 0) x = T(1) + ldexp(T(1), -53);  // the tie between 1 and its successor
    x = ldexp(x, trial % 3 == 0 ? spread(engine) : spread(engine) % 30);
    const double d = geomint::to_double(x);
    INFO("x = " << x.str(0, std::ios::scientific));
    if (!std::isnormal(d)) {
      CHECK(same(d, static_cast<double>(x)));
      continue;
    }
    const exact_float X(x), D(d), up(std::nextafter(d, HUGE_VAL)), down(std::nextafter(d, -HUGE_VAL));
    const exact_float error = abs(X - D);
    CHECK(error <= abs(X - up));
    CHECK(error <= abs(X - down));
    if (error == abs(X - up) || error == abs(X - down)) {  // a tie: the even one
      std::uint64_t bits = 0;
      std::memcpy(&bits, &d, sizeof d);
      CHECK((bits & 1) == 0);
    }
  }
  CHECK(same(geomint::to_double(T(0)), 0.0));
  CHECK(same(geomint::to_double(T(-0.0)), -0.0));
  CHECK(std::isinf(geomint::to_double(std::numeric_limits<T>::infinity())));
  CHECK(std::isnan(geomint::to_double(std::numeric_limits<T>::quiet_NaN())));
  CHECK(same(geomint::to_double(ldexp(T(1), 5000)), static_cast<double>(ldexp(T(1), 5000))));
  // The largest double rounds up to infinity when x is above it by half an ulp.
  const T beyond = T(std::numeric_limits<double>::max()) + ldexp(T(1), 970);
  CHECK(same(geomint::to_double(beyond), static_cast<double>(beyond)));
}
}  // namespace

TEST_CASE("mantissa arithmetic: cpp_bin_float results are the exact ones rounded once", "[core][mantissa]") {
  check_against_exact<boost::multiprecision::cpp_bin_float_50>();
  check_against_exact<boost::multiprecision::cpp_bin_float_100>();
  check_hand_made<boost::multiprecision::cpp_bin_float_50>();
  check_hand_made<boost::multiprecision::cpp_bin_float_100>();
}

TEST_CASE("mantissa arithmetic: to_double rounds to the nearest double", "[core][mantissa]") {
  check_to_double<boost::multiprecision::cpp_bin_float_50>();
  check_to_double<boost::multiprecision::cpp_bin_float_100>();
}

TEST_CASE("mantissa arithmetic: other types use the operators", "[core][mantissa]") {
  STATIC_REQUIRE(geomint::exact_mantissa_arithmetic_v<boost::multiprecision::cpp_bin_float_50>);
  STATIC_REQUIRE(!geomint::exact_mantissa_arithmetic_v<boost::multiprecision::cpp_bin_float_quad>);  // one 128-bit integer
  STATIC_REQUIRE(!geomint::exact_mantissa_arithmetic_v<double>);
  const double a = 0.1, b = 0.7;
  CHECK(geomint::fast_sum(a, b) == a + b);
  CHECK(geomint::fast_difference(a, b) == a - b);
  CHECK(geomint::fast_product(a, b) == a * b);
  CHECK(geomint::to_double(1.0f / 3) == static_cast<double>(1.0f / 3));
  using quad = boost::multiprecision::cpp_bin_float_quad;
  const quad x = quad(1) / quad(3), y = quad(2) / quad(7);
  CHECK(geomint::fast_sum(x, y) == quad(x + y));
  CHECK(geomint::fast_product(x, y) == quad(x * y));
}
