/// An rkn tableau (q'' = f(q)) on a Lagrangian that is not natural: a readable static_assert.
#include <geomint/integrator.hpp>
#include <geomint/mechanics/systems.hpp>
#include <geomint/methods/tableau_method.hpp>
using R = geomint::rational;
struct verlet {
  static auto tableau() {
    return geomint::methods::make_rkn<R>({0, 1}, {{0, 0}, {R(1, 2), 0}}, {R(1, 2), 0}, {R(1, 2), R(1, 2)});
  }
};
#if GEOMINT_EXPECT_FAILURE
using chosen_system = geomint::systems::charged;
#else
using chosen_system = geomint::systems::pendulum;
#endif
using chosen_integrator = geomint::integrator<geomint::methods::tableau_method<verlet>, chosen_system, double>;
chosen_integrator make() { return chosen_integrator(); }
