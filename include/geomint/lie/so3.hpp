#pragma once
/// SO(3) and so(3) over any real scalar: hat/vee, the coefficient functions of Rodrigues'
/// formula (accurate at every angle, small angles included), exp, log, Cayley map and inverse.
///
/// Every function is a template on the scalar `T` (double, long double, Boost.Multiprecision
/// `cpp_bin_float_50/100`, `mpfr_float_N` through `<boost/multiprecision/eigen.hpp>`); no
/// constant passes through a double literal. Small angles use power series summed until the
/// next term is below `std::numeric_limits<T>::epsilon()` relative to the sum, so the result is
/// accurate to the working precision at 16 digits and at 50 alike; there is no hard-coded
/// "small angle" cut-off such as `1e-8`.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geomint::lie {

template <class T> using vec3 = Eigen::Matrix<T, 3, 1>;
template <class T> using mat3 = Eigen::Matrix<T, 3, 3>;

/// w^ : the skew matrix with w^ y = w x y.
template <class T>
mat3<T> hat3(const vec3<T>& w) {
  mat3<T> W;
  W << T(0), -w(2), w(1),
       w(2), T(0), -w(0),
       -w(1), w(0), T(0);
  return W;
}

/// Inverse of hat3 on skew matrices (reads the strictly lower/upper entries antisymmetrically,
/// so vee3(M) = vee of the skew part of M).
template <class T>
vec3<T> vee3(const mat3<T>& W) {
  return vec3<T>((W(2, 1) - W(1, 2)) / T(2), (W(0, 2) - W(2, 0)) / T(2), (W(1, 0) - W(0, 1)) / T(2));
}

namespace detail {

/// Sums a power series in t = theta^2, sum_k term_k, where term_0 is given and
/// term_{k+1} = term_k * ratio(k, t); stops when the term is below epsilon relative to the sum.
/// Only used for t < 1, where the terms decrease monotonically and the truncation error is
/// below the first omitted term.
template <class T, class Ratio>
T power_series(T term, const T& t, Ratio ratio) {
  using std::abs;
  const T eps = std::numeric_limits<T>::epsilon();
  T sum = term;
  for (int k = 0; k < 1000; ++k) {
    term *= ratio(k, t);
    sum += term;
    if (abs(term) <= eps * abs(sum)) break;
  }
  return sum;
}

}  // namespace detail

/// Coefficients of Rodrigues' formulae as functions of t = theta^2 (theta = |w|):
///   A = sin(theta)/theta,  B = (1 - cos theta)/theta^2,  C = (theta - sin theta)/theta^3,
///   E = (2B - A)/theta^2  (used by the SE(3) logarithm).
/// For t < 1 they are power series (no cancellation); otherwise the closed forms, written so
/// that B has no cancellation at any angle.
template <class T>
struct rodrigues_coefficients {
  T A, B, C, E;

  static rodrigues_coefficients from_theta_squared(const T& t) {
    using std::sin;
    using std::sqrt;
    rodrigues_coefficients r;
    if (t < T(1)) {
      // A = sum (-1)^k t^k / (2k+1)!
      r.A = detail::power_series(T(1), t, [](int k, const T& x) -> T { return -x / T((2 * k + 2) * (2 * k + 3)); });
      // B = sum (-1)^k t^k / (2k+2)!
      r.B = detail::power_series(T(1) / T(2), t, [](int k, const T& x) -> T { return -x / T((2 * k + 3) * (2 * k + 4)); });
      // C = sum (-1)^k t^k / (2k+3)!
      r.C = detail::power_series(T(1) / T(6), t, [](int k, const T& x) -> T { return -x / T((2 * k + 4) * (2 * k + 5)); });
      // E = sum_m (-1)^m 2(m+1) t^m / (2m+4)!
      {
        using std::abs;
        const T eps = std::numeric_limits<T>::epsilon();
        T f = T(1) / T(24);  // (-1)^m t^m / (2m+4)!
        T sum = T(2) * f;
        for (int m = 0; m < 1000; ++m) {
          f *= -t / T((2 * m + 5) * (2 * m + 6));
          const T term = T(2 * (m + 2)) * f;
          sum += term;
          if (abs(term) <= eps * abs(sum)) break;
        }
        r.E = sum;
      }
    } else {
      const T th = sqrt(t);
      const T s = sin(th);
      const T half = sin(th / T(2));
      r.A = s / th;
      r.B = T(2) * half * half / t;
      r.C = (th - s) / (t * th);
      r.E = (T(2) * r.B - r.A) / t;
    }
    return r;
  }
};

/// exp on so(3) (Rodrigues): I + A w^ + B w^2.
template <class T>
mat3<T> so3_exp(const vec3<T>& w) {
  const auto c = rodrigues_coefficients<T>::from_theta_squared(w.squaredNorm());
  const mat3<T> W = hat3(w);
  return mat3<T>::Identity() + c.A * W + c.B * (W * W);
}

/// The rotation angle theta in [0, pi] of R, from atan2 of the skew and symmetric parts
/// (accurate at every angle, unlike acos((tr R - 1)/2) near 0 and pi).
template <class T>
T so3_angle(const mat3<T>& R) {
  using std::atan2;
  const T s = vee3<T>(R).norm();  // |sin theta|
  const T c = (R.trace() - T(1)) / T(2);
  return atan2(s, c);
}

/// log on SO(3): the w with |w| = theta in [0, pi] and exp(w^) = R. Near theta = pi (where
/// sin theta vanishes) the axis is read from the symmetric part; at exactly pi either sign is
/// a valid logarithm.
template <class T>
vec3<T> so3_log(const mat3<T>& R) {
  using std::sqrt;
  const vec3<T> a = vee3<T>(R);  // = sin(theta) n
  const T theta = so3_angle(R);
  const T c = (R.trace() - T(1)) / T(2);
  const auto k = rodrigues_coefficients<T>::from_theta_squared(theta * theta);
  if (c >= T(0)) return a / k.A;  // theta <= pi/2: A >= 2/pi, no loss
  // theta > pi/2: w w^T = (sym(R) - I)/B + theta^2 I, B >= 4/pi^2 here.
  const mat3<T> S = (R + R.transpose()) / T(2);
  const mat3<T> wwT = (S - mat3<T>::Identity()) / k.B + theta * theta * mat3<T>::Identity();
  int i = 0;
  for (int j = 1; j < 3; ++j)
    if (wwT(j, j) > wwT(i, i)) i = j;
  vec3<T> w = wwT.col(i) / sqrt(wwT(i, i));
  if (w.dot(a) < T(0)) w = -w;
  return w;
}

/// Cayley map on so(3): (I - w^/2)^{-1} (I + w^/2) = I + 4/(4 + |w|^2) (w^ + w^2/2).
template <class T>
mat3<T> so3_cay(const vec3<T>& w) {
  // w^2 = w w^T - |w|^2 I.
  const T t = w.squaredNorm();
  const T f = T(4) / (T(4) + t);
  const T fh = f / T(2);
  mat3<T> R = (fh * w) * w.transpose();
  const T d = T(1) - fh * t;
  R(0, 0) += d;
  R(1, 1) += d;
  R(2, 2) += d;
  R(0, 1) -= f * w(2);
  R(1, 0) += f * w(2);
  R(0, 2) += f * w(1);
  R(2, 0) -= f * w(1);
  R(1, 2) -= f * w(0);
  R(2, 1) += f * w(0);
  return R;
}

/// (I - w^/2)^{-1} y = y + (2 w x y + w x (w x y)) / (4 + |w|^2), in closed form.
template <class T>
vec3<T> so3_cay_left_inverse_apply(const vec3<T>& w, const vec3<T>& y) {
  const vec3<T> wy = w.cross(y);
  return y + (T(2) * wy + w.cross(wy)) / (T(4) + w.squaredNorm());
}

/// Inverse Cayley map on SO(3): w = 2/(1 + tr R) vee(R - R^T); needs 1 + tr R > 0 (rotation
/// angle below pi), otherwise std::domain_error.
template <class T>
vec3<T> so3_cay_inv(const mat3<T>& R) {
  const T d = T(1) + R.trace();
  if (!(d > T(0)))
    throw std::domain_error("geomint::lie::so3_cay_inv: rotation angle pi (1 + tr R <= 0) is outside the Cayley chart");
  return (T(4) / d) * vee3<T>(R);  // 2/(1+trR) * vee(R - R^T) = 2/(1+trR) * 2 vee3(R)
}

}  // namespace geomint::lie
