/// libqd's dd_real and qd_real compiled for a processor with FMA (built with -mfma -mavx512f
/// where the host has FMA, tests/core/CMakeLists.txt): GCC's default -ffp-contract=fast then
/// contracts Dekker's split inside libqd's inline product unless core/qd.hpp routes it through
/// fma. Oracles: exact rational arithmetic (cpp_rational) for the error-free product, and the
/// symplecticity of the Gauss collocation RKN method (Suris 1989; Hairer, Lubich & Wanner,
/// Theorem VI.4.10), exact mathematics, for the coefficients built from those products.
#include <limits>
#include <random>

#include <boost/multiprecision/cpp_int.hpp>

#include "catch.hpp"
#include "geomint/core/qd.hpp"
#include "geomint/methods/collocation_rkn.hpp"

namespace {
using boost::multiprecision::cpp_rational;

/// The exact value of a dd_real or qd_real (the sum of its doubles).
template <class T>
cpp_rational exact_value(const T& x) {
  cpp_rational sum(0);
  for (int k = 0; k < geomint::double_expansion<T>::terms; ++k) sum += cpp_rational(geomint::double_expansion<T>::term(x, k));
  return sum;
}
}  // namespace

TEST_CASE("qd with FMA: the product of two doubles in dd_real is exact", "[core][qd]") {
  STATIC_REQUIRE(std::numeric_limits<double>::digits == 53);
#if !defined(__FMA__)
  FAIL("this file must be compiled for a target with FMA (-mfma)");
#endif
  std::mt19937_64 gen(20261207);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    const double a = u(gen), b = u(gen);
    // 53 + 53 bits: the product is a double-double exactly.
    REQUIRE(exact_value(dd_real(a) * dd_real(b)) == cpp_rational(a) * cpp_rational(b));
    REQUIRE(exact_value(sqr(dd_real(a))) == cpp_rational(a) * cpp_rational(a));
  }
}

TEMPLATE_TEST_CASE("qd with FMA: the Gauss collocation RKN tableau is symplectic to the scalar's round-off", "[core][qd]", dd_real,
                   qd_real) {
  using T = TestType;
  constexpr int S = 8;
  const auto t = geomint::methods::gauss_collocation_rkn<T, S>();
  const T eps = std::numeric_limits<T>::epsilon();
  // b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji) and bbar_i = b_i (1 - c_i), entries of size <= 1;
  // the contracted split left defects of 1e15 eps in dd_real.
  for (std::size_t i = 0; i < S; ++i) {
    CHECK(abs(T(t.bbar[i] - t.b[i] * (T(1) - t.c[i]))) <= T(16) * eps);
    for (std::size_t j = 0; j < S; ++j)
      CHECK(abs(T(t.b[i] * (t.bbar[j] - t.a[i][j]) - t.b[j] * (t.bbar[i] - t.a[j][i]))) <= T(16) * eps);
  }
}
