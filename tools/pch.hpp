#pragma once
/// The precompiled header of the tool units (tools/CMakeLists.txt): Eigen and
/// Boost.Multiprecision, which every tool parses, are parsed once per optimisation level instead
/// of once per unit (GCC 12: about 2.3 s of CPU time per unit; scripts/compile_times.sh). Only third-party
/// headers go in here, so that each tool source still checks that the geomint headers it
/// includes are self-contained.
#include <Eigen/Dense>
#include <boost/multiprecision/cpp_bin_float.hpp>
