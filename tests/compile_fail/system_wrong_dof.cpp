/// dof = 2 but operator() takes vectors of size 1: the contract says to check dof.
#include <geomint/integrator.hpp>
struct oscillator {
#if GEOMINT_EXPECT_FAILURE
  static constexpr int dof = 2;
#else
  static constexpr int dof = 1;
#endif
  template <class S>
  S operator()(const geomint::vec<S, 1>& q, const geomint::vec<S, 1>& v) const { return (v[0] * v[0] - q[0] * q[0]) / S(2); }
};
constexpr bool ok = geomint::checked_system<oscillator, double>;
static_assert(ok);
