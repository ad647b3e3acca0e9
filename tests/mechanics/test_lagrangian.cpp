/// The derivatives of a system (mechanics/lagrangian.hpp): a natural system's own
/// potential_gradient against automatic differentiation of its potential, and its use by the
/// integrators.
#include <cmath>

#include "catch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using geomint::test::eps_tol;

namespace {

/// The pendulum without its potential_gradient: forces come from AD on the same potential.
struct pendulum_by_ad : natural<pendulum_by_ad, 1> {
  template <class S>
  static S potential(const vec<S, 1>& q) { return systems::pendulum::potential<S>(q); }
  template <class T>
  static mat<T, 1> mass_matrix() { return mat<T, 1>::Identity(); }
};

/// Henon-Heiles with the gradient of docs/guide/your_own_system.md.
struct henon_heiles_with_gradient : natural<henon_heiles_with_gradient, 2> {
  template <class S>
  static S potential(const vec<S, 2>& q) { return zoo::henon_heiles::potential<S>(q); }
  template <class S>
  static vec<S, 2> potential_gradient(const vec<S, 2>& q) {
    return vec<S, 2>(S(q[0] + 2 * q[0] * q[1]), S(q[1] + q[0] * q[0] - q[1] * q[1]));
  }
  template <class S>
  static mat<S, 2> mass_matrix() { return mat<S, 2>::Identity(); }
};

/// V = q^2 / 2 with a wrong gradient (2q): the defect must expose it, and lagrangian_q must show
/// that the integrators take the supplied gradient, not AD's.
struct wrong_gradient : natural<wrong_gradient, 1> {
  template <class S>
  static S potential(const vec<S, 1>& q) { return q[0] * q[0] / S(2); }
  template <class S>
  static vec<S, 1> potential_gradient(const vec<S, 1>& q) { return vec<S, 1>(S(2 * q[0])); }
  template <class T>
  static mat<T, 1> mass_matrix() { return mat<T, 1>::Identity(); }
};

}  // namespace

TEMPLATE_LIST_TEST_CASE("lagrangian: supplied potential gradients equal AD on the potential", "[mechanics][lagrangian]",
                        geomint::test::scalar_types) {
  // Second method: forward AD of the potential (dual numbers, whose sin/cos of a multiprecision
  // scalar is geomint's own series, ad/dual.hpp). The two differ by their roundings only.
  using T = TestType;
  for (int k = -6; k <= 6; ++k) {
    const vec<T, 1> q(T(k) / T(2));
    INFO("pendulum, q = " << q[0]);
    CHECK(potential_gradient_defect<systems::pendulum, T>(q) <= T(8));
  }
  for (int k = 1; k <= 5; ++k) {
    const vec<T, 2> q(T(k) / T(3), T(1) - T(k) / T(2));
    INFO("kepler, q = " << q.transpose());
    CHECK(potential_gradient_defect<systems::kepler, T>(q) <= T(8));
  }
  for (int k = -2; k <= 2; ++k) {
    const vec<T, 2> q(T(k) / T(5), T(1) / T(3) - T(k) / T(7));
    INFO("henon-heiles, q = " << q.transpose());
    CHECK(potential_gradient_defect<henon_heiles_with_gradient, T>(q) <= T(8));
  }
  // The outer solar system's gradients are of size 1e-8 and smaller (G m_i m_j / r^2 in AU,
  // days and solar masses), so each body's is compared relative to its own size: at the
  // initial data and with the coordinates moved by up to 2k/7 AU.
  vec<T, 18> qs, vs;
  zoo::outer_solar::initial_data<T>(qs, vs);
  for (int k = 0; k <= 2; ++k) {
    vec<T, 18> q = qs;
    for (int i = 0; i < 18; ++i) q[i] += T(k * (i % 5 - 2)) / T(7);
    const vec<T, 18> ad = -lagrangian_derivatives<zoo::outer_solar, T>::ad_potential_force(q);
    const vec<T, 18> supplied = zoo::outer_solar::potential_gradient<T>(q);
    for (int b = 0; b < zoo::outer_solar::bodies; ++b) {  // per body: Pluto's force is 1e-7 of Jupiter's
      INFO("outer solar, shift " << k << ", body " << b);
      const T size = ad.template segment<3>(3 * b).cwiseAbs().maxCoeff();
      CHECK(size > T(0));
      CHECK((supplied - ad).template segment<3>(3 * b).cwiseAbs().maxCoeff() <= T(64) * std::numeric_limits<T>::epsilon() * size);
    }
  }
  // A wrong gradient is caught: off by |q| = 1/2, i.e. by 1/(2 eps) units.
  CHECK(potential_gradient_defect<wrong_gradient, T>(vec<T, 1>(T(1) / T(2))) >= T(1) / (T(4) * std::numeric_limits<T>::epsilon()));
}

TEST_CASE("lagrangian: the Hessian from a supplied gradient equals two nested levels of AD on V",
          "[mechanics][lagrangian]") {
  // Second method: d^2 V by two nested levels of dual numbers on the potential (written out
  // here; the library takes one level through potential_gradient from 4 degrees of freedom
  // on). Per pair of bodies (3 x 3 blocks), relative to the block's size: the couplings span
  // seven orders of magnitude.
  using S = zoo::outer_solar;
  using D1 = dual<double, 18>;
  using D2 = dual<D1, 18>;
  static_assert(lagrangian_derivatives<S, double>::hessian_from_gradient);
  vec<double, 18> q, v;
  S::initial_data<double>(q, v);
  vec<D2, 18> qd;
  for (int i = 0; i < 18; ++i) qd[i] = D2::variable(D1::variable(q[i], i), i);
  const D2 pot = S::potential<D2>(qd);
  const auto h = lagrangian_derivatives<S, double>::hessian(S{}, q, v);
  for (int a = 0; a < S::bodies; ++a)
    for (int b = 0; b < S::bodies; ++b) {
      double size = 0, diff = 0;
      for (int i = 3 * a; i < 3 * a + 3; ++i)
        for (int j = 3 * b; j < 3 * b + 3; ++j) {
          const double nested = -pot.d[std::size_t(i)].d[std::size_t(j)];
          size = std::max(size, std::abs(nested));
          diff = std::max(diff, std::abs(h.Lqq(i, j) - nested));
        }
      INFO("bodies " << a << ", " << b);
      CHECK(size > 0);
      CHECK(diff <= 64 * std::numeric_limits<double>::epsilon() * size);
    }
  CHECK(h.Lvv == S::mass_matrix<double>());
}

TEMPLATE_LIST_TEST_CASE("lagrangian: L_q takes the system's own gradient when it supplies one", "[mechanics][lagrangian]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  const vec<T, 1> q(T(3) / T(4)), v(T(1));
  // Exact mathematics: the supplied 2q, not AD's q, so -3/2 exactly.
  CHECK(lagrangian_derivatives<wrong_gradient, T>::lagrangian_q(wrong_gradient{}, q, v)[0] == T(-3) / T(2));
  // Without the hook, AD on V: -sin(3/4), within the series' rounding of the library's sine.
  using std::sin;
  CHECK(geomint::test::abs_diff(lagrangian_derivatives<pendulum_by_ad, T>::lagrangian_q(pendulum_by_ad{}, q, v)[0],
                                T(-sin(q[0]))) <= eps_tol<T>(4));
}

TEMPLATE_LIST_TEST_CASE("lagrangian: the fixed-point and Newton forms follow the same path with and without the hook",
                        "[mechanics][lagrangian]", geomint::test::integrator_scalar_types) {
  // Second method: the same scheme on the same potential with forces by AD. Each force differs
  // by a few eps, so 20 steps of a stable orbit (theta0 = 1, tau = 1/4) differ by a few eps
  // per step at most (bound: 16 eps per step).
  using T = TestType;
  const T tau = T(1) / T(4);
  const int steps = 20;
  auto compare = [&]<class Scheme>() {
    using std::abs;
    integrator<Scheme, systems::pendulum, T> A(systems::pendulum{}, tau);
    integrator<Scheme, pendulum_by_ad, T> B(pendulum_by_ad{}, tau);
    auto a = A.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    auto b = B.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    A.advance(a, steps);
    B.advance(b, steps);
    INFO(Scheme::name() << ": |q_a - q_b| = " << (a.q - b.q).norm() << ", |p_a - p_b| = " << (a.p - b.p).norm());
    CHECK((a.q - b.q).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(16 * steps));
    CHECK((a.p - b.p).template lpNorm<Eigen::Infinity>() <= eps_tol<T>(16 * steps));
    // And they did move: the pendulum swings through about a third of its period.
    CHECK(abs(a.q[0] - T(1)) > T(1) / T(10));
  };
  compare.template operator()<lpf_fixed_point<8>>();
  compare.template operator()<lpf<8, gauss_interior, lagrange, newton_solver>>();
}
