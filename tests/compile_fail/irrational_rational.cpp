/// Gauss-Lobatto nodes are irrational: asking for them in `rational` is a readable error.
#include <geomint/core/nodes.hpp>
#if GEOMINT_EXPECT_FAILURE
constexpr auto c = geomint::nodes<geomint::gauss_lobatto, 3, geomint::rational>();
#else
constexpr auto c = geomint::nodes<geomint::equispaced, 3, geomint::rational>();
#endif
static_assert(c[3] == geomint::rational(1));
