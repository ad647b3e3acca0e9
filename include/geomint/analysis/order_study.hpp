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

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "geomint/linalg/types.hpp"

namespace geomint::analysis {

using geomint::dynamic_vector;

/// One step (q, p) -> (q1, p1) of size tau; returns false (or throws) on failure.
template <class T>
using step_function = std::function<bool(const dynamic_vector<T>& q, const dynamic_vector<T>& p, const T& tau,
                                         dynamic_vector<T>& q1, dynamic_vector<T>& p1)>;
/// The exact state (q, p) at time t from the common initial state.
template <class T>
using reference_function = std::function<void(const T& t, dynamic_vector<T>& q, dynamic_vector<T>& p)>;

template <class T>
struct order_result {
  std::vector<T> taus, local_errors, global_errors;
  T local_order = std::numeric_limits<T>::quiet_NaN();   ///< observed exponent of the local error (p + 1)
  T global_order = std::numeric_limits<T>::quiet_NaN();  ///< observed order p
  T error_constant = std::numeric_limits<T>::quiet_NaN();
  bool ok = false;
  std::string failure;  ///< why the study stopped, if !ok
};

/// The observed slope log(e0 / e1) / log(t0 / t1).
template <class T>
T observed_slope(const T& e0, const T& e1, const T& t0, const T& t1) {
  using std::log;
  return log(e0 / e1) / log(t0 / t1);
}

/// Local and global errors of `step` at tau = t_end / N for N in `step_counts` (increasing).
template <class T>
order_result<T> order_study(const step_function<T>& step, const reference_function<T>& reference,
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
  for (long N : step_counts) {
    const T tau = t_end / T(N);
    // Local error: one step against the reference flow at tau.
    if (!step(q0, p0, tau, q1, p1)) {
      r.failure = "step failed at tau = T/" + std::to_string(N);
      return r;
    }
    reference(tau, qe, pe);
    r.local_errors.push_back(distance(q1, qe, p1, pe));
    // Global error at t_end.
    dynamic_vector<T> q = q0, p = p0;
    for (long k = 0; k < N; ++k) {
      if (!step(q, p, tau, q1, p1)) {
        r.failure = "step " + std::to_string(k) + " failed at tau = T/" + std::to_string(N);
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
  r.ok = true;
  return r;
}

}  // namespace geomint::analysis
