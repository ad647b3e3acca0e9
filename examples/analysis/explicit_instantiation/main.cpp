/// Uses the integrator through its compile firewall: this file does not include geomint.
#include <iostream>

#include "spring_pendulum_integrator.hpp"

int main() {
  using T = spring::scalar;
  const spring::result out = spring::run(T(11) / 10, T(1) / 2, T(1) / 10, 100);
  // Printed as double: streaming a 50-digit number here trips a false -Wrestrict of GCC 12 -O3
  // inside Boost's formatter.
  std::cout << "r(10) = " << static_cast<double>(out.r) << ", phi(10) = " << static_cast<double>(out.phi)
            << "\nenergy error = " << static_cast<double>(out.energy_error) << "\n";
  return out.energy_error < T(1) / 1000 ? 0 : 1;
}
