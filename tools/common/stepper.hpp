#pragma once
/// Type-erased one-step maps (q_k, p_k) -> (q_{k+1}, p_{k+1}) of the built-in free systems
/// (harmonic, pendulum, kepler, charged) for every scheme, node family, basis and m = 2..8.
/// One factory per (system, scalar) is compiled once (stepper_tu.cpp) and shared by
/// geomint-run, geomint-order and geomint-symplectic, so the engines are instantiated once.
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "geomint/core/multiprecision.hpp"
#include "geomint/solvers/newton.hpp"
#include "geomint/solvers/step_monitor.hpp"

namespace geomint::tools {

/// A position or momentum of a built-in system (n <= 2; fixed storage, no allocation).
template <class T>
using state_vector = Eigen::Matrix<T, Eigen::Dynamic, 1, Eigen::ColMajor, 2, 1>;

/// The scalar type of `--digits D` in the tools: double, cpp_bin_float_50, cpp_bin_float_100.
template <int Digits>
struct digits_scalar {
  static_assert(Digits == 16 || Digits == 50 || Digits == 100, "geomint tools: digits must be 16, 50 or 100");
  using type = std::conditional_t<Digits == 16, double,
                                  std::conditional_t<Digits == 50, boost::multiprecision::cpp_bin_float_50,
                                                     boost::multiprecision::cpp_bin_float_100>>;
};
template <int Digits>
using scalar_for_digits = typename digits_scalar<Digits>::type;

/// The free systems and the schemes the factory knows.
inline const std::vector<std::string>& free_systems() {
  static const std::vector<std::string> names = {"harmonic", "pendulum", "kepler", "charged"};
  return names;
}
inline const std::vector<std::string>& schemes() {
  static const std::vector<std::string> names = {"lpf", "midpoint", "trapezoidal", "galerkin"};
  return names;
}
/// LPF node families by their command-line names.
inline const std::vector<std::string>& node_families() {
  static const std::vector<std::string> names = {"equispaced", "lobatto", "chebyshev", "gauss-interior"};
  return names;
}

/// A scheme choice: `nodes` and `basis` apply to lpf only, `m` to lpf and galerkin.
struct scheme_spec {
  std::string scheme = "lpf";
  std::string nodes = "equispaced";
  std::string basis = "lagrange";
  int m = 2;
  /// Whether the scheme has an m (midpoint and trapezoidal have none).
  bool has_m() const { return scheme == "lpf" || scheme == "galerkin"; }
  /// The node family column of the tables ("-" where it does not apply).
  std::string nodes_label() const { return scheme == "lpf" ? nodes : "-"; }
};

template <class T>
class stepper {
 public:
  virtual ~stepper() = default;
  virtual int dof() const = 0;
  /// The scheme's name, e.g. "lpf(m=4, gauss_interior, lagrange)".
  virtual std::string name() const = 0;
  /// The step monitor applied by step() (off unless set; see geomint/solvers/step_monitor.hpp).
  void set_monitor(const step_monitor<T>& m) {
    m.validate();
    monitor_ = m;
  }
  const step_monitor<T>& monitor() const { return monitor_; }
  /// One step; checks tau > 0 and finite data, then the monitor; leaves q1/p1 untouched on failure.
  virtual step_status step(const state_vector<T>& q, const state_vector<T>& p, const T& tau, state_vector<T>& q1,
                           state_vector<T>& p1, const newton_options<T>& opt = {}) const = 0;
  /// The energy at (q, p) (NaN where the Legendre transform cannot be inverted).
  virtual T energy(const state_vector<T>& q, const state_vector<T>& p) const = 0;
  /// p = dL/dqdot(q, qdot).
  virtual state_vector<T> momentum(const state_vector<T>& q, const state_vector<T>& qdot) const = 0;

 protected:
  step_monitor<T> monitor_;
};

/// Defined for T = double, cpp_bin_float_50, cpp_bin_float_100 (one TU each per system); throws
/// std::invalid_argument for an unknown scheme, node family, basis or m outside 2..8.
template <class Sys, class T>
std::unique_ptr<stepper<T>> make_system_stepper(const scheme_spec& spec);

}  // namespace geomint::tools

#include "geomint/mechanics/systems.hpp"

namespace geomint::tools {

/// The factory by system name (std::invalid_argument for an unknown one).
template <class T>
std::unique_ptr<stepper<T>> make_stepper(std::string_view system, const scheme_spec& spec) {
  if (system == systems::harmonic::name) return make_system_stepper<systems::harmonic, T>(spec);
  if (system == systems::pendulum::name) return make_system_stepper<systems::pendulum, T>(spec);
  if (system == systems::kepler::name) return make_system_stepper<systems::kepler, T>(spec);
  if (system == systems::charged::name) return make_system_stepper<systems::charged, T>(spec);
  throw std::invalid_argument("unknown system '" + std::string(system) + "'");
}

/// Default initial data (q_0, qdot_0): harmonic (1, 1) as in the paper; pendulum theta = 1 at
/// rest; Kepler e = 0.5 at pericentre; charged particle at (1, 0) with velocity (0, 1).
template <class T>
std::pair<state_vector<T>, state_vector<T>> default_initial_data(std::string_view system) {
  using std::sqrt;
  state_vector<T> q, qdot;
  if (system == systems::harmonic::name || system == systems::pendulum::name) {
    q.resize(1);
    qdot.resize(1);
    q[0] = T(1);
    qdot[0] = system == systems::harmonic::name ? T(1) : T(0);
  } else if (system == systems::kepler::name) {
    q.resize(2);
    qdot.resize(2);
    q << T(1) / T(2), T(0);
    qdot << T(0), sqrt(T(3));
  } else {
    q.resize(2);
    qdot.resize(2);
    q << T(1), T(0);
    qdot << T(0), T(1);
  }
  return {q, qdot};
}

}  // namespace geomint::tools
