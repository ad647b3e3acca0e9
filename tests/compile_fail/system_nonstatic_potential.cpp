/// A natural system whose potential is not static: the contract asks for static members.
#include <geomint/integrator.hpp>
struct oscillator : geomint::natural<oscillator, 1> {
  template <class S>
#if GEOMINT_EXPECT_FAILURE
  S potential(const geomint::vec<S, 1>& q) const { return q[0] * q[0] / S(2); }
#else
  static S potential(const geomint::vec<S, 1>& q) { return q[0] * q[0] / S(2); }
#endif
  template <class S>
  static geomint::mat<S, 1> mass_matrix() { return geomint::mat<S, 1>::Identity(); }
};
constexpr bool ok = geomint::checked_system<oscillator, double>;
static_assert(ok);
