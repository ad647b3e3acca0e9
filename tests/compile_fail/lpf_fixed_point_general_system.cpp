/// The fixed-point form of LPF needs a natural system: a general Lagrangian is refused with a
/// message that names the Newton form instead.
#include <geomint/integrator.hpp>
#include <geomint/mechanics/systems.hpp>
#include <geomint/schemes/lpf_fixed_point.hpp>
#if GEOMINT_EXPECT_FAILURE
using sys = geomint::general<geomint::systems::pendulum>;
#else
using sys = geomint::systems::pendulum;
#endif
geomint::vec<double, 1> one_step() {
  geomint::integrator<geomint::lpf_fixed_point<4>, sys, double> I(sys{}, 0.1);
  auto s = I.initial_state(geomint::vec<double, 1>(1.0), geomint::vec<double, 1>(0.0));
  I.step(s);
  return s.q;
}
