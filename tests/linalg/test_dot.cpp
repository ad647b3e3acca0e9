/// linalg::dot (linalg/dot.hpp): for cpp_bin_float the exact dot product rounded once.
///
/// Independent expected values: the same sums in a 1000-bit binary float, where every product
/// and every partial sum of these data is exact (exact mathematics: the products need 2p bits
/// and the data's exponents span less than 300 bits), rounded by the scalar's own conversion;
/// hand-made ties for the rounding rule; and the multiply-add loop for built-in types and for
/// non-finite data.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "catch.hpp"
#include "geomint/core/multiprecision.hpp"
#include "geomint/linalg/dot.hpp"

namespace {
using exact_float = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<1000, boost::multiprecision::backends::digit_base_2>>;

/// Random data with exponents spread over +-2^60, some zeros, some sums that cancel to a few
/// bits: the result is the exact sum rounded to T (to nearest, ties to even: T's conversion
/// from the exact float), up to the cut products' bits, count 2^(2-2p) of the largest product.
template <class T>
void check_against_exact() {
  using std::abs;
  using std::ldexp;
  std::mt19937 engine(17);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60);
  const int p = std::numeric_limits<T>::digits;
  int cancelled = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int count = trial % 21;  // 0..20 terms
    const int stride = 1 + trial % 3;
    std::vector<T> a(static_cast<std::size_t>(count)), b(static_cast<std::size_t>(count * stride) + 1, T(7));
    for (int k = 0; k < count; ++k) {
      const auto K = static_cast<std::size_t>(k);
      a[K] = ldexp(T(T(unit(engine)) + T(unit(engine)) * T(ldexp(T(1), -40))), exponent(engine));
      b[K * static_cast<std::size_t>(stride)] = T(T(unit(engine)) / T(3));
    }
    if (count > 0 && trial % 5 == 0) a[0] = T(0);
    if (count > 2 && trial % 7 == 0) {  // the first two terms cancel but for their last bits
      const auto s = static_cast<std::size_t>(stride);
      a[1] = ldexp(T(1), exponent(engine));
      b[s] = T(-a[0] * b[0] / a[1]);
      ++cancelled;
    }
    exact_float exact(0), largest(0);
    for (int k = 0; k < count; ++k) {
      const auto K = static_cast<std::size_t>(k);
      const exact_float product = exact_float(a[K]) * exact_float(b[K * static_cast<std::size_t>(stride)]);
      exact += product;
      if (abs(product) > largest) largest = abs(product);
    }
    const T got = geomint::linalg::dot(a.data(), b.data(), static_cast<std::size_t>(count), static_cast<std::size_t>(stride));
    const T rounded = T(exact);
    INFO("trial " << trial << ": count " << count << ", stride " << stride);
    // Equal, or (only the cut bits can move it, and only across a rounding boundary) as close.
    CHECK((got == rounded || abs(exact_float(got) - exact) <=
                                 abs(exact_float(rounded) - exact) + exact_float(count) * ldexp(largest, 2 - 2 * p)));
  }
  REQUIRE(cancelled > 100);
}

/// Ties: 1 + 2^-p lies halfway between 1 and its successor 1 + 2^(1-p), and rounds to the even
/// 1; 1 + 3 2^-p halfway between 1 + 2^(1-p) and 1 + 2^(2-p), and rounds to the even second.
template <class T>
void check_ties() {
  using std::ldexp;
  const int p = std::numeric_limits<T>::digits;
  const T half_ulp = ldexp(T(1), -p);
  const T a[2] = {T(1), half_ulp};
  const T one[2] = {T(1), T(1)};
  CHECK(geomint::linalg::dot(a, one, 2) == T(1));
  const T b[2] = {T(1), T(3) * half_ulp};
  CHECK(geomint::linalg::dot(b, one, 2) == T(T(1) + ldexp(T(1), 2 - p)));
  const T c[2] = {T(-1), T(-3) * half_ulp};
  CHECK(geomint::linalg::dot(c, one, 2) == T(-T(1) - ldexp(T(1), 2 - p)));
  // Exact cancellation gives +0.
  const T d[2] = {T(3), T(-3)};
  CHECK(geomint::linalg::dot(d, one, 2) == T(0));
}
}  // namespace

TEST_CASE("linalg::dot: cpp_bin_float sums are the exact sums rounded once", "[linalg][dot]") {
  check_against_exact<boost::multiprecision::cpp_bin_float_50>();
  check_against_exact<boost::multiprecision::cpp_bin_float_100>();
  check_ties<boost::multiprecision::cpp_bin_float_50>();
  check_ties<boost::multiprecision::cpp_bin_float_100>();
}

TEST_CASE("linalg::dot: non-finite data and built-in types take the loop", "[linalg][dot]") {
  using T = boost::multiprecision::cpp_bin_float_50;
  const T one[3] = {T(1), T(1), T(1)};
  const T with_inf[3] = {T(1), std::numeric_limits<T>::infinity(), T(2)};
  CHECK(geomint::linalg::dot(with_inf, one, 3) == std::numeric_limits<T>::infinity());
  const T with_nan[3] = {T(1), std::numeric_limits<T>::quiet_NaN(), T(2)};
  const T nan_sum = geomint::linalg::dot(with_nan, one, 3);
  CHECK(nan_sum != nan_sum);
  // Products beyond the exponent range overflow as in the loop.
  using std::ldexp;
  const T huge[2] = {T(ldexp(T(1), std::numeric_limits<T>::max_exponent - 2)), T(1)};
  const T big[2] = {T(16), T(1)};
  CHECK(geomint::linalg::dot(huge, big, 2) == geomint::linalg::detail::dot_in_order(huge, big, 2, 1));
  CHECK(geomint::linalg::dot(huge, big, 0) == T(0));
  const double x[4] = {0.1, -0.2, 0.3, 1e-17}, y[4] = {3.0, 1.0 / 3, -7.0, 1.0};
  double loop = 0;
  for (int k = 0; k < 4; ++k) loop += x[k] * y[k];
  CHECK(geomint::linalg::dot(x, y, 4) == loop);
}
