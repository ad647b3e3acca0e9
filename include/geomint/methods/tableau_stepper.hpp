#pragma once
/// A method given as data as a type-erased stepper (geomint/stepper.hpp): what a program needs
/// that reads a method at run time, e.g. from a tableau file (methods/tableau_file.hpp). Apart
/// from geomint/stepper.hpp so that the programs that pick built-in schemes by name do not parse
/// the exact arithmetic of methods/.
///
///   auto s = geomint::make_tableau_stepper<geomint::systems::pendulum, double>(
///       geomint::methods::nystrom_form_of(geomint::methods::read_tableau_file("gauss2.tableau")));

#include <limits>
#include <memory>
#include <string>

#include "geomint/methods/tableau_method.hpp"
#include "geomint/stepper.hpp"

namespace geomint {

/// The stepper of a method given as data (a tableau of any kind or a composition in its Nystrom
/// form over exact coefficients, methods/nystrom_form.hpp) on `sys`, its coefficients converted
/// to T at T's full precision. std::invalid_argument if the method needs a natural system (rkn,
/// prk) and Sys is not one.
template <class Sys, class T, class K>
std::unique_ptr<any_stepper<T>> make_tableau_stepper(const methods::nystrom_form<K>& form, const Sys& sys = Sys{}) {
  using engine = methods::detail::tableau_engine<Sys, T>;
  const std::string name = (form.name.empty() ? std::string("tableau") : form.name) + " (" +
                           std::string(methods::to_string(form.kind)) + ", " + std::to_string(form.stages) + " stages)";
  // A method given as data has no resolution bound of its own (step_monitor.hpp: infinity turns
  // the resolution check off unless the user sets max_tau_omega; the energy criterion applies).
  return std::make_unique<engine_stepper<engine, Sys, T>>(sys, engine(sys, methods::to_scalar<T>(form)), name,
                                                          std::numeric_limits<T>::infinity());
}

}  // namespace geomint
