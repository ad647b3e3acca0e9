#pragma once
/// Observed orders of a one-step map against a reference flow (docs/design.md, "Verification").
///
/// For a ladder of steps tau_i = T / N_i (N_i doubling):
/// - local error  e_loc(tau) = |Phi_tau(z_0) - phi_tau(z_0)|   ~ C_loc tau^(p+1),
/// - global error e_glob(tau) = |Phi_tau^N(z_0) - phi_T(z_0)| ~ C tau^p,
/// in the max norm over (q, p). The observed orders are the slopes between the two finest steps,
/// log(e_i / e_{i+1}) / log(tau_i / tau_{i+1}); the error constant is C = e_glob / tau^p with
/// p the rounded global order at the finer step of that pair. Errors within a round-off margin
/// (10^6 eps per step taken) do not measure the scheme: the slopes then use the finest pair of
/// steps above it, and the study fails if there is none (more digits are needed).
///
/// Observed slopes are a measurement only in the asymptotic regime; asymptotic_regime() below
/// says whether a result is in it (the study tools flag every other row and exit non-zero).

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "geomint/linalg/types.hpp"
#include "geomint/solvers/any_stepper.hpp"

namespace geomint::analysis {

using geomint::dynamic_vector;

/// The exact state (q, p) at time t from the common initial state.
template <class T>
using reference_function = std::function<void(const T& t, dynamic_vector<T>& q, dynamic_vector<T>& p)>;

template <class T>
struct order_result {
  std::vector<T> taus, local_errors, global_errors;
  T local_order = std::numeric_limits<T>::quiet_NaN();   ///< observed exponent of the local error (p + 1)
  T global_order = std::numeric_limits<T>::quiet_NaN();  ///< observed order p
  T error_constant = std::numeric_limits<T>::quiet_NaN();
  /// The successive global orders between neighbouring steps above the round-off margin, and
  /// the index in taus of the coarser step of the first of them.
  std::vector<T> global_orders;
  std::size_t first_order_index = 0;
  /// The size of the solution at t_end, max(|q|, |p|) of the reference (max norm).
  T solution_size = std::numeric_limits<T>::quiet_NaN();
  bool ok = false;
  std::string failure;  ///< why the study stopped, if !ok
};

/// The observed slope log(e0 / e1) / log(t0 / t1).
template <class T>
T observed_slope(const T& e0, const T& e1, const T& t0, const T& t1) {
  using std::log;
  return log(e0 / e1) / log(t0 / t1);
}

/// Local and global errors of the stepper's map at tau = t_end / N for N in `step_counts`
/// (increasing). A failed step ends the study with its step_status message in `failure`.
template <class T>
order_result<T> order_study(any_stepper<T>& stepper, const reference_function<T>& reference,
                            const dynamic_vector<T>& q0, const dynamic_vector<T>& p0, const T& t_end,
                            const std::vector<long>& step_counts) {
  if (step_counts.size() < 2) throw std::invalid_argument("geomint::order_study: needs at least two step counts");
  if (!(t_end > T(0))) throw std::invalid_argument("geomint::order_study: the end time must be > 0");
  for (std::size_t i = 0; i < step_counts.size(); ++i)
    if (step_counts[i] < 1 || (i > 0 && step_counts[i] <= step_counts[i - 1]))
      throw std::invalid_argument("geomint::order_study: step counts must be positive and increasing");
  order_result<T> r;
  auto distance = [](const dynamic_vector<T>& a, const dynamic_vector<T>& b, const dynamic_vector<T>& c,
                     const dynamic_vector<T>& d) {
    using std::max;
    return max(T((a - b).template lpNorm<Eigen::Infinity>()), T((c - d).template lpNorm<Eigen::Infinity>()));
  };
  dynamic_vector<T> qe, pe, q1, p1;
  reference(t_end, qe, pe);
  const dynamic_vector<T> q_end = qe, p_end = pe;
  {
    using std::max;
    r.solution_size = max(T(q_end.template lpNorm<Eigen::Infinity>()), T(p_end.template lpNorm<Eigen::Infinity>()));
  }
  for (long N : step_counts) {
    const T tau = t_end / T(N);
    // Local error: one step against the reference flow at tau.
    if (const step_status st = stepper.try_step(q0, p0, tau, q1, p1); !st) {
      r.failure = "step failed at tau = T/" + std::to_string(N) + " (" + st.message() + ")";
      return r;
    }
    reference(tau, qe, pe);
    r.local_errors.push_back(distance(q1, qe, p1, pe));
    // Global error at t_end.
    dynamic_vector<T> q = q0, p = p0;
    for (long k = 0; k < N; ++k) {
      if (const step_status st = stepper.try_step(q, p, tau, q1, p1); !st) {
        r.failure = "step " + std::to_string(k) + " failed at tau = T/" + std::to_string(N) + " (" + st.message() + ")";
        return r;
      }
      q = q1;
      p = p1;
    }
    r.global_errors.push_back(distance(q, q_end, p, p_end));
    r.taus.push_back(tau);
  }
  // The finest pair above the round-off margin, for each series.
  const T margin = T(1000000) * std::numeric_limits<T>::epsilon();
  auto finest = [&](const std::vector<T>& errors, bool global) -> std::ptrdiff_t {
    for (std::size_t i = errors.size() - 1; i >= 1; --i)
      if (errors[i] > margin * T(global ? step_counts[i] : 1)) return static_cast<std::ptrdiff_t>(i);
    return -1;
  };
  const std::ptrdiff_t local = finest(r.local_errors, false), global = finest(r.global_errors, true);
  if (local < 1 || global < 1) {
    r.failure = "errors at round-off level on the whole ladder: use more digits or larger steps";
    return r;
  }
  const auto l = static_cast<std::size_t>(local), g = static_cast<std::size_t>(global);
  r.local_order = observed_slope(r.local_errors[l - 1], r.local_errors[l], r.taus[l - 1], r.taus[l]);
  r.global_order = observed_slope(r.global_errors[g - 1], r.global_errors[g], r.taus[g - 1], r.taus[g]);
  using std::pow;
  using std::round;
  r.error_constant = r.global_errors[g] / pow(r.taus[g], round(r.global_order));
  // The successive orders of the contiguous run of steps above the margin that ends at g.
  std::size_t first = g;
  while (first > 0 && r.global_errors[first - 1] > margin * T(step_counts[first - 1])) --first;
  r.first_order_index = first;
  for (std::size_t i = first; i < g; ++i)
    r.global_orders.push_back(observed_slope(r.global_errors[i], r.global_errors[i + 1], r.taus[i], r.taus[i + 1]));
  r.ok = true;
  return r;
}

/// The thresholds of asymptotic_regime, in the scalar T.
template <class T>
struct asymptotic_criteria {
  /// Global errors used for an order must be below this share of the solution's size: an
  /// error comparable to the solution is no small perturbation of it (a phase error of order
  /// one on an oscillation), so its slope is not the scheme's order; "well below" is an order
  /// of magnitude (the consistency of successive orders below checks the rest).
  T max_relative_error = T(1) / T(10);
  /// At least this many steps above the round-off margin (two successive orders to compare).
  std::size_t min_ladder = 3;
  /// Successive global orders must agree within this, and the global order lie within it of
  /// an integer >= 1: in the asymptotic regime e(tau) = C tau^p (1 + O(tau)), so successive
  /// slopes converge to the integer p; a quarter of an order separates p from p +- 1 clearly.
  T order_tolerance = T(1) / T(4);
  /// The local order must be at least the global order plus this (local error
  /// O(tau^(p+1)) for a global error O(tau^p); more where its leading term vanishes at z0), and
  /// at least 2 - 1/4 (a consistent one-step map has local error O(tau^2) or smaller).
  T local_excess = T(1) / T(2);
};

/// "ok" when the result is in the asymptotic regime by every criterion above; otherwise
/// "outside: <reason>" (the first failed criterion). A result with r.ok false is "failed".
template <class T>
std::string asymptotic_regime(const order_result<T>& r, const asymptotic_criteria<T>& c = {}) {
  using std::abs;
  using std::round;
  if (!r.ok) return "failed";
  if (!is_finite(r.global_order) || !is_finite(r.local_order)) return "outside: non-finite observed order";
  if (r.taus.size() < c.min_ladder)
    return "outside: a ladder of " + std::to_string(r.taus.size()) + " step counts (at least " +
           std::to_string(c.min_ladder) + " are needed)";
  if (r.global_orders.size() + 1 < c.min_ladder)
    return "outside: fewer than " + std::to_string(c.min_ladder) +
           " steps with errors above round-off (add a coarser step or use more digits)";
  // The three finest steps above round-off: those of the last two successive orders.
  const std::size_t finest = r.first_order_index + r.global_orders.size();
  for (std::size_t i = finest + 1 - c.min_ladder; i <= finest; ++i)
    if (!(r.global_errors[i] <= c.max_relative_error * r.solution_size))
      return "outside: global error not well below the solution's size (" +
             std::to_string(static_cast<double>(r.global_errors[i] / r.solution_size)) + " of it at tau = " +
             std::to_string(static_cast<double>(r.taus[i])) + ")";
  const std::size_t k = r.global_orders.size();
  if (abs(T(r.global_orders[k - 1] - r.global_orders[k - 2])) > c.order_tolerance)
    return "outside: successive global orders disagree";
  if (r.global_order < T(1) - c.order_tolerance) return "outside: global order below 1";
  if (abs(T(r.global_order - round(r.global_order))) > c.order_tolerance) return "outside: non-integer global order";
  if (r.local_order < T(2) - c.order_tolerance) return "outside: local order below 2";
  if (r.local_order < r.global_order + c.local_excess) return "outside: local order below global order + 1";
  return "ok";
}

}  // namespace geomint::analysis
