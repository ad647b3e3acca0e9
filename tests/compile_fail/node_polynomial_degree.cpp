/// A node polynomial whose leading coefficient is zero (its degree is not the number of
/// coefficients minus one): a readable compile error of the constant evaluation.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
#if GEOMINT_EXPECT_FAILURE
constexpr std::array<rational, 4> n{rational(1, 6), rational(-1), rational(1), rational(0)};
#else
constexpr std::array<rational, 3> n{rational(1, 6), rational(-1), rational(1)};  // x^2 - x + 1/6
#endif
constexpr geomint::exact_rkn_tableau tableau = geomint::collocation_tableau_from_polynomial(n);
static_assert(tableau.stages == 2);
