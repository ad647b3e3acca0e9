#pragma once
/// Closed-form solutions of the pendulum and of the Kepler problem in any scalar type, used as
/// references by the work-precision tool (independent of every integrator).
///
/// - Pendulum qddot = -sin q from (theta0, 0), |theta0| < pi: with k = sin(theta0/2),
///   k' = cos(theta0/2), sin(theta/2) = k cd(t, k) and thetadot = -2 k k' sd(t, k) (Jacobi
///   elliptic functions, Boost.Math).
/// - Kepler qddot = -q/|q|^3 with semi-major axis 1 (mean motion 1), eccentricity e, from the
///   pericentre at t = 0: E - e sin E = t (Kepler's equation, Newton), q = (cos E - e,
///   b sin E), qdot = (-sin E, b cos E) / (1 - e cos E), b = sqrt(1 - e^2).

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

namespace geomint::analysis {

template <class T, int n>
struct closed_form_state {
  std::array<T, n> q, p;
};

/// The pendulum released from rest at theta0 (|theta0| < pi), at time t.
template <class T>
closed_form_state<T, 1> pendulum_from_rest(const T& theta0, const T& t) {
  using std::asin;
  using std::cos;
  using std::sin;
  using std::abs;
  if (!(abs(theta0) < boost::math::constants::pi<T>()))
    throw std::invalid_argument("geomint::pendulum_from_rest: |theta0| must be < pi");
  const T k = sin(theta0 / T(2)), kp = cos(theta0 / T(2));
  const T cd = boost::math::jacobi_cd(k, t), sd = boost::math::jacobi_sd(k, t);
  return {{T(T(2) * asin(T(k * cd)))}, {T(T(-2) * k * kp * sd)}};
}

/// The Kepler orbit with a = 1, eccentricity 0 <= e < 1, at pericentre (1 - e, 0) at t = 0.
template <class T>
closed_form_state<T, 2> kepler_from_pericentre(const T& e, const T& t) {
  using std::abs;
  using std::cos;
  using std::floor;
  using std::sin;
  using std::sqrt;
  if (!(e >= T(0) && e < T(1))) throw std::invalid_argument("geomint::kepler_from_pericentre: e must be in [0, 1)");
  const T b = sqrt(T(1) - e * e);
  const T two_pi = boost::math::constants::two_pi<T>();
  const T M = t - two_pi * floor(t / two_pi);
  T E = M + e * sin(M);
  for (int it = 0; it < 200; ++it) {
    const T dE = (E - e * sin(E) - M) / (T(1) - e * cos(E));
    E -= dE;
    if (abs(dE) <= T(4) * std::numeric_limits<T>::epsilon()) break;
  }
  const T Edot = T(1) / (T(1) - e * cos(E));
  return {{T(cos(E) - e), T(b * sin(E))}, {T(-sin(E) * Edot), T(b * cos(E) * Edot)}};
}

}  // namespace geomint::analysis
