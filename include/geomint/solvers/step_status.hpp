#pragma once
/// The outcome of a step, shared by every integrator (free, constrained, beam): one status
/// type with the reason and the step index, and one exception type.
///
/// Convention: `step` is the index k of the step k -> k+1 that was attempted, i.e. the number
/// of steps taken before it; a failed step leaves the integrator's state at step k.

#include <stdexcept>
#include <string>
#include <string_view>

namespace geomint {

/// Why a step failed.
enum class step_failure {
  none,
  invalid_step_size,   ///< tau <= 0 or not finite
  non_finite_input,    ///< q, p (or x^{k-1}, x^k) contain NaN or infinity
  step_index_overflow, ///< the step index k is LONG_MAX: step k + 1 has no index
  singular_jacobian,   ///< the Newton matrix is singular to working precision
  non_finite_iterate,  ///< the iteration (Newton or fixed-point) produced NaN or infinity, or the result is not finite
  no_convergence,      ///< the iteration budget ran out
  energy_growth,       ///< the energy left the bound the options set: the step is outside the scheme's regime
  left_regime,         ///< the step monitor refused the converged step (see step_monitor.hpp)
  map_failed,          ///< a user's one-step map reported a failure (function_stepper, solvers/any_stepper.hpp)
};

inline std::string_view to_string(step_failure f) {
  switch (f) {
    case step_failure::none: return "ok";
    case step_failure::invalid_step_size: return "invalid step size (tau must be finite and > 0)";
    case step_failure::non_finite_input: return "non-finite input state";
    case step_failure::step_index_overflow: return "the step index is at its maximum (LONG_MAX): no further step can be counted";
    case step_failure::singular_jacobian: return "singular Newton Jacobian";
    case step_failure::non_finite_iterate: return "the iterate became non-finite (divergence)";
    case step_failure::no_convergence: return "the iteration (Newton or fixed-point) did not converge";
    case step_failure::energy_growth: return "the energy grew beyond its limit (step outside the scheme's stable regime)";
    case step_failure::left_regime: return "step left the scheme's regime (the step monitor refused it; reduce tau)";
    case step_failure::map_failed: return "the one-step map reported a failure";
  }
  return "unknown";
}

/// Which criterion of the step monitor (step_monitor.hpp) refused a step.
enum class monitor_check {
  none,
  non_finite,  ///< the energy or the local rate at an end of the step is not finite
  resolution,  ///< tau * omega_max above the scheme's bound: the step does not resolve the motion
  energy,      ///< |Delta E| above its share of the energy the step exchanged
};

/// Outcome of one step: success, or the reason and the index of the failing step. Trivially
/// copyable (returned by every step); details that need text travel in integration_error.
struct step_status {
  step_failure reason = step_failure::none;
  long step = 0;        ///< index k of the step k -> k+1 that was attempted
  int iterations = 0;   ///< iterations used (Newton iterations or fixed-point sweeps)
  int node = -1;        ///< the grid node concerned (beam), or -1
  /// For left_regime: the criterion, its observed value and its bound (as double, for the
  /// message only).
  monitor_check regime_check = monitor_check::none;
  double observed = 0, bound = 0;
  explicit operator bool() const { return reason == step_failure::none; }
  std::string message() const {
    std::string text = "geomint: step " + std::to_string(step) + ": " + std::string(to_string(reason));
    if (reason == step_failure::left_regime) {
      if (regime_check == monitor_check::resolution)
        text += ": tau * omega_max = " + std::to_string(observed) + " > " + std::to_string(bound) +
                " (the step does not resolve the fastest local motion)";
      else if (regime_check == monitor_check::energy)
        text += ": |E_{k+1} - E_k| / max(|Delta(p.qdot)| + |Delta L|, tau |Delta dL/dt| / 2) = " + std::to_string(observed) + " > " +
                std::to_string(bound) + " (the energy error is comparable to the energy the step exchanged)";
      else if (regime_check == monitor_check::non_finite)
        text += ": the energy or the local rate is not finite (the Legendre transform failed)";
    }
    if (node >= 0) text += " at node " + std::to_string(node);
    if (iterations > 0) text += " (after " + std::to_string(iterations) + " iterations)";
    return text;
  }
};

/// Thrown by the throwing stepping functions (`step`, `advance`); carries the status and,
/// optionally, a detail appended to its message.
class integration_error : public std::runtime_error {
 public:
  explicit integration_error(const step_status& s, const std::string& detail = {})
      : std::runtime_error(detail.empty() ? s.message() : s.message() + ": " + detail), status_(s) {}
  step_failure reason() const { return status_.reason; }
  long step() const { return status_.step; }
  int node() const { return status_.node; }
  const step_status& status() const { return status_; }

 private:
  step_status status_;
};

}  // namespace geomint
