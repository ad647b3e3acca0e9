#pragma once
/// geomint-run: options and the entry points per scalar (free systems) and per (constrained
/// system, scalar) (one translation unit each).
#include <string>
#include <vector>

namespace geomint::run {

struct options {
  std::string system = "harmonic";
  std::string scheme = "lpf";
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
};

#define GEOMINT_RUN_DECLARE(sys, digits) int run_##sys##_##digits(const options&);
#define GEOMINT_RUN_FOR_DIGITS(sys) GEOMINT_RUN_DECLARE(sys, 16) GEOMINT_RUN_DECLARE(sys, 50) GEOMINT_RUN_DECLARE(sys, 100)
GEOMINT_RUN_FOR_DIGITS(free)  // harmonic, pendulum, kepler, charged (run_free.cpp)
GEOMINT_RUN_FOR_DIGITS(circle)
GEOMINT_RUN_FOR_DIGITS(spherical)
#undef GEOMINT_RUN_FOR_DIGITS
#undef GEOMINT_RUN_DECLARE

}  // namespace geomint::run
