/// SIMD packs of doubles (core/simd.hpp), for 2, 4 and 8 lanes (lanes beyond the target's
/// registers are emulated by the compiler, with the same values). Independent sources: IEEE 754
/// (+ - * / and sqrt correctly rounded, so each lane equals the double operation, and sqrt the
/// square root in 50 digits rounded to double), Boost's cpp_bin_float_50 for sin, cos, exp and
/// log (each lane within one ulp: SLEEF's documented bound for its u10 functions, Shibata &
/// Petrogalli, IEEE TPDS 31 (2020); the C library's per lane without SLEEF), and the systems'
/// scalar forces per lane.
#include <array>
#include <cmath>
#include <limits>

#include "catch.hpp"
#include "geomint/core/simd.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::cpp_bin_float_50;

namespace {

/// Distance in units of the last place of the double nearest to the exact value.
double ulps_from(double x, const cpp_bin_float_50& exact) {
  const double nearest = static_cast<double>(exact);
  const double ulp = std::nextafter(std::fabs(nearest), std::numeric_limits<double>::infinity()) - std::fabs(nearest);
  return static_cast<double>(cpp_bin_float_50(abs(cpp_bin_float_50(x) - exact) / cpp_bin_float_50(ulp)));
}

template <int W>
double_pack<W> pack_of(const std::array<double, 8>& x, int offset) {
  double_pack<W> p;
  for (int j = 0; j < W; ++j) p.set(j, x[static_cast<std::size_t>((offset + j) % 8)]);
  return p;
}

template <int W>
void check_arithmetic() {
  const std::array<double, 8> a{0.1, -2.5, 3e-300, 7.25, -1e300, 0.3333333333333333, 5.0, -0.0};
  const std::array<double, 8> b{1.7, 0.3, -4.0, 1e-10, 2.0, 3.0, -7.5, 11.0};
  const auto x = pack_of<W>(a, 0), y = pack_of<W>(b, 0);
  const auto sum = x + y, difference = x - y, product = x * y, quotient = x / y, negated = -x;
  const auto mixed = x * 2.0 + 1.0;  // the scalars broadcast
  for (int j = 0; j < W; ++j) {
    const auto J = static_cast<std::size_t>(j);
    CHECK(sum[j] == a[J] + b[J]);
    CHECK(difference[j] == a[J] - b[J]);
    CHECK(product[j] == a[J] * b[J]);
    CHECK(quotient[j] == a[J] / b[J]);
    CHECK(negated[j] == -a[J]);
    CHECK(mixed[j] == a[J] * 2.0 + 1.0);
  }
}

template <int W>
void check_functions() {
  double worst_sin = 0, worst_cos = 0, worst_exp = 0, worst_log = 0;
  for (int k = 0; k < 400; k += W) {
    double_pack<W> x, pos;
    for (int j = 0; j < W; ++j) {
      // Points in [-20, 20] off any grid (and a few large ones) for sin and cos; (0, 50] for log.
      const double t = -20.0 + 40.0 * (k + j) / 400.0 + 1e-3 * (j + 1) / 7.0;
      x.set(j, (k + j) % 97 == 0 ? t * 1e3 : t);
      pos.set(j, 0.125 * (k + j + 1) + 1e-3 / (j + 3));
    }
    const auto s = sin(x), c = cos(x), e = exp(x), l = log(pos), r = sqrt(pos);
    for (int j = 0; j < W; ++j) {
      const cpp_bin_float_50 X(x[j]), P(pos[j]);
      worst_sin = std::max(worst_sin, ulps_from(s[j], sin(X)));
      worst_cos = std::max(worst_cos, ulps_from(c[j], cos(X)));
      worst_exp = std::max(worst_exp, ulps_from(e[j], exp(X)));
      worst_log = std::max(worst_log, ulps_from(l[j], log(P)));
      CHECK(r[j] == static_cast<double>(sqrt(P)));  // correctly rounded
      CHECK(r[j] == std::sqrt(pos[j]));
    }
  }
  CHECK(worst_sin <= 1.0);
  CHECK(worst_cos <= 1.0);
  CHECK(worst_exp <= 1.0);
  CHECK(worst_log <= 1.0);
}

/// The force of a system on a pack, lane by lane against the scalar force: equal up to the
/// elementary functions' last bit and the compiler's contraction of a * b + c into one rounding
/// (a few ulps of the largest term).
template <class Sys, int W>
void check_forces(const std::array<vec<double, Sys::dof>, W>& points, double ulps) {
  constexpr int n = Sys::dof;
  vec<double_pack<W>, n> x;
  for (int j = 0; j < W; ++j)
    for (int r = 0; r < n; ++r) x[r].set(j, points[static_cast<std::size_t>(j)][r]);
  const vec<double_pack<W>, n> g = Sys::template potential_gradient<double_pack<W>>(x);
  for (int j = 0; j < W; ++j) {
    const vec<double, n> expected = Sys::template potential_gradient<double>(points[static_cast<std::size_t>(j)]);
    const double scale = expected.template lpNorm<Eigen::Infinity>();
    for (int r = 0; r < n; ++r) CHECK(std::fabs(g[r][j] - expected[r]) <= ulps * std::numeric_limits<double>::epsilon() * scale);
  }
}

}  // namespace

TEST_CASE("simd: + - * / of a pack are those of each lane", "[simd]") {
  check_arithmetic<2>();
  check_arithmetic<4>();
  check_arithmetic<8>();
}

TEST_CASE("simd: sin, cos, exp, log within one ulp of 50 digits; sqrt correctly rounded", "[simd]") {
  check_functions<2>();
  check_functions<4>();
  check_functions<8>();
}

TEST_CASE("simd: the opted-in systems, and a natural system's force per lane is its scalar force",
          "[simd]") {
  STATIC_REQUIRE((simd_width == 2 || simd_width == 4 || simd_width == 8));
  STATIC_REQUIRE(stage_parallel_system<systems::pendulum>);
  STATIC_REQUIRE(stage_parallel_system<zoo::outer_solar>);
  STATIC_REQUIRE(!stage_parallel_system<zoo::henon_heiles>);  // no potential_gradient: AD on V
  std::array<vec<double, 1>, 4> angles;
  for (int j = 0; j < 4; ++j) angles[static_cast<std::size_t>(j)][0] = -1.5 + 0.9 * j;
  check_forces<systems::pendulum, 4>(angles, 1.0);  // one sine each: SLEEF's and libm's
  std::array<vec<double, 2>, 4> planar;
  for (int j = 0; j < 4; ++j) planar[static_cast<std::size_t>(j)] = vec<double, 2>(0.5 + 0.3 * j, -0.2 + 0.25 * j);
  check_forces<systems::kepler, 4>(planar, 8.0);  // compiles on packs, though not opted in
  std::array<vec<double, 18>, 2> bodies;
  vec<double, 18> q0, v0;
  zoo::outer_solar::initial_data(q0, v0);
  bodies[0] = q0;
  bodies[1] = q0 + 0.01 * v0;
  check_forces<zoo::outer_solar, 2>(bodies, 64.0);  // 15 pairs summed per component
}
