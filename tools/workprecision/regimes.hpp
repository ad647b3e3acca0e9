#pragma once
/// geomint-workprecision: the two regimes and the entry point per (problem, digits).
#include "measurement.hpp"
#include "problems.hpp"

namespace geomint::workprecision {

/// double over T = 1000, errors 1e-6..1e-13; goals at 1e-10 (1/2) and 1e-12 (1/3).
inline regime regime_16() { return {16, 1000, 1e-13, {{1e-10, 0.5}, {1e-12, 1.0 / 3.0}}, {1e-6}}; }
/// cpp_bin_float_50 over T = 100, errors 1e-15..1e-40; goal at 1e-30 (1/10).
inline regime regime_50() { return {50, 100, 1e-40, {{1e-30, 0.1}}, {1e-20, 1e-35}}; }

/// The sweeps of one (problem, digits) pair, defined in regime.cpp (one translation unit per digits).
template <class Problem, int Digits>
int run_regime(const settings&);
/// The 50 digits' regime in libqd's dd_real (--scalar dd_real), where libqd is found
/// (GEOMINT_HAVE_QD).
template <class Problem>
int run_regime_double_double(const settings&);

}  // namespace geomint::workprecision
