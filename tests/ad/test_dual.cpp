/// The dual numbers' elementary functions against an independent derivative: the Taylor
/// coefficients of the same function, evaluated on plain 100-digit numbers at 15 equispaced
/// points (step 1e-5) and fitted by a degree-14 polynomial, give f, f', f'', f''' to about 1e-55
/// (truncation h^(15-k), round-off 1e-100 / h^k). Each function is checked at the three nesting
/// depths the integrators use (dual, dual of dual, dual of dual of dual: gradient, Hessian and
/// the Euler-Lagrange Jacobian), over double and cpp_bin_float_50.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include <Eigen/Dense>
#include <boost/math/constants/constants.hpp>

#include "catch.hpp"
#include "geomint/ad/dual.hpp"
#include "scalar_types.hpp"

using geomint::dual;
using R = boost::multiprecision::cpp_bin_float_100;

namespace {

template <class S>
struct base_of {
  using type = S;
};
template <class T, int N>
struct base_of<dual<T, N>> {
  using type = typename base_of<T>::type;
};

/// f, f', f'', f''' of g at 0 from a degree-14 fit through g(j h), j = -7..7, in 100 digits.
template <class G>
std::array<R, 4> reference_derivatives(const G& g) {
  constexpr int K = 7, P = 2 * K + 1;
  const R h = R(1) / R(100000);
  Eigen::Matrix<R, P, P> A;
  Eigen::Matrix<R, P, 1> b;
  for (int i = 0; i < P; ++i) {
    const int j = i - K;
    b[i] = R(g(R(h * R(j))));
    R power(1);
    for (int k = 0; k < P; ++k) {
      A(i, k) = power;
      power *= R(j);
    }
  }
  const Eigen::Matrix<R, P, 1> c = A.fullPivLu().solve(b);
  std::array<R, 4> out;
  R factorial(1), hk(1);
  for (int k = 0; k < 4; ++k) {
    if (k > 0) {
      factorial *= R(k);
      hk *= h;
    }
    out[static_cast<std::size_t>(k)] = c[k] * factorial / hk;
  }
  return out;
}

template <class T>
using D1 = dual<T, 1>;
template <class T>
using D2 = dual<D1<T>, 1>;
template <class T>
using D3 = dual<D2<T>, 1>;

/// t = 0 + e1 (+ e2 (+ e3)): the nested seeds whose result holds f, f', f'', f'''.
template <class T>
D1<T> seed1() { return D1<T>::variable(T(0), 0); }
template <class T>
D2<T> seed2() {
  D2<T> x(seed1<T>());
  x.d[0] = D1<T>(T(1));
  return x;
}
template <class T>
D3<T> seed3() {
  D3<T> x(seed2<T>());
  x.d[0] = D2<T>(D1<T>(T(1)));
  return x;
}

template <class T>
void expect_close(const std::string& what, const T& computed, const R& reference) {
  using std::abs;
  using std::max;
  const T ref = static_cast<T>(reference);
  const T scale = max(T(1), T(abs(ref)));
  INFO(what << ": computed " << computed << ", reference " << ref);
  CHECK(geomint::test::abs_diff(computed, ref) <= geomint::test::eps_tol<T>(64) * scale);
}

/// g(t) at every depth against the 100-digit Taylor coefficients.
template <class T, class G>
void check_function(const std::string& name, const G& g) {
  const std::array<R, 4> ref = reference_derivatives(g);
  const D1<T> y1 = g(seed1<T>());
  expect_close(name + " depth 1 f", y1.v, ref[0]);
  expect_close(name + " depth 1 f'", y1.d[0], ref[1]);
  const D2<T> y2 = g(seed2<T>());
  expect_close(name + " depth 2 f", y2.v.v, ref[0]);
  expect_close(name + " depth 2 f' (inner)", y2.v.d[0], ref[1]);
  expect_close(name + " depth 2 f' (outer)", y2.d[0].v, ref[1]);
  expect_close(name + " depth 2 f''", y2.d[0].d[0], ref[2]);
  const D3<T> y3 = g(seed3<T>());
  expect_close(name + " depth 3 f", y3.v.v.v, ref[0]);
  expect_close(name + " depth 3 f'", y3.d[0].v.v, ref[1]);
  expect_close(name + " depth 3 f''", y3.d[0].d[0].v, ref[2]);
  expect_close(name + " depth 3 f'''", y3.d[0].d[0].d[0], ref[3]);
}

}  // namespace

/// g(t) = f(a + t), with a = NUM/DEN exact in every type; B is the base scalar (for constants).
#define GEOMINT_AT(NUM, DEN, EXPR)                                                  \
  [](const auto& t) {                                                               \
    using S = std::remove_cvref_t<decltype(t)>;                                     \
    using B = typename base_of<S>::type;                                            \
    using std::sin, std::cos, std::tan, std::asin, std::acos, std::atan, std::atan2; \
    using std::sinh, std::cosh, std::tanh, std::exp, std::expm1, std::log;          \
    using std::log1p, std::sqrt, std::cbrt, std::pow, std::hypot, std::abs;         \
    const S x = S(B(NUM) / B(DEN)) + t;                                             \
    [[maybe_unused]] const B half = B(1) / B(2);                                    \
    return S(EXPR);                                                                 \
  }

TEMPLATE_LIST_TEST_CASE("dual numbers: every elementary function at every nesting depth", "[ad][dual]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  check_function<T>("sin", GEOMINT_AT(7, 10, sin(x)));
  check_function<T>("cos", GEOMINT_AT(7, 10, cos(x)));
  check_function<T>("tan", GEOMINT_AT(2, 5, tan(x)));
  check_function<T>("asin", GEOMINT_AT(3, 10, asin(x)));
  check_function<T>("acos", GEOMINT_AT(-9, 20, acos(x)));
  check_function<T>("atan", GEOMINT_AT(13, 10, atan(x)));
  check_function<T>("sinh", GEOMINT_AT(3, 5, sinh(x)));
  check_function<T>("cosh", GEOMINT_AT(-3, 5, cosh(x)));
  check_function<T>("tanh", GEOMINT_AT(3, 5, tanh(x)));
  check_function<T>("exp", GEOMINT_AT(4, 5, exp(x)));
  check_function<T>("expm1", GEOMINT_AT(1, 100, expm1(x)));
  check_function<T>("log", GEOMINT_AT(17, 10, log(x)));
  check_function<T>("log1p", GEOMINT_AT(1, 5, log1p(x)));
  check_function<T>("sqrt", GEOMINT_AT(23, 10, sqrt(x)));
  check_function<T>("cbrt", GEOMINT_AT(19, 10, cbrt(x)));
  check_function<T>("cbrt of a negative", GEOMINT_AT(-21, 10, cbrt(x)));
  check_function<T>("abs of a negative", GEOMINT_AT(-4, 5, abs(x)));
  check_function<T>("abs of a positive", GEOMINT_AT(4, 5, abs(x)));
  check_function<T>("pow(x, 3)", GEOMINT_AT(6, 5, pow(x, 3)));
  check_function<T>("pow(x, -2)", GEOMINT_AT(6, 5, pow(x, -2)));
  check_function<T>("pow(x, 5/2)", GEOMINT_AT(6, 5, pow(x, B(5) * half)));
  check_function<T>("pow(3/2, x)", GEOMINT_AT(6, 5, pow(B(3) * half, x)));
  check_function<T>("pow(x, x^2)", GEOMINT_AT(6, 5, pow(x, S(x * x))));
  // Two arguments moving at different rates along t (catches swapped partial derivatives).
  check_function<T>("atan2(y, x)", GEOMINT_AT(-7, 10, atan2(S(B(3) * half - t * B(2)), x)));
  check_function<T>("atan2(y, constant)", GEOMINT_AT(7, 10, atan2(x, B(-2))));
  check_function<T>("atan2(constant, x)", GEOMINT_AT(7, 10, atan2(B(-2), x)));
  check_function<T>("hypot(x, y)", GEOMINT_AT(-7, 10, hypot(x, S(B(3) * half - t * B(2)))));
  check_function<T>("hypot(x, constant)", GEOMINT_AT(7, 10, hypot(x, B(3))));
  check_function<T>("a composite", GEOMINT_AT(7, 10, exp(sin(x)) * sqrt(B(1) + x * x) / cosh(x)));
}

TEMPLATE_LIST_TEST_CASE("dual numbers: comparisons with plain scalars look at the value", "[ad][dual]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  const D3<T> x = seed3<T>() + T(1) / T(2);
  // (bool first: Catch would try to print a dual, which has no stream operator.)
  const bool less = x < 1, greater = 0 < x, positive = x > T(0), at_most = T(1) >= x, at_most_int = x <= 1;
  const bool nonzero = x != 0, equal = x == T(1) / T(2), above_one = x > 1;
  CHECK(less);
  CHECK(greater);
  CHECK(positive);
  CHECK(at_most);
  CHECK(at_most_int);
  CHECK(nonzero);
  CHECK(equal);
  CHECK_FALSE(above_one);
}

