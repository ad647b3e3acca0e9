/// A system without `static constexpr int dof`: the contract names the missing member.
#include <geomint/integrator.hpp>
struct oscillator {
#if !GEOMINT_EXPECT_FAILURE
  static constexpr int dof = 1;
#endif
  template <class S>
  S operator()(const geomint::vec<S, 1>& q, const geomint::vec<S, 1>& v) const { return (v[0] * v[0] - q[0] * q[0]) / S(2); }
};
using I = geomint::integrator<geomint::midpoint_vi, oscillator, double>;
int main() {
  I integrator(oscillator{}, 0.1);
  auto s = integrator.initial_state(geomint::vec<double, 1>(1.0), geomint::vec<double, 1>(0.0));
  integrator.step(s);
  return s.step == 1 ? 0 : 1;
}
