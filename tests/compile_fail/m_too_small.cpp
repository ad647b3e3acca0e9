/// m = 0 has no interval: a readable static_assert, not a template error cascade.
#include <geomint/core/nodes.hpp>
#if GEOMINT_EXPECT_FAILURE
constexpr auto c = geomint::nodes<geomint::gauss_lobatto, 0, double>();
#else
constexpr auto c = geomint::nodes<geomint::gauss_lobatto, 1, double>();
#endif
static_assert(c[0] == 0.0);
