#pragma once
/// The step skeleton shared by every implicit scheme (free LPF, Galerkin, midpoint,
/// trapezoidal, constrained LPF).
///
/// A scheme is a small *method* that supplies what one step solves: its unknowns, a predictor,
/// its residual rows and its end update. The skeleton owns everything else: the packing of the
/// path into unknowns, the use of a step cache (the previous path extrapolated as the predictor,
/// the factorised Newton matrix reused while it contracts; the caller owns the cache and passes
/// it to each step), the simplified Newton solve and the failure reporting. A method `Method` provides
///
///   using scalar = T;  static constexpr int dof, unknowns;
///   bool predict(q, p, tau, z)            fresh predictor; false if no velocity belongs to p
///   void extrapolate(previous_z, z)        predictor continuing the previous step
///   void residual(q, p, tau, z, F, J*, c*) F(z) and, if J is not null, dF/dz
///   step_status finish(q, p, tau, z, u, c*) the end update at the solution z (an end_update:
///                                          increments where it can, so that compensated
///                                          summation can add them)
///
/// where c, if not null, holds the compensation terms of compensated summation: the step then
/// starts from the state q + c.q, p + c.p, which the method's path and momentum rows use
/// (path_method::from_start), so that a compensated step is the step from that sum and not from
/// its rounded part.
///
/// and optionally `end_momentum(x0, x1, tau, p1, opt)` for the two-step form.

#include <array>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "geomint/core/basis.hpp"
#include "geomint/core/differentiation.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/solvers/newton.hpp"
#include "geomint/solvers/phase_state.hpp"

namespace geomint {
namespace schemes::detail {

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

/// The weights of a degree-M path on a node family in a basis: D_k(i, j) = phi_j^(k)(c_i),
/// D0^{-1} (node values -> controls), and the extrapolation of a step's increments to the
/// next step's. The basis is data, as the nodes are: every (family, basis) of one (T, M) has
/// this type, so an engine's code is compiled once for all of them. In the Lagrange basis
/// D0 = I exactly (`node_values`): the unknowns are node values and `value` needs no product.
template <class T, int M>
struct path_weights {
  using W = Eigen::Matrix<T, M + 1, M + 1>;
  bool node_values = true;
  std::array<T, M + 1> c{};
  W D0, D1, D2, D0inv, extrapolate;

  template <class Family, class Basis>
  static path_weights make() {
    return from_nodes<Basis>(nodes<Family, M, T>());
  }
  /// The weights on the nodes c. Family-free, so all node families of one (T, m, basis) share
  /// this code (it is most of an engine's set-up).
  template <class Basis>
  static path_weights from_nodes(const std::array<T, M + 1>& c) {
    static_assert(basis_kind<Basis>, "geomint: Basis must be lagrange or bernstein");
    path_weights w;
    w.c = c;
    w.node_values = std::is_same_v<Basis, lagrange>;
    // In the Lagrange basis D0 = D0^{-1} = I exactly (l_j(c_i) = delta_ij): no evaluation, no
    // inversion and no products with them.
    if (w.node_values) {
      w.D0 = W::Identity();
      w.D0inv = W::Identity();
    } else {
      w.D0 = to_matrix<T, M + 1>(differentiation_weights_at<0, Basis>(c));
      w.D0inv = inverse_of<T, M + 1>(w.D0);
    }
    w.D1 = to_matrix<T, M + 1>(differentiation_weights_at<1, Basis>(c));
    w.D2 = to_matrix<T, M + 1>(differentiation_weights_at<2, Basis>(c));
    w.extrapolate = extrapolation(w.D0, w.D0inv, w.c, w.node_values);
    return w;
  }

  /// x(c_i) - q for the path q + sum_j phi_j Y_j (both bases are partitions of unity).
  template <int n>
  vec<T, n> value(const Eigen::Matrix<T, n, M + 1>& Y, int i) const {
    if (node_values) return Y.col(i);
    return combine(Y, D0, i);
  }

  /// Increments of the quadratic q + tau c v + (tau c)^2 a / 2 (minus q) at the nodes, mapped
  /// to the basis through D0^{-1}: the predictor of a step that continues no previous one.
  template <int n>
  Eigen::Matrix<T, n, M + 1> quadratic(const vec<T, n>& v, const vec<T, n>& a, const T& tau) const {
    Eigen::Matrix<T, n, M + 1> values;
    for (int i = 0; i <= M; ++i) {
      const T s = tau * c[static_cast<std::size_t>(i)];
      values.col(i) = s * v + (s * s / T(2)) * a;
    }
    if (node_values) return values;
    Eigen::Matrix<T, n, M + 1> Y;
    for (int j = 0; j <= M; ++j) Y.col(j) = combine(values, D0inv, j);
    return Y;
  }

 private:
  /// Maps the increments of a step's path to the predicted increments of the next step:
  /// values at the nodes of the next interval, 1 + c_i, by Lagrange interpolation through the
  /// path's node values, minus its end value, then back to the basis through D0^{-1}.
  static W extrapolation(const W& D0, const W& D0inv, const std::array<T, M + 1>& c, bool node_values) {
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
    W values = node_values ? L : W(L * D0);  // values at 1 + c_i of the path with controls e_j
    for (int i = 0; i <= M; ++i) values.row(i) -= D0.row(M);
    return node_values ? values : W(D0inv * values);
  }
};

/// The increments Y_1..Y_M of a path packed into the first M n unknowns (Y_0 = 0), and back.
template <class T, int n, int M, int N>
Eigen::Matrix<T, n, M + 1> unpack_path(const vec<T, N>& z) {
  static_assert(N >= M * n, "geomint: the unknowns must hold the path increments");
  Eigen::Matrix<T, n, M + 1> Y;
  Y.col(0).setZero();
  for (int j = 1; j <= M; ++j) Y.col(j) = z.template segment<n>((j - 1) * n);
  return Y;
}
template <class T, int n, int M, int N>
void pack_path(const Eigen::Matrix<T, n, M + 1>& Y, vec<T, N>& z) {
  for (int j = 1; j <= M; ++j) z.template segment<n>((j - 1) * n) = Y.col(j);
}

/// The previous path extrapolated (extrapolation matrix E) into the first M n unknowns.
template <class T, int n, int M, int N>
void extrapolate_path(const Eigen::Matrix<T, M + 1, M + 1>& E, const vec<T, N>& previous, vec<T, N>& z) {
  const Eigen::Matrix<T, n, M + 1> Y = unpack_path<T, n, M, N>(previous);
  for (int i = 1; i <= M; ++i) z.template segment<n>((i - 1) * n) = combine(Y, E, i);
}

/// What a method's end update produces: the increments q_{k+1} - q_k and p_{k+1} - p_k where
/// the method forms the new point as an increment (then the skeleton adds them, plainly or with
/// compensated summation), else the new values themselves (flag false; the compensation term
/// of that part is reset to zero).
template <class T, int n>
struct end_update {
  vec<T, n> q = vec<T, n>::Zero();
  vec<T, n> p = vec<T, n>::Zero();
  bool q_is_increment = true;
  bool p_is_increment = true;
};

/// x_{k+1} from x_k and a method's part u of the end update: x_k + u plainly (carry null),
/// with compensated summation (carry: the compensation term, updated), or u itself if it is a
/// value, not an increment.
template <class T, int n>
vec<T, n> apply_end_update(const vec<T, n>& x, const vec<T, n>& u, bool is_increment, vec<T, n>* carry) {
  if (!is_increment) {
    if (carry) carry->setZero();
    return u;
  }
  if (!carry) return x + u;
  vec<T, n> out = x;
  add_compensated(out, *carry, u);
  return out;
}

/// Where the last step of a cache ended (q1, p1 with step tau), to recognise a step that
/// continues it. The part of every engine's cache (`Engine::cache_type`) that says whether what
/// it holds belongs to this step; engines derive from it and add what they carry over
/// (step_cache below, schemes/gauss_fixed_point.hpp). A cache is plain data owned by its caller
/// (the integrator, the stepper), as Eigen's decompositions are: one engine, shared or const,
/// serves any number of caches, one per trajectory or thread.
template <class T, int n>
struct step_continuation {
  bool valid = false;
  T tau{};
  vec<T, n> q1, p1;
  /// Whether a step from (q, p) with tau starts where the remembered one ended.
  bool continues(const vec<T, n>& q, const vec<T, n>& p, const T& step) const {
    return valid && step == tau && q == q1 && p == p1;
  }
  /// Remembers the end of a successful step.
  void record(const T& step, const vec<T, n>& q_end, const vec<T, n>& p_end) {
    valid = true;
    tau = step;
    q1 = q_end;
    p1 = p_end;
  }
};

/// The cache of the step skeleton: the last step's solution, to extrapolate as the predictor
/// when the next step continues it (same q, p and tau), and the factorised Newton matrix, to
/// reuse (factor once, solve many).
template <class T, int n, int N>
struct step_cache : step_continuation<T, n> {
  vec<T, N> z = vec<T, N>::Zero();
  jacobian_cache<T, N> jacobian;
};

/// The generic implicit step over a method (see the top of this file).
template <class Method>
class step_skeleton {
 public:
  using method_type = Method;
  /// The type a derived engine (a scheme's `engine`) converts to: steppers hold this one.
  using skeleton_type = step_skeleton;
  using T = typename Method::scalar;
  static constexpr int n = Method::dof;
  static constexpr int N = Method::unknowns;
  using V = vec<T, n>;
  using unknowns = vec<T, N>;

  explicit step_skeleton(Method method) : method_(std::move(method)) {}

  const Method& method() const { return method_; }

  /// The cache a caller keeps between steps (step_cache above).
  using cache_type = step_cache<T, n, N>;

  /// (q_k, p_k) -> (q_{k+1}, p_{k+1}); `solution` (if not null) receives the unknowns at the
  /// solution. Predictor: when the step continues the last one of `cache` (q_k, p_k and tau
  /// equal to its result), the method's extrapolation of that step's solution, with its
  /// factorised Newton matrix reused while it contracts well; otherwise (or with no cache) the
  /// method's fresh predictor and a fresh matrix. The cache then holds this step. Either way the result solves the same equations to the
  /// Newton tolerance. `carry` (if not null) holds the compensation terms of (q, p) and selects
  /// compensated summation of the end update (phase_state.hpp, add_compensated); it receives
  /// those of (q1, p1). On failure q1, p1 and carry are untouched.
  step_status one_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                       cache_type* mem = nullptr, unknowns* solution = nullptr,
                       phase_carry<T, n>* carry = nullptr) const {
    unknowns z;
    step_status st;
    bool done = false;
    if (mem && mem->continues(q, p, tau)) {
      z = mem->z;
      method_.extrapolate(mem->z, z);
      st = solve(q, p, tau, opt, z, &mem->jacobian, carry);
      done = static_cast<bool>(st);
    }
    if (!done) {
      if (!method_.predict(q, p, tau, z)) {
        if (mem) mem->valid = false;
        return {step_failure::singular_jacobian, 0, 0};
      }
      if (mem) mem->jacobian.valid = false;
      st = solve(q, p, tau, opt, z, mem ? &mem->jacobian : nullptr, carry);
    }
    end_update<T, n> u;
    if (st) {
      const step_status end = method_.finish(q, p, tau, z, u, carry);
      if (!end) st.reason = end.reason;
    }
    if (!st) {
      if (mem) mem->valid = false;
      return st;
    }
    phase_carry<T, n> carry_next;
    if (carry) carry_next = *carry;
    q1 = apply_end_update<T, n>(q, u.q, u.q_is_increment, carry ? &carry_next.q : nullptr);
    p1 = apply_end_update<T, n>(p, u.p, u.p_is_increment, carry ? &carry_next.p : nullptr);
    if (carry) *carry = carry_next;
    if (solution) *solution = z;
    if (mem) {
      mem->record(tau, q1, p1);
      mem->z = z;
      // Reuse the matrix next step only while it contracts fast enough to reach eps from O(1)
      // in six corrections (rate^6 <= eps: about 2e-3 in double, 5e-9 in 50 digits);
      // otherwise a fresh one is cheaper than many slow iterations.
      const T r2 = mem->jacobian.rate * mem->jacobian.rate;
      if (r2 * r2 * r2 > std::numeric_limits<T>::epsilon()) mem->jacobian.valid = false;
    }
    return st;
  }

  /// The two-step form's momentum at the end of the path fitted through x0 and x1.
  step_status end_momentum(const V& x0, const V& x1, const T& tau, V& p1, const newton_options<T>& opt) const
    requires requires(const Method& m) { m.end_momentum(x0, x1, tau, p1, opt); }
  {
    return method_.end_momentum(x0, x1, tau, p1, opt);
  }

 private:
  /// Simplified Newton on the method's residual; round-off is judged against eps |q|.
  step_status solve(const V& q, const V& p, const T& tau, const newton_options<T>& opt, unknowns& z,
                    jacobian_cache<T, N>* jac, const phase_carry<T, n>* carry) const {
    auto residual = [&](const unknowns& zz, unknowns& F, square_matrix<T, N>* J) { method_.residual(q, p, tau, zz, F, J, carry); };
    const T scale = std::numeric_limits<T>::epsilon() * q.template lpNorm<Eigen::Infinity>();
    return newton_solve_simplified<N, T>(residual, z, opt, scale, jac);
  }

  Method method_;
};

}  // namespace schemes::detail
}  // namespace geomint
