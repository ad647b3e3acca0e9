#pragma once
/// Dense output: the polynomial path a step fitted, evaluable anywhere in the step.
///
/// An LPF or Galerkin step from (q_k, p_k) solves for a degree-m path
/// x(t_k + s tau) = sum_j phi_j(s) X_j, s in [0, 1], with X_0 = q_k and X_m = q_{k+1} (LPF
/// paper eq. 8 or 13 for the basis phi_j). `step_path` keeps the control points X_0..X_m and
/// evaluates x(t) and xdot(t) = sum_j phi_j'(s) X_j / tau for t in [t_k, t_{k+1}].
///
/// Accuracy (docs/guide/your_own_system.md, "Dense output"): for LPF the path's second
/// derivative is the degree-(m-2) interpolant of the acceleration at the m-1 interior nodes, so
/// the local error of x(t) inside a step is O(tau^(m+1)) and that of xdot(t) is O(tau^m);
/// globally the dense output has order min(m+1, p) in position and min(m, p) in velocity, where
/// p is the order of the scheme at the nodes (2(m-1) for LPF on Gauss nodes). The same orders
/// are measured for Galerkin (p = 2m). For the
/// midpoint and trapezoidal rules (m = 1) the path is the straight segment between q_k and
/// q_{k+1}: linear interpolation, order 2 in position and a constant secant velocity (order 1).

#include <concepts>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "geomint/core/basis.hpp"
#include "geomint/linalg/types.hpp"

namespace geomint {

/// The path of one step on [t_begin, t_end] = [t_k, t_{k+1}]: degree M in `Basis` on the
/// nodes of `Family` (the family only matters for the Lagrange basis).
template <class T, int n, int M, class Family, class Basis>
class step_path {
 public:
  using vector = vec<T, n>;
  using controls = Eigen::Matrix<T, n, M + 1>;
  static constexpr int degree = M;

  /// An empty path (no step taken); evaluating it throws std::logic_error.
  step_path() = default;
  /// The path with control points X on [t_begin, t_begin + tau]; `t_end` is the step's end
  /// time as the integrator computed it (t_{k+1}; not accumulated, see phase_state).
  step_path(const T& t_begin, const T& t_end, const T& tau, const controls& X)
      : t_begin_(t_begin), t_end_(t_end), tau_(tau), X_(X), valid_(true) {}

  bool empty() const { return !valid_; }
  const T& t_begin() const { return t_begin_; }
  const T& t_end() const { return t_end_; }
  const T& tau() const { return tau_; }
  /// X_0..X_m (node values for the Lagrange basis, Bezier points for Bernstein).
  const controls& control_points() const { return X_; }

  /// x(t) for t in [t_begin, t_end]; std::out_of_range outside the step.
  vector position(const T& t) const { return derivative<0>(t); }
  /// xdot(t) for t in [t_begin, t_end]; std::out_of_range outside the step.
  vector velocity(const T& t) const { return derivative<1>(t); }

 private:
  static std::string show(const T& x) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", static_cast<double>(x));
    return text;
  }

  /// s = (t - t_k) / tau in [0, 1]. The end of the step is accepted as t_end (the integrator's
  /// t_{k+1}) or as t_begin + tau, which may differ by a rounding; s is clamped to 1.
  T local(const T& t) const {
    if (!valid_) throw std::logic_error("geomint::step_path: empty path (no step has been taken)");
    const T last = t_end_ > T(t_begin_ + tau_) ? t_end_ : T(t_begin_ + tau_);
    if (!(t >= t_begin_ && t <= last))
      throw std::out_of_range("geomint::step_path: t = " + show(t) + " is outside the step [" + show(t_begin_) + ", " +
                              show(t_end_) + "]; dense output is valid only within the step that produced it");
    T s = (t - t_begin_) / tau_;
    if (s > T(1)) s = T(1);
    return s;
  }

  template <int K>
  vector derivative(const T& t) const {
    const T s = local(t);
    const auto phi = basis_derivatives<K, Basis, Family, M, T>(s);
    vector out = vector::Zero();
    for (int j = 0; j <= M; ++j) out += phi[static_cast<std::size_t>(j)] * X_.col(j);
    if constexpr (K == 1) out /= tau_;
    return out;
  }

  T t_begin_ = T(0), t_end_ = T(0), tau_ = T(0);
  controls X_ = controls::Zero();
  bool valid_ = false;
};

/// Schemes whose steps fit a polynomial path (lpf, galerkin_vi, midpoint_vi, trapezoidal_vi,
/// constrained_lpf):
/// they name its degree m, node family and basis.
template <class Scheme>
concept scheme_with_path = requires {
  { Scheme::m } -> std::convertible_to<int>;
  typename Scheme::family;
  typename Scheme::basis;
};

/// The path type of a scheme's steps in scalar T with n degrees of freedom (void for schemes
/// without a polynomial path).
template <class Scheme, class T, int n>
struct scheme_path {
  using type = void;
};
template <scheme_with_path Scheme, class T, int n>
struct scheme_path<Scheme, T, n> {
  using type = step_path<T, n, Scheme::m, typename Scheme::family, typename Scheme::basis>;
};

}  // namespace geomint
