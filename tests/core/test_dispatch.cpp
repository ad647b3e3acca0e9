/// core/dispatch.hpp: run-time choices to template arguments. Expected values are the
/// definitions themselves (the type each name denotes, the value each m denotes) and the
/// documented spellings.
#include <geomint/core/dispatch.hpp>

#include <stdexcept>
#include <string>
#include <type_traits>

#include "catch.hpp"

using namespace geomint;

namespace {
template <class Family>
std::string family_of() {
  return std::string(Family::name);
}
}  // namespace

TEST_CASE("dispatch: with_int calls the lambda with the chosen value, and rejects values outside the range") {
  for (int m = 2; m <= 8; ++m) CHECK(with_int<2, 8>(m, []<int M>() { return M; }) == m);
  CHECK(with_int<5, 5>(5, []<int M>() { return M * 10; }) == 50);
  CHECK_THROWS_AS((with_int<2, 8>(1, []<int M>() { return M; })), std::invalid_argument);
  CHECK_THROWS_AS((with_int<2, 8>(9, []<int M>() { return M; })), std::invalid_argument);
  try {
    with_int<2, 8>(9, []<int M>() { return M; });
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "must be an integer in 2..8, got 9");
  }
}

TEST_CASE("dispatch: node families under their printed and their type names, '-' and '_' alike") {
  auto name = [](const char* text) { return with_node_family(text, []<class F>() { return family_of<F>(); }); };
  CHECK(name("equispaced") == "equispaced");
  CHECK(name("gauss-interior") == "gauss-interior");
  CHECK(name("gauss_interior") == "gauss-interior");
  CHECK(name("lobatto") == "lobatto");
  CHECK(name("gauss_lobatto") == "lobatto");
  CHECK(name("gauss-lobatto") == "lobatto");
  CHECK(name("chebyshev") == "chebyshev");
  CHECK(name("chebyshev_lobatto") == "chebyshev");
  CHECK(name("chebyshev-lobatto") == "chebyshev");
  CHECK(name("radau-right") == "radau-right");
  CHECK(name("radau_right") == "radau-right");
  CHECK(name("radau_left") == "radau-left");
  CHECK(with_node_family("gauss_interior", []<class F>() { return std::is_same_v<F, gauss_interior>; }));
  CHECK(with_node_family("radau-left", []<class F>() { return std::is_same_v<F, radau_left>; }));
  // The error names every family of the one list (node_families).
  try {
    name("gauss");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "unknown node family 'gauss' (equispaced|gauss-interior|lobatto|chebyshev|radau-right|radau-left)");
  }
  CHECK_THROWS_AS(name("gauss"), std::invalid_argument);
  CHECK_THROWS_AS(name(""), std::invalid_argument);
  static_assert(canonical_node_family("gauss_lobatto") == gauss_lobatto::name);
  static_assert(!canonical_node_family("legendre"));
}

TEST_CASE("dispatch: bases by name") {
  CHECK(with_basis("lagrange", []<class B>() { return std::is_same_v<B, lagrange>; }));
  CHECK(with_basis("bernstein", []<class B>() { return std::is_same_v<B, bernstein>; }));
  CHECK_THROWS_AS(with_basis("chebyshev", []<class B>() { return 0; }), std::invalid_argument);
}
