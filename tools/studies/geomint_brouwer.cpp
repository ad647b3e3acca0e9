/// geomint-brouwer: how the round-off of the energy grows over long runs in double (Brouwer's
/// law: like t^(1/2) for a random walk, like t for a systematic drift), for LPF m = 8 on
/// Gauss-interior nodes in its Newton form (schemes/lpf.hpp) and in its fixed-point form with
/// exactly symplectic coefficients (schemes/gauss_fixed_point.hpp), each with plain and with
/// compensated summation of the update. Every configuration runs the same ensemble of initial
/// states; the table gives the growth exponent of the ensemble RMS of |E - E0| per window
/// (tools/common/energy_growth.hpp), from step 2^10 and from step 2^16 on.
#include <algorithm>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "energy_growth.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "progress.hpp"

namespace {

constexpr const char* usage =
    "usage: geomint-brouwer [--system pendulum|harmonic] [--steps N] [--trajectories K] [--tau X]\n"
    "                       [--windows]\n"
    "\n"
    "Runs LPF m = 8 on Gauss-interior nodes (Newton form and fixed-point form, each with plain and\n"
    "compensated summation) in double over N steps (default 10^7, at most 10^9) from K initial\n"
    "states (default 4, at most 64): q0 = 1 + k/64, at rest (work: 4 N K steps, at most 2.56e11).\n"
    "Prints per configuration the growth exponent of the ensemble RMS energy error (windows of\n"
    "steps [2^j, 2^(j+1)) from 2^10 and from 2^16 on), the largest |E - E0|, the fixed-point or\n"
    "Newton iterations per step and the CPU microseconds per step. --windows adds the ensemble\n"
    "RMS of every window.\n";

struct result {
  std::string name;
  geomint::tools::energy_growth growth;
  double max_error = 0, cpu_seconds = 0;
  long iterations = 0, steps = 0;
  bool failed = false;
};

template <class Scheme, class Sys>
result measure(const std::string& name, bool compensated, long steps, int trajectories, double tau,
               geomint::tools::progress& bar) {
  result r;
  r.name = name + (compensated ? ", compensated" : ", plain");
  for (int k = 0; k < trajectories; ++k) {
    geomint::integrator<Scheme, Sys, double> I(Sys{}, tau);
    I.set_compensated_summation(compensated);
    auto s = I.initial_state(geomint::vec<double, 1>(1.0 + static_cast<double>(k) / 64), geomint::vec<double, 1>(0.0));
    const double E0 = I.energy(s);
    const std::clock_t start = std::clock();
    for (long step = 1; step <= steps; ++step) {
      const geomint::step_status st = I.try_step(s);
      if (!st) {
        std::cerr << "geomint-brouwer: " << r.name << ": " << st.message() << '\n';
        r.failed = true;
        return r;
      }
      r.iterations += st.iterations;
      const double dE = std::abs(I.energy(s) - E0);
      r.max_error = std::max(r.max_error, dE);
      r.growth.add(step, dE);
      if (step % 4096 == 0) bar.advance(4096);  // (a terminal only; not per step: the step is timed)
    }
    r.cpu_seconds += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    r.steps += steps;
  }
  return r;
}

template <class Sys>
std::vector<result> run_all(long steps, int trajectories, double tau) {
  using namespace geomint;
  std::vector<result> all;
  tools::progress bar("geomint-brouwer", static_cast<std::size_t>(4 * trajectories * steps), "steps");
  for (bool compensated : {false, true}) {
    all.push_back(measure<lpf<8, gauss_interior, lagrange, newton_solver>, Sys>("lpf m = 8, Newton form", compensated, steps, trajectories, tau, bar));
    all.push_back(measure<lpf_fixed_point<8>, Sys>("lpf m = 8, fixed-point form", compensated, steps, trajectories, tau, bar));
  }
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = geomint::cli;
  std::string system = "pendulum";
  long steps = 10'000'000L;
  int trajectories = 4;
  double tau = 0.1;
  bool windows = false;
  cli::parser cl("geomint-brouwer", usage);
  cl.value("--system", [&](const std::string& v) { system = cli::parse_choice("--system", v, {"pendulum", "harmonic"}); })
      .value("--steps", [&](const std::string& v) { steps = cli::parse_integer<long>("--steps", v, 1, 1'000'000'000L); })
      .value("--trajectories", [&](const std::string& v) { trajectories = cli::parse_integer<int>("--trajectories", v, 1, 64); })
      .value("--tau", [&](const std::string& v) { tau = cli::parse_real("--tau", v, cli::real_bound::positive); })
      .toggle("--windows", [&] { windows = true; });
  if (const auto done = cl.parse(argc, argv)) return *done;
  try {
    const std::vector<result> all = system == "pendulum"
                                        ? run_all<geomint::systems::pendulum>(steps, trajectories, tau)
                                        : run_all<geomint::systems::harmonic>(steps, trajectories, tau);
    std::cout << "system=" << system << " tau=" << tau << " steps=" << steps << " trajectories=" << trajectories << '\n';
    std::cout << "method,exponent_from_2^10,exponent_from_2^16,max_energy_error,iterations_per_step,us_per_step\n";
    int status = cli::exit_ok;
    for (const result& r : all) {
      if (r.failed) {
        status = cli::exit_run_failure;
        continue;
      }
      auto fmt = [](const std::optional<std::pair<double, int>>& e) {
        if (!e) return std::string("undefined");
        std::ostringstream o;
        o << std::fixed << std::setprecision(3) << e->first;
        return o.str();
      };
      std::cout << r.name << ',' << fmt(r.growth.exponent(tau)) << ',' << fmt(r.growth.exponent(tau, 16)) << ','
                << std::scientific << std::setprecision(2) << r.max_error << ',' << std::fixed << std::setprecision(2)
                << static_cast<double>(r.iterations) / static_cast<double>(r.steps) << ',' << std::setprecision(3)
                << 1e6 * r.cpu_seconds / static_cast<double>(r.steps) << '\n';
    }
    if (windows) {
      std::cout << "method,window,steps_from,t_mid,rms_energy_error\n";
      for (const result& r : all)
        for (std::size_t j = 0; j < r.growth.count.size(); ++j)
          if (r.growth.count[j] != 0)
            std::cout << r.name << ',' << j << ',' << (1L << j) << ',' << std::defaultfloat << std::setprecision(6)
                      << geomint::tools::energy_growth::t_mid(j, tau) << ',' << std::scientific << std::setprecision(3)
                      << r.growth.rms(j) << '\n';
    }
    return cli::finish_stdout("geomint-brouwer", status);
  } catch (const std::exception& e) {
    std::cerr << "geomint-brouwer: " << e.what() << '\n';
    return cli::finish_stdout("geomint-brouwer", 1);
  }
}
