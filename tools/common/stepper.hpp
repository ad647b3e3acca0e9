#pragma once
/// The tools' steppers: `geomint::make_stepper` (geomint/stepper.hpp) for the free systems, by
/// system name: the built-in systems (mechanics/systems.hpp) with every scheme of the library's
/// factory, and the problem zoo (mechanics/zoo.hpp) with a restricted scheme set (below). Each
/// (system, scalar) factory is compiled once (stepper_tu.cpp) and shared by geomint-run,
/// geomint-order and geomint-symplectic.
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "digits.hpp"
#include "geomint/core/dispatch.hpp"
#include "geomint/core/multiprecision.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "geomint/stepper.hpp"

namespace geomint::tools {

/// A list of system types.
template <class... Sys>
struct system_list {};

/// Every free system of the tools, in the order of their names: the built-in systems, then the
/// zoo. The one name lookup of all tools (with_free_system, free_systems).
using free_system_types = system_list<systems::harmonic, systems::pendulum, systems::kepler, systems::charged,
                                      zoo::henon_heiles, zoo::spring_pendulum, zoo::double_pendulum, zoo::toda3,
                                      zoo::outer_solar, zoo::arenstorf>;

/// Whether Sys is a zoo system (mechanics/zoo.hpp): those have the restricted scheme set.
template <class Sys>
inline constexpr bool is_zoo_system =
    std::is_same_v<Sys, zoo::henon_heiles> || std::is_same_v<Sys, zoo::spring_pendulum> ||
    std::is_same_v<Sys, zoo::double_pendulum> || std::is_same_v<Sys, zoo::toda3> ||
    std::is_same_v<Sys, zoo::outer_solar> || std::is_same_v<Sys, zoo::arenstorf>;

/// The free systems' names, in the order of free_system_types.
template <class... Sys>
std::vector<std::string> system_names(system_list<Sys...>) {
  return {std::string(Sys::name)...};
}
inline const std::vector<std::string>& free_systems() {
  static const std::vector<std::string> names = system_names(free_system_types{});
  return names;
}
/// The names of the built-in systems (zoo = false) or of the zoo systems (zoo = true).
template <class... Sys>
std::vector<std::string> system_names(system_list<Sys...>, bool zoo) {
  std::vector<std::string> out;
  ((is_zoo_system<Sys> == zoo ? out.push_back(std::string(Sys::name)) : void()), ...);
  return out;
}
inline const std::vector<std::string>& builtin_systems() {
  static const std::vector<std::string> names = system_names(free_system_types{}, false);
  return names;
}
inline const std::vector<std::string>& zoo_systems() {
  static const std::vector<std::string> names = system_names(free_system_types{}, true);
  return names;
}
/// Whether the free system called `name` is a zoo system.
inline bool is_zoo_name(std::string_view name) {
  for (const std::string& z : zoo_systems())
    if (z == name) return true;
  return false;
}

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) with_system_from(std::string_view name, F& f, system_list<First, Rest...>) {
  if (name == First::name) return f.template operator()<First>();
  if constexpr (sizeof...(Rest) > 0) {
    return with_system_from(name, f, system_list<Rest...>{});
  } else {
    std::string list;
    for (const std::string& n : free_systems()) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown system '" + std::string(name) + "' (one of " + list + ")");
  }
}
}  // namespace detail

/// f.template operator()<Sys>() for the free system called `name`; std::invalid_argument
/// (listing the names) otherwise.
template <class F>
decltype(auto) with_free_system(std::string_view name, F&& f) {
  return detail::with_system_from(name, f, free_system_types{});
}

/// The scheme names of geomint/stepper.hpp.
inline const std::vector<std::string>& scheme_list() {
  static const std::vector<std::string> names(scheme_names.begin(), scheme_names.end());
  return names;
}
/// The schemes of every system: scheme_list but lpf-fixed-point (natural systems only), what
/// the studies' `--scheme all` means.
inline const std::vector<std::string>& schemes_of_every_system() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const std::string& s : scheme_list())
      if (s != "lpf-fixed-point") out.push_back(s);
    return out;
  }();
  return names;
}

/// The zoo's restricted scheme set, chosen to keep the tools' compile time small (a zoo system
/// costs some 6 schemes, where a built-in system costs 65, 72 if natural): midpoint; lpf on Gauss-interior
/// nodes with the Lagrange basis, m = 2..4 (order 2(m - 1)); galerkin, m = 2..3 (order 2m); in
/// 16 and 50 digits. In 50 digits the outer solar system (18 dof) has m = 2 only: the Newton
/// matrix of a degree-m step has (18 m)^2 entries and is kept on the stack.
template <class Sys, class T>
struct zoo_scheme_set {
  static constexpr bool compiled = std::numeric_limits<T>::digits10 <= 50;
  static constexpr bool large = Sys::dof > 8 && std::numeric_limits<T>::digits10 > 16;
  static constexpr int lpf_max_m = large ? 2 : 4;
  static constexpr int galerkin_max_m = large ? 2 : 3;
  /// "midpoint; lpf --nodes gauss-interior --basis lagrange --m 2..4; galerkin --m 2..3".
  static std::string describe() {
    return "midpoint; lpf --nodes gauss-interior --basis lagrange --m " + m_range(lpf_max_m) + "; galerkin --m " +
           m_range(galerkin_max_m);
  }
  /// "2..hi", or "2".
  static std::string m_range(int hi) { return hi == 2 ? std::string("2") : "2.." + std::to_string(hi); }
  /// Throws std::invalid_argument with a clear message unless `spec` is in the set.
  static void check(const scheme_spec& spec) {
    const std::string who = "--system " + std::string(Sys::name) + ": ";
    if (!compiled)
      throw std::invalid_argument(who + "the zoo systems are compiled in 16 and 50 digits only, not " +
                                  std::to_string(digits_of<T>()));
    const std::string set = " (the zoo's schemes in " + std::to_string(digits_of<T>()) +
                            " digits: " + describe() + ")";
    if (spec.scheme == "midpoint") return;
    if (spec.scheme == "lpf") {
      if (canonical_node_family(spec.nodes) != gauss_interior::name)
        throw std::invalid_argument(who + "lpf is compiled on gauss-interior nodes only, not '" + spec.nodes + "'" + set);
      if (spec.basis != "lagrange")
        throw std::invalid_argument(who + "lpf is compiled with the lagrange basis only, not '" + spec.basis + "'" + set);
      if (spec.m < 2 || spec.m > lpf_max_m)
        throw std::invalid_argument(who + "lpf is compiled for m = " + m_range(lpf_max_m) + ", not " +
                                    std::to_string(spec.m) + set);
      return;
    }
    if (spec.scheme == "galerkin") {
      if (spec.m < 2 || spec.m > galerkin_max_m)
        throw std::invalid_argument(who + "galerkin is compiled for m = " + m_range(galerkin_max_m) + ", not " +
                                    std::to_string(spec.m) + set);
      return;
    }
    throw std::invalid_argument(who + "scheme '" + spec.scheme + "' is not compiled for the zoo systems" + set);
  }
};

/// The stepper of a zoo system for a spec in zoo_scheme_set (instantiated in stepper_tu.cpp only).
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_zoo_stepper(const scheme_spec& spec) {
  using set = zoo_scheme_set<Sys, T>;
  set::check(spec);
  auto make = [&]<class Scheme>() { return make_scheme_stepper<Scheme, Sys, T>(); };
  if (spec.scheme == "midpoint") return make.template operator()<midpoint_vi>();
  if (spec.scheme == "galerkin")
    return with_int<2, set::galerkin_max_m>(spec.m, [&]<int M>() { return make.template operator()<galerkin_vi<M>>(); });
  return with_int<2, set::lpf_max_m>(spec.m, [&]<int M>() { return make.template operator()<lpf<M, gauss_interior, lagrange>>(); });
}

/// The degrees above the library factory's range (geomint::stepper_max_m), for the built-in
/// systems: m = 9..16 for lpf on Gauss-interior nodes with the Lagrange basis, for its
/// fixed-point form (natural systems) and for galerkin, the high-order schemes of the
/// work-precision study (lpf order 2(m - 1), galerkin order 2m), in 16 and 50 digits. One unit
/// per digits compiles their 16 (natural systems: 24) engines for the four built-in systems
/// (stepper_tu.cpp, GEOMINT_STEPPER_HIGH_M).
template <class T>
struct high_m_scheme_set {
  static constexpr int min_m = stepper_max_m + 1;
  static constexpr int max_m = 16;
  static constexpr bool compiled = std::numeric_limits<T>::digits10 <= 50;
  static constexpr const char* describe =
      "m = 9..16 is compiled for --scheme lpf --nodes gauss-interior --basis lagrange, --scheme lpf-fixed-point "
      "and --scheme galerkin, on the built-in free systems, in 16 and 50 digits";
  /// Whether `spec` asks for a degree above the library factory's range (midpoint and
  /// trapezoidal have no degree).
  static bool applies(const scheme_spec& spec) {
    return spec.m > stepper_max_m && spec.has_m();
  }
  /// Throws std::invalid_argument with a clear message unless `spec` is in the set.
  static void check(const scheme_spec& spec) {
    const std::string m = "m = " + std::to_string(spec.m) + ": ";
    if (spec.m > max_m) throw std::invalid_argument(m + "m must be at most " + std::to_string(max_m));
    if (!compiled)
      throw std::invalid_argument(m + "not compiled in " + std::to_string(digits_of<T>()) + " digits (" +
                                  describe + ")");
    if (spec.scheme == "galerkin" || spec.scheme == "lpf-fixed-point") return;
    if (spec.scheme == "lpf" && canonical_node_family(spec.nodes) == gauss_interior::name && spec.basis == "lagrange")
      return;
    throw std::invalid_argument(m + "not compiled for --scheme " + spec.scheme +
                                (spec.scheme == "lpf" ? " --nodes " + spec.nodes + " --basis " + spec.basis : std::string()) +
                                " (" + describe + ")");
  }
};

/// The stepper of a built-in system for a spec in high_m_scheme_set (defined in stepper_tu.cpp
/// for T = double and cpp_bin_float_50).
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_high_m_stepper(const scheme_spec& spec);

/// `geomint::make_stepper<Sys, T>` (built-in systems) or make_zoo_stepper (zoo systems), defined
/// for T = double, cpp_bin_float_50 (and cpp_bin_float_100 for the built-in systems) in one
/// translation unit per (Sys, T) (stepper_tu.cpp).
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_system_stepper(const scheme_spec& spec);

/// Throws std::invalid_argument for lpf-fixed-point on a system that is not natural (the
/// library's factory says so for m <= 8, make_high_m_stepper for m > 8 with this).
template <class Sys>
void check_fixed_point_system(const scheme_spec& spec) {
  if (spec.scheme == "lpf-fixed-point" && !natural_system<Sys>)
    throw std::invalid_argument("--system " + std::string(Sys::name) + ": " + std::string(fixed_point_natural_only));
}

/// Throws std::invalid_argument if the free system called `system` has no stepper for `spec` in
/// the scalar T: an unknown system, a zoo system outside its restricted scheme set, the
/// fixed-point form on a system that is not natural, or a degree above 8 outside
/// high_m_scheme_set. (The built-in systems' other specs are checked by the library's factory.)
template <class T>
void check_scheme(std::string_view system, const scheme_spec& spec) {
  with_free_system(system, [&]<class Sys>() {
    if constexpr (is_zoo_system<Sys>) {
      zoo_scheme_set<Sys, T>::check(spec);
    } else {
      check_fixed_point_system<Sys>(spec);
      if (high_m_scheme_set<T>::applies(spec)) high_m_scheme_set<T>::check(spec);
    }
  });
}

/// The stepper of the free system called `system` (std::invalid_argument for an unknown one or
/// a spec outside the system's scheme set).
template <class T>
std::unique_ptr<any_stepper<T>> make_stepper(std::string_view system, const scheme_spec& spec) {
  return with_free_system(system, [&]<class Sys>() -> std::unique_ptr<any_stepper<T>> {
    if constexpr (is_zoo_system<Sys>) {
      zoo_scheme_set<Sys, T>::check(spec);  // before the factory, which may be a stub
      if constexpr (!zoo_scheme_set<Sys, T>::compiled) return nullptr;  // (check has thrown)
      else return make_system_stepper<Sys, T>(spec);
    } else if (high_m_scheme_set<T>::applies(spec)) {
      high_m_scheme_set<T>::check(spec);
      if constexpr (!high_m_scheme_set<T>::compiled) return nullptr;  // (check has thrown)
      else return make_high_m_stepper<Sys, T>(spec);
    } else {
      return make_system_stepper<Sys, T>(spec);
    }
  });
}

/// The system's initial data (q_0, qdot_0) (`Sys::initial_data`, mechanics/systems.hpp and
/// mechanics/zoo.hpp).
template <class T>
std::pair<dynamic_vector<T>, dynamic_vector<T>> default_initial_data(std::string_view system) {
  return with_free_system(system, [&]<class Sys>() {
    vec<T, Sys::dof> q, qdot;
    Sys::initial_data(q, qdot);
    return std::pair<dynamic_vector<T>, dynamic_vector<T>>(q, qdot);
  });
}

/// The initial state (q0, p0) of a free system for the tools: q0 from `q0_text` (if not empty)
/// or the system's default; p0 from `p0_text` (the canonical momentum, if not empty) or else
/// dL/dqdot(q0, qdot0) with the default velocity qdot0, so that a user's position is never
/// paired with the momentum of the default position (which would change the energy: charged
/// from q0 = (10, 0) with the default momentum starts with E = 32067.8 instead of 0.5).
/// std::invalid_argument naming the flag for a wrong count of values; `parse` reads one value.
template <class T, class Parse>
std::pair<dynamic_vector<T>, dynamic_vector<T>> default_initial_state(std::string_view system, const any_stepper<T>& stepper,
                                                                      const std::vector<std::string>& q0_text,
                                                                      const std::vector<std::string>& p0_text,
                                                                      const Parse& parse) {
  auto [q, qdot] = default_initial_data<T>(system);
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

}  // namespace geomint::tools
