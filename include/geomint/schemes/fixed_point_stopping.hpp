#pragma once
/// When the fixed-point iteration of a step's stage equations stops (schemes/gauss_fixed_point.hpp):
/// the budget of sweeps per scalar and the rule that ends the iteration at the fixed point in T,
/// at the round-off floor, or on the contraction rate, and reports a failure otherwise.

#include <limits>

#include "geomint/solvers/newton.hpp"
#include "geomint/solvers/step_status.hpp"

namespace geomint::schemes::detail {

/// The sweeps allowed: opt.max_iterations per 16 decimal digits of T (rounded up). The
/// iteration converges linearly, gaining about the same number of digits per sweep, so a
/// scalar with more digits needs proportionally more sweeps, where Newton's quadratic
/// convergence needs only a few more iterations (Kepler, m = 2, tau = 1/4 near pericentre:
/// more than 50 sweeps in 50 digits, fewer in double).
template <class T>
int sweep_budget(const newton_options<T>& opt) {
  constexpr int per_double = (std::numeric_limits<T>::digits10 + 15) / 16;
  return opt.max_iterations * (per_double > 1 ? per_double : 1);
}

/// When the iteration stops, from the change of each iteration: when the increments stop
/// changing exactly (a fixed point in T), or, once below eps^(2/3) relative, when the change has
/// grown twice in a row (the round-off floor), or (opt.stop_on_rate) when the contraction rate
/// bounds the change left below eps. Two growths in a row above that level, or the iteration
/// budget (sweep_budget) spent above `tolerance_ulps` eps, is a failure (st.reason).
template <class T>
struct sweep_stopping_rule {
  const newton_options<T>& opt;
  T eps_q;  ///< eps |q|, the scale's floor
  int budget = sweep_budget(opt);
  T previous = std::numeric_limits<T>::infinity();
  int growth = 0;

  /// True when iteration `it`, with this change and increment size, ends the iteration.
  bool stops(const T& change, const T& size, int it, step_status& st) {
    const T eps = std::numeric_limits<T>::epsilon();
    if (change == T(0)) return true;
    const T scale = size + eps_q;
    // As newton_options::stop_on_rate (multiprecision by default): the contraction rate says
    // the change left after this sweep, rho / (1 - rho) times this one, is below eps, so the
    // sweep that would only confirm it is saved.
    if (opt.stop_on_rate && it > 1 && change < previous && rate_bounds_error(T(change / previous), change, scale))
      return true;
    if (change >= previous) {
      // Growing twice in a row: at the round-off floor the fixed point is reached; above it
      // the map is no contraction (tau beyond the iteration's reach).
      if (++growth >= 2) {
        if (change > epsilon_two_thirds<T>() * scale) st.reason = step_failure::no_convergence;
        return true;
      }
    } else {
      growth = 0;
    }
    previous = change;
    if (it < budget) return false;
    if (change > T(opt.tolerance_ulps) * eps * scale) st.reason = step_failure::no_convergence;
    return true;
  }
};

}  // namespace geomint::schemes::detail
