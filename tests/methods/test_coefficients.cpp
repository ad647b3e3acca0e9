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
