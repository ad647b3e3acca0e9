/// Exact coefficients: rationals of any size and the algebraic number field Q(r)
/// (methods/number_field.hpp), checked against exact mathematics.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <stdexcept>

#include "catch.hpp"
#include "geomint/methods/number_field.hpp"
#include "scalar_types.hpp"

using namespace geomint::methods;
using geomint::test::cpp_bin_float_50;
using geomint::test::eps_tol;

namespace {
std::shared_ptr<const algebraic_field> field_of(std::vector<exact_rational> p, std::optional<exact_rational> near = std::nullopt) {
  return algebraic_field::make(std::move(p), near);
}
}  // namespace

TEST_CASE("number field: arithmetic in Q(sqrt 2) is exact", "[methods]") {
  const auto r = field_element::generator(field_of({-2, 0, 1}));
  // (1 + r)(1 - r) = 1 - r^2 = 1 - 2.
  CHECK((field_element(1) + r) * (field_element(1) - r) == field_element(-1));
  CHECK(r * r == field_element(2));
  // 1 / (1 + r) = r - 1 (since (r + 1)(r - 1) = 1).
  CHECK(field_element(1) / (field_element(1) + r) == r - field_element(1));
  CHECK((field_element(1) / (field_element(1) + r)).coefficients() == std::vector<exact_rational>{-1, 1});
  CHECK_THROWS_AS(field_element(1) / (r * r - field_element(2)), std::domain_error);
}

TEST_CASE("number field: the root nearest a point, and polynomials without a real root", "[methods]") {
  using std::sqrt;
  const auto minus = field_element::generator(field_of({-2, 0, 1}, exact_rational(-1)));
  CHECK(minus.to<double>() == -sqrt(2.0));
  const auto plus = field_element::generator(field_of({-2, 0, 1}));  // default: the largest root
  CHECK(plus.to<double>() == sqrt(2.0));
  CHECK_THROWS_AS(field_of({1, 0, 1}), std::invalid_argument);                     // r^2 + 1
  CHECK_THROWS_AS(field_of({-1, 0, 1}, exact_rational(0)), std::invalid_argument);  // +-1 equally near 0
  CHECK_THROWS_AS(field_of({5}), std::invalid_argument);                           // constant
}

TEST_CASE("number field: a reducible polynomial, division where an element shares a factor", "[methods]") {
  // P = (r^2 - 2)(r - 5) = r^3 - 5 r^2 - 2 r + 10, r = sqrt 2 (the root nearest 1).
  const auto r = field_element::generator(field_of({10, -2, -5, 1}, exact_rational(1)));
  CHECK(r.to<double>() == std::sqrt(2.0));
  // r - 5 divides P but is not zero at sqrt 2: 1/(r - 5) = -(r + 5)/23.
  CHECK(field_element(1) / (r - field_element(5)) == (r + field_element(5)) / field_element(-23));
  // r^2 - 2 is zero at sqrt 2.
  CHECK((r * r - field_element(2)).is_zero());
  CHECK_THROWS_AS(field_element(1) / (r * r - field_element(2)), std::domain_error);
}

TEST_CASE("number field: 1/(2 - 2^(1/3)) in 50 digits against the cube root by another route", "[methods]") {
  using T = cpp_bin_float_50;
  const auto r = field_element::generator(field_of({-2, 0, 0, 1}));
  const field_element gamma = field_element(1) / (field_element(2) - r);
  // Independent: 2^(1/3) from Boost's cbrt in T, then the quotient in T.
  const T cube_root = boost::multiprecision::cbrt(T(2));
  const T expected = T(1) / (T(2) - cube_root);
  using boost::multiprecision::abs;
  CHECK(abs(gamma.to<T>() - expected) <= eps_tol<T>(8) * expected);
  CHECK(abs(r.to<T>() - cube_root) <= eps_tol<T>(2) * cube_root);
  // The exact inverse: (2 - r)(4 + 2 r + r^2) = 8 - r^3 = 6, so 1/(2 - r) = (4 + 2 r + r^2)/6.
  CHECK(gamma.coefficients() == std::vector<exact_rational>{exact_rational(2, 3), exact_rational(1, 3), exact_rational(1, 6)});
}

TEST_CASE("exact rationals of any size convert at the scalar's precision", "[methods]") {
  using T = cpp_bin_float_50;
  // 2^200 + 1 over 2^200: beyond 64 bits; in T it is 1 + 2^-200, which rounds to 1.
  const boost::multiprecision::cpp_int big = boost::multiprecision::cpp_int(1) << 200;
  const exact_rational x(big + 1, big);
  CHECK(rational_to<T>(x) == T(1));
  CHECK(rational_to<double>(exact_rational(1, 3)) == 1.0 / 3.0);
  CHECK(rational_to<T>(exact_rational(1, 3)) == T(1) / T(3));
}

TEMPLATE_TEST_CASE("number field: r in every scalar at its full precision", "[methods]", double, long double,
                   cpp_bin_float_50, geomint::test::cpp_bin_float_100) {
  using T = TestType;
  using std::abs;
  using std::sqrt;
  // sqrt 15 and its square: r by bisection in T from the rational bracket, against T's sqrt.
  const auto r = field_element::generator(field_of({-15, 0, 1}));
  const T expected = sqrt(T(15));
  CHECK(abs(T(r.to<T>() - expected)) <= eps_tol<T>(2) * expected);
  // An element: (3 - r)/6 at r = sqrt 15, to a few roundings of its terms (3 + r)/6.
  const field_element x = (field_element(3) - r) / field_element(6);
  const T value = (T(3) - expected) / T(6);
  CHECK(abs(T(x.to<T>() - value)) <= eps_tol<T>(4) * (T(3) + expected) / T(6));
}

TEST_CASE("number field: exact signs of elements close to zero", "[methods]") {
  // sqrt 2 - 99/70 < 0 (99^2 = 9801 > 2 * 70^2 = 9800), sqrt 2 - 140/99 > 0 (140^2 = 19600 <
  // 2 * 99^2 = 19602); 2^(1/3) - 5/4 > 0 and 2^(1/3) - 63/50 < 0 (125 < 128, 250047 > 250000).
  const auto s2 = field_element::generator(field_of({-2, 0, 1}));
  CHECK(exact_sign(s2 - field_element(exact_rational(99, 70))) == -1);
  CHECK(exact_sign(s2 - field_element(exact_rational(140, 99))) == 1);
  CHECK(exact_sign(s2 * s2 - field_element(2)) == 0);
  const auto c2 = field_element::generator(field_of({-2, 0, 0, 1}));
  CHECK(exact_sign(c2 - field_element(exact_rational(5, 4))) == 1);
  CHECK(exact_sign(c2 - field_element(exact_rational(63, 50))) == -1);
  // Beyond the initial bracket (width 2^-64 of the bound): 2^(1/3) - a / 2^80 for a = the floor
  // of 2^(1/3) 2^80 is positive and below 2^-80 (a^3 < 2^241 < (a + 1)^3, checked exactly).
  const boost::multiprecision::cpp_int scale = boost::multiprecision::cpp_int(1) << 80;
  boost::multiprecision::cpp_int a = 0;
  for (int bit = 81; bit >= 0; --bit) {
    const boost::multiprecision::cpp_int trial = a + (boost::multiprecision::cpp_int(1) << bit);
    if (trial * trial * trial <= 2 * scale * scale * scale) a = trial;
  }
  REQUIRE(a * a * a < 2 * scale * scale * scale);
  CHECK(exact_sign(c2 - field_element(exact_rational(a, scale))) == 1);
  CHECK(exact_sign(c2 - field_element(exact_rational(a + 1, scale))) == -1);
}
