#pragma once
/// The definitions of the front ends' stepper factories (declared in geomint/cli/stepper_factories.hpp),
/// and `stepper_unit`, whose explicit instantiation compiles them for a list of systems in one
/// scalar: the translation units that geomint_add_tools (cmake/geomintTools.cmake) generates,
/// one per digits (m <= 8 and tableau files) and one per digits for m = 9..16, so that a build
/// compiles them in parallel:
///
///     template struct geomint::cli::stepper_unit<50, geomint::cli::stepper_part::low, henon_heiles>;
///
/// With GEOMINT_CLI_STEPPER_STUB set, the factories of the unit report that they are not
/// compiled into the program (a digits or part left out of its build) instead.
#include <memory>
#include <stdexcept>
#include <string>

#include "geomint/cli/stepper_factories.hpp"
#include "geomint/methods/tableau_stepper.hpp"

namespace geomint::cli {

namespace detail {
/// The exception of a factory left out of the build.
template <class T>
[[noreturn]] void stepper_not_compiled() {
  throw std::invalid_argument("these schemes in " + std::to_string(digits_of<T>()) +
                              " digits are not compiled into this build (GEOMINT_RUN_MULTIPRECISION=OFF or "
                              "GEOMINT_TOOL_UNITS in geomint's build; DIGITS or HIGH_M_DIGITS of geomint_add_tools)");
}
}  // namespace detail

template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_stepper(const scheme_spec& spec) {
#if GEOMINT_CLI_STEPPER_STUB
  (void)spec;
  detail::stepper_not_compiled<T>();
#else
  return geomint::make_stepper<Sys, T>(spec);
#endif
}

template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_tableau_stepper(const methods::nystrom_form<T>& form) {
#if GEOMINT_CLI_STEPPER_STUB
  (void)form;
  detail::stepper_not_compiled<T>();
#else
  return geomint::make_tableau_stepper<Sys, T>(form);
#endif
}

/// m = 9..16: lpf on Gauss-interior nodes (Lagrange basis), its fixed-point form (natural
/// systems) and galerkin (high_m_scheme_set).
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_high_m_stepper(const scheme_spec& spec) {
#if GEOMINT_CLI_STEPPER_STUB
  (void)spec;
  detail::stepper_not_compiled<T>();
#else
  using set = high_m_scheme_set<T>;
  set::check(spec);
  if constexpr (set::compiled) {
    auto make = [&]<class Scheme>() { return make_scheme_stepper<Scheme, Sys, T>(); };
    if (spec.scheme == "galerkin")
      return with_int<set::min_m, set::max_m>(spec.m, [&]<int M>() { return make.template operator()<galerkin_vi<M>>(); });
    if (spec.scheme == "lpf-fixed-point") {
      check_fixed_point_system<Sys>(spec);  // throws unless Sys is natural
      if constexpr (natural_system<Sys>)
        return with_int<set::min_m, set::max_m>(spec.m,
                                                [&]<int M>() { return make.template operator()<lpf_fixed_point<M>>(); });
    }
    return with_int<set::min_m, set::max_m>(spec.m,
                                            [&]<int M>() { return make.template operator()<lpf<M, gauss_interior, lagrange>>(); });
  } else {
    return nullptr;  // (check has thrown)
  }
#endif
}

/// The parts of a system's factories: m <= 8 and tableau files (low), m = 9..16 (high_m).
enum class stepper_part { low, high_m };

/// Its explicit instantiation compiles the factories of `Part` for the systems Sys... in the
/// scalar of `Digits` (see the header's comment).
template <int Digits, stepper_part Part, class... Sys>
struct stepper_unit {
  using scalar = scalar_for_digits<Digits>;
  /// The factories' addresses: naming them instantiates them in this unit.
  static auto factories() {
    if constexpr (Part == stepper_part::low)
      return std::make_tuple(&make_system_stepper<Sys, scalar>..., &make_system_tableau_stepper<Sys, scalar>...);
    else
      return std::make_tuple(&make_high_m_stepper<Sys, scalar>...);
  }
};

}  // namespace geomint::cli
