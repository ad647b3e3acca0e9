#pragma once
/// geomint-run: options and the entry points per scalar (free systems) and per (constrained
/// system, scalar), one translation unit each.
#include <string>
#include <vector>

namespace geomint::run {

struct options {
  std::string system = "harmonic";
  std::string scheme = "lpf";
  std::string tableau;  ///< --tableau FILE: the method of a tableau file instead of a built-in scheme
  std::string nodes = "equispaced";
  std::string basis = "lagrange";
  int m = 2;
  std::string tau = "0.1";
  long steps = 100;
  long every = 1;
  std::vector<std::string> q0, p0;  ///< empty: the system's default initial data
  int digits = 16;
  bool csv = false;
  bool monitor = true;  ///< the step monitor (geomint/solvers/step_monitor.hpp); --no-monitor turns it off
  bool compensated = false;  ///< --compensated: compensated summation of the q, p update
  bool growth = false;       ///< --growth: fit the exponent of the energy error's growth in t
  bool estimate = false;     ///< --estimate: Richardson's estimate of the global error (run at tau/2)
};

/// The free systems (the built-in harmonic, pendulum, kepler, charged and the zoo systems of
/// tools/common/stepper.hpp) in the scalar of `--digits D` (run_free.cpp).
template <int Digits>
int run_free(const options&);

/// The constrained systems; one translation unit per (system, digits) (run_constrained_tu.cpp).
enum class constrained_system { circle, spherical };
template <constrained_system System, int Digits>
int run_constrained(const options&);

}  // namespace geomint::run
