/// Uses the integrator through its compile firewall: this file does not include geomint.
#include <iostream>

#include "spring_pendulum_integrator.hpp"

int main() {
  using T = spring::scalar;
  const spring::result out = spring::run(T(11) / 10, T(1) / 2, T(1) / 10, 100);
  std::cout.precision(30);
  std::cout << "r(10) = " << out.r << ", phi(10) = " << out.phi << "\nenergy error = " << out.energy_error << "\n";
  return out.energy_error < T(1) / 1000 ? 0 : 1;
}
