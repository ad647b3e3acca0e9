/// The Catch2 main for every test executable (Catch2 v3 brings its own).
#ifndef GEOMINT_CATCH3
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
#endif
