/// A user RKN tableau with floating-point entries (not exact): a readable static_assert.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
#if GEOMINT_EXPECT_FAILURE
using entry = double;
constexpr std::array<entry, 2> c{0.0, 1.0};
#else
using entry = rational;
constexpr std::array<entry, 2> c{rational(0), rational(1)};
#endif
constexpr std::array<rational, 2> bbar{rational(1, 2), rational(0)}, b{rational(1, 2), rational(1, 2)};
constexpr std::array<std::array<rational, 2>, 2> a{{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}};
constexpr geomint::exact_rkn_tableau tableau = geomint::rational_rkn_tableau(c, a, bbar, b);
static_assert(tableau.stages == 2);
