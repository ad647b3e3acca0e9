/// A tableau with a list of the wrong length is a readable static_assert, never a silent zero.
#include <geomint/methods/tableau.hpp>
#include <geomint/core/rational.hpp>
using R = geomint::rational;
#if GEOMINT_EXPECT_FAILURE
constexpr auto verlet = geomint::methods::make_rkn<R>({0, 1}, {{0, 0}, {R(1, 2), 0}}, {R(1, 2)}, {R(1, 2), R(1, 2)});
#else
constexpr auto verlet = geomint::methods::make_rkn<R>({0, 1}, {{0, 0}, {R(1, 2), 0}}, {R(1, 2), 0}, {R(1, 2), R(1, 2)});
#endif
static_assert(verlet.stages == 2);
