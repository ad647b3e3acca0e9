#pragma once
/// Run-time choices to compile-time types: the one dispatch mechanism of the library and its
/// tools. A run-time m, node family or basis calls a generic lambda with the matching template
/// argument, e.g. `geomint::with_int<2, 8>(m, [&]<int M>() { ... })` or
/// `geomint::with_node_family("gauss_interior", [&]<class Family>() { ... })`.
///
/// Names: a family is accepted under its printed name (`Family::name`: equispaced, lobatto,
/// chebyshev, gauss-interior, radau-right, radau-left) and under its type name
/// (`Family::type_name`: gauss_lobatto, chebyshev_lobatto, ...), with '-' and '_'
/// interchangeable.

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "geomint/core/basis.hpp"
#include "geomint/core/nodes.hpp"

namespace geomint {

/// A list of types (the node families).
template <class... F>
struct type_list {};

/// Every node family (core/nodes.hpp), in the order the tools list them: the one list of them.
using node_families = type_list<equispaced, gauss_interior, gauss_lobatto, chebyshev_lobatto, radau_right, radau_left>;

namespace core::detail {
template <class... F>
constexpr std::array<std::string_view, sizeof...(F)> printed_names(type_list<F...>) {
  return {F::name...};
}
}  // namespace core::detail

/// The printed names of the node families and bases, in a fixed order.
inline constexpr auto node_family_names = core::detail::printed_names(node_families{});
inline constexpr std::array<std::string_view, 2> basis_names = {lagrange::name, bernstein::name};

namespace core::detail {
/// a == b with '-' and '_' equal.
constexpr bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const char x = a[i] == '_' ? '-' : a[i], y = b[i] == '_' ? '-' : b[i];
    if (x != y) return false;
  }
  return true;
}
inline std::string joined(const auto& names) {
  std::string out;
  for (std::string_view n : names) {
    if (!out.empty()) out.push_back('|');
    out.append(n);
  }
  return out;
}
}  // namespace core::detail

namespace core::detail {
template <class... F>
constexpr std::optional<std::string_view> canonical_in(std::string_view name, type_list<F...>) {
  const std::string_view printed[] = {F::name...}, types[] = {F::type_name...};
  for (std::size_t i = 0; i < sizeof...(F); ++i)
    if (same_name(name, printed[i]) || same_name(name, types[i])) return printed[i];
  return std::nullopt;
}
template <class First, class... Rest, class F>
decltype(auto) with_family_from(std::string_view printed, F&& f) {
  if constexpr (sizeof...(Rest) > 0) {
    if (printed != First::name) return with_family_from<Rest...>(printed, static_cast<F&&>(f));
  }
  return f.template operator()<First>();
}
template <class... Families, class F>
decltype(auto) with_family_in(std::string_view printed, F&& f, type_list<Families...>) {
  return with_family_from<Families...>(printed, static_cast<F&&>(f));
}
}  // namespace core::detail

/// The printed name of the node family called `name` (see above), or nothing.
constexpr std::optional<std::string_view> canonical_node_family(std::string_view name) {
  return core::detail::canonical_in(name, node_families{});
}

namespace core::detail {
template <int V, int Hi, class F>
decltype(auto) with_int_from(int value, F&& f) {
  if constexpr (V < Hi) {
    if (value != V) return with_int_from<V + 1, Hi>(value, static_cast<F&&>(f));
  }
  return f.template operator()<V>();
}
}  // namespace core::detail

/// `f.template operator()<V>()` for the run-time value in [Lo, Hi]; std::invalid_argument outside.
template <int Lo, int Hi, class F>
decltype(auto) with_int(int value, F&& f) {
  static_assert(Lo <= Hi, "geomint::with_int: empty range");
  if (value < Lo || value > Hi)
    throw std::invalid_argument("must be an integer in " + std::to_string(Lo) + ".." + std::to_string(Hi) + ", got " +
                                std::to_string(value));
  return core::detail::with_int_from<Lo, Hi>(value, static_cast<F&&>(f));
}

/// `f.template operator()<Family>()` for the family called `name`; std::invalid_argument otherwise.
template <class F>
decltype(auto) with_node_family(std::string_view name, F&& f) {
  const auto family = canonical_node_family(name);
  if (!family)
    throw std::invalid_argument("unknown node family '" + std::string(name) + "' (" + core::detail::joined(node_family_names) + ")");
  return core::detail::with_family_in(*family, static_cast<F&&>(f), node_families{});
}

/// `f.template operator()<Basis>()` for the basis called `name`; std::invalid_argument otherwise.
template <class F>
decltype(auto) with_basis(std::string_view name, F&& f) {
  if (name == lagrange::name) return f.template operator()<lagrange>();
  if (name == bernstein::name) return f.template operator()<bernstein>();
  throw std::invalid_argument("unknown basis '" + std::string(name) + "' (" + core::detail::joined(basis_names) + ")");
}

}  // namespace geomint
