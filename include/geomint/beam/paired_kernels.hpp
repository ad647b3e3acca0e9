#pragma once
/// Two neighbouring nodes of the beam at once, in the two lanes of a SIMD register (double
/// only): the node solve (53) with the structured Newton of `solve_node_isotropic`, the two
/// segment updates (54) that end at these nodes, and their Cayley reconstructions (55).
///
/// Every lane performs exactly the floating-point operations, in exactly the order, of the
/// one-node kernels (kernels.hpp, lie/se3.hpp) as Eigen evaluates them for fixed-size double
/// vectors (for instance the 3x3 products sum rows 0 and 1 as (a0 b0 + a1 b1) + a2 b2 and row 2
/// as a0 b0 + (a1 b1 + a2 b2); 6-vector dots as (t0 + (t2 + t4)) + (t1 + (t3 + t5))), so the
/// paired sweep gives results identical to the bit to the one-node sweep; the beam tests check
/// this on long runs. A pair whose Newton solve fails or leaves the finite range in either lane
/// is reported as such, and the caller redoes the two nodes one at a time to report the
/// failure exactly as the one-node path does.

#include <limits>
#include <vector>

#include "geomint/beam/kernels.hpp"
#include "geomint/lie/se3.hpp"

#if defined(__GNUC__)  // GCC and Clang: the vector extension below
#define GEOMINT_BEAM_PAIRED_NODES 1
#else
#define GEOMINT_BEAM_PAIRED_NODES 0
#endif

#if GEOMINT_BEAM_PAIRED_NODES
namespace geomint::beam::detail {

/// Two doubles, one per node: one SSE2/NEON register (GCC/Clang vector extension; arithmetic
/// is element-wise IEEE, scalars broadcast).
typedef double lane __attribute__((vector_size(16)));

struct lane3 {
  lane c[3];
};

inline lane3 lane_cross(const lane3& a, const lane3& b) {
  return {{a.c[1] * b.c[2] - a.c[2] * b.c[1], a.c[2] * b.c[0] - a.c[0] * b.c[2], a.c[0] * b.c[1] - a.c[1] * b.c[0]}};
}

/// `y.cwiseProduct(y).dot(d)` for a 3-vector y: ((y0 y0) d0 + (y1 y1) d1) + (y2 y2) d2.
inline lane lane_weighted_norm2(const lane3& y, const double* d) {
  return ((y.c[0] * y.c[0]) * d[0] + (y.c[1] * y.c[1]) * d[1]) + (y.c[2] * y.c[2]) * d[2];
}

/// `y.squaredNorm()` for a 3-vector y.
inline lane lane_norm2(const lane3& y) { return (y.c[0] * y.c[0] + y.c[1] * y.c[1]) + y.c[2] * y.c[2]; }

/// `a.dot(b)` for 6-vectors.
inline lane lane_dot6(const lane* a, const lane* b) {
  return (a[0] * b[0] + (a[2] * b[2] + a[4] * b[4])) + (a[1] * b[1] + (a[3] * b[3] + a[5] * b[5]));
}

/// The product of two 3x3 matrices (row-major arrays of lanes) as Eigen sums it.
inline void lane_mat3_mul(const lane* A, const lane* B, lane* C) {
  for (int k = 0; k < 3; ++k) {
    C[0 + k] = (A[0] * B[k] + A[1] * B[3 + k]) + A[2] * B[6 + k];
    C[3 + k] = (A[3] * B[k] + A[4] * B[3 + k]) + A[5] * B[6 + k];
    C[6 + k] = A[6] * B[k] + (A[7] * B[3 + k] + A[8] * B[6 + k]);
  }
}

/// A 3x3 matrix (row-major lanes) times a 3-vector, as Eigen sums it.
inline lane3 lane_mat3_apply(const lane* A, const lane3& y) {
  return {{(A[0] * y.c[0] + A[1] * y.c[1]) + A[2] * y.c[2], (A[3] * y.c[0] + A[4] * y.c[1]) + A[5] * y.c[2],
           A[6] * y.c[0] + (A[7] * y.c[1] + A[8] * y.c[2])}};
}

/// The state a sweep reads and writes (the integrator's buffers).
struct paired_buffers {
  const std::vector<lie::vec6<double>>& mu;
  const std::vector<lie::vec6<double>>& gamma;
  const std::vector<lie::vec6<double>>& stress_left;
  const std::vector<lie::vec6<double>>& stress_right;
  const std::vector<lie::SE3<double>>& g;
  std::vector<lie::vec6<double>>& mu_next;
  std::vector<lie::vec6<double>>& gamma_next;
  std::vector<lie::vec6<double>>& stress_left_next;
  std::vector<lie::vec6<double>>& stress_right_next;
  std::vector<lie::SE3<double>>& g_next;
};

/// Constants of a sweep.
struct paired_constants {
  double dt, h, ds, dt_over_ds;
  double d1inv[6];
  double d2[6];
  int max_newton_iterations;
};

/// Sums the pair adds to the sweep, in node order.
struct paired_sums {
  double kinetic[2];
  double potential[2];  ///< segments j - 1/2 and j + 1/2
  double finite_g;      ///< 0, or NaN if a new configuration entry is not finite
  int iterations[2];
};

/// Nodes j and j + 1 (1 <= j, j + 1 <= J - 1) and segments j - 1/2, j + 1/2; `zeta_left` holds
/// zeta_{j-1}^{n+1} on entry and zeta_{j+1}^{n+1} on return. Returns false (nothing to be
/// trusted written) if either Newton solve fails or meets a non-finite value.
template <bool Poisson, int Velocity>
bool paired_nodes(int j, const paired_buffers& b, const paired_constants& k, lie::vec6<double>& zeta_left,
                  paired_sums& out) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double h = k.h, dt = k.dt;
  const double* dr = k.d1inv;
  const lie::vec6<double>& m0 = b.mu[j];
  const lie::vec6<double>& m1 = b.mu[j + 1];
  lane m[6], c[6];
  for (int i = 0; i < 6; ++i) {
    m[i] = lane{m0(i), m1(i)};
    const lane F = (lane{b.stress_left[j](i), b.stress_left[j + 1](i)} + 0.0) -
                   lane{b.stress_right[j - 1](i), b.stress_right[j](i)};
    if constexpr (Poisson) c[i] = m[i] + h * F;
    else c[i] = m[i] + dt * F;
  }
  lane zeta_old[6];
  for (int i = 0; i < 6; ++i) zeta_old[i] = k.d1inv[i] * m[i];
  if constexpr (!Poisson) {
    // + h [zeta, mu]^* = h (pi x w + p x v, p x w)
    const lane3 pi{{m[0], m[1], m[2]}}, p{{m[3], m[4], m[5]}};
    const lane3 w{{zeta_old[0], zeta_old[1], zeta_old[2]}}, v{{zeta_old[3], zeta_old[4], zeta_old[5]}};
    const lane3 a = lane_cross(pi, w), bb = lane_cross(p, v), t = lane_cross(p, w);
    for (int i = 0; i < 3; ++i) {
      c[i] = c[i] + h * (a.c[i] + bb.c[i]);
      c[3 + i] = c[3 + i] + h * t.c[i];
    }
  }
  // Predictor and Newton on the rotational block (solve_node_isotropic).
  const lane3 cpi{{c[0], c[1], c[2]}};
  lane3 pi;
  {
    const lane3 t{{dr[0] * cpi.c[0], dr[1] * cpi.c[1], dr[2] * cpi.c[2]}};
    const lane3 cr = lane_cross(cpi, t);
    for (int i = 0; i < 3; ++i) pi.c[i] = cpi.c[i] + h * cr.c[i];
  }
  const double tol_factor = double(64) * eps * eps, step_factor = double(16) * eps * eps;
  const double hh = h * h;
  const lane cpi_norm2 = lane_weighted_norm2(cpi, dr);
  bool active[2] = {true, true};
  for (int it = 0;; ++it) {
    const lane3 w{{dr[0] * pi.c[0], dr[1] * pi.c[1], dr[2] * pi.c[2]}};
    const lane3 q = lane_cross(pi, w);
    const lane3 r{{(pi.c[0] - cpi.c[0]) - h * q.c[0], (pi.c[1] - cpi.c[1]) - h * q.c[1], (pi.c[2] - cpi.c[2]) - h * q.c[2]}};
    const lane r2 = lane_weighted_norm2(r, dr);
    const lane scale2 = (lane_weighted_norm2(pi, dr) + cpi_norm2) + hh * lane_weighted_norm2(q, dr);
    const lane tol2 = tol_factor * scale2;
    for (int l = 0; l < 2; ++l) {
      if (!active[l]) continue;
      if (!(r2[l] - r2[l] == 0.0) || !(scale2[l] - scale2[l] == 0.0)) return false;
      if (r2[l] <= tol2[l]) {
        active[l] = false;
        out.iterations[l] = it;
      } else if (it == k.max_newton_iterations) {
        return false;
      }
    }
    if (!active[0] && !active[1]) break;
    // J = I + h (w^ - pi^ Dr), rows a0, a1, a2; solved by its adjugate.
    const lane one = lane{1.0, 1.0};
    const lane3 a0{{one, ((-w.c[2]) - ((-pi.c[2]) * dr[1])) * h, (w.c[1] - pi.c[1] * dr[2]) * h}};
    const lane3 a1{{(w.c[2] - pi.c[2] * dr[0]) * h, one, ((-w.c[0]) - ((-pi.c[0]) * dr[2])) * h}};
    const lane3 a2{{((-w.c[1]) - ((-pi.c[1]) * dr[0])) * h, (w.c[0] - pi.c[0] * dr[1]) * h, one}};
    const lane3 col0 = lane_cross(a1, a2), col1 = lane_cross(a2, a0), col2 = lane_cross(a0, a1);
    const lane det = (a0.c[0] * col0.c[0] + a0.c[1] * col0.c[1]) + a0.c[2] * col0.c[2];
    for (int l = 0; l < 2; ++l)
      if (active[l] && (!(det[l] != 0.0) || !(det[l] - det[l] == 0.0))) return false;
    const lane adj[9] = {col0.c[0], col1.c[0], col2.c[0], col0.c[1], col1.c[1], col2.c[1], col0.c[2], col1.c[2], col2.c[2]};
    const lane3 ar = lane_mat3_apply(adj, r);
    const lane inv = 1.0 / det;
    const lane3 delta{{ar.c[0] * inv, ar.c[1] * inv, ar.c[2] * inv}};
    const lane3 next{{pi.c[0] - delta.c[0], pi.c[1] - delta.c[1], pi.c[2] - delta.c[2]}};
    const lane dn = lane_weighted_norm2(delta, dr), pn = lane_weighted_norm2(next, dr);
    if (active[0] && active[1]) {
      pi = next;
    } else {
      const int l = active[0] ? 0 : 1;
      for (int i = 0; i < 3; ++i) pi.c[i][l] = next.c[i][l];
    }
    for (int l = 0; l < 2; ++l) {
      if (active[l] && dn[l] <= step_factor * pn[l]) {
        active[l] = false;
        out.iterations[l] = it + 1;
      }
    }
    if (!active[0] && !active[1]) break;
  }
  // Translational block: (I + h w^) p = c_p in closed form (solve_one_plus_skew).
  lane x[6];
  {
    const lane3 hw{{h * (dr[0] * pi.c[0]), h * (dr[1] * pi.c[1]), h * (dr[2] * pi.c[2])}};
    const lane3 y{{c[3], c[4], c[5]}};
    const lane3 hy = lane_cross(hw, y);
    const lane3 hhy = lane_cross(hw, hy);
    const lane den = 1.0 + lane_norm2(hw);
    for (int i = 0; i < 3; ++i) {
      x[i] = pi.c[i];
      x[3 + i] = y.c[i] + (hhy.c[i] - hy.c[i]) / den;
    }
  }
  lane mu_new[6], zeta_new[6];
  for (int i = 0; i < 6; ++i) {
    if constexpr (Poisson) mu_new[i] = 2.0 * x[i] - m[i];
    else mu_new[i] = x[i];
    zeta_new[i] = k.d1inv[i] * mu_new[i];
    b.mu_next[j](i) = mu_new[i][0];
    b.mu_next[j + 1](i) = mu_new[i][1];
  }
  const lane kin = lane_dot6(mu_new, zeta_new);
  out.kinetic[0] = kin[0];
  out.kinetic[1] = kin[1];
  // Segments j - 1/2 (lane 0: nodes j - 1, j) and j + 1/2 (lane 1: nodes j, j + 1), scheme (54)
  // as segment_update, then their stresses as the integrator's segment_stress.
  {
    lane zl[6], zr[6], gam[6];
    for (int i = 0; i < 6; ++i) {
      zl[i] = lane{zeta_left(i), zeta_new[i][0]};
      zr[i] = zeta_new[i];
      gam[i] = lane{b.gamma[j - 1](i), b.gamma[j](i)};
      zeta_left(i) = zeta_new[i][1];
    }
    lane zbar[6];
    for (int i = 0; i < 6; ++i) zbar[i] = (zl[i] + zr[i]) / 2.0;
    const lane3 w{{zbar[0], zbar[1], zbar[2]}}, v{{zbar[3], zbar[4], zbar[5]}};
    const lane3 gw{{gam[0], gam[1], gam[2]}}, gv{{gam[3], gam[4], gam[5]}};
    const lane3 br_w = lane_cross(w, gw), wgv = lane_cross(w, gv), gwv = lane_cross(gw, v);
    lane rhs[6];
    for (int i = 0; i < 3; ++i) {
      rhs[i] = (gam[i] - h * br_w.c[i]) + k.dt_over_ds * (zr[i] - zl[i]);
      rhs[3 + i] = (gam[3 + i] - h * (wgv.c[i] - gwv.c[i])) + k.dt_over_ds * (zr[3 + i] - zl[3 + i]);
    }
    rhs[3] = rhs[3] - dt * (-w.c[2]);
    rhs[4] = rhs[4] - dt * 0.0;
    rhs[5] = rhs[5] - dt * w.c[0];
    const lane3 hw{{h * w.c[0], h * w.c[1], h * w.c[2]}};
    const lane inv = 1.0 / (1.0 + lane_norm2(hw));
    const lane3 a{{rhs[0], rhs[1], rhs[2]}};
    const lane3 ha = lane_cross(hw, a);
    const lane3 hha = lane_cross(hw, ha);
    const lane3 yw{{a.c[0] + (hha.c[0] - ha.c[0]) * inv, a.c[1] + (hha.c[1] - ha.c[1]) * inv,
                    a.c[2] + (hha.c[2] - ha.c[2]) * inv}};
    const lane3 vy = lane_cross(v, yw);
    const lane3 bb{{rhs[3] - h * vy.c[0], rhs[4] - h * vy.c[1], rhs[5] - h * vy.c[2]}};
    const lane3 hb = lane_cross(hw, bb);
    const lane3 hhb = lane_cross(hw, hb);
    lane gnew[6];
    for (int i = 0; i < 3; ++i) {
      gnew[i] = yw.c[i];
      gnew[3 + i] = bb.c[i] + (hhb.c[i] - hb.c[i]) * inv;
    }
    // sigma = D2 gamma, force = [gamma + e2, sigma]^* = (ps x Gw + ss x Gv, ss x Gw).
    lane sigma[6];
    for (int i = 0; i < 6; ++i) sigma[i] = k.d2[i] * gnew[i];
    const lane3 Gw{{gnew[0] + 0.0, gnew[1] + 0.0, gnew[2] + 0.0}}, Gv{{gnew[3] + 0.0, gnew[4] + 1.0, gnew[5] + 0.0}};
    const lane3 ps{{sigma[0], sigma[1], sigma[2]}}, ss{{sigma[3], sigma[4], sigma[5]}};
    const lane3 f1 = lane_cross(ps, Gw), f2 = lane_cross(ss, Gv), f3 = lane_cross(ss, Gw);
    lane force[6];
    for (int i = 0; i < 3; ++i) {
      force[i] = f1.c[i] + f2.c[i];
      force[3 + i] = f3.c[i];
    }
    for (int i = 0; i < 6; ++i) {
      const lane sd = sigma[i] / k.ds;
      const lane left = sd - force[i] / 2.0, right = sd + force[i] / 2.0;
      b.gamma_next[j - 1](i) = gnew[i][0];
      b.gamma_next[j](i) = gnew[i][1];
      b.stress_left_next[j - 1](i) = left[0];
      b.stress_left_next[j](i) = left[1];
      b.stress_right_next[j - 1](i) = right[0];
      b.stress_right_next[j](i) = right[1];
    }
    const lane pot = lane_dot6(sigma, gnew);
    out.potential[0] = pot[0];
    out.potential[1] = pot[1];
  }
  // Cayley reconstruction (55): g^{n+1} = g^n cay(dt z), cay as lie::cay.
  {
    lane xi[6];
    for (int i = 0; i < 6; ++i) {
      lane z;
      if constexpr (Velocity == 0) z = zeta_old[i];
      else if constexpr (Velocity == 1) z = zeta_new[i];
      else z = (zeta_old[i] + zeta_new[i]) / 2.0;
      xi[i] = dt * z;
    }
    const lane3 w{{xi[0], xi[1], xi[2]}}, y{{xi[3], xi[4], xi[5]}};
    const lane t = lane_norm2(w);
    const lane f = 4.0 / (4.0 + t);
    const lane fh = f / 2.0;
    lane Rc[9];
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) Rc[3 * r + s] = (fh * w.c[r]) * w.c[s];
    const lane d = 1.0 - fh * t;
    Rc[0] = Rc[0] + d;
    Rc[4] = Rc[4] + d;
    Rc[8] = Rc[8] + d;
    Rc[1] = Rc[1] - f * w.c[2];
    Rc[3] = Rc[3] + f * w.c[2];
    Rc[2] = Rc[2] + f * w.c[1];
    Rc[6] = Rc[6] - f * w.c[1];
    Rc[5] = Rc[5] - f * w.c[0];
    Rc[7] = Rc[7] + f * w.c[0];
    const lane3 wy = lane_cross(w, y);
    const lane3 wwy = lane_cross(w, wy);
    const lane den = 4.0 + t;
    const lane3 xc{{y.c[0] + (2.0 * wy.c[0] + wwy.c[0]) / den, y.c[1] + (2.0 * wy.c[1] + wwy.c[1]) / den,
                    y.c[2] + (2.0 * wy.c[2] + wwy.c[2]) / den}};
    const lie::SE3<double>& g0 = b.g[j];
    const lie::SE3<double>& g1 = b.g[j + 1];
    lane R[9];
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) R[3 * r + s] = lane{g0.R(r, s), g1.R(r, s)};
    const lane3 xg{{lane{g0.x(0), g1.x(0)}, lane{g0.x(1), g1.x(1)}, lane{g0.x(2), g1.x(2)}}};
    lane Rn[9];
    lane_mat3_mul(R, Rc, Rn);
    const lane3 Rx = lane_mat3_apply(R, xc);
    lie::SE3<double>& n0 = b.g_next[j];
    lie::SE3<double>& n1 = b.g_next[j + 1];
    lane check = lane{0.0, 0.0};
    for (int r = 0; r < 3; ++r) {
      for (int s = 0; s < 3; ++s) {
        n0.R(r, s) = Rn[3 * r + s][0];
        n1.R(r, s) = Rn[3 * r + s][1];
        check += Rn[3 * r + s] - Rn[3 * r + s];
      }
      const lane xn = xg.c[r] + Rx.c[r];
      n0.x(r) = xn[0];
      n1.x(r) = xn[1];
      check += xn - xn;
    }
    out.finite_g = check[0] + check[1];
  }
  return true;
}

}  // namespace geomint::beam::detail
#endif  // GEOMINT_BEAM_PAIRED_NODES
