/// Exact coefficients to a scalar (methods/coefficients.hpp): every exact type, at the scalar's
/// precision, against the quotient computed in the scalar.
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "catch.hpp"
#include "geomint/core/big_rational.hpp"
#include "geomint/methods/coefficients.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using methods::exact_rational;

TEMPLATE_TEST_CASE("coefficients: rational, big_rational, exact_rational and Q(r) to the scalar", "[methods]", double,
                   geomint::test::cpp_bin_float_50) {
  using T = TestType;
  using std::abs;
  methods::coefficient_converter<T> convert;
  const T third = T(1) / T(3);
  CHECK(convert(rational(1, 3)) == third);
  CHECK(convert(big_rational<4>(rational(1, 3))) == third);
  CHECK(convert(exact_rational(1, 3)) == third);
  CHECK(convert(methods::field_element(exact_rational(1, 3))) == third);
  // 2^(1/3) + 1: the generator computed once in T, then Horner's rule.
  const auto r = methods::field_element::generator(methods::algebraic_field::make({-2, 0, 0, 1}));
  const T value = convert(r + methods::field_element(1));
  CHECK(abs(T(value * value * value - T(3) * value * value + T(3) * value - T(3))) <=
        geomint::test::eps_tol<T>(64));  // (x - 1)^3 = 2, expanded: x^3 - 3x^2 + 3x - 3 = 0
}

TEMPLATE_TEST_CASE("coefficients: a constexpr algebraic_number to the scalar and to the run-time field", "[methods]", double,
                   geomint::test::cpp_bin_float_50) {
  using T = TestType;
  using std::abs;
  static constexpr methods::field_polynomial<3> cube_root_of_two{{-2, 0, 0, 1}, 1, 2};
  using K = methods::algebraic_number<cube_root_of_two>;
  constexpr K theta = K(1) / (K(2) - K::generator());  // Forest & Ruth's step, 1/(2 - 2^(1/3))
  methods::coefficient_converter<T> convert;
  // Expected value: exact mathematics, x = 1/(2 - c) with c^3 = 2, so (2 - 1/x)^3 = 2.
  const T x = convert(theta);
  const T c = T(2) - T(1) / x;
  CHECK(abs(T(c * c * c - T(2))) <= geomint::test::eps_tol<T>(64));
  // The run-time element of the same value: (2 - 1/theta)^3 = 2 exactly, and it converts alike.
  const methods::field_element f = methods::to_field_element(theta);
  const methods::field_element cf = methods::field_element(2) - methods::field_element(1) / f;
  CHECK(cf * cf * cf == methods::field_element(2));
  CHECK(abs(T(convert(f) - x)) <= geomint::test::eps_tol<T>(8));
  // sqrt 15 from the bracket (3, 4], not -sqrt 15.
  static constexpr methods::field_polynomial<2> sqrt15{{-15, 0, 1}, 3, 4};
  const T s = convert(methods::algebraic_number<sqrt15>::generator());
  CHECK(s > T(0));
  CHECK(abs(T(s * s - T(15))) <= geomint::test::eps_tol<T>(64));
}
