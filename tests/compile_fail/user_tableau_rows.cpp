/// A user RKN tableau whose matrix a has a row too many for its two stages: a readable
/// static_assert of geomint::rational_rkn_tableau.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
constexpr std::array<rational, 2> c{rational(0), rational(1)}, bbar{rational(1, 2), rational(0)}, b{rational(1, 2), rational(1, 2)};
#if GEOMINT_EXPECT_FAILURE
constexpr std::array<std::array<rational, 2>, 3> a{{{rational(0), rational(0)}, {rational(1, 2), rational(0)}, {rational(0), rational(0)}}};
#else
constexpr std::array<std::array<rational, 2>, 2> a{{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}};
#endif
constexpr geomint::exact_rkn_tableau tableau = geomint::rational_rkn_tableau(c, a, bbar, b);
static_assert(tableau.stages == 2);
