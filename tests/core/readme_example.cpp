/// The README's core example, compiled and checked by the tests (keep the two in sync).
#include "catch.hpp"

// README-BEGIN core
#include <geomint/geomint.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

using namespace geomint;

// Exact weights at compile time: m = 2 equispaced (the LPF paper's scheme 16).
constexpr auto D1 = differentiation_weights<1, equispaced, 2, rational>();
static_assert(D1[0][0] == rational(-3) && D1[0][1] == rational(4) && D1[0][2] == rational(-1));

// Gauss-Lobatto nodes, constexpr in double ...
constexpr auto lobatto = nodes<gauss_lobatto, 6, double>();
static_assert(lobatto[3] == 0.5);

// ... and to full precision in 50 digits at run time.
inline auto lobatto_50() {
  return nodes<gauss_lobatto, 6, boost::multiprecision::cpp_bin_float_50>();
}
// README-END core

TEST_CASE("README core example", "[core][readme]") {
  const auto c = lobatto_50();
  CHECK(c[3] == boost::multiprecision::cpp_bin_float_50(1) / 2);
  CHECK(static_cast<double>(c[1]) == lobatto[1]);
}
