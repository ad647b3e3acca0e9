/// `geomint::rational a = 0.5;` used to compile (with no warning under -Wall -Wextra) and yield
/// 0/1; the conversion from floating point is deleted, rational(1, 2) is the exact spelling.
#include <geomint/core/rational.hpp>
#if GEOMINT_EXPECT_FAILURE
geomint::rational a = 0.5;
#else
geomint::rational a(1, 2);
#endif
