#pragma once
/// The one step interface: a one-step map (q_k, p_k) -> (q_{k+1}, p_{k+1}) of step size tau,
/// type-erased. The tools step it, and the analyses take it directly: the order study
/// (analysis/order_study.hpp), the symplecticity defect and the energy behaviour
/// (analysis/symplecticity.hpp).
///
/// - `any_stepper<T>`: the interface. An integrator, erased (`geomint::erase(I)`,
///   geomint/stepper.hpp), or a scheme chosen by name (`geomint::make_stepper`).
/// - `function_stepper<T>`: a map of the user's own (a closed-form flow, a hand-written scheme)
///   behind the same interface, checked as every step is.
///
///   auto s = geomint::erase(I);                    // I: geomint::integrator<Scheme, Sys, T>
///   geomint::step_status st = s->try_step(q, p, tau, q1, p1);

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "geomint/linalg/types.hpp"
#include "geomint/solvers/newton.hpp"
#include "geomint/solvers/phase_state.hpp"
#include "geomint/solvers/step_monitor.hpp"
#include "geomint/solvers/step_status.hpp"

namespace geomint {

/// The type-erased stepper over scalar T.
template <class T>
class any_stepper {
 public:
  using vector = dynamic_vector<T>;
  virtual ~any_stepper() = default;
  virtual int dof() const = 0;
  /// The scheme's name, e.g. "lpf(m=4, gauss-interior, lagrange)".
  virtual std::string name() const = 0;
  /// The step monitor applied by try_step (off unless set; see solvers/step_monitor.hpp). A
  /// max_tau_omega of 0 becomes the scheme's resolution bound (schemes/resolution.hpp).
  virtual void set_monitor(const step_monitor<T>& m) {
    m.validate();
    monitor_ = m.for_scheme(resolution_bound_);
  }
  const step_monitor<T>& monitor() const { return monitor_; }
  /// The Newton options of try_step without options (validated: std::invalid_argument).
  const newton_options<T>& options() const { return options_; }
  void set_options(const newton_options<T>& opt) {
    opt.validate();
    options_ = opt;
  }
  /// One step of size tau from (q, p); on failure q1 and p1 are untouched. A state of the wrong
  /// dimension is a programming error (std::invalid_argument).
  /// The stepper keeps its engine's cache (integrator::cache_type) from step to step, so a step
  /// changes it: a stepper serves one trajectory at a time (make one per thread).
  step_status try_step(const vector& q, const vector& p, const T& tau, vector& q1, vector& p1) {
    return step(q, p, tau, q1, p1, options_);
  }
  /// The same step with other Newton options for this step alone.
  step_status try_step(const vector& q, const vector& p, const T& tau, vector& q1, vector& p1,
                       const newton_options<T>& opt) {
    return step(q, p, tau, q1, p1, opt);
  }
  /// The same step with compensated summation of the end update (integrator::
  /// set_compensated_summation): q_carry and p_carry are the compensation terms of (q, p) on
  /// entry (zero to start) and of (q1, p1) on success; on failure all are untouched.
  step_status try_step_compensated(const vector& q, const vector& p, vector& q_carry, vector& p_carry, const T& tau,
                                   vector& q1, vector& p1) {
    return step_compensated(q, p, q_carry, p_carry, tau, q1, p1, options_);
  }
  step_status try_step_compensated(const vector& q, const vector& p, vector& q_carry, vector& p_carry, const T& tau,
                                   vector& q1, vector& p1, const newton_options<T>& opt) {
    return step_compensated(q, p, q_carry, p_carry, tau, q1, p1, opt);
  }
  /// The energy at (q, p) (NaN where the Legendre transform cannot be inverted).
  virtual T energy(const vector& q, const vector& p) const = 0;
  /// p = dL/dqdot(q, qdot).
  virtual vector momentum(const vector& q, const vector& qdot) const = 0;

 protected:
  explicit any_stepper(const T& resolution_bound) : resolution_bound_(resolution_bound) {}
  virtual step_status step(const vector& q, const vector& p, const T& tau, vector& q1, vector& p1,
                           const newton_options<T>& opt) = 0;
  virtual step_status step_compensated(const vector& q, const vector& p, vector& q_carry, vector& p_carry, const T& tau,
                                       vector& q1, vector& p1, const newton_options<T>& opt) = 0;
  step_monitor<T> monitor_;
  newton_options<T> options_;
  T resolution_bound_;  ///< the scheme's bound on tau * omega_max
};

/// A one-step map of the user's own as an any_stepper: `map(q, p, tau, q1, p1)` returns
/// step_status or bool (false: step_failure::map_failed). Every step runs the input checks of
/// an integrator's step (tau finite and > 0, finite data) and refuses a result that is not
/// finite or not of size dof; on failure q1 and p1 are untouched. `energy(q, p)` is optional
/// (NaN without it). There is no Lagrangian: momentum() and set_monitor() throw
/// std::logic_error, and so do the compensated steps (a map gives no increments to sum).
template <class T>
class function_stepper final : public any_stepper<T> {
 public:
  using typename any_stepper<T>::vector;
  using map_type = std::function<step_status(const vector& q, const vector& p, const T& tau, vector& q1, vector& p1)>;
  using energy_type = std::function<T(const vector& q, const vector& p)>;

  template <class Map>
    requires std::is_invocable_v<const Map&, const vector&, const vector&, const T&, vector&, vector&>
  function_stepper(int dof, std::string name, Map map, energy_type energy = {})
      : any_stepper<T>(std::numeric_limits<T>::infinity()),
        dof_(dof),
        name_(std::move(name)),
        map_(wrap(std::move(map))),
        energy_(std::move(energy)) {
    if (dof < 1) throw std::invalid_argument("geomint::function_stepper: dof must be >= 1");
  }
  int dof() const override { return dof_; }
  std::string name() const override { return name_; }
  void set_monitor(const step_monitor<T>&) override {
    throw std::logic_error("geomint::function_stepper: the step monitor needs a system's energy; check the steps in the map");
  }
  T energy(const vector& q, const vector& p) const override {
    return energy_ ? energy_(sized(q), sized(p)) : std::numeric_limits<T>::quiet_NaN();
  }
  vector momentum(const vector&, const vector&) const override {
    throw std::logic_error("geomint::function_stepper: a map has no Lagrangian; give the momenta p directly");
  }

 protected:
  step_status step(const vector& q, const vector& p, const T& tau, vector& q1, vector& p1,
                   const newton_options<T>&) override {
    step_status st = check_step_input(0, tau, sized(q), sized(p));
    if (!st) return st;
    vector a, b;
    st = map_(q, p, tau, a, b);
    if (!st) return st;
    if (a.size() != dof_ || b.size() != dof_ || !all_finite(a) || !all_finite(b)) {
      st.reason = step_failure::non_finite_iterate;
      return st;
    }
    q1 = std::move(a);
    p1 = std::move(b);
    return st;
  }
  step_status step_compensated(const vector&, const vector&, vector&, vector&, const T&, vector&, vector&,
                               const newton_options<T>&) override {
    throw std::logic_error("geomint::function_stepper: compensated summation needs a scheme's increments");
  }

 private:
  template <class Map>
  static map_type wrap(Map map) {
    using R = std::invoke_result_t<const Map&, const vector&, const vector&, const T&, vector&, vector&>;
    if constexpr (std::is_same_v<R, step_status>) {
      return map_type(std::move(map));
    } else {
      static_assert(std::is_same_v<R, bool>, "geomint::function_stepper: the map returns step_status or bool");
      return [map = std::move(map)](const vector& q, const vector& p, const T& tau, vector& q1, vector& p1) {
        step_status st;
        if (!map(q, p, tau, q1, p1)) st.reason = step_failure::map_failed;
        return st;
      };
    }
  }
  const vector& sized(const vector& x) const {
    if (x.size() != dof_)
      throw std::invalid_argument("geomint::function_stepper: a vector of size " + std::to_string(x.size()) +
                                  " for a map of " + std::to_string(dof_) + " degrees of freedom");
    return x;
  }
  int dof_;
  std::string name_;
  map_type map_;
  energy_type energy_;
};

}  // namespace geomint
