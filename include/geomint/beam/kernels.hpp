#pragma once
/// The per-node and per-segment kernels of the beam paper's Poisson integrator.
///
/// Scheme (53), node j (sigma = D2 gamma, Gamma = gamma + e2, ghost segments zero):
///   (mu^{n+1} - mu^n)/dt = F_j^n + [ (zeta^{n+1} + zeta^n)/2, (mu^{n+1} + mu^n)/2 ]^*,
///   F_j^n = (sigma_{j+1/2}^n - sigma_{j-1/2}^n)/ds
///           - 1/2 ([Gamma_{j+1/2}^n, sigma_{j+1/2}^n]^* + [Gamma_{j-1/2}^n, sigma_{j-1/2}^n]^*).
/// With Q(x) = [D1^{-1} x, x]^* and h = dt/2 this is, for the midpoint x = (mu^{n+1} + mu^n)/2,
///   x - h Q(x) = mu^n + h F_j^n,            mu^{n+1} = 2 x - mu^n.
/// The "Hamel" variant (trapezoidal rule in the bracket term, 1/2(Q(mu^{n+1}) + Q(mu^n))) is,
/// for x = mu^{n+1},
///   x - h Q(x) = mu^n + dt F_j^n + h Q(mu^n).
/// Both are the same 6x6 nonlinear system x - h Q(x) = c, solved by Newton's method.
///
/// Scheme (54), segment j + 1/2, with zbar = (zeta_{j+1}^{n+1} + zeta_j^{n+1})/2:
///   (gamma^{n+1} - gamma^n)/dt = (zeta_{j+1}^{n+1} - zeta_j^{n+1})/ds
///                                + [ (gamma^{n+1} + gamma^n + 2 e2)/2, zbar ],
/// i.e. the linear system
///   (I + h ad_zbar) gamma^{n+1} = (I - h ad_zbar) gamma^n + dt (zeta_{j+1} - zeta_j)/ds - dt ad_zbar e2.
/// ad_zbar = [[W, 0], [V, W]] is block lower triangular, so the 6x6 solve is two 3x3 solves
/// with the closed-form inverse (I + hW)^{-1} y = y + (-h w x y + h^2 w x (w x y))/(1 + h^2 |w|^2).

#include <Eigen/LU>
#include <limits>

#include "geomint/lie/se3.hpp"

namespace geomint::beam {

using lie::mat3;
using lie::mat6;
using lie::vec3;
using lie::vec6;

/// Q(x) = [D1^{-1} x, x]^* = ad^T_{D1^{-1} x} x.
template <class T>
vec6<T> rigid_bracket(const vec6<T>& x, const vec6<T>& d1inv) {
  return lie::dual_bracket<T>(vec6<T>(d1inv.cwiseProduct(x)), x);
}

/// The 6x6 matrix I - h dQ(x): with zeta = D1^{-1} x = (w, v), x = (pi, p),
///   dQ(x) delta = (dpi x w + pi x dw + dp x v + p x dv, dp x w + p x dw),  (dw, dv) = D1^{-1} delta,
///   I - h dQ(x) = I + h [[w^ - pi^ Dr, v^ - p^ Dt], [-p^ Dr, w^]]
/// (Dr, Dt: the rotational and translational blocks of D1^{-1}).
template <class T>
mat6<T> rigid_bracket_jacobian(const vec6<T>& x, const vec6<T>& d1inv, const T& h) {
  const vec6<T> zeta = d1inv.cwiseProduct(x);
  const mat3<T> W = lie::hat3<T>(zeta.template head<3>()), V = lie::hat3<T>(zeta.template tail<3>());
  const mat3<T> Pi = lie::hat3<T>(x.template head<3>()), P = lie::hat3<T>(x.template tail<3>());
  mat6<T> J;
  J.template topLeftCorner<3, 3>() = W - Pi * d1inv.template head<3>().asDiagonal();
  J.template topRightCorner<3, 3>() = V - P * d1inv.template tail<3>().asDiagonal();
  J.template bottomLeftCorner<3, 3>() = -(P * d1inv.template head<3>().asDiagonal());
  J.template bottomRightCorner<3, 3>() = W;
  J *= h;
  J += mat6<T>::Identity();
  return J;
}

template <class T>
vec3<T> solve_one_plus_skew(const vec3<T>& w, const T& h, const vec3<T>& y);

/// Outcome of one node solve.
template <class T>
struct newton_result {
  int iterations = 0;       ///< Newton updates applied
  bool converged = false;
  bool finite = true;       ///< false if a non-finite residual appeared
  T residual = T(0);        ///< last weighted residual |r|_{D1^{-1}} (filled when not converged)
  T tolerance = T(0);       ///< the tolerance it was compared with (filled when not converged)
};

/// Solves x - h Q(x) = c by Newton's method, starting from the value in x.
///
/// Norms are weighted by D1^{-1} (the kinetic-energy norm), so rotational and translational
/// components count alike. Stops when the residual is at the rounding level of its own
/// evaluation, |r| <= 8 eps (|x| + |c| + h |Q(x)|) (squared norms, summed), or when the Newton
/// update is below 4 eps |x|. The Jacobian I - h dQ(x) is refreshed at every iteration and
/// factorised by LU with partial pivoting (fixed 6x6, no allocation).
template <class T>
newton_result<T> solve_node(vec6<T>& x, const vec6<T>& c, const T& h, const vec6<T>& d1inv, int max_iterations) {
  const T eps = std::numeric_limits<T>::epsilon();
  auto wnorm2 = [&](const vec6<T>& y) -> T { return y.cwiseProduct(y).dot(d1inv); };
  newton_result<T> out;
  for (int it = 0;; ++it) {
    const vec6<T> q = rigid_bracket<T>(x, d1inv);
    const vec6<T> r = x - c - h * q;
    const T r2 = wnorm2(r);
    const T scale2 = wnorm2(x) + wnorm2(c) + h * h * wnorm2(q);
    const T tol2 = T(64) * eps * eps * scale2;
    using std::sqrt;
    out.iterations = it;
    if (!(r2 - r2 == T(0)) || !(scale2 - scale2 == T(0))) {
      out.finite = false;
      out.residual = r2;
      return out;
    }
    if (r2 <= tol2) {
      out.converged = true;
      return out;
    }
    if (it == max_iterations) {
      out.residual = sqrt(r2);
      out.tolerance = sqrt(tol2);
      return out;
    }
    const mat6<T> J = rigid_bracket_jacobian<T>(x, d1inv, h);
    const vec6<T> delta = Eigen::PartialPivLU<mat6<T>>(J).solve(r);
    x -= delta;
    if (wnorm2(delta) <= T(16) * eps * eps * wnorm2(x)) {
      out.iterations = it + 1;
      out.converged = true;
      return out;
    }
  }
}

/// Solves x - h Q(x) = c when the translational block of D1 is isotropic (D1_4 = D1_5 = D1_6,
/// true for every material of docs/design.md, "Beam conventions"). Then p x v = 0 in Q, so with w = Dr pi
///   pi - h pi x w = c_pi          (3x3, nonlinear: Newton with the closed-form 3x3 inverse),
///   (I + h w^) p = c_p            (linear, closed form once pi is known).
/// Same stopping rules as solve_node (the residual is that of the rotational block, the
/// translational block being solved exactly).
template <class T>
newton_result<T> solve_node_isotropic(vec6<T>& x, const vec6<T>& c, const T& h, const vec6<T>& d1inv,
                                      int max_iterations) {
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  const vec3<T> dr = d1inv.template head<3>();
  const vec3<T> cpi = c.template head<3>();
  auto wnorm2 = [&](const vec3<T>& y) -> T { return y.cwiseProduct(y).dot(dr); };
  vec3<T> pi = x.template head<3>();
  newton_result<T> out;
  for (int it = 0;; ++it) {
    const vec3<T> w = dr.cwiseProduct(pi);
    const vec3<T> q = pi.cross(w);
    const vec3<T> r = pi - cpi - h * q;
    const T r2 = wnorm2(r);
    const T scale2 = wnorm2(pi) + wnorm2(cpi) + h * h * wnorm2(q);
    const T tol2 = T(64) * eps * eps * scale2;
    out.iterations = it;
    if (!(r2 - r2 == T(0)) || !(scale2 - scale2 == T(0))) {
      out.finite = false;
      out.residual = r2;
      return out;
    }
    bool done = r2 <= tol2;
    if (!done && it == max_iterations) {
      out.residual = sqrt(r2);
      out.tolerance = sqrt(tol2);
      return out;
    }
    if (!done) {
      // J = I + h (w^ - pi^ Dr), solved by its adjugate.
      mat3<T> J = lie::hat3<T>(w) - lie::hat3<T>(pi) * dr.asDiagonal();
      J *= h;
      J += mat3<T>::Identity();
      mat3<T> adj;
      const vec3<T> a0 = J.row(0).transpose(), a1 = J.row(1).transpose(), a2 = J.row(2).transpose();
      adj.col(0) = a1.cross(a2);
      adj.col(1) = a2.cross(a0);
      adj.col(2) = a0.cross(a1);
      const T det = a0.dot(adj.col(0));
      if (!(det != T(0)) || !(det - det == T(0))) {
        out.finite = det == T(0);  // singular: a Newton failure; non-finite: reported as such
        out.residual = sqrt(r2);
        out.tolerance = sqrt(tol2);
        return out;
      }
      const vec3<T> delta = (adj * r) * (T(1) / det);
      pi -= delta;
      done = wnorm2(delta) <= T(16) * eps * eps * wnorm2(pi);
      if (done) out.iterations = it + 1;
    }
    if (done) {
      out.converged = true;
      const vec3<T> wfinal = dr.cwiseProduct(pi);
      x.template head<3>() = pi;
      x.template tail<3>() = solve_one_plus_skew<T>(wfinal, h, vec3<T>(c.template tail<3>()));
      return out;
    }
  }
}

/// (I + h w^)^{-1} y in closed form.
template <class T>
vec3<T> solve_one_plus_skew(const vec3<T>& w, const T& h, const vec3<T>& y) {
  const vec3<T> hw = h * w;
  const vec3<T> hy = hw.cross(y);
  return y + (hw.cross(hy) - hy) / (T(1) + hw.squaredNorm());
}

/// Scheme (54) for one segment: gamma^{n+1} from gamma^n and the new velocities of its two
/// end nodes.
/// `h = dt / 2` and `dt_over_ds = dt / ds` are the caller's (constant over a sweep).
template <class T>
vec6<T> segment_update(const vec6<T>& gamma, const vec6<T>& zeta_left, const vec6<T>& zeta_right, const T& dt,
                       const T& h, const T& dt_over_ds) {
  const vec6<T> zbar = (zeta_left + zeta_right) / T(2);
  const vec3<T> w = zbar.template head<3>(), v = zbar.template tail<3>();
  // rhs = gamma - h [zbar, gamma] + dt (zeta_r - zeta_l)/ds - dt [zbar, e2];  [zbar, e2] = (0, w x E2).
  vec6<T> rhs = gamma - h * lie::bracket<T>(zbar, gamma) + dt_over_ds * (zeta_right - zeta_left);
  const vec3<T> w_x_e2(-w(2), T(0), w(0));  // w x (0,1,0)
  rhs.template tail<3>() -= dt * w_x_e2;
  // (I + h ad_zbar) y = rhs with ad_zbar = [[W, 0], [V, W]]: two applications of
  // (I + hW)^{-1} y = y + (h^2 w x (w x y) - h w x y) / (1 + h^2 |w|^2).
  const vec3<T> hw = h * w;
  const T inv = T(1) / (T(1) + hw.squaredNorm());
  const vec3<T> a = rhs.template head<3>();
  const vec3<T> ha = hw.cross(a);
  const vec3<T> y_w = a + (hw.cross(ha) - ha) * inv;
  const vec3<T> b = rhs.template tail<3>() - h * v.cross(y_w);
  const vec3<T> hb = hw.cross(b);
  vec6<T> y;
  y.template head<3>() = y_w;
  y.template tail<3>() = b + (hw.cross(hb) - hb) * inv;
  return y;
}

/// Scheme (54) for one segment of length ds with time step dt.
template <class T>
vec6<T> segment_update(const vec6<T>& gamma, const vec6<T>& zeta_left, const vec6<T>& zeta_right, const T& dt,
                       const T& ds) {
  return segment_update<T>(gamma, zeta_left, zeta_right, dt, T(dt / T(2)), T(dt / ds));
}

}  // namespace geomint::beam
