#pragma once
/// The stepping interface for a holonomically constrained system over a constrained scheme
/// (`constrained_lpf`): the same contract as `integrator` (initial_state, try_step, step,
/// advance, one status and one exception), plus the checked or projected initial data.

#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geomint/linalg/lu_small.hpp"
#include "geomint/mechanics/constraint.hpp"
#include "geomint/schemes/constrained_lpf.hpp"
#include "geomint/schemes/resolution.hpp"
#include "geomint/schemes/step_path.hpp"
#include "geomint/solvers/phase_state.hpp"

namespace geomint {

/// Stepping interface for a constrained system: initial data are checked (or projected),
/// every step reports failures with the step index.
template <class Scheme, lagrangian_system Sys, class Con, class T>
  requires holonomic_constraints<Con, Sys::dof>
class constrained_integrator {
 public:
  static constexpr int n = Sys::dof;
  static constexpr int c = Con::count;
  using vector = vec<T, n>;
  using state = phase_state<T, n>;
  /// Dense output of one step: the path fitted on [t_k, t_{k+1}] (schemes/step_path.hpp). It
  /// meets the constraints at the nodes where the scheme imposes them, not in between, and its
  /// end velocity is the one before the momentum projection.
  using path = step_path<T, n, Scheme::m, typename Scheme::family, typename Scheme::basis>;
  using engine_type = typename Scheme::template engine<Sys, Con, T>;
  /// What a step leaves for the next (integrator::cache_type): the integrator's own in its
  /// non-const steps, the caller's in the const ones.
  using cache_type = typename engine_type::cache_type;

  /// The Newton options are validated here (std::invalid_argument for max_iterations < 1 etc.).
  constrained_integrator(const Sys& sys, const Con& con, const T& tau, newton_options<T> opt = {})
      : engine_(sys, con), tau_(tau), opt_(opt) {
    opt_.validate();
  }

  const T& tau() const { return tau_; }
  /// The optional step monitor (off by default; see step_monitor.hpp). Validated when set; a
  /// max_tau_omega of 0 becomes the scheme's resolution bound (schemes/resolution.hpp), which
  /// the monitor applies to the rate of the unconstrained Lagrangian (the constraint forces'
  /// frequencies are not measured).
  void set_monitor(const step_monitor<T>& m) {
    m.validate();
    monitor_ = m.for_scheme(scheme_resolution_bound<Scheme, T>());
  }

  /// The state at t = 0 from (q_0, qdot_0). Throws std::invalid_argument when q_0 is off the
  /// constraint, or qdot_0 not tangent to it, by more than `tolerance_ulps` eps (scaled by
  /// 1 + |q_0| and 1 + |qdot_0|); use project_initial_state to move such data onto it.
  state initial_state(const vector& q0, const vector& qdot0, int tolerance_ulps = 64) const {
    if (!all_finite(q0) || !all_finite(qdot0))
      throw std::invalid_argument("geomint: initial state is not finite");
    const auto g = constraint_derivatives<Con, T, n>::first(engine_.constraints(), q0);
    const T eps = std::numeric_limits<T>::epsilon();
    const T off = g.f.template lpNorm<Eigen::Infinity>();
    const T normal_speed = (g.G * qdot0).template lpNorm<Eigen::Infinity>();
    const T tol_q = T(tolerance_ulps) * eps * (T(1) + q0.template lpNorm<Eigen::Infinity>());
    const T tol_v = T(tolerance_ulps) * eps * (T(1) + qdot0.template lpNorm<Eigen::Infinity>());
    if (off > tol_q)
      throw std::invalid_argument("geomint: initial position violates the constraints (max |f(q0)| = " +
                                  to_text(off) + "); use project_initial_state");
    if (normal_speed > tol_v)
      throw std::invalid_argument("geomint: initial velocity is not tangent to the constraints (max |G(q0) qdot0| = " +
                                  to_text(normal_speed) + "); use project_initial_state");
    state s;
    s.q = q0;
    s.p = momentum<Sys, T>(engine_.system(), q0, qdot0);
    return s;
  }

  /// Explicit projection of initial data: q_0 moves along G^T to f = 0 (Newton, the closest
  /// point to first order), qdot_0 is replaced by its part tangent to the constraint at the new q_0
  /// (the momentum projection used after every step).
  state project_initial_state(vector q0, const vector& qdot0) const {
    // Non-finite data would otherwise surface as a "singular Jacobian" or a failed projection.
    if (!all_finite(q0) || !all_finite(qdot0))
      throw std::invalid_argument("geomint: initial state is not finite (project_initial_state needs finite q0 and qdot0)");
    using F = constraint_derivatives<Con, T, n>;
    const T eps = std::numeric_limits<T>::epsilon();
    for (int it = 0;; ++it) {
      const auto g = F::first(engine_.constraints(), q0);
      if (g.f.template lpNorm<Eigen::Infinity>() <= T(4) * eps * (T(1) + q0.template lpNorm<Eigen::Infinity>())) break;
      if (it == 50) throw std::invalid_argument("geomint: could not project q0 onto the constraints");
      vec<T, c> y;
      if (!solve_small<T, c>(mat<T, c>(g.G * g.G.transpose()), vec<T, c>(-g.f), y))
        throw std::invalid_argument("geomint: constraint Jacobian is singular at q0");
      q0 += g.G.transpose() * y;
    }
    state s;
    s.q = q0;
    if (!engine_.project_momentum(q0, momentum<Sys, T>(engine_.system(), q0, qdot0), s.p))
      throw std::invalid_argument("geomint: could not project the initial velocity");
    return s;
  }

  /// Compensated summation of the positions (off by default; integrator.hpp): q_{k+1} = q_k + dq
  /// is added with its rounding error carried in the state (phase_state::carry); the momentum is
  /// projected onto the hidden constraint at q_{k+1} and stored as a value (its carry is 0).
  void set_compensated_summation(bool on) { compensated_ = on; }
  bool compensated_summation() const { return compensated_; }

  /// The integrator's own cache; `cache() = {}` forgets the last step.
  cache_type& cache() { return cache_; }

  /// One step without throwing; on failure s is unchanged.
  step_status try_step(state& s) { return try_step(s, cache_); }
  /// The same step with the caller's cache.
  step_status try_step(state& s, cache_type& cache) const {
    const step_status st = check_step_input(s.step, tau_, s.q, s.p);
    if (!st) return st;
    vector q1, p1;
    phase_carry<T, n> carry1 = s.carry;
    phase_carry<T, n>* carry = compensated_ ? &carry1 : nullptr;
    return finish_step(s, engine_.one_step(s.q, s.p, tau_, q1, p1, opt_, &cache, nullptr, carry), q1, p1, tau_,
                       monitor_, engine_.system(), carry);
  }
  /// One step; throws integration_error (reason and step index) on failure.
  void step(state& s) { step(s, cache_); }
  void step(state& s, cache_type& cache) const {
    const step_status st = try_step(s, cache);
    if (!st) throw integration_error(st);
  }
  /// `count` steps; throws on the first failure.
  void advance(state& s, long count) { advance(s, count, cache_); }
  void advance(state& s, long count, cache_type& cache) const {
    for (long i = 0; i < count; ++i) step(s, cache);
  }

  /// One step and its path (see `path`); throws integration_error on failure.
  path step_with_path(state& s) {
    path out;
    const step_status st = try_step_with_path(s, out, cache_);
    if (!st) throw integration_error(st);
    return out;
  }
  /// As step_with_path without throwing: on failure s and `out` are unchanged.
  step_status try_step_with_path(state& s, path& out) { return try_step_with_path(s, out, cache_); }
  step_status try_step_with_path(state& s, path& out, cache_type& cache) const {
    const step_status in = check_step_input(s.step, tau_, s.q, s.p);
    if (!in) return in;
    vector q1, p1;
    typename engine_type::unknowns z;
    const vector q0 = s.q;
    const T t0 = s.t;
    phase_carry<T, n> carry1 = s.carry;
    phase_carry<T, n>* carry = compensated_ ? &carry1 : nullptr;
    const step_status st = finish_step(s, engine_.one_step(s.q, s.p, tau_, q1, p1, opt_, &cache, &z, carry), q1, p1, tau_, monitor_,
                                       engine_.system(), carry);
    if (st) out = path(t0, s.t, tau_, engine_.method().path(q0, z));
    return st;
  }

  /// The two-step form; `drop` gives the paper's printed scheme (23) for the circle.
  vector two_step(const vector& x_prev, const vector& x_curr, endpoint_terms ends, long k = 1) const {
    vector x_next;
    step_status st = engine_.two_step(x_prev, x_curr, tau_, ends, x_next, opt_);
    st.step = k;
    if (!st) throw integration_error(st);
    return x_next;
  }

  T energy(const state& s) const { return energy(s.q, s.p); }
  T energy(const vector& q, const vector& p) const { return energy_qp<Sys, T>(engine_.system(), q, p); }
  T violation(const state& s) const { return constraint_violation<Con, T, n>(engine_.constraints(), s.q); }
  /// max |G(q) qdot|: the hidden (velocity) constraint.
  T velocity_violation(const state& s) const {
    vector v;
    if (!lagrangian_derivatives<Sys, T>::velocity(engine_.system(), s.q, s.p, v))
      return std::numeric_limits<T>::quiet_NaN();
    const auto g = constraint_derivatives<Con, T, n>::first(engine_.constraints(), s.q);
    return T((g.G * v).template lpNorm<Eigen::Infinity>());
  }

 private:
  static std::string to_text(const T& x) {
    std::ostringstream os;
    os.precision(6);
    os << x;
    return os.str();
  }
  engine_type engine_;
  cache_type cache_;
  T tau_;
  newton_options<T> opt_;
  step_monitor<T> monitor_;
  bool compensated_ = false;
};

}  // namespace geomint
