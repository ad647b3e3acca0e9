#pragma once
/// geomint-workprecision, measurement: for every method a sweep of runs (steps growing by
/// 2^(1/4), or tolerances by 10^(1/4)), each a timed pass of the stepping loop alone
/// (CLOCK_PROCESS_CPUTIME_ID; short runs repeated and the fastest kept) and an untimed pass
/// that monitors the energy; then further timing passes over every run of every method (the
/// fastest kept: a machine that slows down for seconds slows one pass, not the others); then
/// the summary at the regime's target errors.
#include <algorithm>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geomint/core/checked_cast.hpp"
#include "methods.hpp"
#include "progress.hpp"

namespace geomint::workprecision {

/// The two regimes of --digits.
struct regime {
  int digits = 16;
  double t_end = 1000;
  double floor = 1e-13;  ///< a sweep stops below this final error
  struct goal {
    double error, ratio;
  };
  std::vector<goal> goals;     ///< best geomint / best peer CPU time at these errors
  std::vector<double> others;  ///< further errors reported without a goal
};

struct settings {
  std::string system = "pendulum";
  int digits = 16;
  std::string scalar = "double";  ///< --scalar (its default: double, or cpp_bin_float_50 for --digits 50)
  bool csv = false;
  std::optional<double> t_end;
  std::optional<double> max_seconds;
  std::vector<std::string> only;
  int passes = 2;           ///< timing passes over all runs (--passes)
  bool compensated = true;  ///< geomint's schemes with compensated summation (--plain-summation: off)
};

/// |(q, p) - (q, p)_ref| (Euclidean) in the reference scalar R.
template <class R, class T, int n>
double phase_error(const arr<T, n>& q, const arr<T, n>& p, const analysis::closed_form_state<R, n>& ref) {
  R sum(0);
  for (std::size_t i = 0; i < std::size_t(n); ++i) {
    const R dq = widen<R>(q[i]) - ref.q[i], dp = widen<R>(p[i]) - ref.p[i];
    sum += dq * dq + dp * dp;
  }
  using std::sqrt;
  return static_cast<double>(R(sqrt(sum)));
}

/// The fastest of repeated timed runs (at least 3, up to 20 or 0.05 s of CPU time), the final
/// state in q, p and the steps taken; nullopt if a run fails. Each run has max_seconds of CPU
/// time (run_budget); one that needs more throws run_stopped.
template <class P, class T>
std::optional<double> fastest_run(const method<T, P::n>& m, long knob, const T& t_end, arr<T, P::n>& q,
                                  arr<T, P::n>& p, long& steps, double max_seconds) {
  double best = std::numeric_limits<double>::infinity(), spent = 0;
  for (int rep = 0; rep < 20; ++rep) {
    q = P::template q0<T>();
    p = P::template v0<T>();
    run_budget::current().start(max_seconds);
    const double t0 = cpu_now();
    steps = m.run(knob, t_end, q, p, nullptr);
    const double dt = cpu_now() - t0;
    if (steps < 0) return std::nullopt;
    best = std::min(best, dt);
    spent += dt;
    if (spent > 0.2 || (rep >= 2 && spent > 0.05)) break;
  }
  return best;
}

/// One point of a sweep: the fastest timed run and an untimed, monitored run (the monitor
/// costs time of its own: that run has four times the budget).
template <class P, class T, class R>
std::optional<result> measure(const method<T, P::n>& m, long knob, const T& t_end,
                              const analysis::closed_form_state<R, P::n>& ref, double max_seconds) {
  constexpr int n = P::n;
  result r;
  r.method = m.name;
  r.knob = knob;
  arr<T, n> q{}, p{};
  long steps = 0;
  const auto best = fastest_run<P, T>(m, knob, t_end, q, p, steps, max_seconds);
  if (!best) return std::nullopt;
  r.cpu = *best;
  r.steps = steps;
  r.tau = to_double(T(t_end / from_int64<T>(std::max(1L, steps))));
  r.final_error = phase_error<R, T, P::n>(q, p, ref);
  arr<T, n> q2 = P::template q0<T>(), p2 = P::template v0<T>();
  const T E0 = P::energy(q2, p2);
  T worst(0);
  const monitor_fn<T, n> monitor = [&](const arr<T, n>& qq, const arr<T, n>& pp) {
    using std::abs;
    const T d = abs(T(P::energy(qq, pp) - E0));
    if (d > worst) worst = d;
  };
  run_budget::current().start(4 * max_seconds);
  if (m.run(knob, t_end, q2, p2, &monitor) < 0) return std::nullopt;
  r.max_energy_error = to_double(worst);
  return r;
}

template <class P, class T, class R>
int run_sweeps(const settings& o, const regime& g, std::vector<method<T, P::n>> all) {
  const double t_end_d = o.t_end.value_or(g.t_end * P::horizon);
  const double max_seconds = o.max_seconds.value_or(g.digits == 16 ? 1.0 : 4.0);
  // An integer T exactly in T and R (from its integer value, not through double).
  const auto whole = checked_integer<long>(t_end_d);
  const bool integer = whole && double(*whole) == t_end_d;
  const T t_end = integer ? from_int64<T>(*whole) : T(t_end_d);
  const auto ref = P::template exact<R>(integer ? R(*whole) : R(t_end_d));
  if (!o.only.empty()) {
    for (const auto& name : o.only)
      if (std::none_of(all.begin(), all.end(), [&](const auto& m) { return m.name == name; }))
        throw std::invalid_argument("unknown method '" + name + "' (see --help)");
    std::erase_if(all, [&](const auto& m) { return std::find(o.only.begin(), o.only.end(), m.name) == o.only.end(); });
  }
  const std::string scalar = o.scalar;
  std::map<std::string, std::vector<result>> by_method;
  tools::progress bar("geomint-workprecision", all.size() * static_cast<std::size_t>(o.passes), "ladders");
  for (const auto& m : all) {
    long knob = m.first;
    double prev_error = std::numeric_limits<double>::infinity();
    int worse = 0;
    for (int k = 0; k < 160; ++k) {  // 40 decades of tolerance, 40 doublings of steps
      std::optional<result> r;
      try {
        // Each run is stopped after S CPU seconds; the first of a sweep gets at least one second,
        // so that every method has its first point (which the sweep criteria then judge).
        r = measure<P, T, R>(m, knob, t_end, ref, k == 0 ? std::max(max_seconds, 1.0) : max_seconds);
      } catch (const run_stopped& e) {
        std::cerr << "geomint-workprecision: " << m.name << " at knob " << knob << ": " << e.what() << "; its sweep ends here\n";
        break;
      } catch (const std::exception& e) {
        std::cerr << "geomint-workprecision: " << m.name << " failed at knob " << knob << ": " << e.what() << " (skipped)\n";
        break;
      }
      if (!r) {
        std::cerr << "geomint-workprecision: " << m.name << " failed at knob " << knob << " (skipped)\n";
        if (m.kind == knob_kind::tolerance) break;  // the controller met round-off
      } else {
        by_method[m.name].push_back(*r);
        if (m.kind == knob_kind::none || r->final_error < g.floor || r->cpu > max_seconds) break;
        // Round-off floor: four runs without improvement, a factor sqrt 2 in tau (adaptive error
        // control is erratic: eight), or a tolerance below the scalar's precision.
        if (m.kind == knob_kind::tolerance && knob >= 4 * (g.digits - 2)) break;
        if (r->final_error >= prev_error && r->final_error < 1e-6) {
          if (++worse >= (m.kind == knob_kind::tolerance ? 8 : 4)) break;
        } else {
          worse = 0;
        }
        prev_error = std::min(prev_error, r->final_error);
      }
      if (m.kind == knob_kind::tolerance) ++knob;  // tolerance / 10^(1/4)
      else knob = std::max(knob + 1, std::lround(double(knob) * std::pow(2.0, 0.25)));
    }
    bar.advance();  // (a terminal only)
  }
  // The further timing passes: every run again, the fastest time kept.
  for (int pass = 2; pass <= o.passes; ++pass)
    for (const auto& m : all) {
      for (result& r : by_method[m.name]) {
        arr<T, P::n> q{}, p{};
        long steps = 0;
        try {
          if (const auto best = fastest_run<P, T>(m, r.knob, t_end, q, p, steps, std::max(max_seconds, 1.0)))
            r.cpu = std::min(r.cpu, *best);
        } catch (const run_stopped&) {  // slower this pass: the first pass's time stands
        }
      }
      bar.advance();
    }
  bar.finish();
  if (o.csv) std::cout << "method,tau,steps,cpu_seconds,final_error,max_energy_error\n";
  else
    std::cout << "system " << P::name << ", T = " << t_end_d << ", " << scalar
              << "; reference: " << P::reference
              << " in a wider scalar; CPU time: the fastest of " << o.passes
              << " timing passes\n"
              << std::left << std::setw(36) << "method" << std::right << std::setw(12) << "tau" << std::setw(10)
              << "steps" << std::setw(12) << "cpu [s]" << std::setw(12) << "final err" << std::setw(12) << "max dE"
              << "\n";
  for (const auto& m : all)
    for (const result& r : by_method[m.name]) {
      if (o.csv)
        std::cout << std::setprecision(6) << r.method << ',' << r.tau << ',' << r.steps << ',' << r.cpu << ','
                  << r.final_error << ',' << r.max_energy_error << '\n';
      else
        std::cout << std::left << std::setw(36) << r.method << std::right << std::setprecision(4) << std::setw(12) << r.tau
                  << std::setw(10) << r.steps << std::setw(12) << r.cpu << std::setw(12) << r.final_error << std::setw(12)
                  << r.max_energy_error << "\n";
    }
  const char* pre = o.csv ? "# " : "";
  std::cout << pre << "summary (" << P::name << ", " << scalar << ", T = " << t_end_d << "; reference: " << P::reference
            << "): CPU seconds at final error, log-log interpolation between measured points\n";
  auto report = [&](double target, std::optional<double> goal) {
    std::optional<double> best_g, best_p;
    std::string name_g = "none", name_p = "none";
    for (const auto& m : all) {
      const auto c = cpu_at(by_method[m.name], target);
      if (!c) continue;
      auto& best = m.peer ? best_p : best_g;
      auto& name = m.peer ? name_p : name_g;
      if (!best || *c < *best) {
        best = c;
        name = m.name;
      }
    }
    std::cout << pre << "  error " << std::setprecision(0) << std::scientific << target << std::defaultfloat
              << std::setprecision(4) << ": best geomint " << name_g << " ";
    if (best_g) std::cout << *best_g << " s";
    else std::cout << "n/a";
    std::cout << ", best peer " << name_p << " ";
    if (best_p) std::cout << *best_p << " s";
    else std::cout << "n/a";
    if (best_g && best_p) {
      const double ratio = *best_g / *best_p;
      std::cout << ", ratio " << std::setprecision(3) << ratio;
      if (goal) std::cout << " (goal <= " << *goal << ": " << (ratio <= *goal ? "met" : "not met") << ")";
    }
    std::cout << "\n";
  };
  for (const auto& goal : g.goals) report(goal.error, P::goals ? std::optional<double>(goal.ratio) : std::nullopt);
  for (double e : g.others) report(e, std::nullopt);
  // A study without a single measured run is a failure, not a table (main.cpp: exit status 3).
  if (std::all_of(all.begin(), all.end(), [&](const auto& m) { return by_method[m.name].empty(); })) return -1;
  return 0;
}

}  // namespace geomint::workprecision
