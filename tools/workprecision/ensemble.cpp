/// geomint-ensemble: work-precision of many trajectories in double, stepped together one per
/// SIMD lane (geomint/ensemble.hpp) or one by one by the scalar integrator, on the ensembles of
/// ensemble_data.hpp. For each method a ladder of step sizes tau = T / steps (steps growing by
/// 2^(1/4)); each run integrates every trajectory to T and is timed (CPU time, the fastest of
/// repeated runs); its error is the largest final phase error |(q, qdot) - (q, qdot)_ref| over
/// the trajectories. References: the pendulum's closed form in cpp_bin_float_50, Henon-Heiles'
/// Taylor-series flow in long double (analysis/reference_flow.hpp: accelerations in closed form).
#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "ensemble_data.hpp"
#include "geomint/cli/parser.hpp"
#include "geomint/ensemble.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "points.hpp"

namespace {

namespace wp = geomint::workprecision;

struct options {
  std::string system = "pendulum";
  int trajectories = 1024;
  double t_end = 1000;
  std::uint64_t seed = 1;
  bool csv = false;
  double max_seconds = 2;
  int passes = 2;
  std::vector<std::string> only;
};

/// A method: integrates the states (q, p = qdot: unit mass) in place `steps` times with tau.
template <int n>
using method_run = std::function<void(std::vector<geomint::phase_state<double, n>>&, double, long)>;

template <int n>
struct method {
  std::string name;
  method_run<n> run;
};

/// The sweeps' stopping rule: on the fixed point (the scalar integrator's default) or also on
/// the contraction rate (newton_options::stop_on_rate; the variants "-stop-on-rate").
geomint::newton_options<double> options_with(bool stop_on_rate) {
  geomint::newton_options<double> opt;
  opt.stop_on_rate = stop_on_rate;
  return opt;
}
std::string suffix(bool stop_on_rate) { return stop_on_rate ? "-stop-on-rate" : ""; }

template <class Sys, int M>
method<Sys::dof> ensemble_method(bool stop_on_rate) {
  return {"ensemble-m" + std::to_string(M) + suffix(stop_on_rate),
          [stop_on_rate](std::vector<geomint::phase_state<double, Sys::dof>>& s, double tau, long steps) {
            const geomint::ensemble_integrator<M, Sys> e(tau, options_with(stop_on_rate));
            e.integrate(s, steps);
          }};
}

/// The scalar integrator (LPF on Gauss-interior nodes, its default solver, compensated
/// summation as the ensemble), one trajectory after the other with a cache each.
template <class Sys, int M>
method<Sys::dof> one_by_one_method(bool stop_on_rate) {
  return {"one-by-one-m" + std::to_string(M) + suffix(stop_on_rate),
          [stop_on_rate](std::vector<geomint::phase_state<double, Sys::dof>>& s, double tau, long steps) {
            geomint::integrator<geomint::lpf<M, geomint::gauss_interior>, Sys, double> I(Sys{}, tau, options_with(stop_on_rate));
            I.set_compensated_summation(true);
            for (auto& x : s) {
              typename decltype(I)::cache_type cache{};
              for (long k = 0; k < steps; ++k) {
                const geomint::step_status st = I.try_step(x, cache);
                if (!st) throw geomint::integration_error(st);
              }
            }
          }};
}

template <int n>
std::vector<geomint::phase_state<double, n>> states_of(const std::vector<wp::ensemble_state>& x0) {
  std::vector<geomint::phase_state<double, n>> s(x0.size());
  for (std::size_t k = 0; k < x0.size(); ++k)
    for (int i = 0; i < n; ++i) {
      s[k].q[i] = x0[k][static_cast<std::size_t>(i)];
      s[k].p[i] = x0[k][static_cast<std::size_t>(n + i)];
    }
  return s;
}

template <int n>
double largest_error(const std::vector<geomint::phase_state<double, n>>& s, const wp::final_states& ref) {
  std::vector<wp::ensemble_state> x(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    for (int i = 0; i < n; ++i) x[k].push_back(s[k].q[i]);
    for (int i = 0; i < n; ++i) x[k].push_back(s[k].p[i]);  // unit mass: p = qdot
  }
  return wp::largest_error(x, ref);
}

/// The fastest of repeated timed runs (at least 2, until 0.2 s are spent), CPU seconds per
/// trajectory; the states of the last run in `out`.
template <int n>
double timed(const method<n>& m, const std::vector<geomint::phase_state<double, n>>& start, double tau, long steps,
             std::vector<geomint::phase_state<double, n>>& out) {
  double best = std::numeric_limits<double>::infinity(), spent = 0;
  for (int rep = 0; rep < 10; ++rep) {
    out = start;
    const double t0 = wp::cpu_now();
    m.run(out, tau, steps);
    const double dt = wp::cpu_now() - t0;
    best = std::min(best, dt);
    spent += dt;
    if (rep >= 1 && spent > 0.2) break;
  }
  return best / static_cast<double>(start.size());
}

template <class Sys>
int run(const options& o) {
  constexpr int n = Sys::dof;
  const auto x0 = wp::ensemble_initial_states(o.system, o.trajectories, o.seed);
  const wp::final_states ref = wp::references<Sys>(x0, o.t_end);
  const auto start = states_of<n>(x0);
  std::vector<method<n>> all;
  for (bool rate : {false, true}) {
    all.push_back(ensemble_method<Sys, 8>(rate));
    all.push_back(ensemble_method<Sys, 10>(rate));
    all.push_back(ensemble_method<Sys, 12>(rate));
  }
  for (bool rate : {false, true}) {
    all.push_back(one_by_one_method<Sys, 10>(rate));
    all.push_back(one_by_one_method<Sys, 12>(rate));
  }
  std::vector<std::vector<wp::result>> results;
  for (const method<n>& m : all) {
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), m.name) == o.only.end()) continue;
    std::vector<wp::result> pts;
    double previous = std::numeric_limits<double>::infinity();
    int worse = 0;
    // tau from T/100 (the pendulum's period is 6.3 to 11.6) down by 2^(1/4) per run.
    for (long knob = 0; knob < 64; ++knob) {
      const long steps = std::lround(o.t_end / 10 * std::pow(2.0, 2.5 + double(knob) / 4));
      const double tau = o.t_end / double(steps);
      std::vector<geomint::phase_state<double, n>> out;
      wp::result r;
      try {
        r.cpu = timed(m, start, tau, steps, out);
      } catch (const std::exception& e) {
        std::cerr << "geomint-ensemble: " << m.name << " at tau = " << tau << ": " << e.what() << " (skipped)\n";
        continue;
      }
      r.method = m.name;
      r.knob = knob;
      r.tau = tau;
      r.steps = steps;
      r.final_error = largest_error<n>(out, ref);
      pts.push_back(r);
      if (r.final_error < 1e-13 || r.cpu * o.trajectories > o.max_seconds) break;
      if (r.final_error >= previous && ++worse >= 2) break;
      if (r.final_error < previous) worse = 0;
      previous = std::min(previous, r.final_error);
    }
    for (int pass = 2; pass <= o.passes; ++pass)
      for (wp::result& r : pts) {
        std::vector<geomint::phase_state<double, n>> out;
        r.cpu = std::min(r.cpu, timed(m, start, r.tau, r.steps, out));
      }
    results.push_back(std::move(pts));
  }
  if (o.csv) std::cout << "method,tau,steps,cpu_seconds_per_trajectory,max_final_error\n";
  else
    std::cout << "system " << o.system << ", " << o.trajectories << " trajectories (seed " << o.seed << "), T = " << o.t_end
              << ", double, " << geomint::ensemble_width << " lanes per pack; CPU time per trajectory, the fastest of " << o.passes
              << " passes\n"
              << std::left << std::setw(20) << "method" << std::right << std::setw(12) << "tau" << std::setw(10) << "steps"
              << std::setw(16) << "cpu/traj [s]" << std::setw(14) << "max error\n";
  for (const auto& pts : results)
    for (const wp::result& r : pts) {
      if (o.csv)
        std::cout << std::setprecision(6) << r.method << ',' << r.tau << ',' << r.steps << ',' << r.cpu << ',' << r.final_error << '\n';
      else
        std::cout << std::left << std::setw(20) << r.method << std::right << std::setprecision(4) << std::setw(12) << r.tau
                  << std::setw(10) << r.steps << std::setw(16) << r.cpu << std::setw(14) << r.final_error << "\n";
    }
  wp::print_ensemble_summary(std::cout, o.system, o.trajectories, results, o.csv);
  return 0;
}

const char* usage =
    "usage: geomint-ensemble [--system pendulum|henon-heiles] [--trajectories N (1..65536)] [--t-end T (0..10^5)]\n"
    "                        [--seed K] [--csv] [--max-seconds S (> 0)] [--passes N (1..10)] [--methods a,b,...]\n"
    "Work-precision of ensembles in double: N trajectories (default 1024) from random initial data\n"
    "(pendulum: released from rest at 0.1..2.5 rad; henon-heiles: from the origin with energies\n"
    "1/24..1/12 in random directions; seed K, default 1) to T (default 1000), by\n"
    "  ensemble-m8, -m10, -m12: geomint::ensemble_integrator (LPF on Gauss-interior nodes, the\n"
    "      trajectories one per SIMD lane, compensated summation), and\n"
    "  one-by-one-m10, -m12: the scalar integrator lpf<m, gauss_interior>, one trajectory after\n"
    "      the other, with a cache each and compensated summation;\n"
    "  each also as NAME-stop-on-rate: sweeps that stop on their contraction rate as well.\n"
    "Each method runs a ladder of fixed step sizes tau = T/steps (steps growing by 2^(1/4)) until the\n"
    "largest final error over the trajectories is below 1e-13, stops improving, or one run takes more\n"
    "than S CPU seconds (default 2). The error is |(q, qdot) - (q, qdot)_ref| at T, the reference the\n"
    "pendulum's closed form in 50 digits or Henon-Heiles' Taylor-series flow in long double.\n"
    "--csv prints method,tau,steps,cpu_seconds_per_trajectory,max_final_error and the summary as '#'\n"
    "lines. Exit status: 0, 2 (bad command line), 1 (failure), 4 (output failed).\n";

}  // namespace

int main(int argc, char** argv) {
  options o;
  geomint::cli::parser cl("geomint-ensemble", usage);
  cl.toggle("--csv", [&] { o.csv = true; })
      .value("--system", [&](const std::string& v) { o.system = geomint::cli::parse_choice("--system", v, {"pendulum", "henon-heiles"}); })
      .value("--trajectories", [&](const std::string& v) { o.trajectories = geomint::cli::parse_integer<int>("--trajectories", v, 1, 65536); })
      .value("--t-end",
             [&](const std::string& v) {
               o.t_end = geomint::cli::parse_real("--t-end", v, geomint::cli::real_bound::positive);
               if (o.t_end > 1e5) throw geomint::cli::usage_error("--t-end is out of range: '" + v + "' (expected T <= 10^5)");
             })
      .value("--seed", [&](const std::string& v) { o.seed = geomint::cli::parse_integer<std::uint64_t>("--seed", v, 0, ~std::uint64_t(0)); })
      .value("--max-seconds",
             [&](const std::string& v) { o.max_seconds = geomint::cli::parse_real("--max-seconds", v, geomint::cli::real_bound::positive); })
      .value("--passes", [&](const std::string& v) { o.passes = geomint::cli::parse_integer<int>("--passes", v, 1, 10); })
      .value("--methods", [&](const std::string& v) { o.only = geomint::cli::split_list("--methods", v); });
  if (const auto done = cl.parse(argc, argv)) return *done;
  try {
    const int status = o.system == "pendulum" ? run<geomint::systems::pendulum>(o) : run<geomint::zoo::henon_heiles>(o);
    return geomint::cli::finish_stdout("geomint-ensemble", status);
  } catch (const std::exception& e) {
    std::cerr << "geomint-ensemble: " << e.what() << "\n";
    return geomint::cli::finish_stdout("geomint-ensemble", 1);
  }
}
