#pragma once
/// The systems of a command-line tool: a list of system types, looked up by name at run time.
///
/// A system of the tools is a system of the library (mechanics/lagrangian.hpp: `dof` and a
/// Lagrangian, or `natural<Sys, n>`) with two more members: its name on the command line and its
/// default initial data (a position and a velocity), as the zoo's systems have them
/// (mechanics/zoo.hpp):
///
///     static constexpr std::string_view name = "henon-heiles";
///     template <class T> static void initial_data(geomint::vec<T, dof>& q, geomint::vec<T, dof>& qdot);
#include <concepts>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "geomint/linalg/types.hpp"

namespace geomint::cli {

/// Whether Sys has what the tools need besides the Lagrangian: `name` and `initial_data`.
template <class Sys>
concept tool_system = requires(vec<double, Sys::dof>& q) {
  { std::string_view(Sys::name) };
  Sys::template initial_data<double>(q, q);
};

/// A list of system types (each a tool_system, with distinct names).
template <class... Sys>
struct system_list {
  static_assert(sizeof...(Sys) > 0, "geomint::cli::system_list: name at least one system");
  static_assert((tool_system<Sys> && ...),
                "geomint::cli: a system of the tools needs `static constexpr std::string_view name = \"...\";` and "
                "`template <class T> static void initial_data(geomint::vec<T, dof>& q, geomint::vec<T, dof>& qdot)` "
                "(docs/guide/your_own_tools.md)");
  static constexpr std::size_t size = sizeof...(Sys);
};

/// The names of the systems, in the list's order.
template <class... Sys>
std::vector<std::string> system_names(system_list<Sys...>) {
  return {std::string(Sys::name)...};
}

/// "a, b, c".
inline std::string comma_list(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) with_system_from(std::string_view name, F& f, const std::vector<std::string>& all,
                                system_list<First, Rest...>) {
  if (name == First::name) return f.template operator()<First>();
  if constexpr (sizeof...(Rest) > 0) {
    return with_system_from(name, f, all, system_list<Rest...>{});
  } else {
    throw std::invalid_argument("unknown system '" + std::string(name) + "' (one of " + comma_list(all) + ")");
  }
}
}  // namespace detail

/// `f.template operator()<Sys>()` for the system of the list called `name`; std::invalid_argument
/// (listing the names) otherwise.
template <class... Sys, class F>
decltype(auto) with_system(system_list<Sys...> list, std::string_view name, F&& f) {
  return detail::with_system_from(name, f, system_names(list), list);
}

/// Whether the list has a system called `name`.
template <class... Sys>
bool has_system(system_list<Sys...>, std::string_view name) {
  return ((name == Sys::name) || ...);
}

}  // namespace geomint::cli
