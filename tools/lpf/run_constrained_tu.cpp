/// One (constrained system, digits) entry point of geomint-run (see CMakeLists.txt).
#if GEOMINT_RUN_STUB
#include <iostream>

#include "run.hpp"
#else
#include "run_constrained.hpp"
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
using scalar = tools::scalar_for_digits<GEOMINT_RUN_DIGITS>;
struct circle {
  using system = systems::free_particle_2d;
  using constraints = systems::unit_circle;
};
struct spherical {
  using system = systems::spherical_pendulum;
  using constraints = systems::unit_sphere;
};
}  // namespace

#define GEOMINT_RUN_CAT2(a, b, c) run_##a##_##c
#define GEOMINT_RUN_CAT(a, c) GEOMINT_RUN_CAT2(a, _, c)
int GEOMINT_RUN_CAT(GEOMINT_RUN_SYSTEM, GEOMINT_RUN_DIGITS)(const options& o) {
  using choice = GEOMINT_RUN_SYSTEM;
  return run_constrained_system<choice::system, choice::constraints, scalar>(o);
}
}  // namespace geomint::run
#endif
