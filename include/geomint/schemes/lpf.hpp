#pragma once
/// The local-path-fitting variational integrator (Kong & Yang 2020, section 2).
///
/// On [t_k, t_k + tau] the path is x(t) = sum_j phi_j((t - t_k)/tau) X_j, a polynomial of
/// degree m in a Lagrange (eq. 8) or Bernstein (eq. 13) basis with X_0 = x^k and X_m = x^{k+1}.
/// The Euler-Lagrange equations hold at the interior nodes c_1..c_{m-1} (eq. 12), which makes
/// the integral S of eq. (6) vanish, so dL_d/dx^k = -dL/dxdot(t_k) and dL_d/dx^{k+1} =
/// dL/dxdot(t_{k+1}) (eq. 7, 9, 10); the discrete Euler-Lagrange equation (3) is the momentum
/// match (11). One-step form (docs/design.md, "The one-step form"): given (q_k, p_k) solve for X_1..X_m from
/// eq. (12) and dL/dxdot(t_k) = p_k, then p_{k+1} = dL/dxdot(t_{k+1}).

#include <array>
#include <atomic>
#include <limits>
#include <stdexcept>
#include <string>

#include "geomint/core/differentiation.hpp"
#include "geomint/solvers/newton.hpp"

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

/// What an engine remembers of its last step, to start the next one well when it continues
/// from where the last one ended (same q, p and tau): the path, to extrapolate as the predictor,
/// and the factorised Newton matrix, to reuse. Guarded by a try-lock: a call that finds it
/// busy (the same engine used from another thread) simply does not use it. A copy starts empty.
template <class T, int n, int M>
struct lpf_step_memory {
  std::atomic_flag busy;  // clear on construction (C++20)
  bool valid = false;
  T tau{};
  vec<T, n> q1, p1;
  Eigen::Matrix<T, n, M + 1> Y;
  jacobian_cache<T, M * n> jacobian;
  lpf_step_memory() = default;
  lpf_step_memory(const lpf_step_memory&) : lpf_step_memory() {}
  lpf_step_memory& operator=(const lpf_step_memory&) {
    valid = false;
    jacobian.valid = false;
    return *this;
  }
};

/// Holds an atomic_flag for the lifetime of a scope if it was free.
class try_lock_flag {
 public:
  explicit try_lock_flag(std::atomic_flag& f) : flag_(f), owned_(!f.test_and_set(std::memory_order_acquire)) {}
  ~try_lock_flag() {
    if (owned_) flag_.clear(std::memory_order_release);
  }
  try_lock_flag(const try_lock_flag&) = delete;
  try_lock_flag& operator=(const try_lock_flag&) = delete;
  bool owned() const { return owned_; }

 private:
  std::atomic_flag& flag_;
  bool owned_;
};

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
      : sys_(sys), D0_(D0), D1_(D1), D2_(D2), D0inv_(inverse_of(D0)), c_(c),
        d0_identity_(D0 == W::Identity()), extrapolate_(extrapolation(D0, D0inv_, c)) {
    interior_quadrature(c, quad_b_, quad_beta_);
    if constexpr (natural_system<Sys>) minv_ = inverse_of<T, n>(Sys::template mass_matrix<T>());
  }

  /// (q_k, p_k) -> (q_{k+1}, p_{k+1}); X receives the control points X_0..X_m of the fitted path.
  ///
  /// The unknowns are the increments Y_j = X_j - q_k (j = 1..m): both bases are partitions of
  /// unity, so x(c_i) = q_k + sum_j D0(i, j) Y_j and the derivative rows act on Y alone. The
  /// increments are O(tau), so the differentiation weights do not amplify the round-off of q_k.
  /// Solved by simplified Newton (newton.hpp). Predictor: when the step continues the engine's
  /// previous one (q_k, p_k and tau equal to its result), the previous path extrapolated to
  /// [t_k, t_k + tau] (error O(tau^(m+1))), and the previous step's factorised Newton matrix is
  /// reused while it contracts well; otherwise the quadratic Taylor polynomial
  /// q + s qdot + s^2 qddot / 2 and a fresh matrix. Either way the result solves the same
  /// equations to the Newton tolerance.
  step_status one_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                       controls* X_out = nullptr) const {
    try_lock_flag lock(memory_.busy);
    lpf_step_memory<T, n, M>* mem = lock.owned() ? &memory_ : nullptr;
    controls Y;
    step_status st;
    bool done = false;
    if (mem && mem->valid && tau == mem->tau && q == mem->q1 && p == mem->p1) {
      for (int i = 0; i <= M; ++i) Y.col(i) = combine(mem->Y, extrapolate_, i);
      Y.col(0).setZero();
      st = solve(q, p, tau, opt, Y, &mem->jacobian);
      done = static_cast<bool>(st);
    }
    if (!done) {
      V v0;
      if (!D::velocity(sys_, q, p, v0)) {
        if (mem) mem->valid = false;
        return {step_failure::singular_jacobian, 0, 0};
      }
      const V a0 = D::acceleration(sys_, q, v0);
      Y = predict_controls<T, n, M>(D0inv_, c_, V::Zero(), v0, a0, tau);
      Y.col(0).setZero();
      if (mem) mem->jacobian.valid = false;
      st = solve(q, p, tau, opt, Y, mem ? &mem->jacobian : nullptr);
    }
    if (!st) {
      if (mem) mem->valid = false;
      return st;
    }
    if constexpr (natural_system<Sys>) {
      // At the solution M xddot(c_i) = L_q(x(c_i)) at the m-1 interior nodes, and xddot has
      // degree m-2, so it is interpolated exactly there: p_{k+1} = p_k + tau sum_i b_i L_q(x_i)
      // and q_{k+1} = q_k + tau M^{-1} p_k + tau^2 M^{-1} sum_i beta_i L_q(x_i), with b_i and
      // beta_i the integrals of l_i(s) and (1 - s) l_i(s) over [0, 1]. The same map as
      // differentiating the path at t_{k+1}, but the Newton and round-off errors of the
      // increments enter only through tau^2 L_qq, not through D1 / tau (as in an RKN update).
      V sb = V::Zero(), sbeta = V::Zero();
      for (int i = 1; i < M; ++i) {
        const V x = d0_identity_ ? V(q + Y.col(i)) : V(q + combine(Y, D0_, i));
        const V f = D::gradient(sys_, x, V::Zero()).Lq;
        sb += quad_b_[i - 1] * f;
        sbeta += quad_beta_[i - 1] * f;
      }
      p1 = p + tau * sb;
      V dq;  // tau M^{-1} (p + tau sbeta), written out (for n = 1 Eigen's product is a mixed-type inner product)
      for (int r = 0; r < n; ++r) {
        T sum(0);
        for (int c = 0; c < n; ++c) sum += minv_(r, c) * (p[c] + tau * sbeta[c]);
        dq[r] = tau * sum;
      }
      q1 = q + dq;
    } else {
      q1 = q + (d0_identity_ ? V(Y.col(M)) : combine(Y, D0_, M));
      p1 = D::momentum_of(sys_, q1, V(combine(Y, D1_, M) / tau));
    }
    if (X_out) {
      for (int j = 0; j <= M; ++j) X_out->col(j) = q + Y.col(j);
    }
    if (mem) {
      mem->valid = true;
      mem->tau = tau;
      mem->q1 = q1;
      mem->p1 = p1;
      mem->Y = Y;
      // Reuse the matrix next step only while it contracts fast enough to reach eps from O(1)
      // in six corrections (rate^6 <= eps: about 2e-3 in double, 5e-9 in 50 digits);
      // otherwise a fresh one is cheaper than many slow iterations.
      const T r2 = mem->jacobian.rate * mem->jacobian.rate;
      if (r2 * r2 * r2 > std::numeric_limits<T>::epsilon()) mem->jacobian.valid = false;
    }
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
  /// Solves the one-step equations for the increments Y_1..Y_m from the predictor in Y.
  step_status solve(const V& q, const V& p, const T& tau, const newton_options<T>& opt, controls& Y,
                    jacobian_cache<T, M * n>* jac) const {
    constexpr int N = M * n;
    vec<T, N> z;
    for (int j = 1; j <= M; ++j) z.template segment<n>((j - 1) * n) = Y.col(j);
    const T tau2 = tau * tau;
    auto residual = [&](const vec<T, N>& zz, vec<T, N>& F, mat<T, N>* J) {
      for (int j = 1; j <= M; ++j) Y.col(j) = zz.template segment<n>((j - 1) * n);
      if (J) J->setZero();
      // Row block 0: tau (dL/dxdot(t_k) - p_k) = 0 (eq. 9 with eq. 11).
      {
        const V x = d0_identity_ ? q : V(q + combine(Y, D0_, 0));
        const V v = combine(Y, D1_, 0) / tau;
        if (J) {
          const hessian_data<T, n> h = D::hessian(sys_, x, v);
          F.template segment<n>(0) = tau * (h.Lv - p);
          for (int j = 1; j <= M; ++j)
            J->template block<n, n>(0, (j - 1) * n) = (tau * D0_(0, j)) * h.Lvq + D1_(0, j) * h.Lvv;
        } else {
          F.template segment<n>(0) = tau * (D::momentum_of(sys_, x, v) - p);
        }
      }
      // Row blocks 1..m-1: tau^2 E(x(c_i), xdot(c_i), xddot(c_i)) = 0 (eq. 12).
      for (int i = 1; i < M; ++i) {
        const V x = d0_identity_ ? V(q + Y.col(i)) : V(q + combine(Y, D0_, i));
        const V v = combine(Y, D1_, i) / tau;
        const V a = combine(Y, D2_, i) / tau2;
        if (J) {
          const el_data<T, n> e = D::euler_lagrange(sys_, x, v, a);
          F.template segment<n>(i * n) = tau2 * e.E;
          for (int j = 1; j <= M; ++j)
            J->template block<n, n>(i * n, (j - 1) * n) =
                (tau2 * D0_(i, j)) * e.Ex + (tau * D1_(i, j)) * e.Ev + D2_(i, j) * e.Ea;
        } else {
          F.template segment<n>(i * n) = tau2 * D::el_residual(sys_, x, v, a);
        }
      }
    };
    const T scale = std::numeric_limits<T>::epsilon() * q.template lpNorm<Eigen::Infinity>();
    const step_status st = newton_solve_simplified<N, T>(residual, z, opt, scale, jac);
    for (int j = 1; j <= M; ++j) Y.col(j) = z.template segment<n>((j - 1) * n);
    return st;
  }

  /// Maps the increments of a step's path to the predicted increments of the next step:
  /// values at the nodes of the next interval, 1 + c_i, by Lagrange interpolation through the
  /// path's node values, minus its end value, then back to the basis through D0^{-1}.
  static W extrapolation(const W& D0, const W& D0inv, const std::array<T, M + 1>& c) {
    W L;  // L(i, k) = l_k(1 + c_i), the Lagrange polynomials on the nodes
    for (int i = 0; i <= M; ++i)
      for (int k = 0; k <= M; ++k) {
        const T t = T(1) + c[static_cast<std::size_t>(i)];
        T l(1);
        for (int j = 0; j <= M; ++j)
          if (j != k)
            l *= (t - c[static_cast<std::size_t>(j)]) / (c[static_cast<std::size_t>(k)] - c[static_cast<std::size_t>(j)]);
        L(i, k) = l;
      }
    W values = L * D0;  // values at 1 + c_i of the path with controls e_j
    for (int i = 0; i <= M; ++i) values.row(i) -= D0.row(M);
    return D0inv * values;
  }

  /// b_i = int_0^1 l_i(s) ds and beta_i = int_0^1 (1 - s) l_i(s) ds for the Lagrange
  /// polynomials l_i on the interior nodes c_1..c_{m-1} (degree m-2), by the (m-1)-point
  /// Gauss-Legendre rule (exact to degree 2m-3 >= m-1).
  static void interior_quadrature(const std::array<T, M + 1>& c, std::array<T, M - 1>& b, std::array<T, M - 1>& beta) {
    const auto g = nodes<gauss_interior, M, T>();  // ends + the M-1 Gauss points
    b.fill(T(0));
    beta.fill(T(0));
    for (int k = 1; k < M; ++k) {
      const T gk = g[static_cast<std::size_t>(k)];
      const T dp = legendre_at<T>(M - 1, gk).dp;
      const T w = T(1) / (T(4) * gk * (T(1) - gk) * dp * dp);
      for (int i = 1; i < M; ++i) {
        T l(1);
        for (int j = 1; j < M; ++j)
          if (j != i)
            l *= (gk - c[static_cast<std::size_t>(j)]) / (c[static_cast<std::size_t>(i)] - c[static_cast<std::size_t>(j)]);
        b[static_cast<std::size_t>(i - 1)] += w * l;
        beta[static_cast<std::size_t>(i - 1)] += w * (T(1) - gk) * l;
      }
    }
  }

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
  bool d0_identity_;  // Lagrange basis: x(c_i) = X_i
  W extrapolate_;
  std::array<T, M - 1> quad_b_, quad_beta_;
  mat<T, n> minv_ = mat<T, n>::Zero();  // M^{-1} (natural systems)
  mutable lpf_step_memory<T, n, M> memory_;
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
