// An outside project using the installed package.
#include <geomint/geomint.hpp>
#include <iostream>

constexpr auto D2 = geomint::differentiation_weights<2, geomint::equispaced, 2, geomint::rational>();
static_assert(D2[1][1] == geomint::rational(-8));
// An analysis beyond the compilers' default constant-evaluation budget: it compiles only with the
// limit that geomint::geomint sets for its consumers (docs/guide/building.md). Gauss collocation
// is symplectic, so det M = 1 on y'' = -y.
static_assert(geomint::linear_stability(geomint::galerkin_tableau<8>()).determinant_is_one);

int main() {
  const auto c = geomint::nodes<geomint::gauss_lobatto, 4, double>();
  // The interior Lobatto nodes for m = 4 are (1 -+ sqrt(3/7))/2 and 1/2.
  const double expected = 0.5 * (1.0 - std::sqrt(3.0 / 7.0));
  if (std::abs(c[1] - expected) > 4 * std::numeric_limits<double>::epsilon()) {
    std::cout << "consumer: wrong node " << c[1] << "\n";
    return 1;
  }
  std::cout << "consumer: ok\n";
  return 0;
}
