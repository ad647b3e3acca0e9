/// Exact weights are supported up to max_exact_m; beyond, a readable static_assert.
#include <geomint/core/differentiation.hpp>
#if GEOMINT_EXPECT_FAILURE
constexpr auto D = geomint::differentiation_weights<1, geomint::equispaced, geomint::max_exact_m + 1, geomint::rational>();
#else
constexpr auto D = geomint::differentiation_weights<1, geomint::equispaced, geomint::max_exact_m, geomint::rational>();
#endif
static_assert(D[0][0] < geomint::rational(0));
