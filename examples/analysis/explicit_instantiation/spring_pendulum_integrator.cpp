/// The one translation unit that instantiates the 50-digit spring-pendulum integrator.
#include "spring_pendulum_integrator.hpp"

#include <geomint/core/multiprecision.hpp>
#include <geomint/integrator.hpp>
#include <geomint/mechanics/zoo.hpp>

namespace spring {
result run(const scalar& r0, const scalar& phi0, const scalar& tau, long steps) {
  using T = scalar;
  geomint::integrator<geomint::lpf<4, geomint::gauss_interior>, geomint::zoo::spring_pendulum, T> I(
      geomint::zoo::spring_pendulum{}, tau);
  auto s = I.initial_state(geomint::vec<T, 2>(r0, phi0), geomint::vec<T, 2>(T(0), T(0)));
  const T e0 = I.energy(s);
  I.advance(s, steps);
  using std::abs;
  return {s.q[0], s.q[1], T(abs(T(I.energy(s) - e0)))};
}
}  // namespace spring
