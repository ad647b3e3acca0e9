#pragma once
/// The systems of the project's tools (geomint-run, geomint-order, geomint-symplectic): the
/// built-in systems (mechanics/systems.hpp) and the problem zoo (mechanics/zoo.hpp), each with
/// every scheme, as one system_list of the installed front ends (geomint/cli/), and the steppers
/// by name over that list. The factories are compiled once for all tools (tools/common/CMakeLists.txt).
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geomint/cli/digits.hpp"
#include "geomint/cli/steppers.hpp"
#include "geomint/cli/study.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"

namespace geomint::tools {

using cli::digits_of;
using cli::scalar_for_digits;
using cli::system_list;
using cli::with_digits;

/// The built-in systems, the zoo systems, and both: the free systems of the tools, in the order
/// of their names.
using builtin_system_types = system_list<systems::harmonic, systems::pendulum, systems::kepler, systems::charged>;
using zoo_system_types = system_list<zoo::henon_heiles, zoo::spring_pendulum, zoo::double_pendulum, zoo::toda3,
                                     zoo::outer_solar, zoo::arenstorf>;
using free_system_types = system_list<systems::harmonic, systems::pendulum, systems::kepler, systems::charged,
                                      zoo::henon_heiles, zoo::spring_pendulum, zoo::double_pendulum, zoo::toda3,
                                      zoo::outer_solar, zoo::arenstorf>;

/// The names of the free systems, of the built-in ones and of the zoo.
inline const std::vector<std::string>& free_systems() {
  static const std::vector<std::string> names = cli::system_names(free_system_types{});
  return names;
}
inline const std::vector<std::string>& builtin_systems() {
  static const std::vector<std::string> names = cli::system_names(builtin_system_types{});
  return names;
}
inline const std::vector<std::string>& zoo_systems() {
  static const std::vector<std::string> names = cli::system_names(zoo_system_types{});
  return names;
}

/// The names of the natural systems of a list (those of lpf-fixed-point).
template <class... S>
std::vector<std::string> natural_system_names(system_list<S...>) {
  std::vector<std::string> out;
  ([&] {
    if constexpr (natural_system<S>) out.push_back(std::string(S::name));
  }(), ...);
  return out;
}
inline const std::vector<std::string>& natural_free_systems() {
  static const std::vector<std::string> names = natural_system_names(free_system_types{});
  return names;
}
inline const std::vector<std::string>& natural_zoo_systems() {
  static const std::vector<std::string> names = natural_system_names(zoo_system_types{});
  return names;
}

/// f.template operator()<Sys>() for the free system called `name` (std::invalid_argument
/// listing the names otherwise).
template <class F>
decltype(auto) with_free_system(std::string_view name, F&& f) {
  return cli::with_system(free_system_types{}, name, std::forward<F>(f));
}

/// The stepper of the free system called `system` (cli::make_stepper over free_system_types).
template <class T>
std::unique_ptr<any_stepper<T>> make_stepper(std::string_view system, const scheme_spec& spec) {
  return cli::make_stepper<T>(free_system_types{}, system, spec);
}

/// Throws std::invalid_argument if the free system called `system` has no stepper for `spec` in
/// the scalar T (cli::check_scheme over free_system_types).
template <class T>
void check_scheme(std::string_view system, const scheme_spec& spec) {
  cli::check_scheme<T>(free_system_types{}, system, spec);
}

/// The initial state (q0, p0) of the free system called `system` (cli::default_initial_state).
template <class T, class Parse>
std::pair<dynamic_vector<T>, dynamic_vector<T>> default_initial_state(std::string_view system, const any_stepper<T>& stepper,
                                                                      const std::vector<std::string>& q0_text,
                                                                      const std::vector<std::string>& p0_text,
                                                                      const Parse& parse) {
  return cli::default_initial_state<T>(free_system_types{}, system, stepper, q0_text, p0_text, parse);
}

/// The free system's initial data (q_0, qdot_0).
template <class T>
std::pair<dynamic_vector<T>, dynamic_vector<T>> default_initial_data(std::string_view system) {
  return cli::default_initial_data<T>(free_system_types{}, system);
}

/// The study programs' settings (geomint-order, geomint-symplectic): `--system all` is the
/// built-in systems, `--system zoo` the zoo; default system pendulum in 50 digits.
inline cli::study_tool study_tool(std::string program, std::string usage) {
  cli::study_tool tool;
  tool.program = std::move(program);
  tool.usage = std::move(usage);
  tool.default_system = "pendulum";
  tool.default_digits = 50;
  tool.groups = {{"all", builtin_systems()}, {"zoo", zoo_systems()}};
  return tool;
}

}  // namespace geomint::tools
