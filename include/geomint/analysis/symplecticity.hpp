#pragma once
/// Symplecticity and long-time energy behaviour of a stepper's one-step map z = (q, p) -> Phi_tau(z)
/// (any_stepper, solvers/any_stepper.hpp).
///
/// - `one_step_jacobian`: J = dPhi/dz by central differences with one Richardson extrapolation,
///   error O(delta^4) + O(eps/delta); delta = eps^(1/5) balances both, so in 50-digit arithmetic
///   J is accurate to about 1e-40 (the map itself must be solved to working precision).
/// - `symplectic_defect`: max |(J^T Omega J - Omega)_ij| with Omega = [[0, I], [-I, 0]];
///   zero for a symplectic map, up to the accuracy of J.
/// - `energy_behaviour`: max |H - H0| over a run and the least-squares slope of H - H0 in t.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include "geomint/solvers/any_stepper.hpp"

namespace geomint::analysis {

template <class T>
using phase_vector = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template <class T>
using phase_matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
namespace detail {
/// One step of the stepper from z = (q, p) into z1.
template <class T>
step_status phase_step(any_stepper<T>& stepper, const T& tau, const phase_vector<T>& z, phase_vector<T>& z1) {
  const int n = stepper.dof();
  if (z.size() != 2 * n)
    throw std::invalid_argument("geomint::analysis: a phase vector of size " + std::to_string(z.size()) + " for " +
                                std::to_string(n) + " degrees of freedom");
  dynamic_vector<T> q1, p1;
  const step_status st = stepper.try_step(dynamic_vector<T>(z.head(n)), dynamic_vector<T>(z.tail(n)), tau, q1, p1);
  if (st) {
    z1.resize(2 * n);
    z1 << q1, p1;
  }
  return st;
}
}  // namespace detail

/// The canonical structure matrix Omega = [[0, I], [-I, 0]] of dimension 2n.
template <class T>
phase_matrix<T> canonical_omega(int n) {
  phase_matrix<T> omega = phase_matrix<T>::Zero(2 * n, 2 * n);
  for (int i = 0; i < n; ++i) {
    omega(i, n + i) = T(1);
    omega(n + i, i) = T(-1);
  }
  return omega;
}

/// The default difference step eps^(1/5) (relative to 1 + |z_j|).
template <class T>
T default_difference_step() {
  using std::pow;
  return pow(std::numeric_limits<T>::epsilon(), T(1) / T(5));
}

/// J = dPhi_tau/dz at z. Throws std::runtime_error with the step's reason if the map fails near z.
template <class T>
phase_matrix<T> one_step_jacobian(any_stepper<T>& stepper, const T& tau, const phase_vector<T>& z,
                                  const T& delta = default_difference_step<T>()) {
  if (!(delta > T(0))) throw std::invalid_argument("geomint::one_step_jacobian: delta must be > 0");
  const Eigen::Index d = z.size();
  phase_matrix<T> J(d, d);
  phase_vector<T> plus, minus;
  auto central = [&](Eigen::Index j, const T& h) {
    phase_vector<T> zp = z, zm = z;
    zp[j] += h;
    zm[j] -= h;
    for (const auto& [from, to] : {std::pair{&zp, &plus}, std::pair{&zm, &minus}})
      if (const step_status st = detail::phase_step(stepper, tau, *from, *to); !st)
        throw std::runtime_error("geomint::one_step_jacobian: the map failed at a perturbed state: " + st.message());
    return phase_vector<T>((plus - minus) / (T(2) * h));
  };
  for (Eigen::Index j = 0; j < d; ++j) {
    using std::abs;
    const T h = delta * (T(1) + abs(z[j]));
    // Richardson: (4 D(h/2) - D(h)) / 3 cancels the h^2 term of the central difference.
    J.col(j) = (T(4) * central(j, h / T(2)) - central(j, h)) / T(3);
  }
  return J;
}

/// max_ij |(J^T Omega J - Omega)_ij|.
template <class T>
T symplectic_defect(const phase_matrix<T>& J) {
  if (J.rows() != J.cols() || J.rows() % 2 != 0) throw std::invalid_argument("geomint::symplectic_defect: J must be 2n x 2n");
  const phase_matrix<T> omega = canonical_omega<T>(static_cast<int>(J.rows() / 2));
  return (J.transpose() * omega * J - omega).cwiseAbs().maxCoeff();
}

template <class T>
struct energy_result {
  T max_error = T(0);  ///< max_k |H_k - H_0|
  T drift = T(0);      ///< least-squares slope of H_k - H_0 against t_k
  long steps = 0;      ///< steps completed
  bool ok = true;
  phase_vector<T> last;  ///< the state after the last completed step
  std::string failure;   ///< the failed step's reason, if !ok
};

/// Runs `steps` steps of size tau from z0 and summarises H_k - H_0, H the stepper's energy.
template <class T>
energy_result<T> energy_behaviour(any_stepper<T>& stepper, const phase_vector<T>& z0, const T& tau, long steps) {
  if (!(tau > T(0))) throw std::invalid_argument("geomint::energy_behaviour: tau must be > 0");
  const int n = stepper.dof();
  auto energy = [&](const phase_vector<T>& z) {
    return stepper.energy(dynamic_vector<T>(z.head(n)), dynamic_vector<T>(z.tail(n)));
  };
  energy_result<T> r;
  const T h0 = energy(z0);
  phase_vector<T> z = z0, z1;
  // Running sums for the slope of y = H - H0 against t (t_0 = 0 included).
  T st(0), sy(0), stt(0), sty(0);
  long count = 1;
  for (long done = 0; done < steps; ++done) {  // k = done + 1 <= steps: no overflow, also for steps = LONG_MAX
    const long k = done + 1;
    if (const step_status status = detail::phase_step(stepper, tau, z, z1); !status) {
      r.ok = false;
      r.failure = status.message();
      break;
    }
    z = z1;
    using std::abs;
    const T t = tau * T(k);
    const T y = energy(z) - h0;
    if (abs(y) > r.max_error) r.max_error = abs(y);
    st += t;
    sy += y;
    stt += t * t;
    sty += t * y;
    ++count;
    r.steps = k;
  }
  const T c = T(count);
  const T denominator = c * stt - st * st;
  r.drift = denominator > T(0) ? (c * sty - st * sy) / denominator : T(0);
  r.last = z;
  return r;
}

}  // namespace geomint::analysis
