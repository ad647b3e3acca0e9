#pragma once
/// What the methods on a polynomial path share (free LPF, Galerkin, midpoint, trapezoidal,
/// constrained LPF; step_skeleton.hpp): the system, the path weights, the predictor (fresh, or
/// continuing the previous step), the control points of a solved path, and the start of the
/// two-step form's end-momentum solve. A method derives from `path_method` and adds its
/// residual rows and its end update.

#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/schemes/step_skeleton.hpp"

namespace geomint::schemes::detail {

/// The base of a method whose first M n unknowns are the increments Y_1..Y_M = X_1..X_M - q_k
/// of a degree-M path in the basis of its weights (Y_0 = 0). `Unknowns` counts all of them; those after the
/// path (a constrained method's multipliers) start at zero and are the method's own.
template <class Sys, class T, int M, int Unknowns = M * Sys::dof>
class path_method {
 public:
  static_assert(Unknowns >= M * Sys::dof, "geomint: the unknowns must hold the path increments");
  using scalar = T;
  static constexpr int dof = Sys::dof;
  static constexpr int n = dof;
  static constexpr int unknowns = Unknowns;
  using V = vec<T, n>;
  using Z = vec<T, unknowns>;
  using controls = Eigen::Matrix<T, n, M + 1>;
  using D = lagrangian_derivatives<Sys, T>;
  using weights = path_weights<T, M>;

  path_method(const Sys& sys, const weights& w) : sys_(sys), w_(w) {}

  /// The quadratic Taylor polynomial q + s qdot + s^2 qddot / 2 at the nodes; the unknowns
  /// after the path zero. False if no velocity belongs to p.
  bool predict(const V& q, const V& p, const T& tau, Z& z) const {
    V v0;
    if (!D::velocity(sys_, q, p, v0)) return false;
    const V a0 = D::acceleration(sys_, q, v0);
    z.setZero();
    pack_path<T, n, M, unknowns>(w_.template quadratic<n>(v0, a0, tau), z);
    return true;
  }
  /// The previous path extrapolated to [t_k, t_k + tau] (error O(tau^(m+1))); the unknowns
  /// after the path (in z already) kept.
  void extrapolate(const Z& previous, Z& z) const { extrapolate_path<T, n, M, unknowns>(w_.extrapolate, previous, z); }

  /// q + d, the point at increment d from the step's start: with compensated summation
  /// (carry not null) from the state q + carry.q, the two small parts added first.
  static V from_start(const V& q, const V& d, const phase_carry<T, n>* carry) {
    return carry ? V(q + V(carry->q + d)) : V(q + d);
  }
  /// L_v - p_k, or L_v - (p_k + carry.p) with the small parts subtracted last.
  static V momentum_mismatch(const V& Lv, const V& p, const phase_carry<T, n>* carry) {
    return carry ? V(V(Lv - p) - carry->p) : V(Lv - p);
  }

  /// The control points X_0..X_M of the path fitted on the step from q_k with unknowns z.
  controls path(const V& q, const Z& z) const {
    controls X = unpack_path<T, n, M, unknowns>(z);
    for (int j = 0; j <= M; ++j) X.col(j) += q;
    return X;
  }

 protected:
  /// The segment from x0 to x1 at the nodes: x0 + c_i (x1 - x0).
  controls segment_values(const V& x0, const V& x1) const {
    controls values;
    for (int i = 0; i <= M; ++i) values.col(i) = x0 + w_.c[static_cast<std::size_t>(i)] * (x1 - x0);
    return values;
  }
  /// The controls of the path with the given node values, its ends pinned to x0 and x1 (exact
  /// there; the interior controls start the end-momentum solve).
  controls pinned_controls(const controls& values, const V& x0, const V& x1) const {
    controls X;
    for (int j = 0; j <= M; ++j) X.col(j) = combine(values, w_.D0inv, j);
    X.col(0) = x0;
    X.col(M) = x1;
    return X;
  }

  Sys sys_;
  weights w_;
};

}  // namespace geomint::schemes::detail
