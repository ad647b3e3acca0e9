#pragma once
/// Run-time choices to compile-time types: the one dispatch mechanism of the library and its
/// tools. A run-time m, node family or basis calls a generic lambda with the matching template
/// argument, e.g. `geomint::with_int<2, 8>(m, [&]<int M>() { ... })` or
/// `geomint::with_node_family("gauss_interior", [&]<class Family>() { ... })`.
///
/// Names: a family is accepted under its printed name (`Family::name`: equispaced, lobatto,
/// chebyshev, gauss-interior) and under its type name (gauss_lobatto, chebyshev_lobatto,
/// gauss_interior), with '-' and '_' interchangeable.

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "geomint/core/basis.hpp"
#include "geomint/core/nodes.hpp"

namespace geomint {

/// The printed names of the node families and bases, in a fixed order.
inline constexpr std::array<std::string_view, 4> node_family_names = {equispaced::name, gauss_interior::name,
                                                                      gauss_lobatto::name, chebyshev_lobatto::name};
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

/// The printed name of the node family called `name` (see above), or nothing.
constexpr std::optional<std::string_view> canonical_node_family(std::string_view name) {
  using core::detail::same_name;
  if (same_name(name, equispaced::name)) return equispaced::name;
  if (same_name(name, gauss_interior::name)) return gauss_interior::name;
  if (same_name(name, gauss_lobatto::name) || same_name(name, "gauss_lobatto")) return gauss_lobatto::name;
  if (same_name(name, chebyshev_lobatto::name) || same_name(name, "chebyshev_lobatto")) return chebyshev_lobatto::name;
  return std::nullopt;
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
  if (family == equispaced::name) return f.template operator()<equispaced>();
  if (family == gauss_interior::name) return f.template operator()<gauss_interior>();
  if (family == gauss_lobatto::name) return f.template operator()<gauss_lobatto>();
  if (family == chebyshev_lobatto::name) return f.template operator()<chebyshev_lobatto>();
  throw std::invalid_argument("unknown node family '" + std::string(name) + "' (" +
                              core::detail::joined(node_family_names) + ")");
}

/// `f.template operator()<Basis>()` for the basis called `name`; std::invalid_argument otherwise.
template <class F>
decltype(auto) with_basis(std::string_view name, F&& f) {
  if (name == lagrange::name) return f.template operator()<lagrange>();
  if (name == bernstein::name) return f.template operator()<bernstein>();
  throw std::invalid_argument("unknown basis '" + std::string(name) + "' (" + core::detail::joined(basis_names) + ")");
}

}  // namespace geomint
