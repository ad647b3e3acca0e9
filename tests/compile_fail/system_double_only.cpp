/// A Lagrangian written for double only: the contract says it must be templated on the scalar.
#include <geomint/integrator.hpp>
struct oscillator {
  static constexpr int dof = 1;
#if GEOMINT_EXPECT_FAILURE
  double operator()(const geomint::vec<double, 1>& q, const geomint::vec<double, 1>& v) const {
    return (v[0] * v[0] - q[0] * q[0]) / 2.0;
  }
#else
  template <class S>
  S operator()(const geomint::vec<S, 1>& q, const geomint::vec<S, 1>& v) const { return (v[0] * v[0] - q[0] * q[0]) / S(2); }
#endif
};
constexpr bool ok = geomint::checked_system<oscillator, double>;
static_assert(ok);
