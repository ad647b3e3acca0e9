/// The elementary functions of core/elementary.hpp against the scalar's own functions in higher
/// precision (cpp_bin_float_100 checks cpp_bin_float_50, 150 digits check 100 digits): Boost's
/// sqrt, sin and cos, an independent implementation (correctly rounded square root,
/// hypergeometric series for the sine). In built-in types the functions are the standard
/// library's, bit for bit.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>

#include <boost/math/constants/constants.hpp>

#include "catch.hpp"
#include "geomint/core/elementary.hpp"
#include "scalar_types.hpp"

namespace {
using boost::multiprecision::cpp_bin_float_100;
using boost::multiprecision::cpp_bin_float_50;
using H150 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<150>>;

/// inverse_sqrt within 2 eps relative: Newton's last iteration leaves an error below 2^-200
/// relative, and its rounding (the correction's and the sum's) about one unit of the last place.
template <class T, class H>
void check_inverse_sqrt() {
  using std::abs;
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  std::mt19937 engine(11);
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(-1000, 1000);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    using std::ldexp;
    const T x = ldexp(T(T(mantissa(engine)) + T(mantissa(engine)) * eps * T(1 << 20)), exponent(engine));
    const H exact = H(1) / sqrt(H(x));
    INFO("x = " << x);
    CHECK(abs(H(geomint::inverse_sqrt(x)) - exact) <= H(2 * eps) * exact);
    ++checked;
  }
  REQUIRE(checked == 400);
  // Outside double's normal range, and at 0 and below: 1 / sqrt in T.
  using std::ldexp;
  for (const T& x : {T(ldexp(T(1), -1100)), T(ldexp(T(3), 1100)), T(0), T(-4)}) {
    const T expected = T(1) / sqrt(x);
    const T got = geomint::inverse_sqrt(x);
    if (expected != expected) {
      CHECK(got != got);
    } else {
      CHECK(got == expected);
    }
  }
}

/// sin_cos, sine and cosine. For |x| < 9/8 (the table): within 4 eps relative of each result
/// (the rounded table values, the series truncated below eps/8 and about three roundings, at a
/// cancellation of at most half: core/elementary.hpp). Further out (by quadrant): the evaluated
/// function is the scalar's, the other sqrt(1 - s^2), whose error is the evaluated one's times
/// |s / c| <= 9/8 plus the rounding of the square root, so each is within the scalar's own sin
/// and cos errors in T that way plus 2 units of the last place. sine and cosine are sin_cos's
/// two results, bit for bit, in the table, and the scalar's sin and cos outside it; so is
/// sin_cos for arguments too large for the quadrant.
template <class T, class H>
void check_sin_cos() {
  using std::abs;
  const T eps = std::numeric_limits<T>::epsilon();
  int in_table = 0, by_quadrant = 0;
  auto check = [&](const T& x) {
    const std::pair<T, T> sc = geomint::sin_cos(x);
    const H hs = sin(H(x)), hc = cos(H(x));
    INFO("x = " << x);
    if (abs(x) < T(9) / T(8)) {
      CHECK(geomint::sine(x) == sc.first);
      CHECK(geomint::cosine(x) == sc.second);
      CHECK(abs(H(sc.first) - hs) <= H(4 * eps) * abs(hs));
      CHECK(abs(H(sc.second) - hc) <= H(4 * eps) * abs(hc));
      ++in_table;
    } else {
      const H library_s = abs(H(T(sin(x))) - hs), library_c = abs(H(T(cos(x))) - hc);
      const H inherited = H(9) / H(8) * (library_s > library_c ? library_s : library_c);
      CHECK(abs(H(sc.first) - hs) <= library_s + inherited + H(2 * eps) * abs(hs));
      CHECK(abs(H(sc.second) - hc) <= library_c + inherited + H(2 * eps) * abs(hc));
      CHECK(geomint::sine(x) == T(sin(x)));
      CHECK(geomint::cosine(x) == T(cos(x)));
      ++by_quadrant;
    }
  };
  // Next to every quadrant boundary k pi/4 (|k| <= 40), where the quadrant method changes the
  // function it evaluates; a grid of [-20, 20]; next to the table's points j/128 and the
  // midpoints between them (where the nearest point changes), and small arguments down to 2^-295.
  const T quarter_pi = boost::math::constants::pi<T>() / T(4);
  for (int k = -40; k <= 40; ++k)
    for (int j = -3; j <= 3; ++j) check(T(T(k) * quarter_pi + T(j) * T(1000) * eps));
  for (int i = -2000; i <= 2000; ++i) check(T(T(i) / T(100)));
  for (int j = -288; j <= 288; ++j)
    for (int d = -1; d <= 1; ++d) check(T(T(j) / T(256) + T(d) * eps));
  for (int e = 1; e <= 300; e += 7) {
    using std::ldexp;
    check(T(ldexp(T(1), -e)));
    check(T(-ldexp(T(3), -e)));
  }
  // In the table: k = -1, 0, 1 of the boundaries, |i| <= 112 of the grid, all next to the
  // table points but 9/8, 9/8 + eps and their negatives, and the small arguments but -3/2.
  CHECK(in_table == 3 * 7 + 225 + (3 * 577 - 4) + (2 * 43 - 1));
  REQUIRE(in_table + by_quadrant == 81 * 7 + 4001 + 3 * 577 + 2 * 43);
  for (const T& x : {T(T(1) / eps), T(-T(1) / eps), T(std::int64_t(1) << 62)}) {
    const std::pair<T, T> sc = geomint::sin_cos(x);
    CHECK(sc.first == T(sin(x)));
    CHECK(sc.second == T(cos(x)));
  }
}
}  // namespace

TEST_CASE("elementary: inverse_sqrt in multiprecision", "[core][elementary]") {
  check_inverse_sqrt<cpp_bin_float_50, cpp_bin_float_100>();
  check_inverse_sqrt<cpp_bin_float_100, H150>();
}

TEST_CASE("elementary: sin_cos sine and cosine in multiprecision", "[core][elementary]") {
  check_sin_cos<cpp_bin_float_50, cpp_bin_float_100>();
  check_sin_cos<cpp_bin_float_100, H150>();
}

TEST_CASE("elementary: built-in types keep the standard library's functions", "[core][elementary]") {
  for (int i = -2000; i <= 2000; ++i) {
    const double x = double(i) / 100;
    const std::pair<double, double> sc = geomint::sin_cos(x);
    CHECK(sc.first == std::sin(x));
    CHECK(sc.second == std::cos(x));
    CHECK(geomint::sine(x) == std::sin(x));
    CHECK(geomint::cosine(x) == std::cos(x));
    if (x > 0) CHECK(geomint::inverse_sqrt(x) == 1 / std::sqrt(x));
  }
}
