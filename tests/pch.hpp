#pragma once
/// The precompiled header of every Catch2 test executable (tests/CMakeLists.txt): Catch2, Eigen
/// and Boost.Multiprecision are parsed once per build instead of once per test source, which
/// saves several seconds of compile time per source. Only third-party headers go in here (CMake
/// marks the precompiled header as a system header, which silences its warnings), so the
/// geomint headers keep their warnings and each test still checks that the geomint headers it
/// includes are self-contained.
#include <Eigen/Dense>
#include <boost/multiprecision/cpp_bin_float.hpp>
#ifdef GEOMINT_HAVE_MPFR
#include <boost/multiprecision/mpfr.hpp>
#endif

#include "catch.hpp"
