/// A rational overflow in a constant expression is a compile error, never a wrapped value.
#include <geomint/core/rational.hpp>
#include <cstdint>
#include <limits>
constexpr geomint::rational big(std::numeric_limits<std::int64_t>::max());
#if GEOMINT_EXPECT_FAILURE
constexpr geomint::rational r = big + geomint::rational(1);
#else
constexpr geomint::rational r = big - geomint::rational(1);
#endif
static_assert(r.den == 1);
