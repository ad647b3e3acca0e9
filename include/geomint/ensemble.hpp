#pragma once
/// Ensembles: many trajectories of one natural system in double, stepped together, one
/// trajectory per lane of a SIMD pack (core/simd.hpp).
///
///   geomint::ensemble_integrator<12, geomint::zoo::henon_heiles> E(tau);
///   std::vector<geomint::phase_state<double, 2>> states = ...;  // (q, p) of each trajectory
///   E.integrate(states, steps);                                    // each state steps `steps` times
///
/// The map of each trajectory is the one of `integrator<lpf<M, gauss_interior>, Sys, double>`
/// with compensated summation (its fixed-point form, schemes/gauss_fixed_point.hpp): the same
/// rounded coefficients, predictor, Jacobi sweeps, per-trajectory stopping rule and compensated
/// update, with each lane doing what the one-trajectory step does, in the same order. A lane
/// whose sweeps have stopped keeps its increments while the others go on, so every trajectory
/// takes exactly the sweeps it would take alone, and its results are the scalar integrator's
/// bit for bit where the forces use the same functions (SLEEF's vector sine of the same width
/// as the scalar integrator's stage packs, a polynomial) and the compiler does not contract the
/// two codes' multiply-adds differently into fmas (tests/schemes/test_ensemble.cpp). Unlike
/// lpf<m, gauss_interior> there is no Newton fallback: a step beyond the sweeps' reach fails.
/// Trajectories are taken W at a time;
/// the last block's empty lanes repeat its last trajectory and are discarded.
///
/// Sys must supply `template <class S> static vec<S, dof> potential_gradient(const vec<S, dof>&)`
/// that compiles on double_pack (as a system that opts in to stage_parallel_forces does;
/// docs/guide/your_own_system.md). A step that fails on some lane (sweeps that do not converge,
/// a non-finite force) throws integration_error naming the trajectory; the states of its block
/// are then those before that step, the blocks before it are complete and those after untouched.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "geomint/core/simd.hpp"
#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/schemes/gauss_fixed_point.hpp"
#include "geomint/solvers/phase_state.hpp"

namespace geomint {

template <int M, class Sys, int W = ensemble_width>
class ensemble_integrator {
  static_assert(M >= 2 && M <= max_floating_m, "geomint::ensemble_integrator: m must be in 2..max_floating_m (16)");
  static_assert(natural_system<Sys>, "geomint::ensemble_integrator: Sys must be a natural system (derived from geomint::natural)");
  static_assert(mechanics::detail::supplies_potential_gradient<Sys, double_pack<W>>,
                "geomint::ensemble_integrator: Sys must supply `template <class S> static geomint::vec<S, dof> "
                "potential_gradient(const geomint::vec<S, dof>&)`, instantiated here on SIMD packs");

 public:
  static constexpr int S = M - 1;
  static constexpr int n = Sys::dof;
  /// Trajectories per pack.
  static constexpr int lanes = W;
  using pack = double_pack<W>;
  using state = phase_state<double, n>;

  /// std::invalid_argument for a tau that is not finite and positive, or invalid options.
  explicit ensemble_integrator(double tau, newton_options<double> opt = {})
      : k_(schemes::detail::gauss_nystrom_coefficients<double, S>::make()),
        minv_(schemes::detail::inverse_of<double, n>(Sys::template mass_matrix<double>())),
        tau_(tau),
        opt_(opt) {
    if (!(tau > 0) || !(tau <= std::numeric_limits<double>::max()))
      throw std::invalid_argument("geomint::ensemble_integrator: tau must be finite and > 0, got " + std::to_string(tau));
    opt_.validate();
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
      for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J) mu_by_column_[J][I] = k_.mu[I][J];
  }

  double tau() const { return tau_; }

  /// Steps every state `steps` times (see the top of the file). Non-finite data and a step index
  /// without successor are refused before any step (integration_error naming the trajectory).
  void integrate(std::span<state> states, long steps) const {
    if (steps < 0) throw std::invalid_argument("geomint::ensemble_integrator: steps must be >= 0");
    for (std::size_t k = 0; k < states.size(); ++k) {
      step_status st = check_step_input(states[k].step, tau_, states[k].q, states[k].p);
      if (st && !checked_add(states[k].step, steps)) st.reason = step_failure::step_index_overflow;
      if (!st) throw integration_error(st, "trajectory " + std::to_string(k));
    }
    for (std::size_t first = 0; first < states.size(); first += W) integrate_block(states, first, steps);
  }

 private:
  using V = std::array<pack, n>;
  /// A lane-wise comparison's result: all bits set where true.
  using lane_mask = decltype(std::declval<typename pack::register_type>() < std::declval<typename pack::register_type>());
  using stages = std::array<V, S>;

  /// The lanes of one block: positions, momenta, their compensation terms, the last step's
  /// stage increments.
  struct block {
    V q, p, cq, cp;
    stages F;
  };

  void integrate_block(std::span<state> states, std::size_t first, long steps) const {
    const std::size_t count = std::min<std::size_t>(W, states.size() - first);
    // The lanes' data component by component, each pack one load.
    std::array<std::array<double, W>, 4 * n> lanes;
    for (int l = 0; l < W; ++l) {
      const state& s = states[first + std::min(static_cast<std::size_t>(l), count - 1)];
      for (int r = 0; r < n; ++r) {
        lanes[static_cast<std::size_t>(r)][static_cast<std::size_t>(l)] = s.q[r];
        lanes[static_cast<std::size_t>(n + r)][static_cast<std::size_t>(l)] = s.p[r];
        lanes[static_cast<std::size_t>(2 * n + r)][static_cast<std::size_t>(l)] = s.carry.q[r];
        lanes[static_cast<std::size_t>(3 * n + r)][static_cast<std::size_t>(l)] = s.carry.p[r];
      }
    }
    block b;
    for (int r = 0; r < n; ++r) {
      b.q[r] = pack::load(lanes[static_cast<std::size_t>(r)].data());
      b.p[r] = pack::load(lanes[static_cast<std::size_t>(n + r)].data());
      b.cq[r] = pack::load(lanes[static_cast<std::size_t>(2 * n + r)].data());
      b.cp[r] = pack::load(lanes[static_cast<std::size_t>(3 * n + r)].data());
    }
    for (long k = 0; k < steps; ++k) {
      const block before = b;
      int failed_lane = -1;
      const step_status st = one_step(b, k > 0, failed_lane);
      if (!st) {
        commit(states, first, count, before, k);
        step_status report = st;
        // (A padded lane repeats the block's last trajectory, which fails first, in lane order.)
        const std::size_t which = first + std::min(static_cast<std::size_t>(failed_lane), count - 1);
        report.step = states[which].step;
        throw integration_error(report, "trajectory " + std::to_string(which));
      }
    }
    commit(states, first, count, b, steps);
  }

  /// The block's lanes into their states after `steps` steps, with the step index and time as
  /// phase_state::commit forms them (t = t0 + (k - k0) tau).
  void commit(std::span<state> states, std::size_t first, std::size_t count, const block& b, long steps) const {
    if (steps == 0) return;
    for (std::size_t l = 0; l < count; ++l) {
      state& s = states[first + l];
      const int lane = static_cast<int>(l);
      vec<double, n> q1, p1;
      phase_carry<double, n> c1;
      for (int r = 0; r < n; ++r) {
        q1[r] = b.q[r][lane];
        p1[r] = b.p[r][lane];
        c1.q[r] = b.cq[r][lane];
        c1.p[r] = b.cp[r][lane];
      }
      s.commit(q1, p1, c1, tau_);
      s.step += steps - 1;  // (integrate checked that it does not overflow)
      s.t = s.t0 + static_cast<double>(s.step - s.k0) * tau_;
    }
  }

  /// One step of every lane: the scalar engine's one_step with compensated summation
  /// (schemes/gauss_fixed_point.hpp), lane by lane. On failure, failed_lane is the first lane
  /// that failed and b is unusable.
  step_status one_step(block& b, bool continues, int& failed_lane) const {
    using std::abs;
    const V v = inverse_mass(b.p);
    const V dv = inverse_mass(b.cp);
    std::array<double, S> hb;
    stages cv, offset;
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
      hb[I] = tau_ * k_.b[I];
      for (int r = 0; r < n; ++r) {
        cv[I][r] = pack(k_.c[I]) * v[r];
        offset[I][r] = b.cq[r] + pack(tau_) * (pack(k_.c[I]) * dv[r]);
      }
    }
    stages F;
    if (continues) {
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
        for (int r = 0; r < n; ++r) {
          pack x(0.0);
          for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J) x += pack(k_.extrapolate[I][J]) * b.F[J][r];
          F[I][r] = x;
        }
    } else {
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
        V x;
        for (int r = 0; r < n; ++r) x[r] = b.q[r] + pack(tau_ * k_.c[I]) * v[r];
        F[I] = scaled_force(hb[I], x);
      }
    }
    // The sweeps, each lane under its own stopping rule: sweep_stopping_rule's
    // (schemes/fixed_point_stopping.hpp), lane by lane in vector form.
    const double eps = std::numeric_limits<double>::epsilon();
    const lane_mask all = pack(0.0).v == pack(0.0).v, none = ~all;
    lane_mask active = all;  // lanes still sweeping: all bits set, else 0
    pack eps_q(0.0);         // eps |q|_inf, the scale's floor
    for (int r = 0; r < n; ++r) {
      const pack a = abs(b.q[r]);
      eps_q = pack(a.v > eps_q.v ? a.v : eps_q.v);
    }
    eps_q = pack(eps) * eps_q;
    pack previous(std::numeric_limits<double>::infinity());
    lane_mask growth = none & all;  // 0 in every lane
    const int budget = schemes::detail::sweep_budget(opt_);
    const pack largest(std::numeric_limits<double>::max()), floor_level(epsilon_two_thirds<double>()),
        tolerance(static_cast<double>(opt_.tolerance_ulps) * eps), eighth(0.125);
    step_status st;
    bool running = true;
    for (int it = 1; it <= budget && running; ++it) {
      st.iterations = it;
      // A Jacobi sweep (sweep_in_builtin): every stage's combination from this sweep's F.
      stages next;
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
        V z;
        for (int r = 0; r < n; ++r) z[r] = pack(0.0);
        for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J)
          for (int r = 0; r < n; ++r) z[r] += pack(mu_by_column_[J][I]) * F[J][r];
        const V mz = inverse_mass(z);
        V x;
        for (int r = 0; r < n; ++r) x[r] = b.q[r] + fma(pack(tau_), cv[I][r] + mz[r], offset[I][r]);
        next[I] = scaled_force(hb[I], x);
      }
      // The change, the size and the finiteness of the new increments, and the new increments
      // for the lanes still sweeping.
      pack change(0.0), size(0.0);
      lane_mask finite = all;
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
        for (int r = 0; r < n; ++r) {
          const pack a = abs(next[I][r]), d = abs(next[I][r] - F[I][r]);
          finite = finite & (a.v <= largest.v);
          size = pack(a.v > size.v ? a.v : size.v);
          change = pack(d.v > change.v ? d.v : change.v);
          F[I][r] = pack(active ? next[I][r].v : F[I][r].v);
        }
      // sweep_stopping_rule::stops: a fixed point; the contraction rate (opt.stop_on_rate);
      // growing twice in a row (a failure above eps^(2/3)); the budget (a failure above the
      // tolerance).
      const pack scale = size + eps_q;
      lane_mask stop = change.v == pack(0.0).v, fail = none;
      if (opt_.stop_on_rate && it > 1) {
        const pack rho = change / previous;
        stop |= ~stop & (change.v < previous.v) & (rho.v <= eighth.v) &
                ((rho * change).v <= ((pack(1.0) - rho) * pack(eps) * scale).v);
      }
      const lane_mask grew = ~stop & (change.v >= previous.v);
      growth = grew ? growth + 1 : growth & none;
      const lane_mask twice = grew & (growth >= 2);
      fail |= twice & (change.v > (floor_level * scale).v);
      stop |= twice;
      previous = pack(stop ? previous.v : change.v);
      if (it == budget) {
        fail |= ~stop & (change.v > (tolerance * scale).v);
        stop = all;
      }
      // The first lane (in lane order) that fails, as the lane-by-lane loop would report it.
      const lane_mask bad = active & (~finite | fail);
      for (int l = 0; l < W; ++l)
        if (bad[l]) {
          failed_lane = l;
          st.reason = finite[l] ? step_failure::no_convergence : step_failure::non_finite_iterate;
          return st;
        }
      active &= ~stop;
      running = false;
      for (int l = 0; l < W; ++l) running = running || active[l] != 0;
    }
    // The compensated update (exact_update): increments to twice the working precision.
    V se;
    for (int r = 0; r < n; ++r) {
      pack sum(0.0);
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) sum += pack(k_.e[I]) * F[I][r];
      se[r] = sum;
    }
    const V mse = inverse_mass(se);
    for (int r = 0; r < n; ++r) {
      const pack rest = dv[r] + mse[r];
      pack dp(0.0), dp_lo(0.0);
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
        pack sum, err;
        two_sum(dp, F[I][r], sum, err);
        dp = sum;
        dp_lo += err;
      }
      pack w, w_lo;
      two_sum(v[r], rest, w, w_lo);
      const pack dq = pack(tau_) * w;
      const pack dq_lo = fma(pack(tau_), w, -dq) + pack(tau_) * w_lo;
      add_twice(b.q[r], b.cq[r], dq, dq_lo);
      add_twice(b.p[r], b.cp[r], dp, dp_lo);
    }
    b.F = F;
    return st;
  }

  /// add_compensated of solvers/phase_state.hpp for one component of packs.
  static void add_twice(pack& x, pack& carry, const pack& dx, const pack& dx_lo) {
    pack s, e;
    two_sum(x, dx, s, e);
    const pack small = e + (carry + dx_lo);
    two_sum(s, small, x, carry);
  }

  /// -grad V at the points x, times hb.
  static V scaled_force(double hb, const V& x) {
    vec<pack, n> xv;
    for (int r = 0; r < n; ++r) xv[r] = x[r];
    const vec<pack, n> g = Sys::template potential_gradient<pack>(xv);
    V out;
    for (int r = 0; r < n; ++r) out[r] = pack(hb) * -g[r];
    return out;
  }

  /// M^{-1} x as the scalar engine forms it: skipped for a unit mass matrix, one product per
  /// entry for a diagonal one, the row sums otherwise.
  V inverse_mass(const V& x) const {
    if (unit_mass_) return x;
    V out;
    for (int r = 0; r < n; ++r) {
      if (diagonal_mass_) {
        out[r] = pack(minv_(r, r)) * x[r];
        continue;
      }
      pack sum(0.0);
      for (int c = 0; c < n; ++c) sum += pack(minv_(r, c)) * x[c];
      out[r] = sum;
    }
    return out;
  }


  schemes::detail::gauss_nystrom_coefficients<double, S> k_;
  mat<double, n> minv_;
  bool unit_mass_ = minv_.isIdentity(0), diagonal_mass_ = minv_.isDiagonal(0);
  double tau_;
  newton_options<double> opt_;
  std::array<std::array<double, S>, S> mu_by_column_{};
};

}  // namespace geomint
