// Axioms of se(3)/SE(3) with the conventions of docs/design.md, "Beam conventions", for double and
// cpp_bin_float_50. Every expected value is exact mathematics (an identity that holds for all
// arguments) or a second, independent computation (matrix commutator, matrix inverse via LU,
// Taylor series of the 4x4 matrix exponential); tolerances are multiples of the scalar's
// epsilon.
#include <random>
#include <tuple>

#include <Eigen/LU>
#include <boost/math/constants/constants.hpp>

#include "catch.hpp"
#include "geomint/lie/se3.hpp"
#include "scalar_types.hpp"

namespace gl = geomint::lie;
using geomint::test::eps_tol;
using std::abs;
using Types = geomint::test::integrator_scalar_types;

namespace {

/// Deterministic test vectors with entries k/64, k in [-128, 128]: exact in every scalar type.
template <class T>
struct sampler {
  std::mt19937 gen{20250601u};
  std::uniform_int_distribution<int> dist{-128, 128};
  T scalar() { return T(dist(gen)) / T(64); }
  gl::vec3<T> v3() { return gl::vec3<T>(scalar(), scalar(), scalar()); }
  gl::vec6<T> v6() {
    gl::vec6<T> x;
    for (int i = 0; i < 6; ++i) x(i) = scalar();
    return x;
  }
};

/// Taylor series of the matrix exponential, summed until the term is below epsilon
/// (independent of the closed forms; fine for |X| <= 4, loses at most ~e^4 ulps).
template <class T>
gl::mat4<T> taylor_expm(const gl::mat4<T>& X) {
  gl::mat4<T> sum = gl::mat4<T>::Identity(), term = gl::mat4<T>::Identity();
  for (int k = 1; k < 400; ++k) {
    term = (term * X) / T(k);
    sum += term;
    if (term.template lpNorm<Eigen::Infinity>() <= std::numeric_limits<T>::epsilon() / T(16)) break;
  }
  return sum;
}

template <class Derived>
typename Derived::Scalar max_abs(const Eigen::MatrixBase<Derived>& m) {
  return m.template lpNorm<Eigen::Infinity>();
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("hat/vee, ad and the bracket agree with the matrix commutator", "[lie]", Types) {
  using T = TestType;
  sampler<T> s;
  for (int trial = 0; trial < 20; ++trial) {
    const gl::vec6<T> xi = s.v6(), eta = s.v6();
    REQUIRE(gl::vee<T>(gl::hat<T>(xi)) == xi);  // exact: hat/vee only copy entries
    // Second method: [xi, eta] = vee(xi^ eta^ - eta^ xi^).
    const gl::mat4<T> X = gl::hat<T>(xi), Y = gl::hat<T>(eta);
    const gl::vec6<T> commutator = gl::vee<T>(gl::mat4<T>(X * Y - Y * X));
    CHECK(max_abs(gl::bracket<T>(xi, eta) - commutator) <= eps_tol<T>(16));
    CHECK(max_abs(gl::vec6<T>(gl::ad<T>(xi) * eta) - gl::bracket<T>(xi, eta)) <= eps_tol<T>(16));
    // Antisymmetry (exact math).
    CHECK(max_abs(gl::vec6<T>(gl::bracket<T>(xi, eta) + gl::bracket<T>(eta, xi))) <= eps_tol<T>(4));
  }
}

TEMPLATE_LIST_TEST_CASE("Jacobi identity", "[lie]", Types) {
  using T = TestType;
  sampler<T> s;
  for (int trial = 0; trial < 20; ++trial) {
    const gl::vec6<T> a = s.v6(), b = s.v6(), c = s.v6();
    const gl::vec6<T> j = gl::bracket<T>(a, gl::bracket<T>(b, c)) + gl::bracket<T>(b, gl::bracket<T>(c, a)) +
                          gl::bracket<T>(c, gl::bracket<T>(a, b));
    // Entries are at most ~2^4 in size; each double bracket rounds a few times.
    CHECK(max_abs(j) <= eps_tol<T>(256));
  }
}

TEMPLATE_LIST_TEST_CASE("dual bracket: <ad_xi^T mu, eta> = <mu, ad_xi eta>", "[lie]", Types) {
  using T = TestType;
  sampler<T> s;
  for (int trial = 0; trial < 20; ++trial) {
    const gl::vec6<T> xi = s.v6(), eta = s.v6(), mu = s.v6();
    const T lhs = gl::dual_bracket<T>(xi, mu).dot(eta);
    const T rhs = mu.dot(gl::bracket<T>(xi, eta));
    CHECK(abs(lhs - rhs) <= eps_tol<T>(256));
    // Second method: the transpose of the ad matrix.
    CHECK(max_abs(gl::vec6<T>(gl::ad<T>(xi).transpose() * mu) - gl::dual_bracket<T>(xi, mu)) <= eps_tol<T>(16));
  }
}

TEMPLATE_LIST_TEST_CASE("Ad, Ad^* and the coadjoint action", "[lie]", Types) {
  using T = TestType;
  sampler<T> s;
  for (int trial = 0; trial < 20; ++trial) {
    const gl::SE3<T> g = gl::exp<T>(s.v6()), h = gl::exp<T>(s.v6());
    const gl::vec6<T> xi = s.v6(), eta = s.v6(), mu = s.v6();
    // Second method: Ad_g xi = vee(g xi^ g^{-1}) with 4x4 matrices.
    const gl::vec6<T> conj = gl::vee<T>(gl::mat4<T>(g.matrix() * gl::hat<T>(xi) * g.inverse().matrix()));
    CHECK(max_abs(gl::Ad<T>(g, xi) - conj) <= eps_tol<T>(512));
    CHECK(max_abs(gl::vec6<T>(gl::Ad<T>(g) * xi) - gl::Ad<T>(g, xi)) <= eps_tol<T>(64));
    // Ad of a bracket: Ad_g [xi, eta] = [Ad_g xi, Ad_g eta]  (Ad_g is a Lie algebra morphism).
    CHECK(max_abs(gl::vec6<T>(gl::Ad<T>(g, gl::bracket<T>(xi, eta)) - gl::bracket<T>(gl::Ad<T>(g, xi), gl::Ad<T>(g, eta)))) <=
          eps_tol<T>(4096));
    // Homomorphism: Ad_{gh} = Ad_g Ad_h.
    CHECK(max_abs(gl::mat6<T>(gl::Ad<T>(g * h) - gl::Ad<T>(g) * gl::Ad<T>(h))) <= eps_tol<T>(1024));
    // Pairings: <Ad^*_g mu, xi> = <mu, Ad_g xi>,  <coAd(g, mu), Ad_g xi> = <mu, xi>.
    CHECK(abs(gl::Ad_dual<T>(g, mu).dot(xi) - mu.dot(gl::Ad<T>(g, xi))) <= eps_tol<T>(4096));
    CHECK(abs(gl::coAd<T>(g, mu).dot(gl::Ad<T>(g, xi)) - mu.dot(xi)) <= eps_tol<T>(4096));
    // coAd is a left action: coAd(gh, mu) = coAd(g, coAd(h, mu)).
    CHECK(max_abs(gl::vec6<T>(gl::coAd<T>(g * h, mu) - gl::coAd<T>(g, gl::coAd<T>(h, mu)))) <= eps_tol<T>(4096));
  }
}

TEMPLATE_LIST_TEST_CASE("Cayley map: group membership, closed form, inverse, cay(-xi) = cay(xi)^-1", "[lie]", Types) {
  using T = TestType;
  sampler<T> s;
  for (int trial = 0; trial < 30; ++trial) {
    const gl::vec6<T> xi = s.v6();
    const gl::SE3<T> g = gl::cay<T>(xi);
    // Membership: R^T R = I, det R = 1 (bottom row of the 4x4 form is (0,0,0,1) by construction).
    CHECK(max_abs(gl::mat3<T>(g.R.transpose() * g.R - gl::mat3<T>::Identity())) <= eps_tol<T>(32));
    CHECK(abs(g.R.determinant() - T(1)) <= eps_tol<T>(32));
    // Second method: (I - X/2)^{-1} (I + X/2) by LU with partial pivoting.
    const gl::mat4<T> X = gl::hat<T>(xi), I4 = gl::mat4<T>::Identity();
    const gl::mat4<T> by_lu = (I4 - X / T(2)).partialPivLu().solve(gl::mat4<T>(I4 + X / T(2)));
    CHECK(max_abs(gl::mat4<T>(g.matrix() - by_lu)) <= eps_tol<T>(256));
    // cay(-xi) = cay(xi)^{-1} (exact math: (I+X/2) and (I-X/2) commute).
    const gl::SE3<T> gm = gl::cay<T>(gl::vec6<T>(-xi));
    CHECK(max_abs(gl::mat4<T>((gm * g).matrix() - I4)) <= eps_tol<T>(128));
    // Closed-form inverse.
    CHECK(max_abs(gl::vec6<T>(gl::cay_inv<T>(g) - xi)) <= eps_tol<T>(512));
  }
  // Rotation by pi is outside the Cayley chart: a clear error, not inf/NaN.
  gl::SE3<T> flip;
  flip.R = gl::so3_exp<T>(gl::vec3<T>(boost::math::constants::pi<T>(), T(0), T(0)));
  flip.R(1, 2) = flip.R(2, 1) = T(0);  // make exactly diag(1, -1, -1)
  CHECK_THROWS_AS(gl::cay_inv<T>(flip), std::domain_error);
}

TEMPLATE_LIST_TEST_CASE("exp agrees with the Taylor series of the 4x4 matrix exponential", "[lie]", Types) {
  using T = TestType;
  sampler<T> s;
  for (int trial = 0; trial < 20; ++trial) {
    gl::vec6<T> xi = s.v6();
    xi /= T(2);  // |X| <= ~3.5: the Taylor sum (the second method) stays accurate
    const gl::SE3<T> g = gl::exp<T>(xi);
    CHECK(max_abs(gl::mat4<T>(g.matrix() - taylor_expm<T>(gl::hat<T>(xi)))) <= eps_tol<T>(512));
    CHECK(max_abs(gl::mat3<T>(g.R.transpose() * g.R - gl::mat3<T>::Identity())) <= eps_tol<T>(32));
    CHECK(abs(g.R.determinant() - T(1)) <= eps_tol<T>(32));
  }
}

TEMPLATE_LIST_TEST_CASE("exp/log round trip, small angles and angles near pi included", "[lie]", Types) {
  using T = TestType;
  using std::pow;
  const T eps = std::numeric_limits<T>::epsilon();
  const T pi = boost::math::constants::pi<T>();
  sampler<T> s;
  // Angles from 1e-(digits+5) (where theta^2 underflows the first series correction) up to pi - 1e-6.
  const int digits = std::numeric_limits<T>::digits10;
  std::vector<T> angles;
  for (int k = digits + 5; k >= 1; k -= 3) angles.push_back(pow(T(10), -k));
  for (int num : {500, 999, 1000, 1001, 2000, 3000}) angles.push_back(T(num) / T(1000));
  angles.push_back(pi - pow(T(10), -6));
  for (const T& theta : angles) {
    for (int trial = 0; trial < 3; ++trial) {
      gl::vec3<T> axis = s.v3();
      if (axis.norm() == T(0)) axis = gl::vec3<T>(T(1), T(0), T(0));
      axis.normalize();
      const gl::vec6<T> xi = gl::make_twist<T>(gl::vec3<T>(theta * axis), s.v3());
      const gl::SE3<T> g = gl::exp<T>(xi);
      const gl::vec6<T> back = gl::log<T>(g);
      // Relative precision of the rotation vector (its size is theta) and of v.
      CHECK(max_abs(gl::vec3<T>(back.template head<3>() - xi.template head<3>())) <= T(64) * eps * theta);
      CHECK(max_abs(gl::vec3<T>(back.template tail<3>() - xi.template tail<3>())) <= T(256) * eps);
      // And exp(log(g)) = g.
      CHECK(max_abs(gl::mat4<T>(gl::exp<T>(back).matrix() - g.matrix())) <= eps_tol<T>(256));
    }
  }
  // exp(0) = identity and log(identity) = 0, exactly.
  CHECK(gl::exp<T>(gl::vec6<T>::Zero()).matrix() == gl::mat4<T>::Identity());
  CHECK(gl::log<T>(gl::SE3<T>::identity()) == gl::vec6<T>::Zero());
}

TEMPLATE_LIST_TEST_CASE("Rodrigues coefficients: series and closed forms meet at theta = 1", "[lie]", Types) {
  using T = TestType;
  // Just below the switch the series is used, just above the closed form; both approximate
  // the same analytic function, so they agree to a few ulps plus the change over the gap.
  const T below = T(1) - std::numeric_limits<T>::epsilon();
  const auto a = gl::rodrigues_coefficients<T>::from_theta_squared(below);
  const auto b = gl::rodrigues_coefficients<T>::from_theta_squared(T(1));
  CHECK(abs(a.A - b.A) <= eps_tol<T>(8));
  CHECK(abs(a.B - b.B) <= eps_tol<T>(8));
  CHECK(abs(a.C - b.C) <= eps_tol<T>(16));
  CHECK(abs(a.E - b.E) <= eps_tol<T>(64));
  // Exact values at t = 0: A = 1, B = 1/2, C = 1/6, E = 1/12.
  const auto z = gl::rodrigues_coefficients<T>::from_theta_squared(T(0));
  CHECK(z.A == T(1));
  CHECK(z.B == T(1) / T(2));
  CHECK(z.C == T(1) / T(6));
  CHECK(z.E == T(1) / T(12));
}
