#pragma once
/// The precompiled header of every tool unit (tools/CMakeLists.txt): Eigen and
/// Boost.Multiprecision, which every tool parses, are parsed once per build instead of once
/// per unit (about 5 s of GCC 12 CPU time per unit, docs/results/ci.md). Only third-party
/// headers go in here, so that each tool source still checks that the geomint headers it
/// includes are self-contained.
#include <Eigen/Dense>
#include <boost/multiprecision/cpp_bin_float.hpp>
