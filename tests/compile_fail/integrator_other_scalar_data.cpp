/// Double initial data given to a 50-digit integrator: a compile error that asks for an
/// explicit conversion (.template cast<T>()).
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <geomint/core/multiprecision.hpp>
#include <geomint/integrator.hpp>
#include <geomint/mechanics/systems.hpp>
using T = boost::multiprecision::cpp_bin_float_50;
int main() {
  geomint::integrator<geomint::midpoint_vi, geomint::systems::pendulum, T> integrator(geomint::systems::pendulum{},
                                                                                         T(1) / T(10));
  const geomint::vec<double, 1> q0(1.0), v0(0.0);
#if GEOMINT_EXPECT_FAILURE
  auto s = integrator.initial_state(q0, v0);
#else
  auto s = integrator.initial_state(q0.template cast<T>(), v0.template cast<T>());
#endif
  integrator.step(s);
  return s.step == 1 ? 0 : 1;
}
