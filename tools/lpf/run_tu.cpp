/// One (system, digits) entry point of geomint-run; compiled once per pair (see CMakeLists.txt).
#if GEOMINT_RUN_STUB
#include <iostream>

#include "run.hpp"
#else
#include "run_impl.hpp"
#endif

#if !defined(GEOMINT_RUN_SYSTEM) || !defined(GEOMINT_RUN_DIGITS)
#error "define GEOMINT_RUN_SYSTEM and GEOMINT_RUN_DIGITS"
#endif

#if GEOMINT_RUN_STUB
namespace geomint::run {
/// Built with GEOMINT_RUN_MULTIPRECISION=OFF: this scalar type is not compiled in.
#define GEOMINT_RUN_STUB_CAT2(a, b, c) run_##a##_##c
#define GEOMINT_RUN_STUB_CAT(a, c) GEOMINT_RUN_STUB_CAT2(a, _, c)
int GEOMINT_RUN_STUB_CAT(GEOMINT_RUN_SYSTEM, GEOMINT_RUN_DIGITS)(const options&) {
  std::cerr << "geomint-run: --digits " << GEOMINT_RUN_DIGITS
            << " is not compiled into this build (configured with GEOMINT_RUN_MULTIPRECISION=OFF)\n";
  return 2;
}
}  // namespace geomint::run
#else
namespace geomint::run {
namespace {
#if GEOMINT_RUN_DIGITS == 16
using scalar = double;
#elif GEOMINT_RUN_DIGITS == 50
using scalar = boost::multiprecision::cpp_bin_float_50;
#else
using scalar = boost::multiprecision::cpp_bin_float_100;
#endif
}  // namespace

#define GEOMINT_RUN_CAT2(a, b, c) run_##a##_##c
#define GEOMINT_RUN_CAT(a, c) GEOMINT_RUN_CAT2(a, _, c)
int GEOMINT_RUN_CAT(GEOMINT_RUN_SYSTEM, GEOMINT_RUN_DIGITS)(const options& o) {
  return run_system<systems::GEOMINT_RUN_SYSTEM, scalar>(o);
}
}  // namespace geomint::run
#endif
