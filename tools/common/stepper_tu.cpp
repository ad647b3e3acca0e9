/// The tools' stepper factory, instantiated for the four built-in systems (with
/// GEOMINT_STEPPER_HIGH_M their degrees 9..16) or for all zoo systems (GEOMINT_STEPPER_ZOO), in
/// the scalar of GEOMINT_STEPPER_DIGITS (see CMakeLists.txt).
#include <stdexcept>
#include <string>

#include "stepper.hpp"

#if !defined(GEOMINT_STEPPER_DIGITS)
#error "define GEOMINT_STEPPER_DIGITS"
#endif

namespace geomint::tools {

#if GEOMINT_STEPPER_STUB
/// The stub of a unit left out of the build: a multiprecision unit with
/// GEOMINT_RUN_MULTIPRECISION=OFF, or any unit not named in GEOMINT_TOOL_UNITS (CMakeLists.txt).
template <class T>
[[noreturn]] void not_compiled() {
  throw std::invalid_argument("these schemes in " + std::to_string(digits_of<T>()) +
                              " digits are not compiled into this build (GEOMINT_RUN_MULTIPRECISION=OFF or "
                              "GEOMINT_TOOL_UNITS)");
}
#endif

#if defined(GEOMINT_STEPPER_HIGH_M)
/// m = 9..16: lpf on Gauss-interior nodes (Lagrange basis), its fixed-point form (natural
/// systems) and galerkin (high_m_scheme_set).
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_high_m_stepper(const scheme_spec& spec) {
#if GEOMINT_STEPPER_STUB
  (void)spec;
  not_compiled<T>();
#else
  using set = high_m_scheme_set<T>;
  set::check(spec);
  auto make = [&]<class Scheme>() { return make_scheme_stepper<Scheme, Sys, T>(); };
  if (spec.scheme == "galerkin")
    return with_int<set::min_m, set::max_m>(spec.m, [&]<int M>() { return make.template operator()<galerkin_vi<M>>(); });
  if (spec.scheme == "lpf-fixed-point") {
    check_fixed_point_system<Sys>(spec);  // throws unless Sys is natural
    if constexpr (natural_system<Sys>)
      return with_int<set::min_m, set::max_m>(spec.m, [&]<int M>() { return make.template operator()<lpf_fixed_point<M>>(); });
  }
  return with_int<set::min_m, set::max_m>(spec.m,
                                          [&]<int M>() { return make.template operator()<lpf<M, gauss_interior, lagrange>>(); });
#endif
}
#else
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_stepper(const scheme_spec& spec) {
#if GEOMINT_STEPPER_STUB
  (void)spec;
  not_compiled<T>();
#else
  if constexpr (is_zoo_system<Sys>)
    return make_zoo_stepper<Sys, T>(spec);
  else
    return geomint::make_stepper<Sys, T>(spec);
#endif
}
#endif

using scalar = scalar_for_digits<GEOMINT_STEPPER_DIGITS>;
#if defined(GEOMINT_STEPPER_HIGH_M)
template std::unique_ptr<any_stepper<scalar>> make_high_m_stepper<systems::harmonic, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_high_m_stepper<systems::pendulum, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_high_m_stepper<systems::kepler, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_high_m_stepper<systems::charged, scalar>(const scheme_spec&);
#elif defined(GEOMINT_STEPPER_ZOO)
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<zoo::henon_heiles, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<zoo::spring_pendulum, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<zoo::double_pendulum, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<zoo::toda3, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<zoo::outer_solar, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<zoo::arenstorf, scalar>(const scheme_spec&);
#else
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<systems::harmonic, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<systems::pendulum, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<systems::kepler, scalar>(const scheme_spec&);
template std::unique_ptr<any_stepper<scalar>> make_system_stepper<systems::charged, scalar>(const scheme_spec&);
#endif

}  // namespace geomint::tools
