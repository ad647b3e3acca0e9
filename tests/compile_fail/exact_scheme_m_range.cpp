/// The exact derivation is defined for m = 2..8: m = 9 gives a readable static_assert.
#include <geomint/analysis/exact_scheme.hpp>
#if GEOMINT_EXPECT_FAILURE
constexpr auto scheme = geomint::exact_two_step<9>();
#else
constexpr auto scheme = geomint::exact_two_step<2>();
#endif
static_assert(scheme.order >= 2);
