#pragma once
/// Any tableau as a scheme of the one integrator: `integrator<tableau_method<P>, Sys, T>` steps
/// the method P::tableau() (an rk, prk, rkn or nystrom tableau, or a composition, over any
/// coefficient type; methods/tableau.hpp) on the system Sys in the scalar T:
///
///   struct verlet { static auto tableau() { return geomint::methods::make_rkn<geomint::rational>(...); } };
///   geomint::integrator<geomint::methods::tableau_method<verlet>, geomint::systems::pendulum, double> I;
///
/// The step runs the method's Nystrom form (methods/nystrom_form.hpp) on the state (q, p):
/// - natural systems (L = qdot^T M qdot / 2 - V): every kind; F = M^{-1} f, f = -grad V, so the
///   stage unknowns are the forces f_i = f(Q_i), v = M^{-1} p, and
///   q1 = q + d h v + h^2 M^{-1} sum_j bbar_j f_j, p1 = p + h sum_j b_j f_j (both increments,
///   so compensated summation applies);
/// - other Lagrangian systems: nystrom and rk tableaux; F(q, v) is the acceleration of the
///   Euler-Lagrange equations L_vv a = L_q - L_vq v (AD derivatives, mechanics/lagrangian.hpp),
///   the stage unknowns the accelerations a_i, with the Legendre map at both ends: v from p by
///   the inverse map at the start, p1 = dL/dqdot(q1, v1) at the end.
/// Explicit forms (A, and Ap where it matters, strictly lower triangular) are stepped stage by
/// stage. Implicit ones solve their stage equations by simplified Newton (the matrix evaluated
/// at the predictor, reused while the iteration contracts by 2 or better, refreshed otherwise;
/// LU of linalg/lu_small.hpp), stopping when the correction is at the eps(T) level (the rules of
/// solvers/newton.hpp); a singular matrix, a non-finite iterate or an exhausted budget is the
/// step's status, never a silent result.

#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "geomint/linalg/lu_small.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/solvers/newton.hpp"
#include "geomint/solvers/phase_state.hpp"
#include "geomint/solvers/step_status.hpp"

namespace geomint::methods {

namespace detail {

/// The engine of a Nystrom form on the system Sys in the scalar T (see the top of the file).
template <class Sys, class T>
class tableau_engine {
 public:
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;
  using stage_values = Eigen::Matrix<T, n, Eigen::Dynamic>;
  using unknowns = dynamic_vector<T>;
  /// Nothing is carried from one step to the next (each step starts from its explicit predictor).
  struct cache_type {};

  /// std::invalid_argument if the form needs a natural system (rkn, prk) and Sys is not one.
  tableau_engine(const Sys& sys, nystrom_form<T> form) : sys_(sys), f_(std::move(form)) {
    if (!natural_system<Sys> && f_.natural_only)
      throw std::invalid_argument("a " + std::string(to_string(f_.kind)) +
                                  " tableau runs on natural systems only (L = qdot^T M qdot / 2 - V(q))");
    s_ = f_.stages;
    A_.resize(s_, s_);
    Ap_.resize(s_, s_);
    for (int i = 0; i < s_; ++i)
      for (int j = 0; j < s_; ++j) {
        A_(i, j) = f_.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        Ap_(i, j) = f_.ap[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      }
    if constexpr (natural_system<Sys>) {
      if (!invert_small<T, n>(Sys::template mass_matrix<T>(), minv_)) throw std::invalid_argument("singular mass matrix");
    }
  }

  const nystrom_form<T>& form() const { return f_; }

  /// (q, p) -> (q1, p1) (the engine contract of integrator.hpp); `solution` (if not null)
  /// receives the stage unknowns; `carry` selects compensated summation. On failure q1, p1 and
  /// carry are untouched.
  step_status one_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                       cache_type* = nullptr, unknowns* solution = nullptr,
                       phase_carry<T, n>* carry = nullptr) const {
    opt.validate();
    if constexpr (natural_system<Sys>)
      return natural_step(q, p, tau, q1, p1, opt, solution, carry);
    else
      return general_step(q, p, tau, q1, p1, opt, solution, carry);
  }

 private:
  /// sum_j w_j X_j (the end update's sums).
  V weighted(const std::vector<T>& w, const stage_values& x) const {
    V out = V::Zero();
    for (int j = 0; j < s_; ++j) out += w[static_cast<std::size_t>(j)] * x.col(j);
    return out;
  }
  /// The (i, j) block of the Newton matrix J, element by element: GCC 12 at -O3 flags Eigen's
  /// packet copy of a fixed 1 x 1 block into the dynamic J as out of bounds (-Warray-bounds, a
  /// false positive that -Werror turns into a build failure of the gcc preset).
  static void set_block(Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>& J, int i, int j, const mat<T, n>& block) {
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) J(i * n + r, j * n + c) = block(r, c);
  }
  /// sum_j W(i, j) X_j.
  template <class W>
  V combine(const W& w, int i, const stage_values& x) const {
    V out = V::Zero();
    for (int j = 0; j < s_; ++j) out += w(i, j) * x.col(j);
    return out;
  }

  // --- natural systems: unknowns are the stage forces f_i = -grad V(Q_i) ---------------------
  /// M^{-1} x, as loops (for n = 1 Eigen would make the product an inner product).
  V inverse_mass(const V& x) const {
    V out;
    for (int r = 0; r < n; ++r) {
      T sum(0);
      for (int k = 0; k < n; ++k) sum += minv_(r, k) * x[k];
      out[r] = sum;
    }
    return out;
  }
  V force(const V& x) const { return lagrangian_derivatives<Sys, T>::lagrangian_q(sys_, x, V::Zero()); }

  step_status natural_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                           unknowns* solution, phase_carry<T, n>* carry) const {
    const V offset = carry ? carry->q : V::Zero();
    const V v = inverse_mass(carry ? V(p + carry->p) : p);
    const T h2 = tau * tau;
    auto stage = [&](int i, const stage_values& g) {
      return V(q + V(offset + T(tau * f_.c[static_cast<std::size_t>(i)]) * v + h2 * inverse_mass(combine(A_, i, g))));
    };
    stage_values g = stage_values::Zero(n, s_);
    step_status st;
    if (f_.explicit_positions) {
      for (int i = 0; i < s_; ++i) {
        g.col(i) = force(stage(i, g));
        if (!all_finite(g.col(i))) return {step_failure::non_finite_iterate, 0, 0};
      }
    } else {
      for (int i = 0; i < s_; ++i) g.col(i) = force(V(q + V(offset + T(tau * f_.c[static_cast<std::size_t>(i)]) * v)));
      unknowns z = Eigen::Map<const unknowns>(g.data(), n * s_);
      auto residual = [&](const unknowns& zz, unknowns& F, Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>* J) {
        const stage_values gz = Eigen::Map<const stage_values>(zz.data(), n, s_);
        for (int i = 0; i < s_; ++i) {
          const V Q = stage(i, gz);
          if (J) {
            const hessian_data<T, n> hd = lagrangian_derivatives<Sys, T>::hessian(sys_, Q, V::Zero());
            F.template segment<n>(i * n) = gz.col(i) - hd.Lq;
            mat<T, n> K;  // Lqq M^{-1}, as loops (for n = 1 Eigen makes the product a scalar)
            for (int r = 0; r < n; ++r)
              for (int c = 0; c < n; ++c) {
                T sum(0);
                for (int k = 0; k < n; ++k) sum += hd.Lqq(r, k) * minv_(k, c);
                K(r, c) = sum;
              }
            for (int j = 0; j < s_; ++j) {
              mat<T, n> block = -(h2 * A_(i, j)) * K;
              if (i == j) block += mat<T, n>::Identity();
              set_block(*J, i, j, block);
            }
          } else {
            F.template segment<n>(i * n) = gz.col(i) - force(Q);
          }
        }
      };
      st = solve(residual, z, opt);
      if (!st) return st;
      g = Eigen::Map<const stage_values>(z.data(), n, s_);
    }
    const V bbar_sum = weighted(f_.bbar, g), b_sum = weighted(f_.b, g);
    const V dq = T(tau * f_.d) * v + h2 * inverse_mass(bbar_sum);
    const V dp = tau * b_sum;
    commit(q, p, dq, dp, q1, p1, carry);
    if (solution) *solution = Eigen::Map<const unknowns>(g.data(), n * s_);
    return st;
  }

  // --- other Lagrangians: unknowns are the stage accelerations a_i --------------------------
  /// L_vv a = L_q - L_vq v at (x, v); false if L_vv is singular there.
  bool acceleration(const V& x, const V& v, V& a) const {
    const hessian_data<T, n> h = lagrangian_derivatives<Sys, T>::hessian(sys_, x, v);
    return solve_small<T, n>(h.Lvv, V(h.Lq - h.Lvq * v), a) && all_finite(a);
  }

  step_status general_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                           unknowns* solution, phase_carry<T, n>* carry) const {
    using D = lagrangian_derivatives<Sys, T>;
    const V offset = carry ? carry->q : V::Zero();
    V v;
    if (!D::velocity(sys_, V(q + offset), carry ? V(p + carry->p) : p, v)) return {step_failure::singular_jacobian, 0, 0};
    const T h2 = tau * tau;
    auto position = [&](int i, const stage_values& a) {
      return V(q + V(offset + T(tau * f_.c[static_cast<std::size_t>(i)]) * v + h2 * combine(A_, i, a)));
    };
    auto velocity = [&](int i, const stage_values& a) { return V(v + tau * combine(Ap_, i, a)); };
    stage_values a = stage_values::Zero(n, s_);
    step_status st;
    if (f_.explicit_velocities) {
      for (int i = 0; i < s_; ++i) {
        V ai;
        if (!acceleration(position(i, a), velocity(i, a), ai)) return {step_failure::non_finite_iterate, 0, 0};
        a.col(i) = ai;
      }
    } else {
      V a0;
      if (!acceleration(V(q + offset), v, a0)) return {step_failure::non_finite_iterate, 0, 0};
      for (int i = 0; i < s_; ++i) a.col(i) = a0;
      unknowns z = Eigen::Map<const unknowns>(a.data(), n * s_);
      // E(Q_i, V_i, a_i) = 0 (the Euler-Lagrange expression), dE/da_j = E_x h^2 a_ij + E_v h ap_ij + E_a delta_ij.
      auto residual = [&](const unknowns& zz, unknowns& F, Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>* J) {
        const stage_values az = Eigen::Map<const stage_values>(zz.data(), n, s_);
        for (int i = 0; i < s_; ++i) {
          const V Q = position(i, az), Vi = velocity(i, az), ai = az.col(i);
          if (J) {
            const el_data<T, n> e = D::euler_lagrange(sys_, Q, Vi, ai);
            F.template segment<n>(i * n) = e.E;
            for (int j = 0; j < s_; ++j) {
              mat<T, n> block = T(h2 * A_(i, j)) * e.Ex + T(tau * Ap_(i, j)) * e.Ev;
              if (i == j) block += e.Ea;
              set_block(*J, i, j, block);
            }
          } else {
            F.template segment<n>(i * n) = D::el_residual(sys_, Q, Vi, ai);
          }
        }
      };
      st = solve(residual, z, opt);
      if (!st) return st;
      a = Eigen::Map<const stage_values>(z.data(), n, s_);
    }
    const V bbar_sum = weighted(f_.bbar, a), b_sum = weighted(f_.b, a);
    const V dq = T(tau * f_.d) * v + h2 * bbar_sum;
    const V v1 = v + tau * b_sum;
    // p1 from the Legendre map at the new point: a value, not an increment (its carry is zero).
    phase_carry<T, n> next;
    if (carry) next = *carry;
    q1 = apply_end(q, dq, carry ? &next.q : nullptr);
    next.p.setZero();
    p1 = D::momentum_of(sys_, V(q1 + next.q), v1);
    if (carry) *carry = next;
    if (solution) *solution = Eigen::Map<const unknowns>(a.data(), n * s_);
    return st;
  }

  static V apply_end(const V& x, const V& dx, V* carry) {
    if (!carry) return V(x + dx);
    V out = x;
    add_compensated(out, *carry, dx);
    return out;
  }

  /// q1 = q + dq, p1 = p + dp (compensated with a carry).
  static void commit(const V& q, const V& p, const V& dq, const V& dp, V& q1, V& p1, phase_carry<T, n>* carry) {
    phase_carry<T, n> next;
    if (carry) next = *carry;
    q1 = apply_end(q, dq, carry ? &next.q : nullptr);
    p1 = apply_end(p, dp, carry ? &next.p : nullptr);
    if (carry) *carry = next;
  }

  /// Simplified Newton on the stage equations (the convergence rules of
  /// solvers/newton.hpp::newton_solve_simplified, at run-time size).
  template <class Residual>
  step_status solve(Residual&& residual, unknowns& z, const newton_options<T>& opt) const {
    using std::abs;
    const int N = static_cast<int>(z.size());
    const T eps = std::numeric_limits<T>::epsilon();
    const T tol = T(opt.tolerance_ulps) * eps;
    const T floor_level = epsilon_two_thirds<T>();
    const T scale = z.template lpNorm<Eigen::Infinity>();
    Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> J(N, N), lu(N, N);
    std::vector<int> row(static_cast<std::size_t>(N)), col(static_cast<std::size_t>(N));
    unknowns F(N);
    step_status st;
    bool refresh = true;
    T previous(0);
    for (int it = 1; it <= opt.max_iterations; ++it) {
      st.iterations = it;
      const bool fresh = refresh;
      residual(z, F, fresh ? &J : nullptr);
      if (!all_finite(F) || (fresh && !all_finite(J))) {
        st.reason = step_failure::non_finite_iterate;
        return st;
      }
      if (fresh) {
        lu = J;
        if (!linalg::detail::lu_factor(lu.data(), N, row.data(), col.data(), linalg::pivoting::partial)) {
          st.reason = step_failure::singular_jacobian;
          return st;
        }
        refresh = false;
      }
      unknowns dz = -F;
      linalg::detail::lu_solve(lu.data(), N, row.data(), col.data(), dz.data());
      if (!all_finite(dz)) {
        st.reason = step_failure::non_finite_iterate;
        return st;
      }
      z += dz;
      const T size = dz.template lpNorm<Eigen::Infinity>();
      const T s = scale + z.template lpNorm<Eigen::Infinity>();
      const T rho = (!fresh && it > 1) ? T(size / previous) : T(1);
      const bool converged = size <= eps * s || (size <= tol * s && (fresh || rho <= T(1) / T(8))) ||
                             (it > 1 && size <= floor_level * s && size * T(2) > previous);
      if (converged) return st;
      if (!fresh && it > 1 && rho > T(1) / T(2)) refresh = true;
      previous = size;
    }
    st.reason = step_failure::no_convergence;
    return st;
  }

  Sys sys_;
  nystrom_form<T> f_;
  int s_ = 0;
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> A_, Ap_;
  mat<T, n> minv_ = mat<T, n>::Identity();
};

/// The kind of a tableau type (of its base for a composition).
template <class Tab>
constexpr method_kind kind_of() {
  if constexpr (requires { Tab::kind; })
    return Tab::kind;
  else
    return kind_of<typename Tab::base_type>();
}

}  // namespace detail

/// The scheme of the method `Provider::tableau()` (see the top of the file), or of
/// `Provider::numeric_tableau<T>()` where present. `Provider::name()`, if present, names it.
template <class Provider>
struct tableau_method {
  using tableau_type = std::remove_cvref_t<decltype(Provider::tableau())>;
  static std::string name() {
    if constexpr (requires { Provider::name(); })
      return std::string(Provider::name());
    else
      return std::string(to_string(detail::kind_of<tableau_type>())) + " tableau";
  }
  template <class Sys, class T>
  struct engine : detail::tableau_engine<Sys, T> {
    static_assert(natural_system<Sys> || (detail::kind_of<tableau_type>() != method_kind::rkn &&
                                          detail::kind_of<tableau_type>() != method_kind::prk),
                  "geomint::methods::tableau_method: an rkn or prk tableau runs on natural systems only (derived from "
                  "geomint::natural); for a general Lagrangian write the method as a nystrom (or rk) tableau");
    explicit engine(const Sys& sys) : detail::tableau_engine<Sys, T>(sys, form()) {}
    /// The Nystrom form in T: of `Provider::numeric_tableau<T>()` where the provider computes
    /// its coefficients in T itself (methods/collocation_algebra.hpp), else of the exact tableau.
    static nystrom_form<T> form() {
      if constexpr (requires { Provider::template numeric_tableau<T>(); })
        return nystrom_form_of(Provider::template numeric_tableau<T>());
      else
        return to_scalar<T>(nystrom_form_of(Provider::tableau()));
    }
  };
};

}  // namespace geomint::methods
