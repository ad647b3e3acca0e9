/// A node polynomial with a root outside [0, 1], x^2 - 3x/2 + 1/2 = (x - 1/2)(x - 1) is fine,
/// x^2 - 2x + 3/4 = (x - 1/2)(x - 3/2) is not: a readable compile error (Sturm count).
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
#if GEOMINT_EXPECT_FAILURE
constexpr std::array<rational, 3> n{rational(3, 4), rational(-2), rational(1)};
#else
constexpr std::array<rational, 3> n{rational(1, 2), rational(-3, 2), rational(1)};
#endif
constexpr geomint::exact_rkn_tableau tableau = geomint::collocation_tableau_from_polynomial(n);
static_assert(tableau.stages == 2);
