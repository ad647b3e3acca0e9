#pragma once
/// An optional check that a converged step resolved the motion it approximates.
///
/// Newton can converge to a solution of the discrete equations that has nothing to do with the
/// flow: with tau far beyond the scheme's regime (pendulum, m = 2, tau = 10) the step
/// "succeeds" while the energy jumps by two orders of magnitude; and an unconditionally stable
/// scheme (the midpoint rule) conserves the energy of the harmonic oscillator exactly at
/// tau = 100 while its phase is meaningless. The monitor judges the step itself, never the
/// energy's value (whose zero is arbitrary), with two criteria:
///
///  1. Resolution: tau * omega_max <= max_tau_omega, where omega_max is the fastest local rate
///     of the linearised flow (fastest_local_rate below) at the step's start and end, and the
///     bound is the scheme's (schemes/resolution.hpp: 2s + 1 for a scheme of order 2s, where
///     the Gauss method's phase error per step is one radian).
///  2. Energy: |E_{k+1} - E_k| <= max_energy_change_ratio * S + 2^10 eps (|p . qdot| + |L| at
///     both ends), S = max(|Delta(p . qdot)| + |Delta L|, tau |Delta Ldot| / 2), Ldot = dL/dt
///     along the flow at each end. E = p . qdot - L, so the first term of S is the energy the
///     step exchanges between the terms of E: a constant added to L (the potential's zero)
///     cancels in Delta L, and for a natural system it is 2|Delta T| + |Delta T - Delta V|,
///     between |Delta T| + |Delta V| and three times that. A variational scheme's energy error
///     stays O(tau^p) (backward error analysis; Hairer, Lubich, Wanner, Geometric Numerical
///     Integration, 2nd ed. (2006), ch. IX), a small part of what a resolved step exchanges;
///     the default ratio 1/10 refuses steps whose energy error is comparable to the exchange.
///     The exchange of a step that straddles an extremum of the kinetic energy (a turning point
///     of a pendulum) vanishes to first order while the step's energy error does not; there the
///     second term, the step times the change of the rate of exchange (d(p . qdot)/dt = dL/dt
///     along the flow), is its second-order size: for a step with the extremum at its midpoint,
///     p . qdot and L each vary by tau |Delta Ldot| / 8 on each half, tau |Delta Ldot| / 2 in
///     all, to second order in tau (natural systems: p . qdot = 2T, L = 2T - E). It is small
///     against the first term away from extrema. Without it, resolved runs were refused at
///     extrema (Henon-Heiles at tau = 1/10 with the trapezoidal and midpoint rules, Ruth's
///     order-3 method on the pendulum: tests/solvers/test_step_monitor.cpp).
///     The round-off floor (2^10 eps times the terms of E, i.e. the rounding of E and of the
///     solve's tolerance with room) means a step that conserves energy to round-off is never
///     refused, whatever the scale (a system at rest, a parabolic orbit with E = 0).
///  A step whose energy or rate is not finite (the Legendre transform not invertible) is
///  refused too. A refused step is step_failure::left_regime, and the caller keeps the state.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Core>

#include "geomint/core/mantissa.hpp"
#include "geomint/linalg/lu_small.hpp"
#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/solvers/newton.hpp"

namespace geomint {

/// What the monitor measures at one state: E = p . qdot - L, its two terms, and omega_max.
template <class T>
struct monitor_point {
  T energy = std::numeric_limits<T>::quiet_NaN();
  T p_qdot = std::numeric_limits<T>::quiet_NaN();  ///< p . qdot (2T for a natural system)
  T lagrangian = std::numeric_limits<T>::quiet_NaN();
  T rate = T(0);  ///< omega_max (0 when not measured)
  /// dL/dt = d(p . qdot)/dt along the flow (L_q . qdot + L_qdot . qddot, qddot from the
  /// Euler-Lagrange equations): the rate at which the terms of E exchange energy.
  T lagrangian_rate = std::numeric_limits<T>::quiet_NaN();
};

namespace detail {
/// ||X^32||_inf^(1/32), by five squarings with renormalisation: an upper bound of the spectral
/// radius of X (rho <= ||X^k||^(1/k) for an induced norm) that tends to it; exact for a normal
/// X, within a factor (32 kappa)^(1/32) for eigenvectors of condition kappa or a Jordan block.
template <class T>
T spectral_radius_bound(Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> x) {
  using std::sqrt;
  auto norm = [](const auto& m) { return T(m.cwiseAbs().rowwise().sum().maxCoeff()); };
  T c = norm(x);
  if (!(c > T(0)) || !is_finite(c)) return c;
  x /= c;
  T factor(1);
  for (int j = 1; j <= 5; ++j) {
    x = (x * x).eval();
    T nx = norm(x);
    if (!(nx > T(0))) return T(0);  // nilpotent to working precision
    x /= nx;
    for (int r = 0; r < j; ++r) nx = sqrt(nx);  // nx^(1/2^j)
    factor *= nx;
  }
  return T(c * factor);
}

/// x as a dynamic matrix, element by element: GCC 12 at -O3 flags Eigen's packet copy of a
/// fixed 1 x 1 matrix into a dynamic one as out of bounds (-Warray-bounds, a false positive).
template <class T, int n>
Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> to_dynamic(const mat<T, n>& x) {
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> out(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) out(r, c) = x(r, c);
  return out;
}
}  // namespace detail

/// omega_max at (q, qdot): the spectral radius of the Jacobian of the first-order flow
/// (q, qdot)' = (qdot, a(q, qdot)), J = [[0, I], [a_q, a_qdot]], from the linearised
/// Euler-Lagrange equations E(q, qdot, a) = 0: a_q = -E_a^{-1} E_q, a_qdot = -E_a^{-1} E_qdot
/// (E_q, E_qdot, E_a from mechanics/lagrangian.hpp). For a natural system a_q = -M^{-1} Hess V
/// and a_qdot = 0, so omega_max = sqrt(rho(M^{-1} Hess V)) (the fastest oscillation, or the
/// fastest exponential rate near an unstable equilibrium). Estimated by
/// detail::spectral_radius_bound on J balanced as [[0, s I], [a_q / s, a_qdot]] with
/// s = sqrt(|a_q|) (or |a_qdot| where a_q = 0). NaN where E_a or M is singular.
template <class Sys, class T>
T fastest_local_rate(const Sys& sys, const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& qdot) {
  constexpr int n = Sys::dof;
  using D = lagrangian_derivatives<Sys, T>;
  using dense = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using std::sqrt;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  mat<T, n> aq;
  if constexpr (natural_system<Sys>) {
    const hessian_data<T, n> h = D::hessian(sys, q, qdot);
    const mat<T, n> M = Sys::template mass_matrix<T>();
    for (int j = 0; j < n; ++j) {
      vec<T, n> col;
      if (!solve_small<T, n>(M, vec<T, n>(h.Lqq.col(j)), col)) return nan;
      aq.col(j) = col;  // M^{-1} L_qq = -M^{-1} Hess V
    }
    // The spectrum of J is +-sqrt of that of a_q: the n x n problem suffices.
    const T r = detail::spectral_radius_bound<T>(detail::to_dynamic<T, n>(aq));
    return is_finite(r) ? T(sqrt(r)) : nan;
  } else {
    vec<T, n> a;
    {
      const hessian_data<T, n> h = D::hessian(sys, q, qdot);
      if (!solve_small<T, n>(h.Lvv, vec<T, n>(h.Lq - h.Lvq * qdot), a)) return nan;
    }
    const el_data<T, n> e = D::euler_lagrange(sys, q, qdot, a);
    mat<T, n> av;
    for (int j = 0; j < n; ++j) {
      vec<T, n> cq, cv;
      if (!solve_small<T, n>(e.Ea, vec<T, n>(-e.Ex.col(j)), cq) || !solve_small<T, n>(e.Ea, vec<T, n>(-e.Ev.col(j)), cv))
        return nan;
      aq.col(j) = cq;
      av.col(j) = cv;
    }
    const T aq_norm = T(aq.cwiseAbs().rowwise().sum().maxCoeff());
    const T av_norm = T(av.cwiseAbs().rowwise().sum().maxCoeff());
    const T s = aq_norm > T(0) ? T(sqrt(aq_norm)) : av_norm > T(0) ? av_norm : T(1);
    dense J = dense::Zero(2 * n, 2 * n);
    J.topRightCorner(n, n) = s * dense::Identity(n, n);
    J.bottomLeftCorner(n, n) = detail::to_dynamic<T, n>(aq) / s;
    J.bottomRightCorner(n, n) = detail::to_dynamic<T, n>(av);
    return detail::spectral_radius_bound<T>(J);
  }
}

/// The monitor's measurement at (q, p): qdot from the inverse Legendre transform, E, p . qdot,
/// L and (if with_rate) omega_max. NaN fields where qdot cannot be found.
template <class Sys, class T>
monitor_point<T> measure_monitor_point(const Sys& sys, const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& p,
                                       bool with_rate) {
  monitor_point<T> m;
  vec<T, Sys::dof> v;
  if (!lagrangian_derivatives<Sys, T>::velocity(sys, q, p, v)) return m;
  const auto g = lagrangian_derivatives<Sys, T>::gradient(sys, q, v);
  m.p_qdot = v.dot(g.Lv);
  m.lagrangian = g.L;
  m.energy = T(m.p_qdot - m.lagrangian);
  {
    const hessian_data<T, Sys::dof> h = lagrangian_derivatives<Sys, T>::hessian(sys, q, v);
    vec<T, Sys::dof> a;
    if (solve_small<T, Sys::dof>(h.Lvv, vec<T, Sys::dof>(h.Lq - h.Lvq * v), a))
      m.lagrangian_rate = T(h.Lq.dot(v) + h.Lv.dot(a));
  }
  if (with_rate) m.rate = fastest_local_rate<Sys, T>(sys, q, v);
  return m;
}

/// Off by default; see the top of this file for the two criteria.
template <class T>
struct step_monitor {
  bool enabled = false;
  /// In (0, 1]: the largest |Delta E| / (|Delta(p . qdot)| + |Delta L|) of a step (above the
  /// round-off floor).
  T max_energy_change_ratio = T(1) / T(10);
  /// The largest tau * omega_max; 0 (the default) means the scheme's bound, filled in by the
  /// integrator or stepper when the monitor is set (schemes/resolution.hpp); infinity turns
  /// the resolution check off.
  T max_tau_omega = T(0);

  /// The round-off floor of the energy check, in units of eps (|p . qdot| + |L|) at both ends.
  static T round_off_units() { return T(1024); }

  /// The monitor on, with the default bounds.
  static step_monitor on() {
    step_monitor m;
    m.enabled = true;
    return m;
  }

  /// This monitor with max_tau_omega = scheme_bound if it was 0 (the scheme's own bound).
  step_monitor for_scheme(const T& scheme_bound) const {
    step_monitor m = *this;
    if (m.max_tau_omega == T(0)) m.max_tau_omega = scheme_bound;
    return m;
  }

  /// Whether the resolution check runs (a finite bound).
  bool checks_resolution() const { return enabled && is_finite(max_tau_omega) && max_tau_omega > T(0); }

  /// Throws std::invalid_argument for a ratio that is not a finite number in (0, 1], or a
  /// max_tau_omega that is NaN or negative.
  void validate() const {
    if (!is_finite(max_energy_change_ratio) || !(max_energy_change_ratio > T(0)) || max_energy_change_ratio > T(1))
      throw std::invalid_argument("step_monitor: max_energy_change_ratio must be a finite number in (0, 1]");
    if (!(max_tau_omega >= T(0)))
      throw std::invalid_argument("step_monitor: max_tau_omega must be >= 0 (0: the scheme's bound; infinity: no check)");
  }

  /// Checks the step of size tau from `before` to `after`; on refusal sets st.reason =
  /// left_regime, st.regime_check and the figures of its message. A no-op when disabled or
  /// when st already reports a failure.
  void check(const T& tau, const monitor_point<T>& before, const monitor_point<T>& after, step_status& st) const {
    if (!enabled || !st) return;
    using std::abs;
    using std::max;
    auto refuse = [&](monitor_check c, const T& observed, const T& bound) {
      st.reason = step_failure::left_regime;
      st.regime_check = c;
      st.observed = to_double(observed);
      st.bound = to_double(bound);
    };
    const T inf = std::numeric_limits<T>::infinity();
    if (!is_finite(before.energy) || !is_finite(after.energy) || !is_finite(before.p_qdot) || !is_finite(after.p_qdot) ||
        !is_finite(before.lagrangian) || !is_finite(after.lagrangian) || !is_finite(before.rate) || !is_finite(after.rate) ||
        !is_finite(before.lagrangian_rate) || !is_finite(after.lagrangian_rate))
      return refuse(monitor_check::non_finite, inf, T(0));
    if (checks_resolution()) {
      const T resolution = T(tau * max(before.rate, after.rate));
      if (resolution > max_tau_omega) return refuse(monitor_check::resolution, resolution, max_tau_omega);
    }
    const T change = abs(T(after.energy - before.energy));
    const T exchange = T(abs(T(after.p_qdot - before.p_qdot)) + abs(T(after.lagrangian - before.lagrangian)));
    const T scale = max(exchange, T(tau * abs(T(after.lagrangian_rate - before.lagrangian_rate)) / T(2)));
    const T floor = round_off_units() * std::numeric_limits<T>::epsilon() *
                    (abs(before.p_qdot) + abs(before.lagrangian) + abs(after.p_qdot) + abs(after.lagrangian));
    if (change > max_energy_change_ratio * scale + floor)
      refuse(monitor_check::energy, scale > T(0) ? T(change / scale) : inf, max_energy_change_ratio);
  }
};

}  // namespace geomint
