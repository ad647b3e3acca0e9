#pragma once
/// The common stepping interface over a scheme (lpf, midpoint_vi, trapezoidal_vi, galerkin_vi),
/// a Lagrangian system and a scalar type.
///
///   geomint::integrator<geomint::lpf<4, geomint::gauss_interior>, geomint::systems::pendulum, T> I(sys, tau);
///   auto s = I.initial_state(q0, qdot0);   // p_0 = dL/dqdot(q_0, qdot_0)
///   I.step(s);                              // (q_k, p_k) -> (q_{k+1}, p_{k+1}); throws integration_error
///   I.try_step(s, cache);                   // the same through a const integrator and a cache of the caller's
///   auto [x0, x1] = I.start(q0, qdot0);     // consistent start of the two-step form
///   auto x2 = I.two_step(x0, x1);           // (x^{k-1}, x^k) -> x^{k+1} (eq. 11-12; schemes 16-22)
///   auto path = I.step_with_path(s);        // one step and its path: path.position(t), path.velocity(t)

#include <type_traits>
#include <utility>

#include "geomint/schemes/classical.hpp"
#include "geomint/schemes/lpf.hpp"
#include "geomint/schemes/paper_schemes.hpp"
#include "geomint/schemes/resolution.hpp"
#include "geomint/schemes/step_path.hpp"
#include "geomint/solvers/phase_state.hpp"

namespace geomint {

template <class Scheme, class Sys, class T>
class integrator {
  static_assert(eigen_scalar_ready<T>::value,
                "geomint::integrator: T is a Boost.Multiprecision number but its Eigen traits are not included: "
                "#include <geomint/core/multiprecision.hpp> (or <geomint/geomint.hpp>, or a Boost.Multiprecision "
                "header before geomint's headers)");
  static_assert(checked_system<Sys, T>, "geomint::integrator: Sys does not satisfy the system contract (see above)");
  static_assert(!is_dual<T>::value, "geomint::integrator: T is the working scalar (double, a Boost.Multiprecision type), not a dual");

 public:
  static constexpr int n = contract_dof<Sys>();
  using scalar = T;
  using scheme = Scheme;
  using system = Sys;
  using vector = vec<T, n>;
  using state = phase_state<T, n>;
  /// The dense output of one step (step_path; void for a scheme without a polynomial path).
  using path = typename scheme_path<Scheme, T, n>::type;
  /// The scheme's engine: its coefficients and the system, fixed at construction.
  using engine_type = typename Scheme::template engine<Sys, T>;
  /// What a step leaves for the next: the last solution (the next predictor) and the factorised
  /// Newton matrix (reused while it contracts), or the fixed-point form's stage increments.
  /// The integrator owns one (`cache()`) and uses it in its non-const steps; the const steps take
  /// the caller's, so that one const integrator serves many trajectories or threads, each with
  /// its own cache. A cache only speeds the next step that continues its last one (same q, p and
  /// tau); every step solves the same equations to the Newton tolerance with or without it.
  using cache_type = typename engine_type::cache_type;

  /// tau is checked at every step (an invalid tau is reported with the step index).
  /// The Newton options are validated here (std::invalid_argument for max_iterations < 1 etc.).
  explicit integrator(const Sys& sys = Sys{}, const T& tau = T(1) / T(10), newton_options<T> opt = {})
      : sys_(sys), engine_(sys), tau_(tau), opt_(opt) {
    opt_.validate();
  }

  const T& tau() const { return tau_; }
  void set_tau(const T& tau) { tau_ = tau; }
  const Sys& system_ref() const { return sys_; }
  newton_options<T>& options() { return opt_; }
  const newton_options<T>& options() const { return opt_; }
  /// The optional step monitor (off by default; see step_monitor.hpp). Validated when set; a
  /// max_tau_omega of 0 becomes the scheme's resolution bound (schemes/resolution.hpp).
  void set_monitor(const step_monitor<T>& m) {
    m.validate();
    monitor_ = m.for_scheme(scheme_resolution_bound<Scheme, T>());
  }
  const step_monitor<T>& monitor() const { return monitor_; }
  /// Compensated summation of the end update (off by default): q_{k+1} = q_k + dq and
  /// p_{k+1} = p_k + dp are added with their rounding errors carried in the state
  /// (phase_state::carry, solvers/phase_state.hpp), so that the sum loses eps |dq| per step
  /// instead of eps |q|. Used where a scheme forms the new point as an increment (LPF and
  /// Galerkin on natural systems, midpoint, trapezoidal; q of every LPF step); the steps stay
  /// the same to rounding. Six additions per component. Measured effect on long runs (the
  /// energy error still grows about linearly: the rounded coefficients of the scheme, not the
  /// summation, dominate): docs/results/long_runs.md, "Brouwer's law".
  void set_compensated_summation(bool on) { compensated_ = on; }
  bool compensated_summation() const { return compensated_; }

  /// The state at t = 0 from (q_0, qdot_0): p_0 = dL/dqdot.
  state initial_state(const vector& q0, const vector& qdot0) const {
    state s;
    s.q = q0;
    s.p = momentum<Sys, T>(sys_, q0, qdot0);
    return s;
  }

  /// Data of another scalar type is not converted silently (a double carries 16 digits, not
  /// those of T): convert explicitly, e.g. `I.initial_state(q0.template cast<T>(), v0.template cast<T>())`.
  template <class U>
    requires(!std::is_same_v<U, T>)
  state initial_state(const vec<U, n>&, const vec<U, n>&) const {
    static_assert(std::is_same_v<U, T>,
                  "geomint::integrator: the initial data has another scalar type than the integrator. Convert it "
                  "explicitly with q0.template cast<T>() (double data carries only 16 significant digits)");
    return {};
  }
  template <class U>
    requires(!std::is_same_v<U, T>)
  std::pair<vector, vector> start(const vec<U, n>&, const vec<U, n>&) const {
    static_assert(std::is_same_v<U, T>,
                  "geomint::integrator: the initial data has another scalar type than the integrator. Convert it "
                  "explicitly with q0.template cast<T>() (double data carries only 16 significant digits)");
    return {};
  }

  /// The integrator's own cache (see cache_type); `cache() = {}` forgets the last step.
  cache_type& cache() { return cache_; }

  /// One step of the one-step form without throwing; on failure s is unchanged.
  step_status try_step(state& s) { return try_step(s, cache_); }
  /// The same step with the caller's cache.
  step_status try_step(state& s, cache_type& cache) const {
    const step_status st = check_step_input(s.step, tau_, s.q, s.p);
    if (!st) return st;
    vector q1 = vector::Zero(), p1 = vector::Zero();
    phase_carry<T, n> carry1 = s.carry;
    phase_carry<T, n>* carry = compensated_ ? &carry1 : nullptr;
    return finish_step(s, engine_.one_step(s.q, s.p, tau_, q1, p1, opt_, &cache, nullptr, carry), q1, p1, tau_,
                       monitor_, sys_, carry);
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

  /// Dense output: one step (as `step`) that also returns the polynomial path it fitted on
  /// [t_k, t_{k+1}], to evaluate x(t) and xdot(t) anywhere in the step (schemes/step_path.hpp;
  /// its accuracy is documented there). For midpoint_vi and trapezoidal_vi the path is the
  /// straight segment (linear interpolation).
  auto step_with_path(state& s)
    requires scheme_with_path<Scheme>
  {
    path out;
    const step_status st = try_step_with_path(s, out, cache_);
    if (!st) throw integration_error(st);
    return out;
  }
  /// As step_with_path without throwing: on failure s and `out` are unchanged.
  template <class Path>
    requires(scheme_with_path<Scheme> && std::is_same_v<Path, path>)
  step_status try_step_with_path(state& s, Path& out) {
    return try_step_with_path(s, out, cache_);
  }
  template <class Path>
    requires(scheme_with_path<Scheme> && std::is_same_v<Path, path>)
  step_status try_step_with_path(state& s, Path& out, cache_type& cache) const {
    const step_status in = check_step_input(s.step, tau_, s.q, s.p);
    if (!in) return in;
    vector q1 = vector::Zero(), p1 = vector::Zero();
    typename engine_type::unknowns z;
    const vector q0 = s.q;
    const T t0 = s.t;
    phase_carry<T, n> carry1 = s.carry;
    phase_carry<T, n>* carry = compensated_ ? &carry1 : nullptr;
    const step_status st =
        finish_step(s, engine_.one_step(s.q, s.p, tau_, q1, p1, opt_, &cache, &z, carry), q1, p1, tau_, monitor_, sys_, carry);
    if (st) out = Path(t0, s.t, tau_, engine_.method().path(q0, z));
    return st;
  }

  /// The two-step form (x^{k-1}, x^k) -> x^{k+1} (eq. 3/11): the momentum at t_k from the path
  /// on [t_{k-1}, t_k], then one step. `k` only labels errors.
  vector two_step(const vector& x_prev, const vector& x_curr, long k = 1) {
    const vector p = momentum_at_end(x_prev, x_curr, k);
    state s;
    s.step = k;
    s.q = x_curr;
    s.p = p;
    step(s);
    return s.q;
  }
  /// d_2 L_d(x^{k-1}, x^k): the momentum at x^k of the path fitted on [t_{k-1}, t_k] (eq. 10).
  vector momentum_at_end(const vector& x_prev, const vector& x_curr, long k = 1) const {
    step_status st = check(k, x_prev, x_curr);
    vector p = vector::Zero();
    if (st) st = engine_.end_momentum(x_prev, x_curr, tau_, p, opt_);
    st.step = k;
    if (!st) throw integration_error(st);
    return p;
  }
  /// Consistent start of the two-step form: x^0 = q_0 and x^1 from one step of the one-step
  /// form with p_0 = dL/dqdot(q_0, qdot_0). Then two_step reproduces the one-step trajectory.
  std::pair<vector, vector> start(const vector& q0, const vector& qdot0) {
    state s = initial_state(q0, qdot0);
    step(s);
    return {q0, s.q};
  }

  /// Energy qdot . dL/dqdot - L at (q, p) (inverse Legendre transform for qdot).
  T energy(const state& s) const { return energy(s.q, s.p); }
  T energy(const vector& q, const vector& p) const { return energy_qp<Sys, T>(sys_, q, p); }

 private:
  step_status check(long k, const vector& a, const vector& b) const { return check_step_input(k, tau_, a, b); }

  Sys sys_;
  engine_type engine_;
  cache_type cache_;
  T tau_;
  newton_options<T> opt_;
  step_monitor<T> monitor_;
  bool compensated_ = false;
};

}  // namespace geomint
