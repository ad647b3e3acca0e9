/// One (system, digits) instantiation of the stepper factory (see CMakeLists.txt).
#include "stepper_impl.hpp"

#if !defined(GEOMINT_STEPPER_SYSTEM) || !defined(GEOMINT_STEPPER_DIGITS)
#error "define GEOMINT_STEPPER_SYSTEM and GEOMINT_STEPPER_DIGITS"
#endif

namespace geomint::tools {
using scalar = scalar_for_digits<GEOMINT_STEPPER_DIGITS>;
template std::unique_ptr<stepper<scalar>> make_system_stepper<systems::GEOMINT_STEPPER_SYSTEM, scalar>(const scheme_spec&);
}  // namespace geomint::tools
