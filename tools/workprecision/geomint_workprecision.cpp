/// geomint-workprecision: work-precision comparison of geomint's variational integrators with
/// Boost.Odeint's symplectic steppers on the pendulum and the Kepler problem.
///
/// For every method and a geometric sequence of step sizes, integrates to t = T (default 1000)
/// in double and records the CPU time of the stepping loop, the final phase-space error
/// |(q, p) - (q, p)_ref| (Euclidean) and the largest energy error max_k |H(q_k, p_k) - H_0|.
/// The stepping loop is timed alone (CLOCK_PROCESS_CPUTIME_ID; short runs are repeated and the
/// fastest kept); the energy is monitored in a second, untimed pass, identically for all methods.
///
/// Reference: the closed-form solutions, evaluated in cpp_bin_float_50 (independent of every
/// integrator): pendulum sin(theta/2) = k cd(t, k), thetadot = -2 k k' sd(t, k), k = sin(theta0/2)
/// (Boost.Math Jacobi elliptic functions); Kepler (a = 1, e = 0.5, period 2 pi) from Kepler's
/// equation E - e sin E = t solved by Newton in 50 digits. `--check-reference` integrates the
/// same problem with Odeint's controlled runge_kutta_fehlberg78 in cpp_bin_float_50 (abs/rel
/// tolerance 1e-30) and prints its distance to the closed form at t = T.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/numeric/odeint/stepper/base/symplectic_rkn_stepper_base.hpp>  // the m4 header misses it (Boost 1.74)
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/velocity_verlet.hpp>

#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"

/// Odeint's norm_inf descends value_type chains; a Boost.Multiprecision number is its own end.
template <>
struct boost::numeric::odeint::detail::extract_value_type<boost::multiprecision::cpp_bin_float_50, void> {
  using type = boost::multiprecision::cpp_bin_float_50;
};

namespace {

namespace odeint = boost::numeric::odeint;
using mp = boost::multiprecision::cpp_bin_float_50;

const char* usage =
    "usage: geomint-workprecision [--system pendulum|kepler] [--csv] [--t-end T (> 0, default 1000)]\n"
    "                             [--max-seconds S (> 0, default 1)] [--methods a,b,...] [--check-reference]\n"
    "Work-precision of geomint's variational integrators (double) against Boost.Odeint's\n"
    "symplectic_rkn_sb3a_mclachlan, symplectic_rkn_sb3a_m4_mclachlan and velocity_verlet.\n"
    "Pendulum: theta0 = 1, thetadot0 = 0. Kepler: e = 0.5, q0 = (0.5, 0), qdot0 = (0, sqrt 3).\n"
    "For each method the step size tau = T/steps decreases by sqrt(2) until the final error is\n"
    "below 1e-13, stops improving, or one run takes more than S CPU seconds.\n"
    "--csv prints method,tau,steps,cpu_seconds,final_error,max_energy_error (one row per run)\n"
    "followed by the summary as '#' lines; otherwise a table and the summary. The summary\n"
    "interpolates (log-log) each method's CPU time at final error 1e-10 and 1e-6 and compares\n"
    "the best geomint scheme with the fastest Odeint stepper.\n"
    "The reference is the closed-form solution in cpp_bin_float_50; --check-reference also\n"
    "integrates with Odeint's controlled runge_kutta_fehlberg78 in cpp_bin_float_50 (tolerance\n"
    "1e-30) and prints its distance to the closed form (slow: 2-4 CPU minutes for T = 1000).\n"
    "--methods restricts the run to a comma-separated list of method names (see the table).\n";

int fail(const std::string& why) {
  std::cerr << "geomint-workprecision: " << why << "\n" << usage;
  return 2;
}

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

// ---------------------------------------------------------------------------------------------
// Problems: initial data, energy, force for Odeint, and the closed-form reference in 50 digits.

template <int n>
using dvec = std::array<double, n>;

struct pendulum_problem {
  using sys = geomint::systems::pendulum;
  static constexpr int n = 1;
  static constexpr const char* name = "pendulum";
  static dvec<n> q0() { return {1.0}; }
  static dvec<n> p0() { return {0.0}; }
  static double energy(const dvec<n>& q, const dvec<n>& p) { return p[0] * p[0] / 2 + (1 - std::cos(q[0])); }
  static void force(const dvec<n>& q, dvec<n>& f) { f[0] = -std::sin(q[0]); }
  template <class S>
  static void force_t(const std::array<S, n>& q, std::array<S, n>& f) {
    using std::sin;
    f[0] = -sin(q[0]);
  }
  /// sin(theta/2) = k cd(t, k), thetadot = -2 k k' sd(t, k), k = sin(theta0/2), k' = cos(theta0/2).
  static std::pair<std::array<mp, n>, std::array<mp, n>> exact(const mp& t) {
    using std::asin;
    using std::cos;
    using std::sin;
    const mp k = sin(mp(1) / 2), kp = cos(mp(1) / 2);
    const mp cd = boost::math::jacobi_cd(k, t), sd = boost::math::jacobi_sd(k, t);
    return {{mp(2 * asin(k * cd))}, {mp(-2 * k * kp * sd)}};
  }
};

struct kepler_problem {
  using sys = geomint::systems::kepler;
  static constexpr int n = 2;
  static constexpr const char* name = "kepler";
  static dvec<n> q0() { return {0.5, 0.0}; }
  static dvec<n> p0() { return {0.0, std::sqrt(3.0)}; }
  static double energy(const dvec<n>& q, const dvec<n>& p) {
    return (p[0] * p[0] + p[1] * p[1]) / 2 - 1 / std::sqrt(q[0] * q[0] + q[1] * q[1]);
  }
  static void force(const dvec<n>& q, dvec<n>& f) {
    const double r2 = q[0] * q[0] + q[1] * q[1];
    const double s = 1 / (r2 * std::sqrt(r2));
    f[0] = -q[0] * s;
    f[1] = -q[1] * s;
  }
  template <class S>
  static void force_t(const std::array<S, n>& q, std::array<S, n>& f) {
    using std::sqrt;
    const S r2 = q[0] * q[0] + q[1] * q[1];
    const S s = 1 / (r2 * sqrt(r2));
    f[0] = -q[0] * s;
    f[1] = -q[1] * s;
  }
  /// a = 1, e = 1/2, mean motion 1: E - e sin E = t, q = (cos E - e, b sin E), b = sqrt(1 - e^2).
  static std::pair<std::array<mp, n>, std::array<mp, n>> exact(const mp& t) {
    using std::abs;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const mp e = mp(1) / 2, b = sqrt(1 - e * e);
    const mp two_pi = boost::math::constants::two_pi<mp>();
    mp M = t - two_pi * floor(t / two_pi);
    mp E = M + e * sin(M);
    for (int it = 0; it < 100; ++it) {
      const mp dE = (E - e * sin(E) - M) / (1 - e * cos(E));
      E -= dE;
      if (abs(dE) < 100 * std::numeric_limits<mp>::epsilon()) break;
    }
    const mp Edot = 1 / (1 - e * cos(E));
    return {{mp(cos(E) - e), mp(b * sin(E))}, {mp(-sin(E) * Edot), mp(b * cos(E) * Edot)}};
  }
};

// ---------------------------------------------------------------------------------------------
// One run of one method: a stepper object with reset(), step() and state access.

struct result {
  std::string method;
  double tau = 0;
  long steps = 0;
  double cpu = 0;
  double final_error = 0;
  double max_energy_error = 0;
};

/// A method: runs `steps` steps of size tau; returns false on a failed step. The state after the
/// run is in q, p. `monitor` (may be empty) is called after every step.
template <int n>
struct method {
  std::string name;
  bool odeint = false;
  double tau_max = 0.1;  ///< the largest step size tried
  std::function<bool(double tau, long steps, dvec<n>& q, dvec<n>& p,
                     const std::function<void(const dvec<n>&, const dvec<n>&)>* monitor)>
      run;
};

template <class Problem, class Scheme>
method<Problem::n> geomint_method(const std::string& name, double tau_max) {
  constexpr int n = Problem::n;
  method<n> m;
  m.name = name;
  m.tau_max = tau_max;
  m.run = [](double tau, long steps, dvec<n>& q, dvec<n>& p,
             const std::function<void(const dvec<n>&, const dvec<n>&)>* monitor) {
    using I = geomint::integrator<Scheme, typename Problem::sys, double>;
    const I integ(typename Problem::sys{}, tau);
    typename I::state s;
    for (int i = 0; i < n; ++i) {
      s.q[i] = q[static_cast<std::size_t>(i)];
      s.p[i] = p[static_cast<std::size_t>(i)];
    }
    for (long k = 0; k < steps; ++k) {
      if (!integ.try_step(s)) return false;
      if (monitor) {
        dvec<n> qq, pp;
        for (int i = 0; i < n; ++i) {
          qq[static_cast<std::size_t>(i)] = s.q[i];
          pp[static_cast<std::size_t>(i)] = s.p[i];
        }
        (*monitor)(qq, pp);
      }
    }
    for (int i = 0; i < n; ++i) {
      q[static_cast<std::size_t>(i)] = s.q[i];
      p[static_cast<std::size_t>(i)] = s.p[i];
    }
    return true;
  };
  return m;
}

/// Odeint's symplectic RKN steppers (unit mass: dq/dt = p, dp/dt = force(q)).
template <class Problem, class Stepper>
method<Problem::n> odeint_rkn(const std::string& name, double tau_max) {
  constexpr int n = Problem::n;
  method<n> m;
  m.name = name;
  m.odeint = true;
  m.tau_max = tau_max;
  m.run = [](double tau, long steps, dvec<n>& q, dvec<n>& p,
             const std::function<void(const dvec<n>&, const dvec<n>&)>* monitor) {
    Stepper stepper;
    auto coor = [](const dvec<n>& pp, dvec<n>& dqdt) { dqdt = pp; };
    auto mom = [](const dvec<n>& qq, dvec<n>& dpdt) { Problem::force(qq, dpdt); };
    double t = 0;
    for (long k = 0; k < steps; ++k) {
      stepper.do_step(std::make_pair(coor, mom), std::make_pair(std::ref(q), std::ref(p)), t, tau);
      t += tau;
      if (monitor) (*monitor)(q, p);
    }
    return true;
  };
  return m;
}

/// Odeint's velocity_verlet (one force evaluation per step: it keeps the last acceleration).
template <class Problem>
method<Problem::n> odeint_verlet(const std::string& name, double tau_max) {
  constexpr int n = Problem::n;
  method<n> m;
  m.name = name;
  m.odeint = true;
  m.tau_max = tau_max;
  m.run = [](double tau, long steps, dvec<n>& q, dvec<n>& p,
             const std::function<void(const dvec<n>&, const dvec<n>&)>* monitor) {
    odeint::velocity_verlet<dvec<n>> stepper;
    auto accel = [](const dvec<n>& qq, const dvec<n>&, dvec<n>& a, double) { Problem::force(qq, a); };
    double t = 0;
    for (long k = 0; k < steps; ++k) {
      stepper.do_step(accel, std::make_pair(std::ref(q), std::ref(p)), t, tau);
      t += tau;
      if (monitor) (*monitor)(q, p);
    }
    return true;
  };
  return m;
}

template <class Problem>
std::vector<method<Problem::n>> methods() {
  using namespace geomint;
  using P = Problem;
  std::vector<method<P::n>> all;
  // tau_max: the first step size, chosen so that the first error is around 1e-2..1e-4.
  all.push_back(geomint_method<P, trapezoidal_vi>("trapezoidal", 0.05));
  all.push_back(geomint_method<P, midpoint_vi>("midpoint", 0.05));
  all.push_back(geomint_method<P, galerkin_vi<2>>("galerkin-m2", 0.25));
  all.push_back(geomint_method<P, galerkin_vi<3>>("galerkin-m3", 0.5));
  all.push_back(geomint_method<P, galerkin_vi<4>>("galerkin-m4", 2.0));
  all.push_back(geomint_method<P, lpf<2, gauss_interior>>("lpf-m2-gauss-interior", 0.05));
  all.push_back(geomint_method<P, lpf<3, gauss_interior>>("lpf-m3-gauss-interior", 0.25));
  all.push_back(geomint_method<P, lpf<4, gauss_interior>>("lpf-m4-gauss-interior", 0.5));
  all.push_back(geomint_method<P, lpf<5, gauss_interior>>("lpf-m5-gauss-interior", 1.0));
  all.push_back(geomint_method<P, lpf<6, gauss_interior>>("lpf-m6-gauss-interior", 2.0));
  all.push_back(geomint_method<P, lpf<8, gauss_interior>>("lpf-m8-gauss-interior", 2.0));
  all.push_back(odeint_rkn<P, odeint::symplectic_rkn_sb3a_mclachlan<dvec<P::n>>>(
      "odeint-symplectic_rkn_sb3a_mclachlan", 0.25));
  all.push_back(odeint_rkn<P, odeint::symplectic_rkn_sb3a_m4_mclachlan<dvec<P::n>>>(
      "odeint-symplectic_rkn_sb3a_m4_mclachlan", 0.25));
  all.push_back(odeint_verlet<P>("odeint-velocity_verlet", 0.05));
  return all;
}

// ---------------------------------------------------------------------------------------------

struct settings {
  std::string system = "pendulum";
  bool csv = false;
  double t_end = 1000;
  double max_seconds = 1;
  std::vector<std::string> only;
  bool check_reference = false;
};

template <class Problem>
double phase_error(const dvec<Problem::n>& q, const dvec<Problem::n>& p,
                   const std::pair<std::array<mp, Problem::n>, std::array<mp, Problem::n>>& ref) {
  mp sum(0);
  for (std::size_t i = 0; i < std::size_t(Problem::n); ++i) {
    const mp dq = mp(q[i]) - ref.first[i], dp = mp(p[i]) - ref.second[i];
    sum += dq * dq + dp * dp;
  }
  using std::sqrt;
  return static_cast<double>(sqrt(sum));
}

/// One (method, steps) point: a timed pass (repeated while short) and an untimed energy pass.
template <class Problem>
std::optional<result> measure(const method<Problem::n>& m, long steps, const settings& o,
                              const std::pair<std::array<mp, Problem::n>, std::array<mp, Problem::n>>& ref) {
  constexpr int n = Problem::n;
  const double tau = o.t_end / double(steps);
  result r;
  r.method = m.name;
  r.tau = tau;
  r.steps = steps;
  dvec<n> q{}, p{};
  double best = std::numeric_limits<double>::infinity(), spent = 0;
  for (int rep = 0; rep < 20; ++rep) {
    q = Problem::q0();
    p = Problem::p0();
    const double t0 = cpu_now();
    const bool ok = m.run(tau, steps, q, p, nullptr);
    const double dt = cpu_now() - t0;
    if (!ok) return std::nullopt;
    best = std::min(best, dt);
    spent += dt;
    if (spent > 0.2 || (rep >= 2 && spent > 0.05)) break;
  }
  r.cpu = best;
  r.final_error = phase_error<Problem>(q, p, ref);
  dvec<n> q2 = Problem::q0(), p2 = Problem::p0();
  const double E0 = Problem::energy(q2, p2);
  double worst = 0;
  const std::function<void(const dvec<n>&, const dvec<n>&)> monitor = [&](const dvec<n>& qq, const dvec<n>& pp) {
    worst = std::max(worst, std::abs(Problem::energy(qq, pp) - E0));
  };
  if (!m.run(tau, steps, q2, p2, &monitor)) return std::nullopt;
  r.max_energy_error = worst;
  return r;
}

/// CPU time at a target final error, interpolated log-log between the two measured points that
/// bracket it (the first crossing from above as tau decreases); empty if not bracketed.
std::optional<double> cpu_at(const std::vector<result>& pts, double target) {
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const result &a = pts[i], &b = pts[i + 1];
    if (a.final_error >= target && b.final_error <= target && a.final_error > 0 && b.final_error > 0) {
      if (a.final_error == b.final_error) return std::min(a.cpu, b.cpu);
      const double s = (std::log(target) - std::log(a.final_error)) / (std::log(b.final_error) - std::log(a.final_error));
      return std::exp(std::log(a.cpu) + s * (std::log(b.cpu) - std::log(a.cpu)));
    }
  }
  return std::nullopt;
}

template <class Problem>
void check_reference(const settings& o) {
  constexpr int n = Problem::n;
  using st = std::array<mp, 2 * n>;
  auto rhs = [](const st& x, st& dxdt, const mp&) {
    std::array<mp, n> q, f;
    for (int i = 0; i < n; ++i) q[std::size_t(i)] = x[std::size_t(i)];
    Problem::force_t(q, f);
    for (int i = 0; i < n; ++i) {
      dxdt[std::size_t(i)] = x[std::size_t(n + i)];
      dxdt[std::size_t(n + i)] = f[std::size_t(i)];
    }
  };
  st x;
  const auto q0 = Problem::exact(mp(0));
  for (int i = 0; i < n; ++i) {
    x[std::size_t(i)] = q0.first[std::size_t(i)];
    x[std::size_t(n + i)] = q0.second[std::size_t(i)];
  }
  const mp tol("1e-30");
  using controlled = odeint::controlled_runge_kutta<odeint::runge_kutta_fehlberg78<st, mp>>;
  controlled stepper{typename controlled::error_checker_type(tol, tol)};
  const double c0 = cpu_now();
  mp t(0), dt("1e-3");
  const mp t_end(o.t_end);
  long steps = 0;
  while (t < t_end) {
    if (t + dt > t_end) dt = t_end - t;
    if (stepper.try_step(rhs, x, t, dt) == odeint::success) ++steps;
  }
  const auto ref = Problem::exact(t_end);
  mp diff(0);
  for (int i = 0; i < n; ++i) {
    using std::abs;
    diff = std::max(diff, mp(abs(x[std::size_t(i)] - ref.first[std::size_t(i)])));
    diff = std::max(diff, mp(abs(x[std::size_t(n + i)] - ref.second[std::size_t(i)])));
  }
  std::cout << (o.csv ? "# " : "") << "reference check: odeint controlled runge_kutta_fehlberg78, cpp_bin_float_50, tol 1e-30, "
            << steps << " steps, " << std::setprecision(3) << cpu_now() - c0
            << " s: max |difference to closed form| at t = " << o.t_end << ": " << std::setprecision(3)
            << static_cast<double>(diff) << "\n";
}

template <class Problem>
int run_all(const settings& o) {
  const auto ref = Problem::exact(mp(o.t_end));
  if (o.check_reference) check_reference<Problem>(o);
  std::vector<method<Problem::n>> all = methods<Problem>();
  if (!o.only.empty()) {
    for (const auto& name : o.only)
      if (std::none_of(all.begin(), all.end(), [&](const auto& m) { return m.name == name; }))
        return fail("unknown method '" + name + "'");
    std::erase_if(all, [&](const auto& m) { return std::find(o.only.begin(), o.only.end(), m.name) == o.only.end(); });
  }
  if (o.csv) std::cout << "method,tau,steps,cpu_seconds,final_error,max_energy_error\n";
  else
    std::cout << "system " << Problem::name << ", T = " << o.t_end << ", double; reference: closed form in cpp_bin_float_50\n"
              << std::left << std::setw(42) << "method" << std::right << std::setw(12) << "tau" << std::setw(10)
              << "steps" << std::setw(12) << "cpu [s]" << std::setw(12) << "final err" << std::setw(12) << "max dE"
              << "\n";
  std::map<std::string, std::vector<result>> by_method;
  for (const auto& m : all) {
    long steps = std::max(1L, std::lround(std::ceil(o.t_end / m.tau_max)));
    double prev_error = std::numeric_limits<double>::infinity();
    int worse = 0;
    for (int k = 0; k < 60; ++k) {
      const auto r = measure<Problem>(m, steps, o, ref);
      if (!r) {
        std::cerr << "geomint-workprecision: " << m.name << " failed at tau = " << o.t_end / double(steps)
                  << " (skipped)\n";
      } else {
        by_method[m.name].push_back(*r);
        if (o.csv)
          std::cout << std::setprecision(6) << r->method << ',' << r->tau << ',' << r->steps << ',' << r->cpu << ','
                    << r->final_error << ',' << r->max_energy_error << '\n'
                    << std::flush;
        else
          std::cout << std::left << std::setw(42) << r->method << std::right << std::setprecision(4) << std::setw(12)
                    << r->tau << std::setw(10) << r->steps << std::setw(12) << r->cpu << std::setw(12) << r->final_error
                    << std::setw(12) << r->max_energy_error << "\n"
                    << std::flush;
        if (r->final_error < 1e-13 || r->cpu > o.max_seconds) break;
        if (r->final_error >= prev_error && r->final_error < 1e-6) {
          if (++worse >= 2) break;  // round-off floor
        } else {
          worse = 0;
        }
        prev_error = std::min(prev_error, r->final_error);
      }
      // Next step count: tau / sqrt(2).
      steps = std::max(steps + 1, std::lround(double(steps) * std::sqrt(2.0)));
    }
  }
  // Summary.
  const char* pre = o.csv ? "# " : "";
  std::cout << pre << "summary (" << Problem::name << ", T = " << o.t_end
            << "): CPU seconds at final error, log-log interpolation between measured points\n";
  for (const double target : {1e-10, 1e-6}) {
    std::optional<double> best_g, best_o;
    std::string name_g = "none", name_o = "none";
    for (const auto& m : all) {
      const auto c = cpu_at(by_method[m.name], target);
      if (!c) continue;
      auto& best = m.odeint ? best_o : best_g;
      auto& name = m.odeint ? name_o : name_g;
      if (!best || *c < *best) {
        best = c;
        name = m.name;
      }
    }
    std::cout << pre << "  error " << std::setprecision(0) << std::scientific << target << std::defaultfloat
              << std::setprecision(4) << ": best geomint " << name_g << " ";
    if (best_g) std::cout << *best_g << " s"; else std::cout << "n/a";
    std::cout << ", fastest odeint " << name_o << " ";
    if (best_o) std::cout << *best_o << " s"; else std::cout << "n/a";
    if (best_g && best_o) {
      const double goal = target < 1e-8 ? 0.5 : 1.5;
      const double ratio = *best_g / *best_o;
      std::cout << ", ratio " << std::setprecision(3) << ratio << " (goal <= " << goal << ": "
                << (ratio <= goal ? "met" : "not met") << ")";
    }
    std::cout << "\n";
  }
  return 0;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

bool parse_positive(const std::string& s, double& out) {
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0' && std::isfinite(out) && out > 0;
}

}  // namespace

int main(int argc, char** argv) {
  settings o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    std::string v;
    if (a == "--csv") {
      o.csv = true;
    } else if (a == "--check-reference") {
      o.check_reference = true;
    } else if (a == "--help" || a == "-h") {
      std::cout << usage;
      return 0;
    } else if (a == "--system") {
      if (!value(v) || (v != "pendulum" && v != "kepler")) return fail("--system must be pendulum or kepler");
      o.system = v;
    } else if (a == "--t-end") {
      if (!value(v) || !parse_positive(v, o.t_end)) return fail("--t-end must be a number > 0");
    } else if (a == "--max-seconds") {
      if (!value(v) || !parse_positive(v, o.max_seconds)) return fail("--max-seconds must be a number > 0");
    } else if (a == "--methods") {
      if (!value(v) || split(v).empty()) return fail("--methods needs a comma-separated list of method names");
      o.only = split(v);
    } else {
      return fail("unknown argument '" + a + "'");
    }
  }
  try {
    return o.system == "kepler" ? run_all<kepler_problem>(o) : run_all<pendulum_problem>(o);
  } catch (const std::exception& e) {
    std::cerr << "geomint-workprecision: " << e.what() << "\n";
    return 1;
  }
}
