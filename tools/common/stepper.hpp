#pragma once
/// The tools' steppers: `geomint::make_stepper` (geomint/stepper.hpp) for the built-in free
/// systems, by system name. Each (system, scalar) factory is compiled once (stepper_tu.cpp) and
/// shared by geomint-run, geomint-order and geomint-symplectic.
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "digits.hpp"
#include "geomint/core/multiprecision.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/stepper.hpp"

namespace geomint::tools {

/// f.template operator()<Sys>() for the free system called `name`; std::invalid_argument otherwise.
template <class F>
decltype(auto) with_free_system(std::string_view name, F&& f) {
  if (name == systems::harmonic::name) return f.template operator()<systems::harmonic>();
  if (name == systems::pendulum::name) return f.template operator()<systems::pendulum>();
  if (name == systems::kepler::name) return f.template operator()<systems::kepler>();
  if (name == systems::charged::name) return f.template operator()<systems::charged>();
  throw std::invalid_argument("unknown system '" + std::string(name) + "'");
}
/// The free systems' names, in the order of with_free_system.
inline const std::vector<std::string>& free_systems() {
  static const std::vector<std::string> names = {std::string(systems::harmonic::name), std::string(systems::pendulum::name),
                                                 std::string(systems::kepler::name), std::string(systems::charged::name)};
  return names;
}
/// The scheme names of geomint/stepper.hpp.
inline const std::vector<std::string>& scheme_list() {
  static const std::vector<std::string> names(scheme_names.begin(), scheme_names.end());
  return names;
}

/// `geomint::make_stepper<Sys, T>`, defined for T = double, cpp_bin_float_50, cpp_bin_float_100
/// in one translation unit per (Sys, T) (stepper_tu.cpp).
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_stepper(const scheme_spec& spec);

/// The stepper of the free system called `system` (std::invalid_argument for an unknown one).
template <class T>
std::unique_ptr<any_stepper<T>> make_stepper(std::string_view system, const scheme_spec& spec) {
  return with_free_system(system, [&]<class Sys>() { return make_system_stepper<Sys, T>(spec); });
}

/// The system's initial data (q_0, qdot_0) (`Sys::initial_data`, mechanics/systems.hpp).
template <class T>
std::pair<dynamic_vector<T>, dynamic_vector<T>> default_initial_data(std::string_view system) {
  return with_free_system(system, [&]<class Sys>() {
    vec<T, Sys::dof> q, qdot;
    Sys::initial_data(q, qdot);
    return std::pair<dynamic_vector<T>, dynamic_vector<T>>(q, qdot);
  });
}

}  // namespace geomint::tools
