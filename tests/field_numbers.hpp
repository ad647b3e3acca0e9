#pragma once
/// q(n, d): the rational n / d as an exact field element (methods/number_field.hpp), for the
/// suites that write exact coefficients (`using geomint::test::field_numbers::q;`).
#include "geomint/methods/number_field.hpp"

namespace geomint::test::field_numbers {
inline methods::field_element q(long n, long d = 1) { return methods::field_element(methods::exact_rational(n, d)); }
}  // namespace geomint::test::field_numbers
