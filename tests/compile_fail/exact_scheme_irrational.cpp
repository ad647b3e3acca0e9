/// Gauss-Lobatto nodes are irrational for m >= 3: no exact scheme, a readable static_assert.
#include <geomint/analysis/exact_scheme.hpp>
#if GEOMINT_EXPECT_FAILURE
constexpr auto scheme = geomint::exact_two_step<3, geomint::gauss_lobatto>();
#else
constexpr auto scheme = geomint::exact_two_step<3, geomint::equispaced>();
#endif
static_assert(scheme.order == 2);
