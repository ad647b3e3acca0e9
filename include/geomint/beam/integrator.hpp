#pragma once
/// The Poisson integrator of the geometrically exact beam (beam paper, Algorithm 1) and the
/// "Hamel" variant, on the staggered grid with free ends.
///
/// One step n -> n+1:
///   1. scheme (53) (or its Hamel variant) at every node: a 6x6 Newton solve for mu_j^{n+1};
///   2. scheme (54) on every segment: a 6x6 linear solve for gamma_{j+1/2}^{n+1};
///   3. Cayley reconstruction (55): g_j^{n+1} = g_j^n cay(dt zeta_j), zeta = D1^{-1} mu,
///      with zeta_j = zeta_j^n as printed in the paper (`cayley_velocity::previous`), or
///      zeta_j^{n+1} / the average of the two (options; see docs/results/beam.md for what each does to
///      the momentum).
/// The three are done in one sweep over the nodes (node j, then segment j - 1/2, then the
/// reconstruction of node j); in double, two neighbouring nodes at a time in SIMD lanes
/// (paired_kernels.hpp), with results identical to the bit to the one-node path.
/// The step is computed into separate buffers and committed only when every value is finite,
/// every Newton solve has converged and the energy has not blown up; otherwise `try_step`
/// returns the failure (reason, step index, node) and `step` throws it as an integration_error
/// (solvers/step_status.hpp, shared with the other integrators); the state stays at the last
/// good step.

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "geomint/beam/grid.hpp"
#include "geomint/beam/kernels.hpp"
#include "geomint/beam/material.hpp"
#include "geomint/beam/paired_kernels.hpp"
#include "geomint/lie/se3.hpp"
#include "geomint/solvers/step_status.hpp"

namespace geomint::beam {

/// Which time discretisation of the bracket term [zeta, mu]^* in the momentum equation.
enum class scheme {
  poisson,  ///< eq. (53): implicit midpoint, [(zeta^{n+1}+zeta^n)/2, (mu^{n+1}+mu^n)/2]^*
  hamel     ///< trapezoidal rule, 1/2([zeta^{n+1}, mu^{n+1}]^* + [zeta^n, mu^n]^*)
};

/// The velocity used by the per-node Cayley reconstruction (55).
enum class cayley_velocity {
  previous,  ///< zeta^n: eq. (55) as printed, g^{n+1} = g^n cay(dt D1^{-1} mu^n)
  current,   ///< zeta^{n+1}: the velocity scheme (54) uses for the same step
  midpoint   ///< (zeta^n + zeta^{n+1})/2
};

/// Which configurations the diagnostics (momentum, centreline) use.
enum class reconstruction {
  per_node,          ///< g_j integrated in time at every node by (55)
  strain_consistent  ///< g_0 by (55), then g_{j+1} = g_j cay(ds (gamma_{j+1/2} + e2))
};

inline const char* to_string(scheme s) { return s == scheme::poisson ? "poisson" : "hamel"; }

template <class T>
struct options {
  T dt = T(0);                                        ///< time step (must be set, > 0)
  scheme method = scheme::poisson;
  cayley_velocity velocity = cayley_velocity::previous;
  reconstruction configurations = reconstruction::per_node;
  int max_newton_iterations = 12;
  /// Use the structured node solve (3x3 Newton + closed-form translational block) when the
  /// translational inertia is isotropic; false forces the general 6x6 Newton (LU).
  bool structured_solve = true;
  /// A step whose total energy exceeds this factor times the initial energy is rejected as
  /// unstable (the scheme keeps the energy within O(dt) of its initial value when stable).
  /// Must be finite and > 1 (checked by the integrator's constructor).
  T energy_growth_limit = T(100);
};

/// Energies and spatial momentum of a beam state.
template <class T>
struct diagnostics {
  long step = 0;
  T t = T(0);
  T kinetic = T(0);    ///< ds sum_j 1/2 <mu_j, D1^{-1} mu_j>, j = 0..J (full weight at the ends)
  T potential = T(0);  ///< ds sum_j 1/2 <D2 gamma_{j+1/2}, gamma_{j+1/2}> over the segments
  T total = T(0);
  vec3<T> P = vec3<T>::Zero();  ///< spatial linear momentum  ds sum_j R_j p_j
  vec3<T> L = vec3<T>::Zero();  ///< spatial angular momentum ds sum_j (R_j pi_j + x_j x R_j p_j)
};

/// How far the per-node reconstruction is from the strain-consistent one.
template <class T>
struct reconstruction_drift {
  T max_position = T(0);  ///< max_j |x_j - x~_j|
  T max_rotation = T(0);  ///< max_j angle(R_j^T R~_j)
};

/// Newton statistics since construction.
struct newton_statistics {
  long solves = 0;
  long iterations = 0;
  int max_iterations = 0;
};

template <class T>
class integrator {
 public:
  using state_vector = std::vector<vec6<T>>;
  using configuration_vector = std::vector<lie::SE3<T>>;

  /// mu0: J+1 node momenta; gamma0: J segment strains; g0: J+1 node configurations (default:
  /// the strain-consistent chain from g_0 = identity, g_{j+1} = g_j cay(ds (gamma0 + e2))).
  integrator(const material<T>& mat, const staggered_grid<T>& grid, state_vector mu0, state_vector gamma0,
             const options<T>& opt, std::optional<configuration_vector> g0 = std::nullopt)
      : mat_(mat), grid_(grid), opt_(opt), mu_(std::move(mu0)), gamma_(std::move(gamma0)) {
    mat_.validate();
    if (!(opt_.dt > T(0)) || !(opt_.dt - opt_.dt == T(0)))
      throw std::invalid_argument("geomint::beam::integrator: the time step dt must be finite and > 0");
    if (opt_.max_newton_iterations < 1)
      throw std::invalid_argument("geomint::beam::integrator: max_newton_iterations must be >= 1");
    // NaN would make the guard `e > limit * E0` always false, i.e. silently off.
    if (!(opt_.energy_growth_limit > T(1)) || !(opt_.energy_growth_limit - opt_.energy_growth_limit == T(0)))
      throw std::invalid_argument("geomint::beam::integrator: energy_growth_limit must be finite and > 1");
    if (!(grid_.length > T(0)) || !(grid_.length - grid_.length == T(0)))
      throw std::invalid_argument("geomint::beam::integrator: the grid length must be finite and positive");
    const int J = grid_.segments;
    if (static_cast<int>(mu_.size()) != J + 1)
      throw std::invalid_argument("geomint::beam::integrator: mu0 must have J + 1 = " + std::to_string(J + 1) + " entries");
    if (static_cast<int>(gamma_.size()) != J)
      throw std::invalid_argument("geomint::beam::integrator: gamma0 must have J = " + std::to_string(J) + " entries");
    for (const auto& m : mu_)
      if (!m.allFinite()) throw std::invalid_argument("geomint::beam::integrator: mu0 is not finite");
    for (const auto& g : gamma_)
      if (!g.allFinite()) throw std::invalid_argument("geomint::beam::integrator: gamma0 is not finite");
    d1inv_ = mat_.D1.cwiseInverse();
    structured_ = opt_.structured_solve && mat_.D1(3) == mat_.D1(4) && mat_.D1(4) == mat_.D1(5);
    ds_ = grid_.ds();
    if (g0) {
      if (static_cast<int>(g0->size()) != J + 1)
        throw std::invalid_argument("geomint::beam::integrator: g0 must have J + 1 entries");
      g_ = std::move(*g0);
    } else {
      g_.assign(J + 1, lie::SE3<T>::identity());
      g_ = chain_from(g_[0]);
    }
    dt_over_ds_ = opt_.dt / ds_;
    stress_left_.resize(J);
    stress_right_.resize(J);
    for (int j = 0; j < J; ++j) {
      vec6<T> sigma;
      segment_stress(gamma_[j], sigma, stress_left_[j], stress_right_[j]);
    }
    mu_next_ = mu_;
    gamma_next_ = gamma_;
    stress_left_next_ = stress_left_;
    stress_right_next_ = stress_right_;
    g_next_ = g_;
    energy0_ = energy();
  }

  const material<T>& mat() const { return mat_; }
  const staggered_grid<T>& grid() const { return grid_; }
  const options<T>& opts() const { return opt_; }
  long steps_taken() const { return step_; }
  T time() const { return T(step_) * opt_.dt; }
  const state_vector& mu() const { return mu_; }
  const state_vector& gamma() const { return gamma_; }
  /// The per-node configurations integrated by (55).
  const configuration_vector& node_configurations() const { return g_; }
  /// g_0 from (55), then g_{j+1} = g_j cay(ds (gamma_{j+1/2} + e2)).
  configuration_vector strain_consistent_configurations() const { return chain_from(g_[0]); }
  /// The configurations the options select for diagnostics.
  configuration_vector configurations() const {
    return opt_.configurations == reconstruction::per_node ? g_ : strain_consistent_configurations();
  }
  const newton_statistics& newton() const { return stats_; }
  T initial_energy() const { return energy0_; }

  /// ds / max_i sqrt(D2_i / D1_i): the CFL bound of the explicit (symplectic Euler) part
  /// for the fastest linear wave; informational (used in error messages).
  T stability_estimate() const {
    using std::sqrt;
    T c2 = T(0);
    for (int i = 0; i < 6; ++i) c2 = std::max<T>(c2, mat_.D2(i) / mat_.D1(i));
    return ds_ / sqrt(c2);
  }

  /// Total energy ds (sum_j 1/2 <mu_j, zeta_j> + sum_segments 1/2 <sigma, gamma>).
  T energy() const {
    T k = T(0), p = T(0);
    for (std::size_t j = 0; j < mu_.size(); ++j) k += kinetic_term(mu_[j]);
    for (std::size_t j = 0; j < gamma_.size(); ++j) p += potential_term(gamma_[j]);
    return ds_ * (k + p) / T(2);
  }

  diagnostics<T> diagnose() const {
    diagnostics<T> d;
    d.step = step_;
    d.t = time();
    T k = T(0), p = T(0);
    for (std::size_t j = 0; j < mu_.size(); ++j) k += kinetic_term(mu_[j]);
    for (std::size_t j = 0; j < gamma_.size(); ++j) p += potential_term(gamma_[j]);
    d.kinetic = ds_ * k / T(2);
    d.potential = ds_ * p / T(2);
    d.total = d.kinetic + d.potential;
    const configuration_vector g = configurations();
    vec6<T> J = vec6<T>::Zero();
    for (std::size_t j = 0; j < mu_.size(); ++j) J += lie::coAd<T>(g[j], mu_[j]);
    J *= ds_;
    d.L = J.template head<3>();
    d.P = J.template tail<3>();
    return d;
  }

  reconstruction_drift<T> drift() const {
    const configuration_vector c = strain_consistent_configurations();
    reconstruction_drift<T> d;
    for (std::size_t j = 0; j < g_.size(); ++j) {
      d.max_position = std::max<T>(d.max_position, (g_[j].x - c[j].x).norm());
      d.max_rotation = std::max<T>(d.max_rotation, lie::so3_angle<T>(mat3<T>(g_[j].R.transpose() * c[j].R)));
    }
    return d;
  }

  /// Advances one step; throws integration_error (state unchanged) if it cannot be completed.
  void step() {
    const step_status st = try_step();
    if (!st) throw integration_error(st, failure_detail_);
  }

  /// Advances n steps; throws on the first failure.
  void advance(long n) {
    for (long i = 0; i < n; ++i) step();
  }

  /// One step without throwing: the failure (reason, step index k = steps taken, node) or
  /// success; on failure the state is unchanged and `failure_detail()` explains it.
  step_status try_step() {
    const bool poisson = opt_.method == scheme::poisson;
    switch (opt_.velocity) {
      case cayley_velocity::previous:
        return poisson ? (structured_ ? sweep<true, true, cayley_velocity::previous>() : sweep<true, false, cayley_velocity::previous>())
                       : (structured_ ? sweep<false, true, cayley_velocity::previous>() : sweep<false, false, cayley_velocity::previous>());
      case cayley_velocity::current:
        return poisson ? (structured_ ? sweep<true, true, cayley_velocity::current>() : sweep<true, false, cayley_velocity::current>())
                       : (structured_ ? sweep<false, true, cayley_velocity::current>() : sweep<false, false, cayley_velocity::current>());
      default:
        return poisson ? (structured_ ? sweep<true, true, cayley_velocity::midpoint>() : sweep<true, false, cayley_velocity::midpoint>())
                       : (structured_ ? sweep<false, true, cayley_velocity::midpoint>() : sweep<false, false, cayley_velocity::midpoint>());
    }
  }

  /// Why the last failed step failed (empty after a successful step).
  const std::string& failure_detail() const { return failure_detail_; }

 private:
  // sigma = D2 gamma, force = [gamma + e2, sigma]^*, and the two ways the segment enters the
  // stress term F of (53) at its end nodes: at its left node j (segment j + 1/2)
  // sigma/ds - force/2, at its right node j + 1 (segment (j + 1) - 1/2) sigma/ds + force/2.
  void segment_stress(const vec6<T>& gamma, vec6<T>& sigma, vec6<T>& left, vec6<T>& right) const {
    sigma = mat_.D2.cwiseProduct(gamma);
    const vec6<T> Gamma = gamma + axis<T>();
    const vec6<T> force = lie::dual_bracket<T>(Gamma, sigma);
    const vec6<T> sigma_ds = sigma / ds_;
    left = sigma_ds - force / T(2);
    right = sigma_ds + force / T(2);
  }

  // <mu, D1^{-1} mu> and <D2 gamma, gamma>: the summands of the energy.
  T kinetic_term(const vec6<T>& mu) const {
    const vec6<T> zeta = d1inv_.cwiseProduct(mu);
    return mu.dot(zeta);
  }
  T potential_term(const vec6<T>& gamma) const {
    const vec6<T> sigma = mat_.D2.cwiseProduct(gamma);
    return sigma.dot(gamma);
  }

  // One step as a single sweep over the nodes, specialised on the options: at node j the
  // node solve (53), then the segment j - 1/2 (54) (both its end velocities are then known),
  // then the reconstruction (55) of node j, and the energy sums. Same arithmetic, in the same
  // order, as solving all nodes, then all segments, then all reconstructions; writes only the
  // *_next_ buffers, swapped in when every check has passed.
  template <bool Poisson, bool Structured, cayley_velocity Velocity>
  step_status sweep() {
    const int J = grid_.segments;
    const T dt = opt_.dt, h = opt_.dt / T(2);
    const long n1 = step_ + 1;
    const int max_newton = opt_.max_newton_iterations;
    long iterations = 0;
    int max_iterations = stats_.max_iterations;
    auto flush_statistics = [&](int solves) {
      stats_.solves += solves;
      stats_.iterations += iterations;
      stats_.max_iterations = max_iterations;
    };
    T k = T(0), p = T(0);
    T finite_g = T(0);  // sum of (v - v) over every new configuration entry: 0, or NaN if one is not finite
    vec6<T> zeta_left;  // zeta_{j-1}^{n+1}
    step_status failure;
    // Node j, then segment j - 1/2, then the reconstruction of node j; false on failure.
    auto one_node = [&](int j) -> bool {
      vec6<T> F = vec6<T>::Zero();
      if (j < J) F += stress_left_[j];
      if (j > 0) F -= stress_right_[j - 1];
      const vec6<T>& m = mu_[j];
      vec6<T> c;
      if constexpr (Poisson) {
        c = m + h * F;
      } else {
        const vec6<T> zeta = d1inv_.cwiseProduct(m);
        c = m + dt * F + h * lie::dual_bracket<T>(zeta, m);
      }
      // Predictor: one fixed-point step of x = c + h Q(x) from x = c (error O(h^2)); the
      // structured path only needs the rotational part, pi = c_pi + h c_pi x (Dr c_pi).
      vec6<T> x = c;
      newton_result<T> r;
      if constexpr (Structured) {
        const vec3<T> cpi = c.template head<3>();
        x.template head<3>() += h * cpi.cross(vec3<T>(d1inv_.template head<3>().cwiseProduct(cpi)));
        r = solve_node_isotropic<T>(x, c, h, d1inv_, max_newton);
      } else {
        x += h * rigid_bracket<T>(c, d1inv_);
        r = solve_node<T>(x, c, h, d1inv_, max_newton);
      }
      iterations += r.iterations;
      max_iterations = std::max(max_iterations, r.iterations);
      if (!r.finite || !r.converged) {
        flush_statistics(j + 1);
        failure = !r.finite ? fail_non_finite(n1, j, "the Newton solve of scheme (53)") : fail_newton(n1, j, r);
        return false;
      }
      vec6<T>& mu_new = mu_next_[j];
      if constexpr (Poisson)
        mu_new = T(2) * x - m;
      else
        mu_new = x;
      const vec6<T> zeta_new = d1inv_.cwiseProduct(mu_new);
      k += mu_new.dot(zeta_new);
      // 2. Scheme (54) on the segment j - 1/2 between nodes j - 1 and j.
      if (j > 0) {
        vec6<T>& gamma_new = gamma_next_[j - 1];
        gamma_new = segment_update<T>(gamma_[j - 1], zeta_left, zeta_new, dt, h, dt_over_ds_);
        vec6<T> sigma;
        segment_stress(gamma_new, sigma, stress_left_next_[j - 1], stress_right_next_[j - 1]);
        p += sigma.dot(gamma_new);
      }
      zeta_left = zeta_new;
      // 3. Cayley reconstruction (55).
      vec6<T> z;
      if constexpr (Velocity == cayley_velocity::previous)
        z = d1inv_.cwiseProduct(m);
      else if constexpr (Velocity == cayley_velocity::current)
        z = zeta_new;
      else
        z = (vec6<T>(d1inv_.cwiseProduct(m)) + zeta_new) / T(2);
      lie::SE3<T>& g_new = g_next_[j];
      g_new = g_[j] * lie::cay<T>(vec6<T>(dt * z));
      finite_g += (g_new.R - g_new.R).sum() + (g_new.x - g_new.x).sum();
      return true;
    };
    int j = 0;
#if GEOMINT_BEAM_PAIRED_NODES
    if constexpr (std::is_same_v<T, double> && Structured) {
      // Nodes 1 .. J - 1 two at a time (detail::paired_nodes, identical arithmetic per lane).
      if (!one_node(0)) return failure;
      j = 1;
      detail::paired_buffers buffers{mu_, gamma_, stress_left_, stress_right_, g_,
                                     mu_next_, gamma_next_, stress_left_next_, stress_right_next_, g_next_};
      detail::paired_constants constants{dt, h, ds_, dt_over_ds_, {}, {}, max_newton};
      for (int i = 0; i < 6; ++i) {
        constants.d1inv[i] = d1inv_(i);
        constants.d2[i] = mat_.D2(i);
      }
      constexpr int velocity = Velocity == cayley_velocity::previous ? 0 : Velocity == cayley_velocity::current ? 1 : 2;
      for (; j + 1 <= J - 1; j += 2) {
        detail::paired_sums sums;
        if (detail::paired_nodes<Poisson, velocity>(j, buffers, constants, zeta_left, sums)) {
          k += sums.kinetic[0];
          k += sums.kinetic[1];
          p += sums.potential[0];
          p += sums.potential[1];
          finite_g += sums.finite_g;
          iterations += sums.iterations[0] + sums.iterations[1];
          max_iterations = std::max({max_iterations, sums.iterations[0], sums.iterations[1]});
        } else {
          // Redo the pair one node at a time: reports the failure as the one-node path does.
          if (!one_node(j) || !one_node(j + 1)) return failure;
        }
      }
    }
#endif
    for (; j <= J; ++j)
      if (!one_node(j)) return failure;
    flush_statistics(J + 1);
    // Checks, then commit.
    const T e = ds_ * (k + p) / T(2);
    if (!(e - e == T(0))) {
      for (int j = 0; j <= J; ++j)
        if (!mu_next_[j].allFinite()) return fail_non_finite(n1, j, "scheme (53)");
      for (int j = 0; j < J; ++j)
        if (!gamma_next_[j].allFinite()) return fail_non_finite(n1, j, "scheme (54) (segment j + 1/2)");
      return fail_non_finite(n1, -1, "the energy");
    }
    if (!(finite_g == T(0)))
      for (int j = 0; j <= J; ++j)
        if (!g_next_[j].R.allFinite() || !g_next_[j].x.allFinite())
          return fail_non_finite(n1, j, "the Cayley reconstruction (55)");
    if (e > opt_.energy_growth_limit * energy0_) {
      std::ostringstream os;
      os << "t = " << time_string(n1) << ": the total energy grew from " << energy0_ << " to " << e << " (more than "
         << opt_.energy_growth_limit << " times): the time step dt = " << opt_.dt
         << " is beyond the stability limit (estimate ds/c_max = " << stability_estimate() << ")";
      return fail(step_failure::energy_growth, -1, 0, os.str());
    }
    mu_.swap(mu_next_);
    gamma_.swap(gamma_next_);
    stress_left_.swap(stress_left_next_);
    stress_right_.swap(stress_right_next_);
    g_.swap(g_next_);
    step_ = n1;
    failure_detail_.clear();
    return {};
  }

  configuration_vector chain_from(const lie::SE3<T>& g0) const {
    configuration_vector c(gamma_.size() + 1);
    c[0] = g0;
    for (std::size_t j = 0; j < gamma_.size(); ++j) {
      const vec6<T> Gamma = gamma_[j] + axis<T>();
      c[j + 1] = c[j] * lie::cay<T>(vec6<T>(ds_ * Gamma));
    }
    return c;
  }

  std::string time_string(long n) const {
    std::ostringstream os;
    os << T(n) * opt_.dt;
    return os.str();
  }

  step_status fail(step_failure reason, int node, int iterations, std::string detail) {
    failure_detail_ = std::move(detail);
    step_status st;
    st.reason = reason;
    st.step = step_;
    st.node = node;
    st.iterations = iterations;
    return st;
  }

  step_status fail_non_finite(long n1, int node, const char* where) {
    std::ostringstream os;
    os << "t = " << time_string(n1) << ": non-finite value in " << where;
    if (node >= 0) os << " at node/segment " << node;
    os << "; the time step dt = " << opt_.dt << " is probably beyond the stability limit (estimate ds/c_max = "
       << stability_estimate() << ")";
    return fail(step_failure::non_finite_iterate, node, 0, os.str());
  }

  step_status fail_newton(long n1, int node, const newton_result<T>& r) {
    std::ostringstream os;
    os << "t = " << time_string(n1) << ": the Newton solve of scheme (53) (" << to_string(opt_.method) << ") at node "
       << node << " did not converge in " << opt_.max_newton_iterations << " iterations (weighted residual "
       << r.residual << " > tolerance " << r.tolerance << "); the time step dt = " << opt_.dt
       << " is probably beyond the stability limit (estimate ds/c_max = " << stability_estimate() << ")";
    return fail(step_failure::no_convergence, node, r.iterations, os.str());
  }

  material<T> mat_;
  staggered_grid<T> grid_;
  options<T> opt_;
  vec6<T> d1inv_;
  bool structured_ = false;
  T ds_;
  T dt_over_ds_;
  long step_ = 0;
  std::string failure_detail_;
  T energy0_ = T(0);
  newton_statistics stats_;
  state_vector mu_, gamma_;
  /// Per segment, its stress terms in F of (53): sigma/ds - force/2 (left node), sigma/ds + force/2 (right node).
  state_vector stress_left_, stress_right_;
  state_vector mu_next_, gamma_next_, stress_left_next_, stress_right_next_;
  configuration_vector g_, g_next_;
};

}  // namespace geomint::beam
