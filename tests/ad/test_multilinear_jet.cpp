/// The multilinear jet (ad/multilinear_jet.hpp) against exact mathematics, in double and
/// cpp_bin_float_50 with tolerances of a few dozen epsilon:
/// - x_0 + e_1 + ... + e_k through f has f^(k)(x_0) as the coefficient of e_1 ... e_k: the
///   closed-form derivatives of sin, cos, exp, expm1, sinh, cosh, log, log1p, 1/x, x^5, x^(5/2),
///   sqrt, 1/sqrt (textbook formulas) and atan (d^k atan x = (-1)^(k-1) (k-1)! sin(k acot x) /
///   (1 + x^2)^(k/2)), k = 0..6;
/// - the mixed partials of a polynomial in three variables, derived by hand;
/// - inverse functions compose to the identity jet on three generic directions (asin(sin x) = x,
///   and the same for acos, atan, atan2, log, log1p, cbrt, hypot, tanh = sinh / cosh);
/// - jets of different numbers of directions mix as the smaller embedded in the larger;
/// - repeated directions (degrees above 1): one direction of degree k gives the same k-th
///   derivatives as k multilinear directions (closed forms above), and the mixed partials of
///   the polynomial in three variables by hand.
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "catch.hpp"
#include "geomint/ad/multilinear_jet.hpp"

namespace multilinear_jet_test {

using geomint::jet;

/// x_0 + e_1 + ... + e_k.
template <class T>
jet<T> along_one_direction(const T& x0, int k) {
  return jet<T>::variable(x0, std::vector<T>(static_cast<std::size_t>(k), T(1)));
}

/// The coefficient of e_1 ... e_k of f(x_0 + e_1 + ... + e_k).
template <class T, class F>
T derivative(F f, const T& x0, int k) {
  return f(along_one_direction(x0, k)).coefficient((std::size_t{1} << k) - 1);
}

/// k! times the coefficient of s^k of f(x_0 + s), s^(k+1) = 0: one direction of degree k.
template <class T, class F>
T derivative_of_degree(F f, const T& x0, int k) {
  if (k == 0) return f(jet<T>(x0)).value();
  T factorial(1);
  for (int j = 2; j <= k; ++j) factorial *= T(j);
  return T(f(jet<T>::variable(x0, {T(1)}, {k})).coefficient(static_cast<std::size_t>(k)) * factorial);
}

template <class T>
bool close(const T& computed, const T& exact) {
  using std::abs;
  return abs(T(computed - exact)) <= T(64) * std::numeric_limits<T>::epsilon() * (T(1) + abs(exact));
}

/// Every coefficient of a equals that of b.
template <class T>
void check_same_jet(const jet<T>& a, const jet<T>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t s = 0; s < a.size(); ++s) {
    INFO("subset " << s);
    CHECK(close(a[s], b[s]));
  }
}

/// k!.
template <class T>
T factorial(int k) {
  T f(1);
  for (int j = 2; j <= k; ++j) f *= T(j);
  return f;
}

/// a (a - 1) ... (a - k + 1).
template <class T>
T falling(const T& a, int k) {
  T f(1);
  for (int j = 0; j < k; ++j) f *= a - T(j);
  return f;
}

TEMPLATE_TEST_CASE("multilinear jet: d^k/dx^k of the elementary functions equal their closed forms", "[ad]", double,
                   boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  // Each closed form is checked on k multilinear directions and on one direction of degree k.
  const auto derivative = [](auto f, const T& x0, int k) {
    const T multilinear = multilinear_jet_test::derivative<T>(f, x0, k);
    CHECK(close(derivative_of_degree<T>(f, x0, k), multilinear));
    return multilinear;
  };
  using std::atan;
  using std::cos;
  using std::exp;
  using std::expm1;
  using std::log;
  using std::log1p;
  using std::pow;
  using std::sin;
  using std::sqrt;
  const T x(7);
  const T x0 = x / T(10);  // 0.7
  for (int k = 0; k <= 6; ++k) {
    INFO("k = " << k);
    const T odd_sign = k % 2 == 0 ? T(1) : T(-1);
    const T s = sin(x0), c = cos(x0), e = exp(x0);
    const T sin_cycle[4] = {s, c, T(-s), T(-c)};  // sin^(k) = sin, cos, -sin, -cos, ...
    const T cos_cycle[4] = {c, T(-s), T(-c), s};
    CHECK(close(derivative([](const auto& y) { return sin(y); }, x0, k), sin_cycle[k % 4]));
    CHECK(close(derivative([](const auto& y) { return cos(y); }, x0, k), cos_cycle[k % 4]));
    CHECK(close(derivative([](const auto& y) { return exp(y); }, x0, k), e));
    CHECK(close(derivative([](const auto& y) { return expm1(y); }, x0, k), k == 0 ? T(expm1(x0)) : e));
    const T sh = (e - T(1) / e) / T(2), ch = (e + T(1) / e) / T(2);
    CHECK(close(derivative([](const auto& y) { return sinh(y); }, x0, k), k % 2 == 0 ? sh : ch));
    CHECK(close(derivative([](const auto& y) { return cosh(y); }, x0, k), k % 2 == 0 ? ch : sh));
    // log^(k) x = (-1)^(k-1) (k-1)! / x^k; the same at 1 + x for log1p.
    const T log_k = k == 0 ? T(log(x0)) : T(-odd_sign * factorial<T>(k - 1) / pow(x0, k));
    CHECK(close(derivative([](const auto& y) { return log(y); }, x0, k), log_k));
    const T log1p_k = k == 0 ? T(log1p(x0)) : T(-odd_sign * factorial<T>(k - 1) / pow(T(1 + x0), k));
    CHECK(close(derivative([](const auto& y) { return log1p(y); }, x0, k), log1p_k));
    // (1/x)^(k) = (-1)^k k! / x^(k+1); (x^a)^(k) = a (a-1) ... (a-k+1) x^(a-k).
    CHECK(close(derivative([](const auto& y) { return T(1) / y; }, x0, k), T(odd_sign * factorial<T>(k) / pow(x0, k + 1))));
    CHECK(close(derivative([](const auto& y) { return pow(y, 5); }, x0, k), T(falling(T(5), k) * pow(x0, 5 - k))));
    const T five_halves = T(5) / T(2), half = T(1) / T(2);
    CHECK(close(derivative([&](const auto& y) { return pow(y, five_halves); }, x0, k),
                T(falling(five_halves, k) * pow(x0, T(five_halves - T(k))))));
    CHECK(close(derivative([](const auto& y) { return sqrt(y); }, x0, k), T(falling(half, k) * pow(x0, T(half - T(k))))));
    CHECK(close(derivative([](const auto& y) { return geomint::inverse_sqrt(y); }, x0, k),
                T(falling(T(-half), k) * pow(x0, T(-half - T(k))))));
    // atan^(k) x = (-1)^(k-1) (k-1)! sin(k acot x) / (1 + x^2)^(k/2), acot x = atan(1/x) (x > 0).
    const T atan_k = k == 0 ? T(atan(x0))
                            : T(-odd_sign * factorial<T>(k - 1) * sin(T(T(k) * atan(T(1) / x0))) / pow(T(1 + x0 * x0), T(T(k) / T(2))));
    CHECK(close(derivative([](const auto& y) { return atan(y); }, x0, k), atan_k));
  }
}

TEMPLATE_TEST_CASE("multilinear jet: the mixed partials of a polynomial in three variables", "[ad]", double,
                   boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  // p = x^2 y z^3 + 3 x y^2 - 2 z at (3/2, -1/2, 2).
  const T x0 = T(3) / T(2), y0 = T(-1) / T(2), z0(2);
  const auto p = [](const jet<T>& x, const jet<T>& y, const jet<T>& z) { return x * x * y * pow(z, 3) + 3 * x * y * y - T(2) * z; };
  const jet<T> x = jet<T>::variable(x0, {T(1), T(0), T(0)});
  const jet<T> y = jet<T>::variable(y0, {T(0), T(1), T(0)});
  const jet<T> z = jet<T>::variable(z0, {T(0), T(0), T(1)});
  const jet<T> v = p(x, y, z);
  // Bit 0: d/dx, bit 1: d/dy, bit 2: d/dz.
  CHECK(close(v[0], T(x0 * x0 * y0 * z0 * z0 * z0 + T(3) * x0 * y0 * y0 - T(2) * z0)));
  CHECK(close(v[1], T(T(2) * x0 * y0 * z0 * z0 * z0 + T(3) * y0 * y0)));
  CHECK(close(v[2], T(x0 * x0 * z0 * z0 * z0 + T(6) * x0 * y0)));
  CHECK(close(v[4], T(T(3) * x0 * x0 * y0 * z0 * z0 - T(2))));
  CHECK(close(v[3], T(T(2) * x0 * z0 * z0 * z0 + T(6) * y0)));
  CHECK(close(v[5], T(T(6) * x0 * y0 * z0 * z0)));
  CHECK(close(v[6], T(T(3) * x0 * x0 * z0 * z0)));
  CHECK(close(v[7], T(T(6) * x0 * z0 * z0)));
  // A repeated direction: x = x0 + e_1 + e_2 gives d^2/dx^2 = 2 y z^3 on e_1 e_2.
  const jet<T> xx = jet<T>::variable(x0, {T(1), T(1)});
  CHECK(close(p(xx, jet<T>(y0), jet<T>(z0))[3], T(T(2) * y0 * z0 * z0 * z0)));

  // Degrees (2, 1, 3): x = x0 + s1, y = y0 + s2, z = z0 + s3 with s1^3 = s2^2 = s3^4 = 0; the
  // coefficient of s1^a s2^b s3^c (index a + 3 b + 6 c) is d^a_x d^b_y d^c_z p / (a! b! c!).
  const std::vector<int> degrees = {2, 1, 3};
  const jet<T> X = jet<T>::variable(x0, {T(1), T(0), T(0)}, degrees);
  const jet<T> Y = jet<T>::variable(y0, {T(0), T(1), T(0)}, degrees);
  const jet<T> Z = jet<T>::variable(z0, {T(0), T(0), T(1)}, degrees);
  const jet<T> w = p(X, Y, Z);
  REQUIRE(w.size() == 24);
  REQUIRE(w.total_degree() == 6);
  const auto at = [](int a, int b, int c) { return static_cast<std::size_t>(a + 3 * b + 6 * c); };
  CHECK(close(w[at(0, 0, 0)], v[0]));
  CHECK(close(w[at(1, 1, 0)], v[3]));
  CHECK(close(w[at(1, 1, 1)], v[7]));
  CHECK(close(w[at(2, 0, 0)], T(y0 * z0 * z0 * z0)));                               // p_xx / 2 = y z^3
  CHECK(close(w[at(0, 1, 0)], v[2]));
  CHECK(close(w[at(2, 1, 0)], T(z0 * z0 * z0)));                                     // p_xxy / 2 = z^3
  CHECK(close(w[at(2, 1, 3)], T(1)));                                                // p_xxyzzz / (2! 3!) = 6 / 6
  CHECK(close(w[at(1, 0, 3)], T(T(2) * x0 * y0)));                                   // p_xzzz / 3! = 12 x y / 6
  CHECK(close(w[at(0, 0, 2)], T(x0 * x0 * y0 * T(3) * z0)));                         // p_zz / 2 = 3 x^2 y z
  CHECK(close(w[at(2, 0, 3)], y0));                                                  // p_xxzzz / (2! 3!) = 12 y / 12
  CHECK(close(w[at(1, 1, 3)], T(T(2) * x0)));                                        // p_xyzzz / 3! = 12 x / 6
  CHECK(close(w[at(0, 1, 3)], T(x0 * x0)));                                          // p_yzzz / 3! = 6 x^2 / 6
  // Jets of different degrees do not combine.
  CHECK_THROWS_AS(X * jet<T>::variable(x0, {T(1), T(0), T(0)}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("multilinear jet: inverse functions compose to the identity", "[ad]", double,
                   boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  const std::vector<T> u = {T(1), T(-2) / T(3), T(5) / T(7)};
  const jet<T> x = jet<T>::variable(T(3) / T(5), u);
  check_same_jet(asin(sin(x)), x);
  check_same_jet(acos(cos(x)), x);
  check_same_jet(atan(tan(x)), x);
  check_same_jet(atan2(sin(x), cos(x)), x);
  check_same_jet(atan2(T(3) * sin(x), T(3) * cos(x)), x);
  check_same_jet(log(exp(x)), x);
  check_same_jet(log1p(expm1(x)), x);
  check_same_jet(sqrt(x) * sqrt(x), x);
  check_same_jet(T(5) * x, hypot(T(3) * x, T(4) * x));
  check_same_jet(tanh(x) * cosh(x), sinh(x));
  check_same_jet(pow(x, T(3) / T(2)), exp(jet<T>(log(x) * (T(3) / T(2)))));
  const jet<T> negative = -x - 1;
  check_same_jet(pow(cbrt(negative), 3), negative);
  check_same_jet(abs(negative), jet<T>(x + 1));
  check_same_jet(T(1) / (T(1) / x), x);
}

TEMPLATE_TEST_CASE("multilinear jet: mixed directions, constants and comparisons", "[ad]", double,
                   boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  const jet<T> a = jet<T>::variable(T(2), {T(1), T(3)});              // 2 + e_1 + 3 e_2
  const jet<T> b = jet<T>::variable(T(-1), {T(1) / T(2), T(0), T(4)});  // -1 + e_1/2 + 4 e_3
  const jet<T> ab = a * b;
  REQUIRE(ab.directions() == 3);
  // (2 + e1 + 3 e2)(-1 + e1/2 + 4 e3), e1^2 = 0: by hand.
  const T expected[8] = {T(-2), T(0), T(-3), T(3) / T(2), T(8), T(4), T(12), T(0)};
  for (std::size_t s = 0; s < 8; ++s) {
    INFO("subset " << s);
    CHECK(close(ab[s], expected[s]));
  }
  check_same_jet(jet<T>(ab / b), jet<T>(a + T(0) * b));  // a widened to three directions
  check_same_jet(jet<T>(2 * a - a / T(2) + 1), jet<T>(a * (T(3) / T(2)) + T(1)));
  CHECK(b < a);
  CHECK(a > 1);
  CHECK(T(-1) == b);
  CHECK(a.coefficient(7) == T(0));
  CHECK_THROWS_AS(jet<T>::zero(jet<T>::max_directions + 1), std::invalid_argument);
}

}  // namespace multilinear_jet_test
