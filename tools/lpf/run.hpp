#pragma once
/// geomint-run: the front end of the free systems is the installed `run` (geomint/cli/run.hpp);
/// the constrained systems have an entry point per (system, scalar), one translation unit each.
#include "geomint/cli/run.hpp"

namespace geomint::run {

using options = cli::run_options;
using cli::parse_scalar;
using cli::report_failure;
using cli::run_monitor;

/// The constrained systems; one translation unit per (system, digits) (run_constrained_tu.cpp).
enum class constrained_system { circle, spherical };
template <constrained_system System, int Digits>
int run_constrained(const options&);

}  // namespace geomint::run
