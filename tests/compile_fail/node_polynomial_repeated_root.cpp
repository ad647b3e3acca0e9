/// A node polynomial with a repeated root, (x - 1/2)^2: a readable compile error.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
#if GEOMINT_EXPECT_FAILURE
constexpr std::array<rational, 3> n{rational(1, 4), rational(-1), rational(1)};
#else
constexpr std::array<rational, 3> n{rational(1, 6), rational(-1), rational(1)};
#endif
constexpr geomint::exact_rkn_tableau tableau = geomint::collocation_tableau_from_polynomial(n);
static_assert(tableau.stages == 2);
