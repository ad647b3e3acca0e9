#pragma once
/// The tools' steppers of a method given as data (a tableau file): geomint::make_tableau_stepper
/// (geomint/methods/tableau_stepper.hpp) on the built-in free systems, by name. Instantiated by
/// the tool that includes it (geomint-run: tools/lpf/run_free.cpp).
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "geomint/methods/tableau_stepper.hpp"
#include "stepper.hpp"

namespace geomint::tools {

/// The stepper of a method given as data (a tableau file's Nystrom form) on the built-in free
/// system called `system` (std::invalid_argument for a zoo system, or for an rkn or prk tableau
/// on a system that is not natural).
template <class T>
std::unique_ptr<any_stepper<T>> make_tableau_stepper(std::string_view system,
                                                     const methods::nystrom_form<methods::field_element>& form) {
  return with_free_system(system, [&]<class Sys>() -> std::unique_ptr<any_stepper<T>> {
    if constexpr (is_zoo_system<Sys>)
      throw std::invalid_argument("--tableau runs on the built-in free systems (harmonic, pendulum, kepler, charged), not on " +
                                  std::string(Sys::name));
    else
      return geomint::make_tableau_stepper<Sys, T>(form);
  });
}

}  // namespace geomint::tools
