/// A row of a with fewer entries than stages is a readable compile error, never a silent 0.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
constexpr geomint::exact_rkn_tableau tableau = geomint::rational_rkn_tableau<2>(
    {rational(0), rational(1)},
#if GEOMINT_EXPECT_FAILURE
    {{{rational(0), rational(0)}, {rational(1, 2)}}},
#else
    {{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}},
#endif
    {rational(1, 2), rational(0)}, {rational(1, 2), rational(1, 2)});
static_assert(tableau.stages == 2);
