/// An integer literal above 2^63 - 1 (here 2^64 + 1, which GCC would truncate to 1 with only a
/// warning as a plain literal) is a compile error with geomint's _q literal, never a wrapped value.
#include <geomint/analysis/rkn_tableau.hpp>
using geomint::rational;
using namespace geomint::literals;
#if GEOMINT_EXPECT_FAILURE
constexpr rational node = rational(1) / 18446744073709551617_q;
#else
constexpr rational node = rational(1) / 9223372036854775807_q;
#endif
constexpr geomint::exact_rkn_tableau tableau =
    geomint::rational_rkn_tableau<1>({node}, {{{rational(0)}}}, {rational(1, 2)}, {rational(1)});
static_assert(tableau.stages == 1 && node.num == 1);
