/// A braced list with fewer entries than stages (here b) is a readable compile error, never a
/// tableau with a silent 0.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
constexpr geomint::exact_rkn_tableau tableau = geomint::rational_rkn_tableau<2>(
    {rational(0), rational(1)}, {{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}}, {rational(1, 2), rational(0)},
#if GEOMINT_EXPECT_FAILURE
    {rational(1, 2)});
#else
    {rational(1, 2), rational(1, 2)});
#endif
static_assert(tableau.stages == 2);
