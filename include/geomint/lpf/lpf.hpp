#pragma once
/// The local-path-fitting variational integrator (Kong & Yang 2020, section 2).
///
/// On [t_k, t_k + tau] the path is x(t) = sum_j phi_j((t - t_k)/tau) X_j, a polynomial of
/// degree m in a Lagrange (eq. 8) or Bernstein (eq. 13) basis with X_0 = x^k and X_m = x^{k+1}.
/// The Euler-Lagrange equations hold at the interior nodes c_1..c_{m-1} (eq. 12), which makes
/// the integral S of eq. (6) vanish, so dL_d/dx^k = -dL/dxdot(t_k) and dL_d/dx^{k+1} =
/// dL/dxdot(t_{k+1}) (eq. 7, 9, 10); the discrete Euler-Lagrange equation (3) is the momentum
/// match (11). One-step form (DESIGN.md section 3): given (q_k, p_k) solve for X_1..X_m from
/// eq. (12) and dL/dxdot(t_k) = p_k, then p_{k+1} = dL/dxdot(t_{k+1}).

#include <array>
#include <stdexcept>
#include <string>

#include "geomint/core/differentiation.hpp"
#include "geomint/lpf/newton.hpp"

namespace geomint {
namespace detail {

/// Dense copy of a square_array into an Eigen matrix.
template <class T, int N>
Eigen::Matrix<T, N, N> to_matrix(const square_array<T, N>& a) {
  Eigen::Matrix<T, N, N> m;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) m(i, j) = a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return m;
}

/// sum_j W(i, j) X_j: the path (or a derivative) at row i of a weight matrix. Written as a
/// loop: for n = 1 Eigen would turn the product into an inner product of mixed types.
template <class T, int n, int C, class Wm>
vec<T, n> combine(const Eigen::Matrix<T, n, C>& X, const Wm& W, int i) {
  vec<T, n> out = vec<T, n>::Zero();
  for (int j = 0; j < C; ++j) out += W(i, j) * X.col(j);
  return out;
}

/// The inverse of a basis-value matrix (nonsingular for distinct nodes).
template <class T, int N>
mat<T, N> inverse_of(const mat<T, N>& A) {
  mat<T, N> inv;
  if (!invert_small<T, N>(A, inv)) throw std::logic_error("geomint: singular basis collocation matrix");
  return inv;
}

/// Predicted control points of the quadratic q + tau c v + (tau c)^2 a / 2: its values at the
/// nodes mapped to the basis through D0^{-1} (identity for Lagrange).
template <class T, int n, int M>
Eigen::Matrix<T, n, M + 1> predict_controls(const Eigen::Matrix<T, M + 1, M + 1>& D0inv, const std::array<T, M + 1>& c,
                                            const vec<T, n>& q, const vec<T, n>& v, const vec<T, n>& a, const T& tau) {
  Eigen::Matrix<T, n, M + 1> values;
  for (int i = 0; i <= M; ++i) {
    const T s = tau * c[static_cast<std::size_t>(i)];
    values.col(i) = q + s * v + (s * s / T(2)) * a;
  }
  Eigen::Matrix<T, n, M + 1> X;
  for (int j = 0; j <= M; ++j) X.col(j) = combine(values, D0inv, j);
  return X;
}

/// The LPF engine for a system, scalar and degree m; the node family and basis enter only
/// through the weight matrices, so one instantiation serves every family and basis.
template <class Sys, class T, int M>
class lpf_engine {
 public:
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;
  using W = Eigen::Matrix<T, M + 1, M + 1>;
  using controls = Eigen::Matrix<T, n, M + 1>;
  using D = derivatives<Sys, T>;

  lpf_engine(const Sys& sys, const W& D0, const W& D1, const W& D2, const std::array<T, M + 1>& c)
      : sys_(sys), D0_(D0), D1_(D1), D2_(D2), D0inv_(inverse_of(D0)), c_(c) {}

  /// (q_k, p_k) -> (q_{k+1}, p_{k+1}); X receives the control points X_0..X_m of the fitted path.
  step_status one_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                       controls* X_out = nullptr) const {
    V v0;
    if (!D::velocity(sys_, q, p, v0)) return {step_failure::singular_jacobian, 0, 0};
    const V a0 = D::acceleration(sys_, q, v0);
    controls X = predict_controls<T, n, M>(D0inv_, c_, q, v0, a0, tau);
    X.col(0) = q;
    constexpr int N = M * n;
    vec<T, N> z;
    for (int j = 1; j <= M; ++j) z.template segment<n>((j - 1) * n) = X.col(j);
    auto residual = [&](const vec<T, N>& zz, vec<T, N>& F, mat<T, N>& J) {
      for (int j = 1; j <= M; ++j) X.col(j) = zz.template segment<n>((j - 1) * n);
      J.setZero();
      // Row block 0: tau (dL/dxdot(t_k) - p_k) = 0 (eq. 9 with eq. 11).
      {
        const V x = combine(X, D0_, 0), v = combine(X, D1_, 0) / tau;
        const hessian_data<T, n> h = D::hessian(sys_, x, v);
        F.template segment<n>(0) = tau * (h.Lv - p);
        for (int j = 1; j <= M; ++j)
          J.template block<n, n>(0, (j - 1) * n) = (tau * D0_(0, j)) * h.Lvq + D1_(0, j) * h.Lvv;
      }
      // Row blocks 1..m-1: tau^2 E(x(c_i), xdot(c_i), xddot(c_i)) = 0 (eq. 12).
      for (int i = 1; i < M; ++i) fill_el_row(X, tau, i, i, 1, M, F, J);
    };
    step_status st = newton_solve<N, T>(residual, z, opt);
    if (!st) return st;
    for (int j = 1; j <= M; ++j) X.col(j) = z.template segment<n>((j - 1) * n);
    q1 = combine(X, D0_, M);
    p1 = D::gradient(sys_, q1, V(combine(X, D1_, M) / tau)).Lv;
    if (X_out) *X_out = X;
    return st;
  }

  /// dL/dxdot at t_{k} of the path fitted on [t_{k-1}, t_k] through x^{k-1} and x^k: solve
  /// eq. (12) for the interior unknowns with both ends fixed, then eq. (10).
  step_status end_momentum(const V& x0, const V& x1, const T& tau, V& p1, const newton_options<T>& opt) const {
    const V vbar = (x1 - x0) / tau;
    const V a = D::acceleration(sys_, x0, vbar);
    controls X;
    for (int i = 0; i <= M; ++i) {
      const T s = c_[static_cast<std::size_t>(i)];
      X.col(i) = x0 + s * (x1 - x0) + (tau * tau * s * (s - T(1)) / T(2)) * a;
    }
    const controls values = X;
    for (int j = 0; j <= M; ++j) X.col(j) = combine(values, D0inv_, j);
    X.col(0) = x0;
    X.col(M) = x1;
    constexpr int N = (M - 1) * n;
    vec<T, N> z;
    for (int j = 1; j < M; ++j) z.template segment<n>((j - 1) * n) = X.col(j);
    auto residual = [&](const vec<T, N>& zz, vec<T, N>& F, mat<T, N>& J) {
      for (int j = 1; j < M; ++j) X.col(j) = zz.template segment<n>((j - 1) * n);
      J.setZero();
      for (int i = 1; i < M; ++i) fill_el_row(X, tau, i, i - 1, 1, M - 1, F, J);
    };
    step_status st = newton_solve<N, T>(residual, z, opt);
    if (!st) return st;
    for (int j = 1; j < M; ++j) X.col(j) = z.template segment<n>((j - 1) * n);
    p1 = D::gradient(sys_, x1, V(combine(X, D1_, M) / tau)).Lv;
    return st;
  }

 private:
  /// Row block `row` of F and J: tau^2 E at node i, derivatives for unknowns X_jlo..X_jhi.
  template <int N>
  void fill_el_row(const controls& X, const T& tau, int i, int row, int jlo, int jhi, vec<T, N>& F,
                   mat<T, N>& J) const {
    const V x = combine(X, D0_, i);
    const V v = combine(X, D1_, i) / tau;
    const V a = combine(X, D2_, i) / (tau * tau);
    const el_data<T, n> e = D::euler_lagrange(sys_, x, v, a);
    const T tau2 = tau * tau;
    F.template segment<n>(row * n) = tau2 * e.E;
    for (int j = jlo; j <= jhi; ++j)
      J.template block<n, n>(row * n, (j - jlo) * n) =
          (tau2 * D0_(i, j)) * e.Ex + (tau * D1_(i, j)) * e.Ev + D2_(i, j) * e.Ea;
  }

  Sys sys_;
  W D0_, D1_, D2_, D0inv_;
  std::array<T, M + 1> c_;
};

}  // namespace detail

/// The LPF scheme of degree m on a node family in a basis: `lpf<4, gauss_interior, lagrange>`.
template <int M, class Family = equispaced, class Basis = lagrange>
struct lpf {
  static_assert(M >= 2, "geomint::lpf: m must be >= 2 (eq. 12 needs at least one interior node)");
  static_assert(M <= max_floating_m, "geomint::lpf: m must be <= max_floating_m (16)");
  static_assert(node_family<Family>,
                "geomint::lpf: Family must be equispaced, gauss_lobatto, chebyshev_lobatto or gauss_interior");
  static_assert(basis_kind<Basis>, "geomint::lpf: Basis must be lagrange or bernstein");
  static constexpr int m = M;
  using family = Family;
  using basis = Basis;
  static std::string name() {
    return "lpf(m=" + std::to_string(M) + ", " + std::string(Family::name) + ", " + std::string(Basis::name) + ")";
  }

  template <class Sys, class T>
  struct engine : detail::lpf_engine<Sys, T, M> {
    explicit engine(const Sys& sys)
        : detail::lpf_engine<Sys, T, M>(sys, detail::to_matrix<T, M + 1>(differentiation_weights<0, Family, M, T, Basis>()),
                                        detail::to_matrix<T, M + 1>(differentiation_weights<1, Family, M, T, Basis>()),
                                        detail::to_matrix<T, M + 1>(differentiation_weights<2, Family, M, T, Basis>()),
                                        nodes<Family, M, T>()) {}
  };
};

/// Readable aliases. The paper's schemes: (16), (18), (19) are m = 2, 3, 4 on equispaced
/// nodes for the harmonic oscillator; (21) and (22) are m = 2 with the Lagrange (eq. 8) and
/// Bernstein (eq. 13) bases.
template <int M, class Basis = lagrange>
using lpf_equispaced = lpf<M, equispaced, Basis>;
template <int M, class Basis = lagrange>
using lpf_gauss = lpf<M, gauss_interior, Basis>;
template <int M, class Basis = lagrange>
using lpf_lobatto = lpf<M, gauss_lobatto, Basis>;
template <int M, class Basis = lagrange>
using lpf_chebyshev = lpf<M, chebyshev_lobatto, Basis>;
using scheme16 = lpf<2, equispaced, lagrange>;
using scheme18 = lpf<3, equispaced, lagrange>;
using scheme19 = lpf<4, equispaced, lagrange>;
using scheme21 = lpf<2, equispaced, lagrange>;
using scheme22 = lpf<2, equispaced, bernstein>;

}  // namespace geomint
