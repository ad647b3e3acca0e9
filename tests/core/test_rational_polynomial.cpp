/// Run-time checks of rational arithmetic and of polynomials over every scalar type.
/// Expected values: exact mathematics (integrals of monomials, Taylor shift identities).
#include <geomint/core/polynomial.hpp>

#include <stdexcept>

#include "catch.hpp"
#include "scalar_types.hpp"

using geomint::polynomial;
using geomint::rational;
using geomint::test::abs_diff;

TEST_CASE("rational overflow throws at run time instead of wrapping", "[core][rational]") {
  const rational big(std::numeric_limits<std::int64_t>::max() / 2 + 1);  // 2^62
  CHECK_THROWS_AS(big * rational(2), std::overflow_error);
  CHECK_THROWS_AS(big + big, std::overflow_error);
  CHECK_THROWS_AS(rational(1, std::numeric_limits<std::int64_t>::max()) * rational(1, 3), std::overflow_error);
  CHECK_THROWS_AS(rational(1, 0), std::domain_error);
  CHECK_THROWS_AS(rational(1) / rational(0), std::domain_error);
  // Results that fit are exact even when the naive intermediates do not fit 64 bits.
  CHECK(big / rational(3) * rational(3) == big);
  CHECK((rational(1, 3) + rational(1, 6)).str() == "1/2");
}

TEMPLATE_LIST_TEST_CASE("polynomial calculus in every scalar type", "[core][polynomial]", geomint::test::scalar_types) {
  using T = TestType;
  const T tol = geomint::test::eps_tol<T>(8);
  // p(t) = 1 + 2t + 3t^2 + 4t^3
  const polynomial<T, 3> p(std::array<T, 4>{T(1), T(2), T(3), T(4)});
  SECTION("evaluation, derivative, integral are exact identities") {
    CHECK(p(T(2)) == T(49));
    CHECK(geomint::derivative(p)(T(2)) == T(2 + 12 + 48));
    CHECK(geomint::derivative<2>(p)(T(1)) == T(6 + 24));
    // int_0^1 p = 1 + 1 + 1 + 1
    CHECK(abs_diff(geomint::integral(p, T(0), T(1)), T(4)) <= tol);
    // int_0^{1/3} t^4 = 1/1215: exact rational, compared in T
    CHECK(abs_diff(geomint::integral(polynomial<T, 4>::monomial(4), T(0), T(1) / T(3)), T(T(1) / T(1215))) <= tol / T(1215));
  }
  SECTION("composition with an affine map agrees with pointwise evaluation") {
    const T scale = T(1) / T(3), shift = T(-2) / T(7);
    const auto q = geomint::compose_affine(p, scale, shift);
    for (int i = 0; i <= 10; ++i) {
      const T t = T(i) / T(10);
      CHECK(abs_diff(q(t), p(T(scale * t + shift))) <= tol * T(10));
    }
  }
  SECTION("products and exact equality") {
    const polynomial<T, 1> a(std::array<T, 2>{T(-1), T(1)});
    const polynomial<T, 1> b(std::array<T, 2>{T(1), T(1)});
    CHECK(a * b == polynomial<T, 2>(std::array<T, 3>{T(-1), T(0), T(1)}));
    CHECK((a * b).degree() == 2);
    CHECK(!(a == b));
  }
}
