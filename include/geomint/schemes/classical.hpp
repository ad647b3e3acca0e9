#pragma once
/// Classical variational integrators from a quadrature of the action (LPF paper eq. 2-3),
/// through the same stepping interface as the LPF scheme:
/// - `midpoint_vi`:   L_d = tau L((x^k + x^{k+1})/2, (x^{k+1} - x^k)/tau), the paper's scheme (17);
/// - `trapezoidal_vi`: L_d = tau/2 [L(x^k, xbar) + L(x^{k+1}, xbar)], Stormer-Verlet for natural systems;
/// - `galerkin_vi<m>`: degree-m polynomial path, action by m-point Gauss-Legendre quadrature,
///   extremised over the interior control points (order 2m).
/// One-step form: p_k = -d_1 L_d, p_{k+1} = d_2 L_d (position-momentum form of eq. 3).

#include <array>
#include <limits>
#include <string>

#include "geomint/schemes/lpf.hpp"

namespace geomint {
namespace detail {

/// Galerkin engine: degree-M path (controls X_0..X_M), Q-point quadrature (g_k, w_k) on [0, 1].
/// L_d = tau sum_k w_k L(x(g_k), xdot(g_k)); G_j = dL_d/dX_j.
template <class Sys, class T, int M, int Q>
class galerkin_engine {
 public:
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;
  using controls = Eigen::Matrix<T, n, M + 1>;
  using D = derivatives<Sys, T>;
  using B = Eigen::Matrix<T, Q, M + 1>;

  galerkin_engine(const Sys& sys, const B& B0, const B& B1, const vec<T, Q>& w, const Eigen::Matrix<T, M + 1, M + 1>& D0,
                  const std::array<T, M + 1>& c)
      : sys_(sys), B0_(B0), B1_(B1), w_(w), D0inv_(inverse_of(D0)), c_(c) {}

  /// Unknowns: the increments Y_j = X_j - q_k (the basis is a partition of unity), solved by
  /// simplified Newton; the iterations after the first need only first derivatives of L.
  step_status one_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt) const {
    V v0;
    if (!D::velocity(sys_, q, p, v0)) return {step_failure::singular_jacobian, 0, 0};
    const V a0 = D::acceleration(sys_, q, v0);
    controls Y = predict_controls<T, n, M>(D0inv_, c_, V::Zero(), v0, a0, tau);
    Y.col(0).setZero();
    constexpr int N = M * n;
    vec<T, N> z;
    for (int j = 1; j <= M; ++j) z.template segment<n>((j - 1) * n) = Y.col(j);
    auto residual = [&](const vec<T, N>& zz, vec<T, N>& F, mat<T, N>* J) {
      for (int j = 1; j <= M; ++j) Y.col(j) = zz.template segment<n>((j - 1) * n);
      assemble_increments(q, Y, tau, F, J);
      F.template segment<n>(0) += tau * p;  // p_k + d_1 L_d = 0
    };
    const T scale = std::numeric_limits<T>::epsilon() * q.template lpNorm<Eigen::Infinity>();
    step_status st = newton_solve_simplified<N, T>(residual, z, opt, scale);
    if (!st) return st;
    for (int j = 1; j <= M; ++j) Y.col(j) = z.template segment<n>((j - 1) * n);
    q1 = q + Y.col(M);
    // p_{k+1} = G_M = sum_j G_j - G_0 - (G_1 + ... + G_{M-1}) = p_k + tau sum_k w_k L_q(x_k, v_k)
    // at the solution (the basis sums to 1, its derivatives to 0): the same value as G_M, but the
    // Newton and round-off errors of Y do not pass through B1 / tau (an RKN-like update).
    V sum = V::Zero();
    for (int k = 0; k < Q; ++k) {
      const V x = q + combine(Y, B0_, k), v = combine(Y, B1_, k) / tau;
      sum += w_[k] * D::gradient(sys_, x, v).Lq;
    }
    p1 = p + tau * sum;
    return st;
  }

  step_status end_momentum(const V& x0, const V& x1, const T& tau, V& p1, const newton_options<T>& opt) const {
    controls X;
    for (int i = 0; i <= M; ++i) X.col(i) = x0 + c_[static_cast<std::size_t>(i)] * (x1 - x0);
    const controls values = X;
    for (int j = 0; j <= M; ++j) X.col(j) = combine(values, D0inv_, j);
    X.col(0) = x0;
    X.col(M) = x1;
    step_status st;
    if constexpr (M >= 2) {
      constexpr int N = (M - 1) * n;
      vec<T, N> z;
      for (int j = 1; j < M; ++j) z.template segment<n>((j - 1) * n) = X.col(j);
      auto residual = [&](const vec<T, N>& zz, vec<T, N>& F, mat<T, N>& J) {
        for (int j = 1; j < M; ++j) X.col(j) = zz.template segment<n>((j - 1) * n);
        assemble(X, tau, 1, 1, F, J);
      };
      st = newton_solve<N, T>(residual, z, opt);
      if (!st) return st;
      for (int j = 1; j < M; ++j) X.col(j) = z.template segment<n>((j - 1) * n);
    }
    p1 = gradient_component(X, tau, M);
    return st;
  }

 private:
  /// G_j = dL_d/dX_j = sum_k w_k [tau L_q B0(k,j) + L_v B1(k,j)].
  V gradient_component(const controls& X, const T& tau, int j) const {
    V G = V::Zero();
    for (int k = 0; k < Q; ++k) {
      const V x = combine(X, B0_, k), v = combine(X, B1_, k) / tau;
      const gradient_data<T, n> g = D::gradient(sys_, x, v);
      G += w_[k] * (tau * B0_(k, j) * g.Lq + B1_(k, j) * g.Lv);
    }
    return G;
  }

  /// One-step system for the path q + sum_j phi_j Y_j: rows tau G_0..tau G_{M-1}, columns
  /// Y_1..Y_M; J (if not null) from second derivatives, F alone from first derivatives.
  template <int N>
  void assemble_increments(const V& q, const controls& Y, const T& tau, vec<T, N>& F, mat<T, N>* J) const {
    constexpr int blocks = N / n;
    F.setZero();
    if (J) J->setZero();
    const T tau2 = tau * tau;
    for (int k = 0; k < Q; ++k) {
      const V x = q + combine(Y, B0_, k), v = combine(Y, B1_, k) / tau;
      if (J) {
        const hessian_data<T, n> h = D::hessian(sys_, x, v);
        for (int r = 0; r < blocks; ++r) {
          const int j = r;
          F.template segment<n>(r * n) += w_[k] * (tau2 * B0_(k, j) * h.Lq + tau * B1_(k, j) * h.Lv);
          for (int s = 0; s < blocks; ++s) {
            const int l = 1 + s;
            J->template block<n, n>(r * n, s * n) +=
                w_[k] * ((tau2 * B0_(k, j) * B0_(k, l)) * h.Lqq + (tau * B0_(k, j) * B1_(k, l)) * h.Lqv +
                         (tau * B1_(k, j) * B0_(k, l)) * h.Lvq + (B1_(k, j) * B1_(k, l)) * h.Lvv);
          }
        }
      } else {
        const gradient_data<T, n> g = D::gradient(sys_, x, v);
        for (int r = 0; r < blocks; ++r) {
          const int j = r;
          F.template segment<n>(r * n) += w_[k] * (tau2 * B0_(k, j) * g.Lq + tau * B1_(k, j) * g.Lv);
        }
      }
    }
  }

  /// Rows j = jrow0..(jrow0 + rows - 1) hold tau G_j; columns are the unknowns X_jcol0..; the
  /// unknown range is X_1..X_M (one-step, jrow0 = 0) or X_1..X_{M-1} (boundary, jrow0 = 1).
  template <int N>
  void assemble(const controls& X, const T& tau, int jrow0, int jcol0, vec<T, N>& F, mat<T, N>& J) const {
    constexpr int blocks = N / n;
    F.setZero();
    J.setZero();
    const T tau2 = tau * tau;
    for (int k = 0; k < Q; ++k) {
      const V x = combine(X, B0_, k), v = combine(X, B1_, k) / tau;
      const hessian_data<T, n> h = D::hessian(sys_, x, v);
      for (int r = 0; r < blocks; ++r) {
        const int j = jrow0 + r;
        F.template segment<n>(r * n) += w_[k] * (tau2 * B0_(k, j) * h.Lq + tau * B1_(k, j) * h.Lv);
        for (int s = 0; s < blocks; ++s) {
          const int l = jcol0 + s;
          J.template block<n, n>(r * n, s * n) +=
              w_[k] * ((tau2 * B0_(k, j) * B0_(k, l)) * h.Lqq + (tau * B0_(k, j) * B1_(k, l)) * h.Lqv +
                       (tau * B1_(k, j) * B0_(k, l)) * h.Lvq + (B1_(k, j) * B1_(k, l)) * h.Lvv);
        }
      }
    }
  }

  Sys sys_;
  B B0_, B1_;
  vec<T, Q> w_;
  Eigen::Matrix<T, M + 1, M + 1> D0inv_;
  std::array<T, M + 1> c_;
};

/// Basis values (K = 0) or derivatives (K = 1) at points g: out(k, j) = phi_j^(K)(g_k).
template <int K, class Basis, class Family, int M, class T, int Q>
Eigen::Matrix<T, Q, M + 1> basis_at(const std::array<T, Q>& g) {
  Eigen::Matrix<T, Q, M + 1> out;
  for (int k = 0; k < Q; ++k) {
    const auto row = basis_derivatives<K, Basis, Family, M, T>(g[static_cast<std::size_t>(k)]);
    for (int j = 0; j <= M; ++j) out(k, j) = row[static_cast<std::size_t>(j)];
  }
  return out;
}

/// Q-point Gauss-Legendre rule on [0, 1]: the interior nodes of gauss_interior<Q + 1> and
/// w = 1 / ((1 - x^2) P_Q'(x)^2) with x = 1 - 2g, 1 - x^2 = 4 g (1 - g).
template <int Q, class T>
void gauss_legendre(std::array<T, Q>& g, vec<T, Q>& w) {
  const auto c = nodes<gauss_interior, Q + 1, T>();
  for (int k = 0; k < Q; ++k) {
    g[static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k + 1)];
    const T gk = g[static_cast<std::size_t>(k)];
    const T dp = legendre_at<T>(Q, gk).dp;
    w[k] = T(1) / (T(4) * gk * (T(1) - gk) * dp * dp);
  }
}

}  // namespace detail

/// Galerkin variational integrator of degree m (path in a basis on a node family; the
/// discrete map does not depend on that choice) with m-point Gauss-Legendre quadrature.
template <int M, class Family = gauss_lobatto, class Basis = lagrange>
struct galerkin_vi {
  static_assert(M >= 1, "geomint::galerkin_vi: degree m must be >= 1");
  static_assert(M <= max_floating_m, "geomint::galerkin_vi: m must be <= max_floating_m (16)");
  static_assert(node_family<Family>, "geomint::galerkin_vi: invalid node family");
  static_assert(basis_kind<Basis>, "geomint::galerkin_vi: Basis must be lagrange or bernstein");
  static constexpr int m = M;
  static std::string name() { return "galerkin(m=" + std::to_string(M) + ", gauss-" + std::to_string(M) + ")"; }

  template <class Sys, class T>
  struct engine : detail::galerkin_engine<Sys, T, M, M> {
    explicit engine(const Sys& sys) : engine(sys, rule()) {}

   private:
    struct rule_data {
      std::array<T, M> g;
      vec<T, M> w;
    };
    static rule_data rule() {
      rule_data r;
      detail::gauss_legendre<M, T>(r.g, r.w);
      return r;
    }
    engine(const Sys& sys, const rule_data& r)
        : detail::galerkin_engine<Sys, T, M, M>(
              sys, detail::basis_at<0, Basis, Family, M, T, M>(r.g), detail::basis_at<1, Basis, Family, M, T, M>(r.g), r.w,
              detail::to_matrix<T, M + 1>(differentiation_weights<0, Family, M, T, Basis>()), nodes<Family, M, T>()) {}
  };
};

/// The midpoint-rule variational integrator: the paper's scheme (17) for the harmonic oscillator.
struct midpoint_vi {
  static std::string name() { return "midpoint"; }
  template <class Sys, class T>
  struct engine : detail::galerkin_engine<Sys, T, 1, 1> {
    explicit engine(const Sys& sys)
        : detail::galerkin_engine<Sys, T, 1, 1>(sys, values(), slopes(), vec<T, 1>::Constant(T(1)),
                                                Eigen::Matrix<T, 2, 2>::Identity(), {T(0), T(1)}) {}
    static Eigen::Matrix<T, 1, 2> values() { return (Eigen::Matrix<T, 1, 2>() << T(1) / T(2), T(1) / T(2)).finished(); }
    static Eigen::Matrix<T, 1, 2> slopes() { return (Eigen::Matrix<T, 1, 2>() << T(-1), T(1)).finished(); }
  };
};

/// The trapezoidal variational integrator (Stormer-Verlet for natural systems).
struct trapezoidal_vi {
  static std::string name() { return "trapezoidal"; }
  template <class Sys, class T>
  struct engine : detail::galerkin_engine<Sys, T, 1, 2> {
    explicit engine(const Sys& sys)
        : detail::galerkin_engine<Sys, T, 1, 2>(sys, values(), slopes(), vec<T, 2>::Constant(T(1) / T(2)),
                                                Eigen::Matrix<T, 2, 2>::Identity(), {T(0), T(1)}) {}
    static Eigen::Matrix<T, 2, 2> values() { return Eigen::Matrix<T, 2, 2>::Identity(); }
    static Eigen::Matrix<T, 2, 2> slopes() { return (Eigen::Matrix<T, 2, 2>() << T(-1), T(1), T(-1), T(1)).finished(); }
  };
};

/// The paper's classical comparison scheme.
using scheme17 = midpoint_vi;

}  // namespace geomint
