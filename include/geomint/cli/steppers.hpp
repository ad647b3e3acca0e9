#pragma once
/// The steppers of the command-line front ends, by system name over a system_list: every scheme
/// of `geomint::make_stepper` (m = 2..8), m = 9..16 for the high-order schemes
/// (high_m_scheme_set), and methods given as data (tableau files), for every system of the list
/// in 16, 50 and 100 digits.
///
/// Each (system, scalar) factory costs some 30 s of compile time, so the factories are function
/// templates declared in geomint/cli/stepper_factories.hpp and defined in
/// geomint/cli/stepper_unit.hpp. A program that includes
/// this header alone gets the definitions too (one translation unit, nothing else to do); a
/// program built with geomint_add_tools (cmake/geomintTools.cmake) defines
/// GEOMINT_CLI_STEPPER_UNITS and gets them from one generated unit per digits, compiled in
/// parallel.
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geomint/cli/stepper_factories.hpp"
#include "geomint/cli/system_list.hpp"

namespace geomint::cli {

/// The names of the built-in schemes (schemes/registry.hpp).
inline const std::vector<std::string>& scheme_list() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const scheme_entry& e : scheme_registry) out.emplace_back(e.name);
    return out;
  }();
  return names;
}
/// The schemes of every system: those that are not for natural systems only, what the studies'
/// `--scheme all` means.
inline const std::vector<std::string>& schemes_of_every_system() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const scheme_entry& e : scheme_registry)
      if (!e.natural_only) out.emplace_back(e.name);
    return out;
  }();
  return names;
}

/// Throws std::invalid_argument if the system called `system` has no stepper for `spec` in the
/// scalar T: an unknown system, the fixed-point form on a system that is not natural, or a
/// degree above 8 outside high_m_scheme_set. (Other specs are checked by the library's factory.)
template <class T, class List>
void check_scheme(List list, std::string_view system, const scheme_spec& spec) {
  with_system(list, system, [&]<class Sys>() {
    check_fixed_point_system<Sys>(spec);
    if (high_m_scheme_set<T>::applies(spec)) high_m_scheme_set<T>::check(spec);
  });
}

/// The stepper of the system called `system` (std::invalid_argument for an unknown one or a spec
/// outside the schemes).
template <class T, class List>
std::unique_ptr<any_stepper<T>> make_stepper(List list, std::string_view system, const scheme_spec& spec) {
  return with_system(list, system, [&]<class Sys>() -> std::unique_ptr<any_stepper<T>> {
    if (!high_m_scheme_set<T>::applies(spec)) return make_system_stepper<Sys, T>(spec);
    high_m_scheme_set<T>::check(spec);
    if constexpr (!high_m_scheme_set<T>::compiled) return nullptr;  // (check has thrown)
    else return make_high_m_stepper<Sys, T>(spec);
  });
}

/// The stepper of a method given as data (a tableau file's or a catalogue method's Nystrom form,
/// in T) on the system called `system` (std::invalid_argument for an rkn or prk tableau on a
/// system that is not natural).
template <class T, class List>
std::unique_ptr<any_stepper<T>> make_tableau_stepper(List list, std::string_view system,
                                                     const methods::nystrom_form<T>& form) {
  return with_system(list, system, [&]<class Sys>() { return make_system_tableau_stepper<Sys, T>(form); });
}

/// The system's initial data (q_0, qdot_0) (`Sys::initial_data`).
template <class T, class List>
std::pair<dynamic_vector<T>, dynamic_vector<T>> default_initial_data(List list, std::string_view system) {
  return with_system(list, system, [&]<class Sys>() {
    vec<T, Sys::dof> q, qdot;
    Sys::initial_data(q, qdot);
    return std::pair<dynamic_vector<T>, dynamic_vector<T>>(q, qdot);
  });
}

/// The initial state (q0, p0) of a system for the tools: q0 from `q0_text` (if not empty) or the
/// system's default; p0 from `p0_text` (the canonical momentum, if not empty) or else
/// dL/dqdot(q0, qdot0) with the default velocity qdot0, so that a user's position is never
/// paired with the momentum of the default position (which would change the energy: charged
/// from q0 = (10, 0) with the default momentum starts with E = 32067.8 instead of 0.5).
/// std::invalid_argument naming the flag for a wrong count of values; `parse` reads one value.
template <class T, class List, class Parse>
std::pair<dynamic_vector<T>, dynamic_vector<T>> default_initial_state(List list, std::string_view system,
                                                                      const any_stepper<T>& stepper,
                                                                      const std::vector<std::string>& q0_text,
                                                                      const std::vector<std::string>& p0_text,
                                                                      const Parse& parse) {
  auto [q, qdot] = default_initial_data<T>(list, system);
  const int n = stepper.dof();
  auto read = [&](const std::vector<std::string>& in, dynamic_vector<T>& out, const char* flag) {
    if (static_cast<int>(in.size()) != n)
      throw std::invalid_argument(std::string(flag) + " needs " + std::to_string(n) + " value(s) for --system " +
                                  std::string(system));
    for (int i = 0; i < n; ++i) out[i] = parse(in[static_cast<std::size_t>(i)]);
  };
  if (!q0_text.empty()) read(q0_text, q, "--q0");
  dynamic_vector<T> p = stepper.momentum(q, qdot);
  if (!p0_text.empty()) read(p0_text, p, "--p0");
  return {q, p};
}

}  // namespace geomint::cli

#if !defined(GEOMINT_CLI_STEPPER_UNITS)
#include "geomint/cli/stepper_unit.hpp"  // the factories' definitions, in this translation unit
#endif
