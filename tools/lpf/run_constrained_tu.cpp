/// One (constrained system, digits) entry point of geomint-run (see CMakeLists.txt).
#include <iostream>

#if GEOMINT_RUN_STUB
#include "run.hpp"
#else
#include "run_constrained.hpp"
#endif

#if !defined(GEOMINT_RUN_SYSTEM) || !defined(GEOMINT_RUN_DIGITS)
#error "define GEOMINT_RUN_SYSTEM and GEOMINT_RUN_DIGITS"
#endif

namespace geomint::run {

template <constrained_system System, int Digits>
int run_constrained(const options& o) {
#if GEOMINT_RUN_STUB
  // Left out of the build: GEOMINT_RUN_MULTIPRECISION=OFF, or not in GEOMINT_TOOL_UNITS.
  (void)o;
  std::cerr << "geomint-run: this constrained system in --digits " << Digits
            << " is not compiled into this build (GEOMINT_RUN_MULTIPRECISION=OFF or GEOMINT_TOOL_UNITS)\n";
  return 2;
#else
  using T = cli::scalar_for_digits<Digits>;
  if constexpr (System == constrained_system::circle)
    return run_constrained_system<systems::free_particle_2d, systems::unit_circle, T>(o);
  else
    return run_constrained_system<systems::spherical_pendulum, systems::unit_sphere, T>(o);
#endif
}

template int run_constrained<constrained_system::GEOMINT_RUN_SYSTEM, GEOMINT_RUN_DIGITS>(const options&);

}  // namespace geomint::run
