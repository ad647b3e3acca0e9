#pragma once
/// An optional check that a converged step stayed in the scheme's regime.
///
/// Newton can converge to a solution of the discrete equations that has nothing to do with the
/// flow: with tau far beyond the scheme's stability region (pendulum, m = 2, tau = 10) the step
/// "succeeds" while the energy jumps by two orders of magnitude. The schemes of this library
/// are variational, so for the autonomous systems they integrate the energy is conserved up to
/// a bounded oscillation of size O(tau^p) (backward error analysis; Hairer, Lubich, Wanner,
/// Geometric Numerical Integration, 2nd ed. (2006), ch. IX). A per-step relative energy change
/// of order one therefore means the step left the regime in which the scheme approximates the
/// flow; the monitor reports it as step_failure::left_regime, and the caller keeps the state.
#include <algorithm>
#include <stdexcept>

#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/solvers/newton.hpp"

namespace geomint {

/// Off by default. When enabled, a step from energy E_k to E_{k+1} is refused when
/// |E_{k+1} - E_k| > max_relative_energy_change * max(|E_k|, |E_{k+1}|), or when E_{k+1} is not
/// finite (the Legendre transform could not be inverted at the new state).
template <class T>
struct step_monitor {
  bool enabled = false;
  /// In (0, 1]: a relative change per step above this is out of the regime. The default 1/10
  /// is far above the per-step energy error of any step the schemes resolve (the energy error
  /// of a resolved run is O(tau^p) over the whole run, not per step) and far below the O(1)
  /// jumps of an unresolved step.
  T max_relative_energy_change = T(1) / T(10);

  /// The monitor on, with the default bound.
  static step_monitor on() {
    step_monitor m;
    m.enabled = true;
    return m;
  }

  /// Throws std::invalid_argument for a bound that is not a finite number in (0, 1].
  void validate() const {
    if (!is_finite(max_relative_energy_change) || !(max_relative_energy_change > T(0)) ||
        max_relative_energy_change > T(1))
      throw std::invalid_argument("step_monitor: max_relative_energy_change must be a finite number in (0, 1]");
  }

  /// Checks the step E_k -> E_{k+1}; on refusal sets st.reason = left_regime and the figures of
  /// its message. A no-op when disabled or when st already reports a failure.
  void check(const T& energy_before, const T& energy_after, step_status& st) const {
    if (!enabled || !st) return;
    using std::abs;
    using std::max;
    if (!is_finite(energy_after) || !is_finite(energy_before)) {
      st.reason = step_failure::left_regime;
      st.observed = std::numeric_limits<double>::infinity();
      st.bound = static_cast<double>(max_relative_energy_change);
      return;
    }
    const T change = abs(T(energy_after - energy_before));
    const T scale = max(abs(energy_before), abs(energy_after));
    if (change > max_relative_energy_change * scale) {
      st.reason = step_failure::left_regime;
      st.observed = static_cast<double>(T(change / scale));
      st.bound = static_cast<double>(max_relative_energy_change);
    }
  }
};

}  // namespace geomint
