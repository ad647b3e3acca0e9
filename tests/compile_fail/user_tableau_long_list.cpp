/// A braced list with more entries than stages (here c) is a readable compile error.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
constexpr geomint::exact_rkn_tableau tableau = geomint::rational_rkn_tableau<2>(
#if GEOMINT_EXPECT_FAILURE
    {rational(0), rational(1), rational(1)},
#else
    {rational(0), rational(1)},
#endif
    {{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}}, {rational(1, 2), rational(0)}, {rational(1, 2), rational(1, 2)});
static_assert(tableau.stages == 2);
