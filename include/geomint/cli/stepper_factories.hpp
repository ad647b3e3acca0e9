#pragma once
/// The stepper factories of the command-line front ends, declared: `geomint::make_stepper`
/// (m <= 8), the degrees of high_m_scheme_set (m = 9..16) and methods given as data, for one
/// (system, scalar). geomint/cli/stepper_unit.hpp defines them; geomint/cli/steppers.hpp
/// dispatches to them by system name.
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "geomint/cli/digits.hpp"
#include "geomint/core/dispatch.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/methods/number_field.hpp"
#include "geomint/stepper.hpp"

namespace geomint::cli {

/// The degrees above the library factory's range (geomint::stepper_max_m): m = 9..16 for lpf on
/// Gauss-interior nodes with the Lagrange basis, for its fixed-point form (natural systems) and
/// for galerkin, the high-order schemes of the work-precision study (lpf order 2(m - 1),
/// galerkin order 2m), in 16 and 50 digits: 16 (natural systems: 24) engines per (system,
/// scalar), compiled in a unit of their own (stepper_unit.hpp).
template <class T>
struct high_m_scheme_set {
  static constexpr int min_m = stepper_max_m + 1;
  static constexpr int max_m = 16;
  static constexpr bool compiled = std::numeric_limits<T>::digits10 <= 50;
  static constexpr const char* describe =
      "m = 9..16 is compiled for --scheme lpf --nodes gauss-interior --basis lagrange, --scheme lpf-fixed-point "
      "and --scheme galerkin, on every free system, in 16 and 50 digits";
  /// Whether `spec` asks for a degree above the library factory's range (midpoint and
  /// trapezoidal have no degree).
  static bool applies(const scheme_spec& spec) { return spec.m > stepper_max_m && spec.has_m(); }
  /// Throws std::invalid_argument with a clear message unless `spec` is in the set.
  static void check(const scheme_spec& spec) {
    const std::string m = "m = " + std::to_string(spec.m) + ": ";
    if (spec.m > max_m) throw std::invalid_argument(m + "m must be at most " + std::to_string(max_m));
    if (!compiled)
      throw std::invalid_argument(m + "not compiled in " + std::to_string(digits_of<T>()) + " digits (" + describe + ")");
    if (spec.scheme == "galerkin" || spec.scheme == "lpf-fixed-point") return;
    if (spec.scheme == "lpf" && canonical_node_family(spec.nodes) == gauss_interior::name && spec.basis == "lagrange")
      return;
    throw std::invalid_argument(m + "not compiled for --scheme " + spec.scheme +
                                (spec.scheme == "lpf" ? " --nodes " + spec.nodes + " --basis " + spec.basis : std::string()) +
                                " (" + describe + ")");
  }
};

/// The factories of one (Sys, T), defined in stepper_unit.hpp: `geomint::make_stepper<Sys, T>`
/// (m <= 8), the degrees of high_m_scheme_set, and geomint::make_tableau_stepper.
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_stepper(const scheme_spec& spec);
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_high_m_stepper(const scheme_spec& spec);
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_tableau_stepper(const methods::nystrom_form<T>& form);

/// Throws std::invalid_argument for lpf-fixed-point on a system that is not natural (the
/// library's factory says so for m <= 8, make_high_m_stepper for m > 8 with this).
template <class Sys>
void check_fixed_point_system(const scheme_spec& spec) {
  if (spec.scheme == "lpf-fixed-point" && !natural_system<Sys>)
    throw std::invalid_argument("--system " + std::string(Sys::name) + ": " + std::string(fixed_point_natural_only));
}

}  // namespace geomint::cli
