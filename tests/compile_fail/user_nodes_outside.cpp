/// Rational collocation nodes outside [0, 1]: a readable compile error.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
#if GEOMINT_EXPECT_FAILURE
constexpr std::array<rational, 2> nodes{rational(1, 3), rational(3, 2)};
#else
constexpr std::array<rational, 2> nodes{rational(1, 3), rational(2, 3)};
#endif
constexpr geomint::exact_rkn_tableau tableau = geomint::collocation_tableau_from_nodes(nodes);
static_assert(tableau.stages == 2);
