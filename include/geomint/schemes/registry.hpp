#pragma once
/// The built-in schemes by name: the one list of them. `make_stepper` (geomint/stepper.hpp), the
/// tools' `--scheme` choices, their usage texts and their option checks read it; a scheme added
/// here and given its type in make_stepper is known to every tool.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/core/nodes.hpp"

namespace geomint {

/// What the tools know of a built-in scheme.
struct scheme_entry {
  std::string_view name{};
  bool has_m = false;              ///< it has a degree m (--m)
  bool has_nodes = false;          ///< a node family and a basis are chosen (--nodes, --basis)
  std::string_view fixed_nodes{};  ///< its node family by construction (printed name), if any
  bool natural_only = false;       ///< it runs on natural systems only
  bool exact_tableau = false;      ///< the exact analysis has its tableau (geomint-scheme, geomint-modified)
  int exact_min_m = 0;             ///< the least m of the exact analysis
  std::string_view nodes_note{};   ///< why --nodes does not apply, where it is not obvious
};

/// Every built-in scheme, in the order of the usage texts. lpf-fixed-point is LPF on
/// Gauss-interior nodes with the fixed-point solver (schemes/lpf_fixed_point.hpp), kept for one
/// release; galerkin's Gauss points are no choice of nodes.
inline constexpr std::array<scheme_entry, 5> scheme_registry{{
    {.name = "lpf", .has_m = true, .has_nodes = true, .exact_tableau = true, .exact_min_m = 2},
    {.name = "lpf-fixed-point", .has_m = true, .fixed_nodes = gauss_interior::name, .natural_only = true,
     .nodes_note = "Gauss-interior nodes by construction"},
    {.name = "midpoint", .exact_tableau = true},
    {.name = "trapezoidal", .exact_tableau = true},
    {.name = "galerkin", .has_m = true, .exact_tableau = true, .exact_min_m = 1,
     .nodes_note = "its map does not depend on nodes"},
}};

/// The entry of `name`, or null.
constexpr const scheme_entry* find_scheme(std::string_view name) {
  for (const scheme_entry& e : scheme_registry)
    if (e.name == name) return &e;
  return nullptr;
}

/// Whether the scheme called `name` takes a node family and a basis.
constexpr bool takes_nodes(std::string_view name) {
  const scheme_entry* e = find_scheme(name);
  return e && e->has_nodes;
}

/// The names of the entries for which pred(entry) holds, joined by `separator`, the last two by
/// `last` ("lpf, lpf-fixed-point and galerkin").
template <class Pred>
std::string scheme_names_where(Pred pred, std::string_view separator = ", ", std::string_view last = ", ") {
  std::string out;
  std::size_t count = 0, total = 0;
  for (const scheme_entry& e : scheme_registry) total += pred(e) ? 1 : 0;
  for (const scheme_entry& e : scheme_registry) {
    if (!pred(e)) continue;
    if (count > 0) out += (count + 1 == total) ? last : separator;
    out += e.name;
    ++count;
  }
  return out;
}

/// Every scheme's name, "lpf|lpf-fixed-point|...", as the usage texts list the choices.
inline std::string scheme_choices() {
  return scheme_names_where([](const scheme_entry&) { return true; }, "|", "|");
}

/// The schemes with a degree m, "lpf, lpf-fixed-point and galerkin"; with `exact_only`, those of
/// the exact analysis.
inline std::string schemes_with_m(bool exact_only = false) {
  return scheme_names_where([&](const scheme_entry& e) { return e.has_m && (e.exact_tableau || !exact_only); }, ", ", " and ");
}

/// The schemes that take a node family and a basis; with `exact_only`, those of the exact analysis.
inline std::string schemes_with_nodes(bool exact_only = false) {
  return scheme_names_where([&](const scheme_entry& e) { return e.has_nodes && (e.exact_tableau || !exact_only); }, ", ", " and ");
}

/// Why --nodes does not apply to each scheme that has an m but no nodes, joined by "; ":
/// "lpf-fixed-point: Gauss-interior nodes by construction; galerkin: its map does not depend on nodes".
inline std::string nodes_notes() {
  std::string out;
  for (const scheme_entry& e : scheme_registry) {
    if (e.nodes_note.empty()) continue;
    out += (out.empty() ? "" : "; ") + std::string(e.name) + ": " + std::string(e.nodes_note);
  }
  return out;
}

/// The schemes with an exact tableau of their own: the --scheme choices of the exact-analysis tools.
inline std::vector<std::string> exact_scheme_names() {
  std::vector<std::string> out;
  for (const scheme_entry& e : scheme_registry)
    if (e.exact_tableau) out.emplace_back(e.name);
  return out;
}

}  // namespace geomint
