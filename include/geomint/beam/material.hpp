#pragma once
/// Material matrices of the geometrically exact beam (docs/design.md, "Beam conventions").
///
/// For a square section of side a (the beam paper leaves them implicit):
///   A = a^2, I = a^4/12, J = 2I, G = E/(2(1+nu)), no shear correction;
///   D1 = diag(rho I, rho J, rho I, rho A, rho A, rho A)   (inertia per unit length),
///   D2 = diag(E I, G J, E I, G A, E A, G A)                (stiffness).
/// Component order is xi = (omega, v); the beam axis is E2, so the second entry is torsion
/// (J, GJ) and the fifth is extension (EA).

#include <stdexcept>

#include "geomint/lie/se3.hpp"

namespace geomint::beam {

template <class T>
struct material {
  lie::vec6<T> D1;  ///< diagonal of the inertia matrix
  lie::vec6<T> D2;  ///< diagonal of the stiffness matrix

  /// Square cross-section of side a, density rho, Young's modulus E, Poisson ratio nu.
  static material square_section(const T& a, const T& rho, const T& E, const T& nu) {
    if (!(a > T(0)) || !(rho > T(0)) || !(E > T(0)) || !(nu > T(-1)))
      throw std::invalid_argument("geomint::beam::material::square_section: need a > 0, rho > 0, E > 0, nu > -1");
    const T A = a * a;
    const T I = A * A / T(12);
    const T J = T(2) * I;
    const T G = E / (T(2) * (T(1) + nu));
    material m;
    m.D1 << rho * I, rho * J, rho * I, rho * A, rho * A, rho * A;
    m.D2 << E * I, G * J, E * I, G * A, E * A, G * A;
    return m;
  }

  /// Checks that both diagonals are finite and positive (the Hamiltonian is then convex).
  void validate() const {
    for (int i = 0; i < 6; ++i)
      if (!(D1(i) > T(0)) || !(D2(i) > T(0)) || !(D1(i) - D1(i) == T(0)) || !(D2(i) - D2(i) == T(0)))
        throw std::invalid_argument("geomint::beam::material: D1 and D2 must be finite and positive");
  }
};

}  // namespace geomint::beam
