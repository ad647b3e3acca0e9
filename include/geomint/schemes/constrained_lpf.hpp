#pragma once
/// The constrained LPF integrator (LPF paper, eq. 4, 5, 14; docs/design.md, "Constraints").
///
/// On [t_k, t_k + tau] the path is x(t) = sum_j phi_j((t - t_k)/tau) X_j as in the free
/// integrator. At the interior nodes c_1..c_{m-1} the constrained Euler-Lagrange equations (4)
/// hold with multipliers lambda_i, and f(x(c_i)) = 0. At t_k the discrete equation (5) allows a
/// momentum jump along grad f(x^k); it is split RATTLE-fashion between the two steps that meet
/// at t_k, so that every stored momentum satisfies the hidden constraint G(q) qdot = 0:
///
///   one step (q_k, p_k) -> (q_{k+1}, p_{k+1}), unknowns X_1..X_m, mu_1..mu_{m-1}, nu:
///     dL/dqdot(t_k) = p_k - G(q_k)^T nu / tau                       (left end, eq. 9 and 5)
///     E(x_i, xdot_i, xddot_i) = G(x_i)^T mu_i / tau^2, f(x_i) = 0   (interior, eq. 4)
///     f(X_m) = 0                                                     (eq. 5 at t_{k+1})
///   then p_{k+1} = dL/dqdot(t_{k+1}) - G(q_{k+1})^T Lambda with Lambda chosen so that the
///   velocity w of p_{k+1} satisfies G(q_{k+1}) w = 0 (the hidden constraint).
///
/// Adding the two half-jumps that meet at t_k gives eq. (5) with tau lambda^k = nu + Lambda,
/// and f(x^k) = 0 at every step. Dropping the jump and the end condition (nu = 0, no f(X_m)
/// = 0) leaves the paper's printed scheme (23) for the particle on a circle (`endpoint_terms`).
/// mu = tau^2 lambda and nu are the unknowns, so every Jacobian column is O(1).

#include <array>
#include <string>

#include "geomint/mechanics/constraint.hpp"
#include "geomint/schemes/path_method.hpp"

namespace geomint {

/// Whether the two-step form keeps eq. (5)'s terms at t_k (multiplier and f(x^k) = 0).
enum class endpoint_terms { keep, drop };

namespace schemes::detail {

/// One constrained LPF step as a method of the step skeleton (step_skeleton.hpp, path_method.hpp). Unknowns:
/// the increments Y_1..Y_m of the path (X_j = q_k + Y_j), the scaled multipliers
/// mu_1..mu_{m-1} of the interior nodes and nu of the jump at t_k. With `drop`, the two-step
/// form's residual leaves out nu and the end condition f(X_m) = 0 (the paper's scheme (23)).
template <class Sys, class Con, class T, int M>
class constrained_lpf_method : public path_method<Sys, T, M, M * (Sys::dof + Con::count)> {
  using base = path_method<Sys, T, M, M * (Sys::dof + Con::count)>;
  using base::sys_;
  using base::w_;

 public:
  using base::n;
  using base::unknowns;
  using typename base::controls;
  using typename base::D;
  using typename base::V;
  using typename base::weights;
  using typename base::Z;
  static constexpr int c = Con::count;
  using F = constraint_derivatives<Con, T, n>;

  constrained_lpf_method(const Sys& sys, const Con& con, const weights& w) : base(sys, w), con_(con) {}

  const Sys& system() const { return sys_; }
  const Con& constraints() const { return con_; }

  /// With a carry (compensated summation) the path starts at q + carry.q and the momentum row
  /// matches p + carry.p (path_method::from_start, momentum_mismatch).
  void residual(const V& q, const V& p, const T& tau, const Z& z, Z& Fv, square_matrix<T, unknowns>* J,
                const phase_carry<T, n>* carry = nullptr) const {
    forward_residual<unknowns, true>(q, p, tau, z, Fv, J, carry);
  }

  /// q_{k+1} = X_m; p_{k+1} = dL/dqdot(t_{k+1}) projected onto the hidden constraint.
  /// q as an increment (compensated with a carry), the projected momentum as a value (end_update).
  step_status finish(const V& q, const V&, const T& tau, const Z& z, end_update<T, n>& u,
                     const phase_carry<T, n>* carry = nullptr) const {
    const controls Y = unpack_path<T, n, M, unknowns>(z);
    u.q = w_.template value<n>(Y, M);
    const V q1 = this->from_start(q, u.q, carry);
    const V p_end = D::gradient(sys_, q1, V(combine(Y, w_.D1, M) / tau)).Lv;
    step_status st;
    u.p_is_increment = false;
    if (!project_momentum(q1, p_end, u.p)) st.reason = step_failure::singular_jacobian;
    return st;
  }

  /// The two-step form (x^{k-1}, x^k) -> x^{k+1}: momentum at t_k from the constrained path on
  /// [t_{k-1}, t_k], then the forward solve with or without eq. (5)'s end terms.
  step_status two_step(const V& x_prev, const V& x_curr, const T& tau, endpoint_terms ends, V& x_next,
                       const newton_options<T>& opt) const {
    V p_minus;
    step_status st = end_momentum(x_prev, x_curr, tau, p_minus, opt);
    if (!st) return st;
    if (ends == endpoint_terms::keep) return forward_solve<unknowns, true>(x_curr, p_minus, tau, opt, x_next);
    return forward_solve<M * n + (M - 1) * c, false>(x_curr, p_minus, tau, opt, x_next);
  }

  /// dL/dqdot at t_k of the path on [t_{k-1}, t_k] through x^{k-1}, x^k whose interior nodes
  /// satisfy eq. (4) and f = 0 (eq. 10).
  step_status end_momentum(const V& x0, const V& x1, const T& tau, V& p1, const newton_options<T>& opt) const {
    controls X = this->pinned_controls(this->segment_values(x0, x1), x0, x1);
    constexpr int N = (M - 1) * (n + c);
    vec<T, N> z = vec<T, N>::Zero();
    for (int j = 1; j < M; ++j) z.template segment<n>((j - 1) * n) = X.col(j);
    constexpr int mu_offset = (M - 1) * n;
    auto residual = [&](const vec<T, N>& zz, vec<T, N>& Fv, square_matrix<T, N>& J) {
      for (int j = 1; j < M; ++j) X.col(j) = zz.template segment<n>((j - 1) * n);
      Fv.setZero();
      J.setZero();
      for (int i = 1; i < M; ++i)
        interior_rows<N>(X, zz, tau, i, /*row=*/(i - 1), /*first unknown=*/1, /*last unknown=*/M - 1, mu_offset,
                         (M - 1) * n, Fv, &J);
    };
    step_status st = newton_solve<N, T>(residual, z, opt);
    if (!st) return st;
    for (int j = 1; j < M; ++j) X.col(j) = z.template segment<n>((j - 1) * n);
    p1 = D::gradient(sys_, x1, V(combine(X, w_.D1, M) / tau)).Lv;
    return st;
  }

  /// The momentum p with dL/dqdot(q, w) = p_end - G(q)^T Lambda and G(q) w = 0 (Newton on
  /// (w, Lambda); one linear solve for a natural system). False if the saddle system is singular.
  bool project_momentum(const V& q, const V& p_end, V& p) const {
    const auto g = F::first(con_, q);
    constexpr int K = n + c;
    V w;
    if (!D::velocity(sys_, q, p_end, w)) return false;
    vec<T, c> Lambda = vec<T, c>::Zero();
    const T eps = std::numeric_limits<T>::epsilon();
    for (int it = 0; it < 50; ++it) {
      const hessian_data<T, n> h = D::hessian(sys_, q, w);
      vec<T, K> r;
      r.template head<n>() = h.Lv + g.G.transpose() * Lambda - p_end;
      r.template tail<c>() = g.G * w;
      mat<T, K> A = mat<T, K>::Zero();
      A.template topLeftCorner<n, n>() = h.Lvv;
      A.template topRightCorner<n, c>() = g.G.transpose();
      A.template bottomLeftCorner<c, n>() = g.G;
      vec<T, K> delta;
      if (!solve_small<T, K>(A, vec<T, K>(-r), delta)) return false;
      w += delta.template head<n>();
      Lambda += delta.template tail<c>();
      if (delta.template lpNorm<Eigen::Infinity>() <= T(16) * eps * (T(1) + w.template lpNorm<Eigen::Infinity>())) {
        p = D::gradient(sys_, q, w).Lv;
        return all_finite(p);
      }
    }
    return false;
  }

 private:
  /// The forward equations from (q_k, p) with X_0 = q_k. Rows 0..n-1: tau (dL/dqdot(t_k) - p) +
  /// G(q_k)^T nu = 0 (eq. 9 with the jump of eq. 5); interior nodes: eq. (4) and f = 0; with
  /// `keep_ends`, f(X_m) = 0 at t_{k+1} (eq. 5). J (if not null) = dF/dz.
  template <int N, bool keep_ends>
  void forward_residual(const V& q, const V& p, const T& tau, const vec<T, N>& z, vec<T, N>& Fv, square_matrix<T, N>* J,
                        const phase_carry<T, n>* carry = nullptr) const {
    constexpr int mu_offset = M * n;                                 // mu_1..mu_{m-1}
    [[maybe_unused]] constexpr int nu_offset = M * n + (M - 1) * c;  // nu (keep only)
    controls X = unpack_path<T, n, M, N>(z);
    for (int j = 0; j <= M; ++j) X.col(j) = this->from_start(q, V(X.col(j)), carry);
    const V x0 = X.col(0);  // q, or q + carry.q
    Fv.setZero();
    if (J) J->setZero();
    const V v = combine(X, w_.D1, 0) / tau;
    if (J) {
      const hessian_data<T, n> h = D::hessian(sys_, x0, v);
      Fv.template segment<n>(0) = tau * this->momentum_mismatch(h.Lv, p, carry);
      for (int j = 1; j <= M; ++j)
        J->template block<n, n>(0, (j - 1) * n) = (tau * w_.D0(0, j)) * h.Lvq + w_.D1(0, j) * h.Lvv;
    } else {
      Fv.template segment<n>(0) = tau * this->momentum_mismatch(D::momentum_of(sys_, x0, v), p, carry);
    }
    if constexpr (keep_ends) {
      const auto g0 = F::first(con_, x0);
      Fv.template segment<n>(0) += g0.G.transpose() * z.template segment<c>(nu_offset);
      if (J) J->template block<n, c>(0, nu_offset) = g0.G.transpose();
    }
    for (int i = 1; i < M; ++i) interior_rows<N>(X, z, tau, i, i, 1, M, mu_offset, M * n, Fv, J);
    if constexpr (keep_ends) {
      const auto gm = F::first(con_, V(X.col(M)));
      Fv.template segment<c>(nu_offset) = gm.f;
      if (J) J->template block<c, n>(nu_offset, (M - 1) * n) = gm.G;
    }
  }

  /// The forward solve of the two-step form (no step memory), x_next = X_m.
  template <int N, bool keep_ends>
  step_status forward_solve(const V& q, const V& p, const T& tau, const newton_options<T>& opt, V& x_next) const {
    V v0;
    if (!D::velocity(sys_, q, p, v0)) return {step_failure::singular_jacobian, 0, 0};
    const V a0 = D::acceleration(sys_, q, v0);
    vec<T, N> z = vec<T, N>::Zero();
    pack_path<T, n, M, N>(w_.template quadratic<n>(v0, a0, tau), z);
    auto residual = [&](const vec<T, N>& zz, vec<T, N>& Fv, square_matrix<T, N>* J) {
      forward_residual<N, keep_ends>(q, p, tau, zz, Fv, J);
    };
    const T scale = std::numeric_limits<T>::epsilon() * q.template lpNorm<Eigen::Infinity>();
    const step_status st = newton_solve_simplified<N, T>(residual, z, opt, scale);
    if (st) x_next = q + w_.template value<n>(unpack_path<T, n, M, N>(z), M);
    return st;
  }

  /// Rows of interior node i: tau^2 E(x_i, xdot_i, xddot_i) - G(x_i)^T mu_i = 0 at row block
  /// `row` (n rows) and f(x_i) = 0 at rows constraint_rows + (i-1) c; derivatives for the
  /// unknowns X_jlo..X_jhi (stored from column 0) and mu_i (column mu_offset + (i-1) c).
  template <int N>
  void interior_rows(const controls& X, const vec<T, N>& z, const T& tau, int i, int row, int jlo, int jhi,
                     int mu_offset, int constraint_rows, vec<T, N>& Fv, square_matrix<T, N>* J) const {
    const V x = combine(X, w_.D0, i);
    const V v = combine(X, w_.D1, i) / tau;
    const V a = combine(X, w_.D2, i) / (tau * tau);
    const int mu_col = mu_offset + (i - 1) * c;
    const vec<T, c> mu = z.template segment<c>(mu_col);
    const T tau2 = tau * tau;
    const int f_row = constraint_rows + (i - 1) * c;
    if (!J) {
      const auto g = F::first(con_, x);
      Fv.template segment<n>(row * n) = tau2 * D::el_residual(sys_, x, v, a) - g.G.transpose() * mu;
      Fv.template segment<c>(f_row) = g.f;
      return;
    }
    const el_data<T, n> e = D::euler_lagrange(sys_, x, v, a);
    const auto g = F::second(con_, x);
    mat<T, n> curvature = mat<T, n>::Zero();  // sum_l mu_l H_l
    for (int l = 0; l < c; ++l) curvature += mu[l] * g.H[static_cast<std::size_t>(l)];
    Fv.template segment<n>(row * n) = tau2 * e.E - g.G.transpose() * mu;
    Fv.template segment<c>(f_row) = g.f;
    for (int j = jlo; j <= jhi; ++j) {
      const int col = (j - jlo) * n;
      J->template block<n, n>(row * n, col) =
          w_.D0(i, j) * (tau2 * e.Ex - curvature) + (tau * w_.D1(i, j)) * e.Ev + w_.D2(i, j) * e.Ea;
      J->template block<c, n>(f_row, col) = w_.D0(i, j) * g.G;
    }
    J->template block<n, c>(row * n, mu_col) = -g.G.transpose();
  }

  Con con_;
};

}  // namespace schemes::detail

/// The constrained LPF scheme: `constrained_lpf<2, equispaced, lagrange>`.
template <int M, class Family = equispaced, class Basis = lagrange>
struct constrained_lpf {
  static_assert(M >= 2, "geomint::constrained_lpf: m must be >= 2 (eq. 4 needs an interior node)");
  static_assert(M <= max_floating_m, "geomint::constrained_lpf: m must be <= max_floating_m (16)");
  static_assert(node_family<Family>,
                "geomint::constrained_lpf: Family must be a node family (geomint::node_family, core/nodes.hpp)");
  static_assert(basis_kind<Basis>, "geomint::constrained_lpf: Basis must be lagrange or bernstein");
  static constexpr int m = M;
  using family = Family;
  using basis = Basis;
  static std::string name() {
    return "constrained-lpf(m=" + std::to_string(M) + ", " + std::string(Family::name) + ", " +
           std::string(Basis::name) + ")";
  }

  template <class Sys, class Con, class T>
  using method = schemes::detail::constrained_lpf_method<Sys, Con, T, M>;
  template <class Sys, class Con, class T>
  struct engine : schemes::detail::step_skeleton<method<Sys, Con, T>> {
    engine(const Sys& sys, const Con& con)
        : schemes::detail::step_skeleton<method<Sys, Con, T>>(
              method<Sys, Con, T>(sys, con, schemes::detail::path_weights<T, M>::template make<Family, Basis>())) {}
    const Sys& system() const { return this->method().system(); }
    const Con& constraints() const { return this->method().constraints(); }
    bool project_momentum(const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& p_end, vec<T, Sys::dof>& p) const {
      return this->method().project_momentum(q, p_end, p);
    }
    step_status two_step(const vec<T, Sys::dof>& x_prev, const vec<T, Sys::dof>& x_curr, const T& tau,
                         endpoint_terms ends, vec<T, Sys::dof>& x_next, const newton_options<T>& opt) const {
      return this->method().two_step(x_prev, x_curr, tau, ends, x_next, opt);
    }
  };
};

}  // namespace geomint
