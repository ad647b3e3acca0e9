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

#include "geomint/core/quadrature.hpp"
#include "geomint/schemes/lpf.hpp"
#include "geomint/schemes/path_method.hpp"

namespace geomint {
namespace schemes::detail {

/// One Galerkin step as a method of the step skeleton: a degree-M path q + sum_j phi_j Y_j
/// (controls on a node family in a basis), the action by a Q-point quadrature (g_k, w_k) on
/// [0, 1]: L_d = tau sum_k w_k L(x(g_k), xdot(g_k)); G_j = dL_d/dX_j. The unknowns are the
/// increments Y_1..Y_M; the residual rows are tau G_0 + tau p_k (= 0, p_k = -d_1 L_d) and
/// tau G_1..tau G_{M-1} (= 0, the path extremises the action).
template <class Sys, class T, int M, int Q>
class galerkin_method : public path_method<Sys, T, M> {
  using base = path_method<Sys, T, M>;
  using base::sys_;

 public:
  using base::n;
  using base::unknowns;
  using typename base::controls;
  using typename base::D;
  using typename base::V;
  using typename base::weights;
  using typename base::Z;
  using B = Eigen::Matrix<T, Q, M + 1>;

  /// B0(k, j) = phi_j(g_k), B1(k, j) = phi_j'(g_k), qw: the quadrature weights.
  galerkin_method(const Sys& sys, const weights& pw, const B& B0, const B& B1, const vec<T, Q>& qw)
      : base(sys, pw), B0_(B0), B1_(B1), qw_(qw) {}

  /// The iterations after the first need only first derivatives of L (J is null then). With a
  /// carry (compensated summation) the path starts at q + carry.q and p_k is p + carry.p.
  void residual(const V& q, const V& p, const T& tau, const Z& z, Z& F, square_matrix<T, unknowns>* J,
                const phase_carry<T, n>* carry = nullptr) const {
    const controls Y = unpack_path<T, n, M, unknowns>(z);
    F.setZero();
    if (J) J->setZero();
    const T tau2 = tau * tau;
    for (int k = 0; k < Q; ++k) {
      const V x = this->from_start(q, combine(Y, B0_, k), carry), v = combine(Y, B1_, k) / tau;
      if (J) {
        const hessian_data<T, n> h = D::hessian(sys_, x, v);
        for (int j = 0; j < M; ++j) {
          F.template segment<n>(j * n) += qw_[k] * (tau2 * B0_(k, j) * h.Lq + tau * B1_(k, j) * h.Lv);
          for (int s = 0; s < M; ++s) {
            const int l = 1 + s;
            J->template block<n, n>(j * n, s * n) +=
                qw_[k] * ((tau2 * B0_(k, j) * B0_(k, l)) * h.Lqq + (tau * B0_(k, j) * B1_(k, l)) * h.Lqv +
                         (tau * B1_(k, j) * B0_(k, l)) * h.Lvq + (B1_(k, j) * B1_(k, l)) * h.Lvv);
          }
        }
      } else {
        const gradient_data<T, n> g = D::gradient(sys_, x, v);
        for (int j = 0; j < M; ++j)
          F.template segment<n>(j * n) += qw_[k] * (tau2 * B0_(k, j) * g.Lq + tau * B1_(k, j) * g.Lv);
      }
    }
    F.template segment<n>(0) += tau * p;  // p_k + d_1 L_d = 0
    if (carry) F.template segment<n>(0) += tau * carry->p;
  }

  /// q_{k+1} = X_M; p_{k+1} = G_M = sum_j G_j - G_0 - (G_1 + ... + G_{M-1}) = p_k + tau sum_k
  /// w_k L_q(x_k, v_k) at the solution (the basis sums to 1, its derivatives to 0): the same
  /// value as G_M, but the Newton and round-off errors of Y do not pass through B1 / tau (an
  /// RKN-like update). Both as increments (u.q = X_M - q_k, u.p = p_{k+1} - p_k).
  step_status finish(const V& q, const V&, const T& tau, const Z& z, end_update<T, n>& u,
                     const phase_carry<T, n>* carry = nullptr) const {
    const controls Y = unpack_path<T, n, M, unknowns>(z);
    u.q = Y.col(M);
    V sum = V::Zero();
    for (int k = 0; k < Q; ++k) {
      const V x = this->from_start(q, combine(Y, B0_, k), carry), v = combine(Y, B1_, k) / tau;
      sum += qw_[k] * D::lagrangian_q(sys_, x, v);
    }
    u.p = tau * sum;
    return {};
  }

  /// G_M of the path through x0, x1 whose interior controls extremise the action.
  step_status end_momentum(const V& x0, const V& x1, const T& tau, V& p1, const newton_options<T>& opt) const {
    controls X = this->pinned_controls(this->segment_values(x0, x1), x0, x1);
    step_status st;
    if constexpr (M >= 2) {
      constexpr int N = (M - 1) * n;
      vec<T, N> z;
      for (int j = 1; j < M; ++j) z.template segment<n>((j - 1) * n) = X.col(j);
      auto residual = [&](const vec<T, N>& zz, vec<T, N>& F, square_matrix<T, N>& J) {
        for (int j = 1; j < M; ++j) X.col(j) = zz.template segment<n>((j - 1) * n);
        interior_rows<N>(X, tau, F, J);
      };
      st = newton_solve<N, T>(residual, z, opt);
      if (!st) return st;
      for (int j = 1; j < M; ++j) X.col(j) = z.template segment<n>((j - 1) * n);
    }
    V G = V::Zero();
    for (int k = 0; k < Q; ++k) {
      const V x = combine(X, B0_, k), v = combine(X, B1_, k) / tau;
      const gradient_data<T, n> g = D::gradient(sys_, x, v);
      G += qw_[k] * (tau * B0_(k, M) * g.Lq + B1_(k, M) * g.Lv);
    }
    p1 = G;
    return st;
  }

 private:
  /// Rows tau G_1..tau G_{M-1}, columns X_1..X_{M-1} (both ends fixed).
  template <int N>
  void interior_rows(const controls& X, const T& tau, vec<T, N>& F, square_matrix<T, N>& J) const {
    constexpr int blocks = N / n;
    F.setZero();
    J.setZero();
    const T tau2 = tau * tau;
    for (int k = 0; k < Q; ++k) {
      const V x = combine(X, B0_, k), v = combine(X, B1_, k) / tau;
      const hessian_data<T, n> h = D::hessian(sys_, x, v);
      for (int r = 0; r < blocks; ++r) {
        const int j = 1 + r;
        F.template segment<n>(r * n) += qw_[k] * (tau2 * B0_(k, j) * h.Lq + tau * B1_(k, j) * h.Lv);
        for (int s = 0; s < blocks; ++s) {
          const int l = 1 + s;
          J.template block<n, n>(r * n, s * n) +=
              qw_[k] * ((tau2 * B0_(k, j) * B0_(k, l)) * h.Lqq + (tau * B0_(k, j) * B1_(k, l)) * h.Lqv +
                       (tau * B1_(k, j) * B0_(k, l)) * h.Lvq + (B1_(k, j) * B1_(k, l)) * h.Lvv);
        }
      }
    }
  }

  B B0_, B1_;
  vec<T, Q> qw_;
};

/// The path weights of a degree-1 path (c = 0, 1): the midpoint and trapezoidal rules.
template <class T>
path_weights<T, 1> linear_path_weights() {
  return path_weights<T, 1>::template make<equispaced, lagrange>();
}

}  // namespace schemes::detail

/// Galerkin variational integrator of degree m (path in a basis on a node family; the
/// discrete map does not depend on that choice) with m-point Gauss-Legendre quadrature.
template <int M, class Family = gauss_lobatto, class Basis = lagrange>
struct galerkin_vi {
  static_assert(M >= 1, "geomint::galerkin_vi: degree m must be >= 1");
  static_assert(M <= max_floating_m, "geomint::galerkin_vi: m must be <= max_floating_m (16)");
  static_assert(node_family<Family>, "geomint::galerkin_vi: invalid node family");
  static_assert(basis_kind<Basis>, "geomint::galerkin_vi: Basis must be lagrange or bernstein");
  static constexpr int m = M;
  using family = Family;
  using basis = Basis;
  static std::string name() { return "galerkin(m=" + std::to_string(M) + ", gauss-" + std::to_string(M) + ")"; }

  template <class Sys, class T>
  using method = schemes::detail::galerkin_method<Sys, T, M, M>;
  template <class Sys, class T>
  struct engine : schemes::detail::step_skeleton<method<Sys, T>> {
    explicit engine(const Sys& sys) : schemes::detail::step_skeleton<method<Sys, T>>(make(sys)) {}

   private:
    /// m-point Gauss-Legendre quadrature of the action (exact for the degree-2m-1 integrands of
    /// polynomial Lagrangians of degree 2 in the path).
    static method<Sys, T> make(const Sys& sys) {
      const auto rule = gauss_legendre_rule<M, T>();
      vec<T, M> w;
      for (int k = 0; k < M; ++k) w[k] = rule.weights[static_cast<std::size_t>(k)];
      return method<Sys, T>(sys, schemes::detail::path_weights<T, M>::template make<Family, Basis>(),
                            schemes::detail::basis_at<0, Basis, Family, M, T, M>(rule.points),
                            schemes::detail::basis_at<1, Basis, Family, M, T, M>(rule.points), w);
    }
  };
};

/// The midpoint-rule variational integrator: the paper's scheme (17) for the harmonic oscillator.
struct midpoint_vi {
  static std::string name() { return "midpoint"; }
  /// The path is the segment from x^k to x^{k+1}: dense output is linear interpolation.
  static constexpr int m = 1;
  using family = equispaced;
  using basis = lagrange;
  template <class Sys, class T>
  using method = schemes::detail::galerkin_method<Sys, T, 1, 1>;
  template <class Sys, class T>
  struct engine : schemes::detail::step_skeleton<method<Sys, T>> {
    /// One quadrature point at 1/2: x = (x^k + x^{k+1}) / 2, xdot = (x^{k+1} - x^k) / tau.
    explicit engine(const Sys& sys)
        : schemes::detail::step_skeleton<method<Sys, T>>(method<Sys, T>(
              sys, schemes::detail::linear_path_weights<T>(), (Eigen::Matrix<T, 1, 2>() << T(1) / T(2), T(1) / T(2)).finished(),
              (Eigen::Matrix<T, 1, 2>() << T(-1), T(1)).finished(), vec<T, 1>::Constant(T(1)))) {}
  };
};

/// The trapezoidal variational integrator (Stormer-Verlet for natural systems).
struct trapezoidal_vi {
  static std::string name() { return "trapezoidal"; }
  /// The path is the segment from x^k to x^{k+1}: dense output is linear interpolation.
  static constexpr int m = 1;
  using family = equispaced;
  using basis = lagrange;
  template <class Sys, class T>
  using method = schemes::detail::galerkin_method<Sys, T, 1, 2>;
  template <class Sys, class T>
  struct engine : schemes::detail::step_skeleton<method<Sys, T>> {
    /// Quadrature points 0 and 1 with weights 1/2; the slope is (x^{k+1} - x^k) / tau at both.
    explicit engine(const Sys& sys)
        : schemes::detail::step_skeleton<method<Sys, T>>(method<Sys, T>(
              sys, schemes::detail::linear_path_weights<T>(), Eigen::Matrix<T, 2, 2>::Identity(),
              (Eigen::Matrix<T, 2, 2>() << T(-1), T(1), T(-1), T(1)).finished(), vec<T, 2>::Constant(T(1) / T(2)))) {}
  };
};

}  // namespace geomint
