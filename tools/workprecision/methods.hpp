#pragma once
/// geomint-workprecision, methods: geomint's schemes and the peers, behind one interface.
///
/// A fixed-step method runs `knob` steps of size T/knob. An adaptive method (Odeint's controlled
/// runge_kutta_fehlberg78 and bulirsch_stoer) runs with absolute and relative tolerance
/// 10^(-knob/4). The Taylor-series flow (analysis/reference_flow.hpp) picks its own order and
/// steps for the scalar's precision and runs once. Every run returns the number of steps taken
/// (or -1 on a failed step); `monitor`, if given, sees the state after every step. Every run
/// loop checks the CPU-time budget of the run (run_budget, --max-seconds) every few steps and
/// throws run_stopped once it is spent, so that no run outlasts its budget by more than a few
/// steps.
#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <boost/numeric/odeint/stepper/base/symplectic_rkn_stepper_base.hpp>  // the m4 header misses it (Boost 1.74)
#include <boost/numeric/odeint/stepper/bulirsch_stoer.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/velocity_verlet.hpp>

#include "geomint/analysis/composition.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/integrator.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "points.hpp"
#include "problems.hpp"

namespace geomint::workprecision {

namespace odeint = boost::numeric::odeint;

template <class T, int n>
using monitor_fn = std::function<void(const arr<T, n>&, const arr<T, n>&)>;

enum class knob_kind { steps, tolerance, none };

/// A run stopped by its CPU-time budget.
struct run_stopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The CPU-time budget of the current run (one per thread): start() before a run; the run loops
/// call check(k) at their step k, which reads the clock every 256 steps (a few ns per step).
class run_budget {
 public:
  static run_budget& current() {
    static thread_local run_budget budget;
    return budget;
  }
  void start(double seconds) {
    limit_ = seconds;
    start_ = cpu_now();
  }
  void check(long k) const {
    if ((k & 255) == 0 && cpu_now() - start_ > limit_)
      throw run_stopped("stopped after " + std::to_string(limit_) + " CPU seconds (--max-seconds)");
  }

 private:
  double limit_ = std::numeric_limits<double>::infinity(), start_ = 0;
};

template <class T, int n>
struct method {
  std::string name;
  bool peer = false;
  knob_kind kind = knob_kind::steps;
  long first = 1;  ///< first knob of the sweep (steps, or four times the tolerance exponent)
  std::function<long(long knob, const T& t_end, arr<T, n>& q, arr<T, n>& p, const monitor_fn<T, n>* mon)> run;
};

/// 10^(-knob/4) computed in T.
template <class T>
T tolerance_of(long knob) {
  using std::pow;
  return T(pow(T(10), T(-from_int64<T>(knob)) / T(4)));
}

/// A geomint scheme; `compensated`: compensated summation of the q, p update
/// (integrator::set_compensated_summation); `stop_on_rate`: newton_options::stop_on_rate on
/// (the default of multiprecision scalars) also in double, where by default the iteration goes
/// on until its correction stops changing (for the round-off behaviour of long runs);
/// `simd_forces`: newton_options::simd_forces (the stage forces on SIMD packs, the default).
template <class P, class Scheme, class T>
method<T, P::n> geomint_method(std::string name, long first_steps, bool compensated, bool stop_on_rate = false,
                               bool simd_forces = true) {
  constexpr int n = P::n;
  method<T, n> m{std::move(name), false, knob_kind::steps, first_steps, {}};
  m.run = [compensated, stop_on_rate, simd_forces](long steps, const T& t_end, arr<T, n>& q, arr<T, n>& v,
                                                   const monitor_fn<T, n>* mon) -> long {
    using I = integrator<Scheme, typename P::sys, T>;
    I integ(typename P::sys{}, T(t_end / from_int64<T>(steps)));
    integ.set_compensated_summation(compensated);
    if (stop_on_rate) integ.options().stop_on_rate = true;
    integ.options().simd_forces = simd_forces;
    // The shared state is (q, v); the scheme's is (q, p = M v).
    const arr<T, n> mass = masses<typename P::sys, T>();
    typename I::state s;
    for (int i = 0; i < n; ++i) {
      s.q[i] = q[std::size_t(i)];
      s.p[i] = mass[std::size_t(i)] * v[std::size_t(i)];
    }
    auto to_shared = [&](arr<T, n>& qq, arr<T, n>& vv) {
      for (int i = 0; i < n; ++i) {
        qq[std::size_t(i)] = s.q[i];
        vv[std::size_t(i)] = s.p[i] / mass[std::size_t(i)];
      }
    };
    const run_budget& budget = run_budget::current();
    for (long k = 0; k < steps; ++k) {
      budget.check(k);
      if (!integ.try_step(s)) return -1;
      if (mon) {
        arr<T, n> qq, vv;
        to_shared(qq, vv);
        (*mon)(qq, vv);
      }
    }
    to_shared(q, v);
    return steps;
  };
  return m;
}

/// Odeint's symplectic RKN steppers (dq/dt = v, dv/dt = force(q) = -M^{-1} grad V).
template <class P, class Stepper, class T>
method<T, P::n> odeint_rkn(std::string name, long first_steps) {
  constexpr int n = P::n;
  method<T, n> m{std::move(name), true, knob_kind::steps, first_steps, {}};
  m.run = [](long steps, const T& t_end, arr<T, n>& q, arr<T, n>& p, const monitor_fn<T, n>* mon) -> long {
    Stepper stepper;
    auto coor = [](const arr<T, n>& pp, arr<T, n>& dqdt) { dqdt = pp; };
    auto mom = [](const arr<T, n>& qq, arr<T, n>& dpdt) { P::force(qq, dpdt); };
    const T tau = t_end / from_int64<T>(steps);
    T t(0);
    const run_budget& budget = run_budget::current();
    for (long k = 0; k < steps; ++k) {
      budget.check(k);
      stepper.do_step(std::make_pair(coor, mom), std::make_pair(std::ref(q), std::ref(p)), t, tau);
      t += tau;
      if (mon) (*mon)(q, p);
    }
    return steps;
  };
  return m;
}

/// Odeint's velocity_verlet (one force evaluation per step: it keeps the last acceleration).
template <class P, class T>
method<T, P::n> odeint_verlet(std::string name, long first_steps) {
  constexpr int n = P::n;
  method<T, n> m{std::move(name), true, knob_kind::steps, first_steps, {}};
  m.run = [](long steps, const T& t_end, arr<T, n>& q, arr<T, n>& p, const monitor_fn<T, n>* mon) -> long {
    odeint::velocity_verlet<arr<T, n>, T> stepper;
    auto accel = [](const arr<T, n>& qq, const arr<T, n>&, arr<T, n>& a, const T&) { P::force(qq, a); };
    const T tau = t_end / from_int64<T>(steps);
    T t(0);
    const run_budget& budget = run_budget::current();
    for (long k = 0; k < steps; ++k) {
      budget.check(k);
      stepper.do_step(accel, std::make_pair(std::ref(q), std::ref(p)), t, tau);
      t += tau;
      if (mon) (*mon)(q, p);
    }
    return steps;
  };
  return m;
}

/// Symmetric composition of Stormer-Verlet (analysis/composition.hpp); coefficients refined in T.
template <class P, class T>
method<T, P::n> composition_method(std::string name, const analysis::symmetric_composition<T>& c, long first_steps) {
  constexpr int n = P::n;
  method<T, n> m{std::move(name), true, knob_kind::steps, first_steps, {}};
  m.run = [gamma = c.gamma()](long steps, const T& t_end, arr<T, n>& q, arr<T, n>& p,
                              const monitor_fn<T, n>* mon) -> long {
    const T tau = t_end / from_int64<T>(steps);
    arr<T, n> f;
    P::force(q, f);
    auto force = [](const arr<T, n>& qq, arr<T, n>& ff) { P::force(qq, ff); };
    const run_budget& budget = run_budget::current();
    for (long k = 0; k < steps; ++k) {
      budget.check(k);
      analysis::composition_step(gamma, q, p, f, tau, force);
      if (mon) (*mon)(q, p);
    }
    return steps;
  };
  return m;
}

/// First-order form x = (q, p) for Odeint's general steppers.
template <class P, class T>
struct first_order_rhs {
  static constexpr int n = P::n;
  void operator()(const arr<T, 2 * n>& x, arr<T, 2 * n>& dxdt, const T&) const {
    arr<T, n> q, f;
    for (int i = 0; i < n; ++i) q[std::size_t(i)] = x[std::size_t(i)];
    P::force(q, f);
    for (int i = 0; i < n; ++i) {
      dxdt[std::size_t(i)] = x[std::size_t(n + i)];
      dxdt[std::size_t(n + i)] = f[std::size_t(i)];
    }
  }
};

/// Controlled stepping to exactly t_end with try_step; returns accepted steps.
template <class P, class T, class Stepper>
long adaptive_run(Stepper& stepper, const T& t_end, arr<T, P::n>& q, arr<T, P::n>& p, const monitor_fn<T, P::n>* mon) {
  constexpr int n = P::n;
  arr<T, 2 * n> x;
  for (int i = 0; i < n; ++i) {
    x[std::size_t(i)] = q[std::size_t(i)];
    x[std::size_t(n + i)] = p[std::size_t(i)];
  }
  const first_order_rhs<P, T> rhs;
  T t(0), dt = t_end / T(1000);
  long accepted = 0;
  arr<T, n> qq, pp;
  // Below this step size the controller has met round-off (tolerance near the scalar's
  // precision): reported as a failed run instead of creeping on.
  const T dt_min = t_end / T(1000000000);
  const run_budget& budget = run_budget::current();
  for (long attempts = 0; t < t_end; ++attempts) {
    if (attempts > 20000000L || dt < dt_min) return -1;
    budget.check(attempts);
    if (t + dt > t_end) dt = t_end - t;
    if (stepper.try_step(rhs, x, t, dt) == odeint::success) {
      ++accepted;
      if (mon) {
        for (int i = 0; i < n; ++i) {
          qq[std::size_t(i)] = x[std::size_t(i)];
          pp[std::size_t(i)] = x[std::size_t(n + i)];
        }
        (*mon)(qq, pp);
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    q[std::size_t(i)] = x[std::size_t(i)];
    p[std::size_t(i)] = x[std::size_t(n + i)];
  }
  return accepted;
}

template <class P, class T>
method<T, P::n> odeint_rkf78(std::string name, long first_knob) {
  constexpr int n = P::n;
  method<T, n> m{std::move(name), true, knob_kind::tolerance, first_knob, {}};
  m.run = [](long knob, const T& t_end, arr<T, n>& q, arr<T, n>& p, const monitor_fn<T, n>* mon) -> long {
    using controlled = odeint::controlled_runge_kutta<odeint::runge_kutta_fehlberg78<arr<T, 2 * n>, T>>;
    const T tol = tolerance_of<T>(knob);
    controlled stepper{typename controlled::error_checker_type(tol, tol)};
    return adaptive_run<P, T>(stepper, t_end, q, p, mon);
  };
  return m;
}

template <class P, class T>
method<T, P::n> odeint_bulirsch_stoer(std::string name, long first_knob) {
  constexpr int n = P::n;
  method<T, n> m{std::move(name), true, knob_kind::tolerance, first_knob, {}};
  m.run = [](long knob, const T& t_end, arr<T, n>& q, arr<T, n>& p, const monitor_fn<T, n>* mon) -> long {
    const T tol = tolerance_of<T>(knob);
    odeint::bulirsch_stoer<arr<T, 2 * n>, T> stepper(tol, tol);
    return adaptive_run<P, T>(stepper, t_end, q, p, mon);
  };
  return m;
}

/// geomint's Taylor-series flow (order and steps chosen for the precision of T).
template <class P, class T>
method<T, P::n> taylor_method(std::string name) {
  constexpr int n = P::n;
  method<T, n> m{std::move(name), true, knob_kind::none, 0, {}};
  m.run = [](long, const T& t_end, arr<T, n>& q, arr<T, n>& v, const monitor_fn<T, n>* mon) -> long {
    const arr<T, n> mass = masses<typename P::sys, T>();
    vec<T, n> q0, p0;
    for (int i = 0; i < n; ++i) {
      q0[i] = q[std::size_t(i)];
      p0[i] = mass[std::size_t(i)] * v[std::size_t(i)];
    }
    analysis::reference_flow<typename P::sys, T> flow(q0, p0);
    auto to_shared = [&](arr<T, n>& qq, arr<T, n>& vv) {
      for (int i = 0; i < n; ++i) {
        qq[std::size_t(i)] = flow.q()[i];
        vv[std::size_t(i)] = flow.qdot()[i];
      }
    };
    // Monitored: 1000 sample times (the flow's own steps are not exposed).
    const long samples = mon ? 1000 : 1;
    // Bounded up front as reference_flow::advance_to is (a run beyond its step bound is
    // refused before the first step), then 256 Taylor steps at a time between two looks at the
    // clock; the flow's t + h == t check ends a run that cannot reach t_end.
    constexpr long max_steps = analysis::reference_flow<typename P::sys, T>::default_max_steps;
    if (flow.estimated_steps(t_end) > from_int64<T>(max_steps))
      throw std::length_error("taylor-series: T = " + std::to_string(to_double(t_end)) + " needs more than " +
                              std::to_string(max_steps) + " Taylor steps");
    const run_budget& budget = run_budget::current();
    for (long k = 1; k <= samples; ++k) {
      const T target = k == samples ? t_end : T(t_end * from_int64<T>(k) / from_int64<T>(samples));
      while (!flow.advance_toward(target, 256)) budget.check(0);
      if (mon) {
        arr<T, n> qq, vv;
        to_shared(qq, vv);
        (*mon)(qq, vv);
      }
    }
    to_shared(q, v);
    return flow.steps();
  };
  return m;
}

}  // namespace geomint::workprecision
