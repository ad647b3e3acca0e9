#pragma once
/// The state of a one-step integrator and the checks every integrator (free, constrained) runs
/// around its scheme's step: input validation before, result checks, the optional monitor and
/// the commit after. A failed step leaves the state unchanged.

#include <limits>
#include <stdexcept>

#include "geomint/core/checked_cast.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/solvers/step_monitor.hpp"
#include "geomint/solvers/step_status.hpp"

namespace geomint {

/// The rounding errors carried by compensated summation (Kahan 1965; Moller 1965): the parts of
/// the exact sums q_0 + sum dq_k and p_0 + sum dp_k that the rounded q and p could not hold.
template <class T, int n>
struct phase_carry {
  vec<T, n> q = vec<T, n>::Zero();
  vec<T, n> p = vec<T, n>::Zero();
};

/// a + b = s + e exactly, s = a + b rounded (Knuth's TwoSum: six additions, any magnitudes).
template <class T>
void two_sum(const T& a, const T& b, T& s, T& e) {
  s = a + b;
  const T b_part = s - a;
  const T a_part = s - b_part;
  e = (a - a_part) + (b - b_part);
}

/// x + (carry + dx) rounded to the nearest scalar, and in carry what that rounding lost, exactly
/// (Knuth's TwoSum: six additions, exact for any magnitudes, so also when p crosses zero and
/// |dp| > |p|). Each component's x + carry is then the exact sum of the increments to within
/// one rounding of each increment (eps |dx|), instead of one rounding of x (eps |x|) per step.
/// This removes the round-off of the summation only: the rounding inside the increments (the
/// scheme's coefficients, the solve) remains (docs/results/long_runs.md, "Brouwer's law").
template <class T, int n>
void add_compensated(vec<T, n>& x, vec<T, n>& carry, const vec<T, n>& dx) {
  for (int i = 0; i < n; ++i) {
    const T y = dx[i] + carry[i];
    const T a = x[i];
    two_sum(a, y, x[i], carry[i]);
  }
}

/// add_compensated for an increment known to twice the working precision, dx + dx_lo (a
/// double-double, e.g. from two_sum and an exact product by fma): x + carry + dx + dx_lo is
/// rounded into x, and carry keeps the rest, so that the increment's own rounding is not lost
/// either. The only rounding left is that of the small terms (carry, dx_lo and the error of
/// x + dx), about eps^2 |x|.
template <class T, int n>
void add_compensated(vec<T, n>& x, vec<T, n>& carry, const vec<T, n>& dx, const vec<T, n>& dx_lo) {
  for (int i = 0; i < n; ++i) {
    T s, e;
    two_sum(x[i], dx[i], s, e);
    const T small = e + (carry[i] + dx_lo[i]);
    two_sum(s, small, x[i], carry[i]);
  }
}

/// A point of the one-step (position-momentum) form.
///
/// Time is never accumulated: t_k = t0 + (k - k0) tau, where (k0, t0) is the step and time at
/// which the current step size tau0 was first used, so 10^7 steps of tau = 1/10 end at exactly
/// the nearest scalar to 10^6. Set `t` (and `step`) before the first step to start elsewhere.
template <class T, int n>
struct phase_state {
  long step = 0;  ///< k
  T t = T(0);     ///< t_k
  vec<T, n> q = vec<T, n>::Zero();
  vec<T, n> p = vec<T, n>::Zero();
  long k0 = 0;    ///< the step at which tau0 was first used
  T t0 = T(0);    ///< t_{k0}
  T tau0 = T(0);  ///< the step size in use since k0 (0 before the first step)
  /// The compensation terms of compensated summation (integrator::set_compensated_summation):
  /// q + carry.q and p + carry.p are the state to about twice the working precision. Zero
  /// unless compensated summation is on; reset it to zero when setting q or p by hand.
  phase_carry<T, n> carry{};

  /// Commits a successful step: (q_{k+1}, p_{k+1}), k + 1 and t_{k+1} = t0 + (k + 1 - k0) tau.
  /// k = LONG_MAX has no successor: check_step_input refuses that step (step_index_overflow),
  /// and commit throws std::overflow_error. A step index set by hand below k0, or so far from
  /// it that k + 1 - k0 overflows, starts a new (k0, t0) at the current step.
  void commit(const vec<T, n>& q1, const vec<T, n>& p1, const T& tau) {
    const auto next = checked_add(step, 1L);
    if (!next) throw std::overflow_error("geomint::phase_state: the step index is at its maximum (LONG_MAX)");
    if (!(tau0 == tau) || step < k0 || !checked_sub(*next, k0)) {
      k0 = step;
      t0 = t;
      tau0 = tau;
    }
    q = q1;
    p = p1;
    step = *next;
    t = t0 + from_int64<T>(step - k0) * tau;
  }
  /// Commits a successful step with its new compensation terms.
  void commit(const vec<T, n>& q1, const vec<T, n>& p1, const phase_carry<T, n>& carry1, const T& tau) {
    commit(q1, p1, tau);
    carry = carry1;
  }
};

/// The checks before step k: k + 1 representable, tau finite and > 0, the data a and b finite.
template <class T, class A, class B>
step_status check_step_input(long k, const T& tau, const A& a, const B& b) {
  step_status st;
  st.step = k;
  if (k == std::numeric_limits<long>::max())
    st.reason = step_failure::step_index_overflow;
  else if (!is_finite(tau) || !(tau > T(0)))
    st.reason = step_failure::invalid_step_size;
  else if (!all_finite(a) || !all_finite(b))
    st.reason = step_failure::non_finite_input;
  return st;
}

/// The checks after a scheme's step st from s to (q1, p1) of size tau: a finite result and,
/// when enabled, the step monitor on the system `sys` (its energy terms and local rate at both
/// ends, step_monitor.hpp); commits to s only if all pass. `carry1` (if not null) holds the
/// compensation terms of the new state, committed with it (compensated summation).
template <class T, int n, class Sys>
step_status finish_step(phase_state<T, n>& s, step_status st, const vec<T, n>& q1, const vec<T, n>& p1, const T& tau,
                        const step_monitor<T>& monitor, const Sys& sys, const phase_carry<T, n>* carry1 = nullptr) {
  st.step = s.step;
  if (!st) return st;
  if (!all_finite(q1) || !all_finite(p1)) {
    st.reason = step_failure::non_finite_iterate;
    return st;
  }
  if (monitor.enabled) {
    const bool rate = monitor.checks_resolution();
    monitor.check(tau, measure_monitor_point<Sys, T>(sys, s.q, s.p, rate), measure_monitor_point<Sys, T>(sys, q1, p1, rate),
                  st);
    if (!st) return st;
  }
  if (carry1)
    s.commit(q1, p1, *carry1, tau);
  else
    s.commit(q1, p1, tau);
  return st;
}

}  // namespace geomint
