#pragma once
/// geomint-workprecision: the two regimes and the entry points per (problem, digits).
#include "measurement.hpp"

namespace geomint::workprecision {

/// double over T = 1000, errors 1e-6..1e-13; goals at 1e-10 (1/2) and 1e-12 (1/3).
inline regime regime_16() { return {16, 1000, 1e-13, {{1e-10, 0.5}, {1e-12, 1.0 / 3.0}}, {1e-6}}; }
/// cpp_bin_float_50 over T = 100, errors 1e-15..1e-40; goal at 1e-30 (1/10).
inline regime regime_50() { return {50, 100, 1e-40, {{1e-30, 0.1}}, {1e-20, 1e-35}}; }

int run_pendulum_16(const settings&);
int run_pendulum_50(const settings&);
int run_kepler_16(const settings&);
int run_kepler_50(const settings&);

}  // namespace geomint::workprecision
