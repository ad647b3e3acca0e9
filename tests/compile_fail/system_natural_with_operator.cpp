/// A natural system that also defines operator() with a magnetic term: impossible, since the
/// fast path (potential and mass matrix only) would drop that term.
#include <geomint/integrator.hpp>
#if GEOMINT_EXPECT_FAILURE
struct magnetic : geomint::natural<magnetic, 2> {
#else
struct magnetic {
  static constexpr int dof = 2;
#endif
  template <class S>
  static S potential(const geomint::vec<S, 2>& q) { return (q[0] * q[0] + q[1] * q[1]) / S(2); }
  template <class S>
  static geomint::mat<S, 2> mass_matrix() { return geomint::mat<S, 2>::Identity(); }
  template <class S>
  S operator()(const geomint::vec<S, 2>& q, const geomint::vec<S, 2>& v) const {
    return (v[0] * v[0] + v[1] * v[1]) / S(2) + (q[0] * v[1] - q[1] * v[0]) / S(2) - potential<S>(q);
  }
};
constexpr bool ok = geomint::checked_system<magnetic, double>;
static_assert(ok);
