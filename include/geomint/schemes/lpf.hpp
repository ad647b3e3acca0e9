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
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "geomint/methods/collocation_rkn.hpp"
#include "geomint/schemes/gauss_fixed_point.hpp"
#include "geomint/schemes/path_method.hpp"

namespace geomint {
namespace schemes::detail {

/// "lpf(m=4, gauss-interior, lagrange)": one function for every (m, family, basis); a solver
/// chosen explicitly is named last: "lpf(m=4, gauss-interior, lagrange, newton)".
inline std::string lpf_name(int m, std::string_view family, std::string_view basis, std::string_view solver = {}) {
  return "lpf(m=" + std::to_string(m) + ", " + std::string(family) + ", " + std::string(basis) +
         (solver.empty() ? std::string() : ", " + std::string(solver)) + ")";
}

/// One LPF step as a method of the step skeleton (step_skeleton.hpp, path_method.hpp). The unknowns are the
/// increments Y_j = X_j - q_k (j = 1..m): both bases are partitions of unity, so
/// x(c_i) = q_k + sum_j D0(i, j) Y_j and the derivative rows act on Y alone. The increments are
/// O(tau), so the differentiation weights do not amplify the round-off of q_k.
template <class Sys, class T, int M>
class lpf_method : public path_method<Sys, T, M> {
  using base = path_method<Sys, T, M>;
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

  lpf_method(const Sys& sys, const weights& w) : base(sys, w) {
    // b_i = int_0^1 l_i and beta_i = int_0^1 (1 - s) l_i for the Lagrange polynomials l_i on the
    // interior nodes: the weights b and bbar of the collocation method on them.
    std::array<T, M - 1> interior;
    for (int i = 1; i < M; ++i) interior[static_cast<std::size_t>(i - 1)] = w_.c[static_cast<std::size_t>(i)];
    const methods::rkn<T, M - 1> tableau = methods::collocation_rkn<T, M - 1>(interior);
    quad_b_ = tableau.b;
    quad_beta_ = tableau.bbar;
    if constexpr (natural_system<Sys>) minv_ = inverse_of<T, n>(Sys::template mass_matrix<T>());
  }

  /// Row block 0: tau (dL/dxdot(t_k) - p_k) = 0 (eq. 9 with eq. 11); row blocks 1..m-1:
  /// tau^2 E(x(c_i), xdot(c_i), xddot(c_i)) = 0 (eq. 12). With a carry (compensated summation)
  /// the path starts at q + carry.q and row 0 matches p + carry.p.
  void residual(const V& q, const V& p, const T& tau, const Z& z, Z& F, square_matrix<T, unknowns>* J,
                const phase_carry<T, n>* carry = nullptr) const {
    const controls Y = unpack_path<T, n, M, unknowns>(z);
    const T tau2 = tau * tau;
    if (J) J->setZero();
    {
      const V x = this->from_start(q, w_.template value<n>(Y, 0), carry);
      const V v = combine(Y, w_.D1, 0) / tau;
      if (J) {
        const hessian_data<T, n> h = D::hessian(sys_, x, v);
        F.template segment<n>(0) = tau * this->momentum_mismatch(h.Lv, p, carry);
        for (int j = 1; j <= M; ++j)
          J->template block<n, n>(0, (j - 1) * n) = (tau * w_.D0(0, j)) * h.Lvq + w_.D1(0, j) * h.Lvv;
      } else {
        F.template segment<n>(0) = tau * this->momentum_mismatch(D::momentum_of(sys_, x, v), p, carry);
      }
    }
    for (int i = 1; i < M; ++i) {
      const V x = this->from_start(q, w_.template value<n>(Y, i), carry);
      const V a = combine(Y, w_.D2, i) / tau2;
      // Natural systems: E = L_q(x) - M a needs no velocity and E_v = 0, so their rows form no
      // D1 Y / tau and no product with the zero block (the same values).
      V v = V::Zero();
      if constexpr (!natural_system<Sys>) v = combine(Y, w_.D1, i) / tau;
      if (J) {
        const el_data<T, n> e = D::euler_lagrange(sys_, x, v, a);
        F.template segment<n>(i * n) = tau2 * e.E;
        for (int j = 1; j <= M; ++j) {
          auto block = J->template block<n, n>(i * n, (j - 1) * n);
          if constexpr (natural_system<Sys>)
            block = (tau2 * w_.D0(i, j)) * e.Ex + w_.D2(i, j) * e.Ea;
          else
            block = (tau2 * w_.D0(i, j)) * e.Ex + (tau * w_.D1(i, j)) * e.Ev + w_.D2(i, j) * e.Ea;
        }
      } else {
        F.template segment<n>(i * n) = tau2 * D::el_residual(sys_, x, v, a);
      }
    }
  }

  /// The end update. Natural systems: at the solution M xddot(c_i) = L_q(x(c_i)) at the m-1
  /// interior nodes, and xddot has degree m-2, so it is interpolated exactly there:
  /// p_{k+1} = p_k + tau sum_i b_i L_q(x_i) and q_{k+1} = q_k + tau M^{-1} p_k +
  /// tau^2 M^{-1} sum_i beta_i L_q(x_i). The same map as differentiating the path at t_{k+1},
  /// but the Newton and round-off errors of the increments enter only through tau^2 L_qq, not
  /// through D1 / tau (as in an RKN update). Other systems: p_{k+1} = dL/dxdot(t_{k+1}) (eq. 10).
  /// Produced as increments (u.q = q_{k+1} - q_k, u.p = p_{k+1} - p_k) except that last p_{k+1};
  /// from q + carry.q, p + carry.p with a carry (compensated summation).
  step_status finish(const V& q, const V& p, const T& tau, const Z& z, end_update<T, n>& u,
                     const phase_carry<T, n>* carry = nullptr) const {
    const controls Y = unpack_path<T, n, M, unknowns>(z);
    if constexpr (natural_system<Sys>) {
      V sb = V::Zero(), sbeta = V::Zero();
      for (int i = 1; i < M; ++i) {
        const V x = this->from_start(q, w_.template value<n>(Y, i), carry);
        const V f = D::lagrangian_q(sys_, x, V::Zero());
        sb += quad_b_[static_cast<std::size_t>(i - 1)] * f;
        sbeta += quad_beta_[static_cast<std::size_t>(i - 1)] * f;
      }
      u.p = tau * sb;
      // tau M^{-1} (p + tau sbeta) (with a carry p + (carry.p + tau sbeta)), written out: for
      // n = 1 Eigen's product is a mixed-type inner product.
      V sp = tau * sbeta;
      if (carry) sp = V(carry->p + sp);
      V dq;
      for (int r = 0; r < n; ++r) {
        T sum(0);
        for (int c = 0; c < n; ++c) sum += minv_(r, c) * (p[c] + sp[c]);
        dq[r] = tau * sum;
      }
      u.q = dq;
    } else {
      u.q = w_.template value<n>(Y, M);
      u.p = D::momentum_of(sys_, this->from_start(q, u.q, carry), V(combine(Y, w_.D1, M) / tau));
      u.p_is_increment = false;
    }
    return {};
  }

  /// dL/dxdot at t_{k} of the path fitted on [t_{k-1}, t_k] through x^{k-1} and x^k: solve
  /// eq. (12) for the interior unknowns with both ends fixed, then eq. (10).
  step_status end_momentum(const V& x0, const V& x1, const T& tau, V& p1, const newton_options<T>& opt) const {
    const V vbar = (x1 - x0) / tau;
    const V a = D::acceleration(sys_, x0, vbar);
    controls values;  // the parabola through x0, x1 with acceleration a
    for (int i = 0; i <= M; ++i) {
      const T s = w_.c[static_cast<std::size_t>(i)];
      values.col(i) = x0 + s * (x1 - x0) + (tau * tau * s * (s - T(1)) / T(2)) * a;
    }
    controls X = this->pinned_controls(values, x0, x1);
    constexpr int N = (M - 1) * n;
    vec<T, N> z;
    for (int j = 1; j < M; ++j) z.template segment<n>((j - 1) * n) = X.col(j);
    auto residual = [&](const vec<T, N>& zz, vec<T, N>& F, square_matrix<T, N>& J) {
      for (int j = 1; j < M; ++j) X.col(j) = zz.template segment<n>((j - 1) * n);
      J.setZero();
      const T tau2 = tau * tau;
      for (int i = 1; i < M; ++i) {
        const V x = combine(X, w_.D0, i);
        const V v = combine(X, w_.D1, i) / tau;
        const V acc = combine(X, w_.D2, i) / tau2;
        const el_data<T, n> e = D::euler_lagrange(sys_, x, v, acc);
        F.template segment<n>((i - 1) * n) = tau2 * e.E;
        for (int j = 1; j < M; ++j)
          J.template block<n, n>((i - 1) * n, (j - 1) * n) =
              (tau2 * w_.D0(i, j)) * e.Ex + (tau * w_.D1(i, j)) * e.Ev + w_.D2(i, j) * e.Ea;
      }
    };
    step_status st = newton_solve<N, T>(residual, z, opt);
    if (!st) return st;
    for (int j = 1; j < M; ++j) X.col(j) = z.template segment<n>((j - 1) * n);
    p1 = D::gradient(sys_, x1, V(combine(X, w_.D1, M) / tau)).Lv;
    return st;
  }

 private:
  std::array<T, M - 1> quad_b_, quad_beta_;
  mat<T, n> minv_ = mat<T, n>::Zero();  // M^{-1} (natural systems)
};

/// The engine of LPF on a natural system with the default solver: the Newton form (the step
/// skeleton over lpf_method) for every node family and basis, and on Gauss-interior nodes in
/// the Lagrange basis the fixed-point form in front of it (gauss_fixed_point.hpp): the same map,
/// solved without a Jacobian in a fraction of the time. A step the fixed-point form cannot take
/// (beyond the sweeps' reach, where the map is no contraction) is taken by Newton. One type for
/// every node family and basis (`skeleton_type`: their steppers share its code); both are data,
/// as the nodes and the basis matrices in the path weights.
template <class Sys, class T, int M>
class lpf_natural_engine {
  using newton_engine = step_skeleton<lpf_method<Sys, T, M>>;
  using fixed_point_engine = gauss_fixed_point_engine<Sys, T, M>;

 public:
  using skeleton_type = lpf_natural_engine;
  using method_type = lpf_method<Sys, T, M>;
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;
  /// The path increments (as the Newton form's), so that dense output works with either solver.
  using unknowns = typename newton_engine::unknowns;
  /// The caches of both forms (each holds the last step it took).
  struct cache_type {
    typename newton_engine::cache_type newton;
    typename fixed_point_engine::cache_type fixed_point;
  };

  lpf_natural_engine(const Sys& sys, const path_weights<T, M>& w, bool gauss_nodes)
      : newton_(method_type(sys, w)) {
    if (gauss_nodes) fixed_point_.emplace(sys);
  }

  const method_type& method() const { return newton_.method(); }
  /// Whether steps are taken by the fixed-point form (Gauss-interior nodes, Lagrange basis).
  bool fixed_point() const { return fixed_point_.has_value(); }

  /// One step (as step_skeleton::one_step): the fixed-point form where it applies and
  /// converges, else Newton. `solution` receives the path increments either way.
  step_status one_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                       cache_type* mem = nullptr, unknowns* solution = nullptr,
                       phase_carry<T, n>* carry = nullptr) const {
    if (fixed_point_) {
      typename fixed_point_engine::unknowns F;
      const std::optional<phase_carry<T, n>> start = carry ? std::optional<phase_carry<T, n>>(*carry) : std::nullopt;
      const step_status st =
          fixed_point_->one_step(q, p, tau, q1, p1, opt, mem ? &mem->fixed_point : nullptr, solution ? &F : nullptr, carry);
      if (st) {
        if (solution) {
          const auto Y = fixed_point_->path_increments(p, tau, F, start ? &*start : nullptr);
          for (int j = 1; j <= M; ++j) solution->template segment<n>((j - 1) * n) = Y[static_cast<std::size_t>(j - 1)];
        }
        return st;
      }
    }
    return newton_.one_step(q, p, tau, q1, p1, opt, mem ? &mem->newton : nullptr, solution, carry);
  }

  /// The two-step form's momentum at the end of the path through x0 and x1 (Newton, eq. 10-12).
  step_status end_momentum(const V& x0, const V& x1, const T& tau, V& p1, const newton_options<T>& opt) const {
    return newton_.end_momentum(x0, x1, tau, p1, opt);
  }

 private:
  newton_engine newton_;
  std::optional<fixed_point_engine> fixed_point_;
};

}  // namespace schemes::detail

/// How an LPF step solves its equations: the fourth parameter of `lpf`.
/// - `default_solver`, the fastest correct choice: on a natural system with Gauss-interior
///   nodes in the Lagrange basis the fixed-point form (schemes/gauss_fixed_point.hpp), Newton
///   for a step beyond its reach; simplified Newton on the path otherwise;
/// - `newton_solver`: simplified Newton on the path increments (step_skeleton.hpp), for every
///   system, node family and basis;
/// - `fixed_point_solver`: the fixed-point form alone (natural systems, Gauss-interior nodes;
///   a step beyond its reach fails: step_failure::no_convergence).
struct default_solver {
  static constexpr std::string_view name{};
};
struct newton_solver {
  static constexpr std::string_view name = "newton";
};
struct fixed_point_solver {
  static constexpr std::string_view name = "fixed-point";
};
template <class Solver>
concept lpf_solver = std::is_same_v<Solver, default_solver> || std::is_same_v<Solver, newton_solver> ||
                     std::is_same_v<Solver, fixed_point_solver>;

namespace schemes::detail {
/// The Newton form: the step skeleton over lpf_method.
template <class Sys, class T, int M, class Family, class Basis>
struct lpf_newton_engine : step_skeleton<lpf_method<Sys, T, M>> {
  explicit lpf_newton_engine(const Sys& sys)
      : step_skeleton<lpf_method<Sys, T, M>>(
            lpf_method<Sys, T, M>(sys, path_weights<T, M>::template make<Family, Basis>())) {}
};
/// The default solver on a natural system (lpf_natural_engine): the fixed-point form on
/// Gauss-interior nodes in the Lagrange basis (its stage values are that basis's unknowns).
template <class Sys, class T, int M, class Family, class Basis>
struct lpf_default_engine : lpf_natural_engine<Sys, T, M> {
  explicit lpf_default_engine(const Sys& sys)
      : lpf_natural_engine<Sys, T, M>(sys, path_weights<T, M>::template make<Family, Basis>(),
                                      std::is_same_v<Family, gauss_interior> && std::is_same_v<Basis, lagrange>) {}
};
/// The fixed-point form alone.
template <class Sys, class T, int M>
struct lpf_fixed_point_engine : gauss_fixed_point_engine<Sys, T, M> {
  static_assert(natural_system<Sys>,
                "geomint::lpf (fixed_point_solver): the fixed-point form needs a natural system (derived from "
                "geomint::natural, with a static potential and a constant mass matrix); use lpf<m, gauss_interior> "
                "(its default solver) for other Lagrangians");
  explicit lpf_fixed_point_engine(const Sys& sys) : gauss_fixed_point_engine<Sys, T, M>(sys) {}
};
/// The engine of lpf<M, Family, Basis, Solver> on Sys in T.
template <class Sys, class T, int M, class Family, class Basis, class Solver>
struct lpf_engine_of {
  using type = lpf_newton_engine<Sys, T, M, Family, Basis>;
};
template <class Sys, class T, int M, class Family, class Basis>
  requires natural_system<Sys>
struct lpf_engine_of<Sys, T, M, Family, Basis, default_solver> {
  using type = lpf_default_engine<Sys, T, M, Family, Basis>;
};
template <class Sys, class T, int M, class Family, class Basis>
struct lpf_engine_of<Sys, T, M, Family, Basis, fixed_point_solver> {
  using type = lpf_fixed_point_engine<Sys, T, M>;
};
}  // namespace schemes::detail

/// The LPF scheme of degree m on a node family in a basis, solved by `Solver` (above; the
/// default is the fastest correct one): `lpf<4, gauss_interior, lagrange>`.
template <int M, class Family = equispaced, class Basis = lagrange, class Solver = default_solver>
struct lpf {
  static_assert(M >= 2, "geomint::lpf: m must be >= 2 (eq. 12 needs at least one interior node)");
  static_assert(M <= max_floating_m, "geomint::lpf: m must be <= max_floating_m (16)");
  static_assert(node_family<Family>,
                "geomint::lpf: Family must be a node family (geomint::node_family, core/nodes.hpp)");
  static_assert(basis_kind<Basis>, "geomint::lpf: Basis must be lagrange or bernstein");
  static_assert(lpf_solver<Solver>, "geomint::lpf: Solver must be default_solver, newton_solver or fixed_point_solver");
  static_assert(!std::is_same_v<Solver, fixed_point_solver> ||
                    (std::is_same_v<Family, gauss_interior> && std::is_same_v<Basis, lagrange>),
                "geomint::lpf: fixed_point_solver needs Gauss-interior nodes in the Lagrange basis");
  static constexpr int m = M;
  using family = Family;
  using basis = Basis;
  using solver = Solver;
  static std::string name() { return schemes::detail::lpf_name(M, Family::name, Basis::name, Solver::name); }

  /// The method behind the Newton form's step skeleton, and the engine the integrator drives.
  template <class Sys, class T>
  using method = schemes::detail::lpf_method<Sys, T, M>;
  template <class Sys, class T>
  struct engine : schemes::detail::lpf_engine_of<Sys, T, M, Family, Basis, Solver>::type {
    explicit engine(const Sys& sys) : schemes::detail::lpf_engine_of<Sys, T, M, Family, Basis, Solver>::type(sys) {}
  };
};

/// Readable aliases by node family (the paper's numbered schemes: schemes/paper_schemes.hpp).
template <int M, class Basis = lagrange>
using lpf_equispaced = lpf<M, equispaced, Basis>;
template <int M, class Basis = lagrange>
using lpf_gauss = lpf<M, gauss_interior, Basis>;
template <int M, class Basis = lagrange>
using lpf_lobatto = lpf<M, gauss_lobatto, Basis>;
template <int M, class Basis = lagrange>
using lpf_chebyshev = lpf<M, chebyshev_lobatto, Basis>;

}  // namespace geomint
