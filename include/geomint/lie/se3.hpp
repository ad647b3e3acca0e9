#pragma once
/// se(3) and SE(3) over any real scalar, with the conventions of docs/design.md, "Beam conventions":
///
///   xi = (omega, v) in R^6,  xi^ = [[omega^, v], [0, 0]] in R^{4x4};
///   [xi, eta] = ad_xi eta = (w x w', w x v' - w' x v)           (= vee([xi^, eta^]));
///   [xi, mu]^* = ad_xi^T mu = (pi x w + p x v, p x w)           for mu = (pi, p);
///   e2 = (0,0,0, 0,1,0)  (the beam axis E2);
///   cay(xi) = (I - xi^/2)^{-1} (I + xi^/2).
///
/// A group element g = (R, x) acts on points by y -> R y + x (4x4 matrix [[R, x], [0, 1]]).
/// Ad_g xi = (R w, R v + x x R w); Ad_dual(g, mu) = Ad_g^T mu (Marsden's Ad^*_g);
/// coAd(g, mu) = Ad_{g^{-1}}^T mu (the coadjoint action, a left action): for a body with body
/// momentum mu at configuration g it is the spatial momentum (R pi + x x R p, R p).
///
/// exp and log are accurate to the working precision at every angle (small angles by power
/// series, see so3.hpp); cay and its inverse are closed forms.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geomint/lie/so3.hpp"

namespace geomint::lie {

template <class T> using vec6 = Eigen::Matrix<T, 6, 1>;
template <class T> using mat6 = Eigen::Matrix<T, 6, 6>;
template <class T> using mat4 = Eigen::Matrix<T, 4, 4>;

/// Builds xi = (omega, v).
template <class T>
vec6<T> make_twist(const vec3<T>& omega, const vec3<T>& v) {
  vec6<T> xi;
  xi.template head<3>() = omega;
  xi.template tail<3>() = v;
  return xi;
}

/// The beam axis e2 = (0, E2) in se(3).
template <class T>
vec6<T> e2() {
  vec6<T> e = vec6<T>::Zero();
  e(4) = T(1);
  return e;
}

/// An element (R, x) of SE(3).
template <class T>
struct SE3 {
  mat3<T> R = mat3<T>::Identity();
  vec3<T> x = vec3<T>::Zero();

  static SE3 identity() { return SE3{}; }
  static SE3 from_matrix(const mat4<T>& M) { return SE3{M.template topLeftCorner<3, 3>(), M.template topRightCorner<3, 1>()}; }

  mat4<T> matrix() const {
    mat4<T> M = mat4<T>::Identity();
    M.template topLeftCorner<3, 3>() = R;
    M.template topRightCorner<3, 1>() = x;
    return M;
  }
  SE3 inverse() const {
    SE3 g;
    g.R = R.transpose();
    g.x = -(g.R * x);
    return g;
  }
  friend SE3 operator*(const SE3& a, const SE3& b) {
    SE3 g;
    g.R = a.R * b.R;
    g.x = a.x + a.R * b.x;
    return g;
  }
  /// The image of a point: R y + x.
  vec3<T> act(const vec3<T>& y) const { return R * y + x; }
};

/// xi^ in R^{4x4}.
template <class T>
mat4<T> hat(const vec6<T>& xi) {
  mat4<T> X = mat4<T>::Zero();
  X.template topLeftCorner<3, 3>() = hat3<T>(xi.template head<3>());
  X.template topRightCorner<3, 1>() = xi.template tail<3>();
  return X;
}

/// Inverse of hat (reads the skew part of the rotation block and the translation column).
template <class T>
vec6<T> vee(const mat4<T>& X) {
  return make_twist<T>(vee3<T>(X.template topLeftCorner<3, 3>()), X.template topRightCorner<3, 1>());
}

/// ad_xi as a 6x6 matrix: [[w^, 0], [v^, w^]].
template <class T>
mat6<T> ad(const vec6<T>& xi) {
  mat6<T> M = mat6<T>::Zero();
  const mat3<T> W = hat3<T>(xi.template head<3>());
  M.template topLeftCorner<3, 3>() = W;
  M.template bottomRightCorner<3, 3>() = W;
  M.template bottomLeftCorner<3, 3>() = hat3<T>(xi.template tail<3>());
  return M;
}

/// [xi, eta] = ad_xi eta = (w x w', w x v' - w' x v).
template <class T>
vec6<T> bracket(const vec6<T>& xi, const vec6<T>& eta) {
  const vec3<T> w = xi.template head<3>(), v = xi.template tail<3>();
  const vec3<T> w2 = eta.template head<3>(), v2 = eta.template tail<3>();
  return make_twist<T>(w.cross(w2), w.cross(v2) - w2.cross(v));
}

/// The dual bracket [xi, mu]^* = ad_xi^T mu = (pi x w + p x v, p x w).
template <class T>
vec6<T> dual_bracket(const vec6<T>& xi, const vec6<T>& mu) {
  const vec3<T> w = xi.template head<3>(), v = xi.template tail<3>();
  const vec3<T> pi = mu.template head<3>(), p = mu.template tail<3>();
  return make_twist<T>(pi.cross(w) + p.cross(v), p.cross(w));
}

/// Ad_g as a 6x6 matrix: [[R, 0], [x^ R, R]].
template <class T>
mat6<T> Ad(const SE3<T>& g) {
  mat6<T> M = mat6<T>::Zero();
  M.template topLeftCorner<3, 3>() = g.R;
  M.template bottomRightCorner<3, 3>() = g.R;
  M.template bottomLeftCorner<3, 3>() = hat3<T>(g.x) * g.R;
  return M;
}

/// Ad_g xi = (R w, R v + x x R w)  (= vee(g xi^ g^{-1})).
template <class T>
vec6<T> Ad(const SE3<T>& g, const vec6<T>& xi) {
  const vec3<T> Rw = g.R * xi.template head<3>();
  return make_twist<T>(Rw, g.R * xi.template tail<3>() + g.x.cross(Rw));
}

/// Ad^*_g mu = Ad_g^T mu = (R^T (pi - x x p), R^T p): <Ad^*_g mu, xi> = <mu, Ad_g xi>.
template <class T>
vec6<T> Ad_dual(const SE3<T>& g, const vec6<T>& mu) {
  const vec3<T> pi = mu.template head<3>(), p = mu.template tail<3>();
  return make_twist<T>(g.R.transpose() * (pi - g.x.cross(p)), g.R.transpose() * p);
}

/// The coadjoint action Ad^*_{g^{-1}} mu = (R pi + x x R p, R p): body momentum -> spatial
/// momentum (angular about the origin, linear). <coAd(g, mu), Ad_g xi> = <mu, xi>.
template <class T>
vec6<T> coAd(const SE3<T>& g, const vec6<T>& mu) {
  const vec3<T> Rp = g.R * mu.template tail<3>();
  return make_twist<T>(g.R * mu.template head<3>() + g.x.cross(Rp), Rp);
}

/// cay(xi) = (I - xi^/2)^{-1} (I + xi^/2) in closed form:
/// R = cay_SO3(w), x = (I - w^/2)^{-1} v.
template <class T>
SE3<T> cay(const vec6<T>& xi) {
  const vec3<T> w = xi.template head<3>();
  return SE3<T>{so3_cay<T>(w), so3_cay_left_inverse_apply<T>(w, xi.template tail<3>())};
}

/// cay^{-1}(g) = vee(2 (g - I)(g + I)^{-1}) in closed form: w = cay_SO3^{-1}(R),
/// v = (I - w^/2) x. Throws std::domain_error for a rotation angle of pi.
template <class T>
vec6<T> cay_inv(const SE3<T>& g) {
  const vec3<T> w = so3_cay_inv<T>(g.R);
  return make_twist<T>(w, g.x - w.cross(g.x) / T(2));
}

/// exp on se(3): R = I + A W + B W^2, x = (I + B W + C W^2) v.
template <class T>
SE3<T> exp(const vec6<T>& xi) {
  const vec3<T> w = xi.template head<3>(), v = xi.template tail<3>();
  const auto c = rodrigues_coefficients<T>::from_theta_squared(w.squaredNorm());
  const mat3<T> W = hat3<T>(w);
  const mat3<T> W2 = W * W;
  SE3<T> g;
  g.R = mat3<T>::Identity() + c.A * W + c.B * W2;
  const vec3<T> wv = w.cross(v);
  g.x = v + c.B * wv + c.C * w.cross(wv);
  return g;
}

/// log on SE(3) (rotation angle in [0, pi]): w = log_SO3(R),
/// v = (I - W/2 + D W^2) x with D = (1 - A/(2B))/theta^2 = E/(2B).
template <class T>
vec6<T> log(const SE3<T>& g) {
  const vec3<T> w = so3_log<T>(g.R);
  const auto c = rodrigues_coefficients<T>::from_theta_squared(w.squaredNorm());
  const T D = c.E / (T(2) * c.B);
  const vec3<T> wx = w.cross(g.x);
  return make_twist<T>(w, g.x - wx / T(2) + D * w.cross(wx));
}

}  // namespace geomint::lie
