/// One (system, digits) instantiation of the tools' stepper factory (see CMakeLists.txt).
#include <stdexcept>
#include <string>

#include "stepper.hpp"

#if !defined(GEOMINT_STEPPER_SYSTEM) || !defined(GEOMINT_STEPPER_DIGITS)
#error "define GEOMINT_STEPPER_SYSTEM and GEOMINT_STEPPER_DIGITS"
#endif

namespace geomint::tools {

template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_stepper(const scheme_spec& spec) {
#if GEOMINT_STEPPER_STUB
  (void)spec;
  throw std::invalid_argument(std::to_string(std::numeric_limits<T>::digits10) +
                              "-digit arithmetic is not compiled into this build (GEOMINT_RUN_MULTIPRECISION=OFF)");
#else
  return geomint::make_stepper<Sys, T>(spec);
#endif
}

using scalar = scalar_for_digits<GEOMINT_STEPPER_DIGITS>;
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<systems::GEOMINT_STEPPER_SYSTEM, scalar>(const scheme_spec&);

}  // namespace geomint::tools
