/// Newton's method (solvers/newton.hpp): full and simplified, convergence to working precision
/// and every failure reason.
///
/// Independent sources of the expected values: closed-form roots (sqrt 2; the intersection of
/// x^2 + y^2 = 4 and x y = 1, x = (sqrt 6 + sqrt 2)/2, y = (sqrt 6 - sqrt 2)/2); equations built
/// to have a singular Jacobian, no root, or a non-finite residual.
#include <array>
#include <cmath>
#include <limits>

#include "catch.hpp"
#include "geomint/solvers/newton.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::abs_diff;
using geomint::test::eps_tol;

namespace {
/// F = (x^2 + y^2 - 4, x y - 1), J = [[2x, 2y], [y, x]].
template <class T>
void circle_hyperbola(const vec<T, 2>& z, vec<T, 2>& F, mat<T, 2>* J) {
  F[0] = z[0] * z[0] + z[1] * z[1] - T(4);
  F[1] = z[0] * z[1] - T(1);
  if (J) *J << T(2) * z[0], T(2) * z[1], z[1], z[0];
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("epsilon_two_thirds: eps^(2/3) of the scalar", "[solvers]", geomint::test::integrator_scalar_types) {
  // Two independent checks: the cube of the result is eps^2 to within a few roundings (exact
  // mathematics), and it equals the library cube root of eps^2 (std::cbrt, or Boost's generic
  // cbrt for a multiprecision scalar, which the helper avoids) to within an ulp.
  using T = TestType;
  using std::abs;
  using std::cbrt;
  const T eps = std::numeric_limits<T>::epsilon();
  const T x = epsilon_two_thirds<T>();
  const T a = eps * eps;
  CHECK(abs(T(x * x * x - a)) <= T(8) * eps * a);
  CHECK(abs(T(x - cbrt(a))) <= T(2) * eps * x);
}

TEMPLATE_LIST_TEST_CASE("newton_solve: quadratic convergence to the closed-form root", "[solvers]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::sqrt;
  vec<T, 1> z(T(1));
  auto sqrt2 = [](const vec<T, 1>& x, vec<T, 1>& F, mat<T, 1>& J) {
    F[0] = x[0] * x[0] - T(2);
    J(0, 0) = T(2) * x[0];
  };
  const step_status st = newton_solve<1, T>(sqrt2, z, newton_options<T>{});
  REQUIRE(st);
  CHECK(abs_diff(z[0], T(sqrt(T(2)))) <= eps_tol<T>(4));
  CHECK(st.iterations <= 12);  // quadratic: about log2(digits) iterations from 1

  vec<T, 2> w(T(2), T(1) / T(2));
  auto full = [](const vec<T, 2>& x, vec<T, 2>& F, mat<T, 2>& J) { circle_hyperbola<T>(x, F, &J); };
  REQUIRE(newton_solve<2, T>(full, w, newton_options<T>{}));
  const T s6 = sqrt(T(6)), s2 = sqrt(T(2));
  CHECK(abs_diff(w[0], T((s6 + s2) / T(2))) <= eps_tol<T>(8));
  CHECK(abs_diff(w[1], T((s6 - s2) / T(2))) <= eps_tol<T>(8));
}

TEMPLATE_LIST_TEST_CASE("newton_solve_simplified: same root, and a reused factorisation", "[solvers]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  using std::sqrt;
  int jacobians = 0;
  auto residual = [&](const vec<T, 2>& x, vec<T, 2>& F, mat<T, 2>* J) {
    if (J) ++jacobians;
    circle_hyperbola<T>(x, F, J);
  };
  jacobian_cache<T, 2> cache;
  vec<T, 2> w(T(2), T(1) / T(2));
  REQUIRE(newton_solve_simplified<2, T>(residual, w, newton_options<T>{}, T(0), &cache));
  const T s6 = sqrt(T(6)), s2 = sqrt(T(2));
  CHECK(abs_diff(w[0], T((s6 + s2) / T(2))) <= eps_tol<T>(16));
  CHECK(abs_diff(w[1], T((s6 - s2) / T(2))) <= eps_tol<T>(16));
  CHECK(cache.valid);
  // Started sqrt(eps) away from the root, the cached matrix (exact to O(sqrt eps) there)
  // contracts by sqrt(eps) per correction: two corrections and no new Jacobian.
  const int before = jacobians;
  vec<T, 2> near = w;
  near[0] += sqrt(std::numeric_limits<T>::epsilon());
  REQUIRE(newton_solve_simplified<2, T>(residual, near, newton_options<T>{}, T(0), &cache));
  CHECK(jacobians == before);
  CHECK(abs_diff(near[0], w[0]) <= eps_tol<T>(16));
}

TEMPLATE_LIST_TEST_CASE("newton_solve_simplified: stop_on_rate stops when the rate bounds the error left", "[solvers]",
                        geomint::test::integrator_scalar_types) {
  // F(z) = z - 1 with the matrix 1 + g: every correction is the error times 1 / (1 + g), so the
  // error contracts by exactly rho = g / (1 + g) per correction (exact mathematics). From
  // z = 1 + eps^(1/8) with rho about eps^(1/4) the corrections are eps^(1/8 + k/4): without
  // stop_on_rate the solve ends with the correction eps^(9/8) that confirms convergence (the
  // one before, eps^(7/8), is above 64 eps); with it, one correction earlier, where rho times
  // the correction (eps^(9/8)) is below eps. Either way the result is the root 1 to 2 eps.
  using T = TestType;
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  const T g = sqrt(sqrt(eps)), start = T(1) + sqrt(sqrt(sqrt(eps)));
  auto residual = [&](const vec<T, 1>& x, vec<T, 1>& F, mat<T, 1>* J) {
    F[0] = x[0] - T(1);
    if (J) (*J)(0, 0) = T(1) + g;
  };
  std::array<int, 2> iterations{};
  for (const bool stop_on_rate : {false, true}) {
    vec<T, 1> z(start);
    newton_options<T> opt;
    opt.stop_on_rate = stop_on_rate;
    opt.double_jacobian = false;  // the matrix 1 + g exactly, so the rate is exactly rho
    const step_status st = newton_solve_simplified<1, T>(residual, z, opt, T(0));
    REQUIRE(st);
    CHECK(abs_diff(z[0], T(1)) <= eps_tol<T>(2));
    iterations[stop_on_rate ? 1 : 0] = st.iterations;
  }
  CHECK(iterations[1] == iterations[0] - 1);
  // The default: on in multiprecision, off in built-in types.
  CHECK(newton_options<T>{}.stop_on_rate == !std::is_floating_point_v<T>);
}

TEMPLATE_LIST_TEST_CASE("newton_solve_simplified: a matrix factorised in double keeps the scalar's precision",
                        "[solvers]", geomint::test::integrator_scalar_types) {
  // The closed-form root of circle_hyperbola (exact mathematics), reached to T's precision with
  // the Newton matrix rounded to double (the default in multiprecision): the residual in T
  // decides the solution, the double matrix only how fast it is reached.
  using T = TestType;
  using std::sqrt;
  constexpr bool multiprecision = !std::is_floating_point_v<T>;
  CHECK(newton_options<T>{}.double_jacobian == multiprecision);
  auto residual = [](const vec<T, 2>& x, vec<T, 2>& F, mat<T, 2>* J) { circle_hyperbola<T>(x, F, J); };
  jacobian_cache<T, 2> cache;
  vec<T, 2> w(T(2), T(1) / T(2));
  const step_status st = newton_solve_simplified<2, T>(residual, w, newton_options<T>{}, T(0), &cache);
  REQUIRE(st);
  CHECK(cache.in_double == multiprecision);
  const T s6 = sqrt(T(6)), s2 = sqrt(T(2));
  CHECK(abs_diff(w[0], T((s6 + s2) / T(2))) <= eps_tol<T>(16));
  CHECK(abs_diff(w[1], T((s6 - s2) / T(2))) <= eps_tol<T>(16));
  if constexpr (multiprecision) {
    // Fallbacks to T, each still reaching the exact root: (a) a matrix beyond double's range
    // (10^400, F = 10^400 (z - 3)); (b) a matrix singular in double but not in T
    // ([[1, 1], [1, 1 + 10^-30]]); (c) a residual beyond double's range at the start
    // (z = 10^400, F = z - 3, J = 1): the correction cannot be formed in double.
    const T big = T(pow(T(10), 400)), tiny = T(pow(T(10), -30));
    {
      vec<T, 1> z(T(0));
      jacobian_cache<T, 1> c;
      auto f = [&](const vec<T, 1>& x, vec<T, 1>& F, mat<T, 1>* J) {
        F[0] = big * (x[0] - T(3));
        if (J) (*J)(0, 0) = big;
      };
      REQUIRE(newton_solve_simplified<1, T>(f, z, newton_options<T>{}, T(0), &c));
      CHECK_FALSE(c.in_double);
      CHECK(abs_diff(z[0], T(3)) <= eps_tol<T>(8));
    }
    {
      // Root of x + y = 2, x + (1 + d) y = 2 + d: x = y = 1.
      vec<T, 2> z(T(0), T(0));
      jacobian_cache<T, 2> c;
      auto f = [&](const vec<T, 2>& x, vec<T, 2>& F, mat<T, 2>* J) {
        F[0] = x[0] + x[1] - T(2);
        F[1] = x[0] + (T(1) + tiny) * x[1] - (T(2) + tiny);
        if (J) *J << T(1), T(1), T(1), T(1) + tiny;
      };
      REQUIRE(newton_solve_simplified<2, T>(f, z, newton_options<T>{}, T(0), &c));
      CHECK_FALSE(c.in_double);
      // The system's condition is about 4 / d = 4 10^30: the root to 16 / d eps.
      const T bound = T(16) * std::numeric_limits<T>::epsilon() / tiny;
      CHECK(abs_diff(z[0], T(1)) <= bound);
      CHECK(abs_diff(z[1], T(1)) <= bound);
    }
    {
      vec<T, 1> z(big);
      jacobian_cache<T, 1> c;
      auto f = [&](const vec<T, 1>& x, vec<T, 1>& F, mat<T, 1>* J) {
        F[0] = x[0] - T(3);
        if (J) (*J)(0, 0) = T(1);
      };
      const step_status s3 = newton_solve_simplified<1, T>(f, z, newton_options<T>{}, T(0), &c);
      REQUIRE(s3);
      CHECK_FALSE(c.in_double);
      CHECK(abs_diff(z[0], T(3)) <= eps_tol<T>(8) * big);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("Newton failures: singular Jacobian, no convergence, non-finite residual", "[solvers]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  // F = x^2 at x = 0: J = 0, singular.
  {
    vec<T, 1> z(T(0));
    auto f = [](const vec<T, 1>& x, vec<T, 1>& F, mat<T, 1>& J) {
      F[0] = x[0] * x[0] + T(1);
      J(0, 0) = T(2) * x[0];
    };
    CHECK(newton_solve<1, T>(f, z, newton_options<T>{}).reason == step_failure::singular_jacobian);
  }
  // F = x^2 + 1 has no real root: from x = 1/2 the iterates wander, the budget runs out.
  {
    vec<T, 1> z(T(1) / T(2));
    auto f = [](const vec<T, 1>& x, vec<T, 1>& F, mat<T, 1>& J) {
      F[0] = x[0] * x[0] + T(1);
      J(0, 0) = T(2) * x[0];
    };
    newton_options<T> opt;
    opt.max_iterations = 5;
    const step_status st = newton_solve<1, T>(f, z, opt);
    CHECK(st.reason == step_failure::no_convergence);
    CHECK(st.iterations == 5);
  }
  // A residual that is NaN at the start.
  {
    vec<T, 1> z(T(-1));
    auto f = [](const vec<T, 1>& x, vec<T, 1>& F, mat<T, 2 - 1>* J) {
      using std::sqrt;
      F[0] = sqrt(x[0]);
      if (J) (*J)(0, 0) = T(1);
    };
    CHECK(newton_solve_simplified<1, T>(f, z, newton_options<T>{}, T(0)).reason ==
          step_failure::non_finite_iterate);
  }
}
