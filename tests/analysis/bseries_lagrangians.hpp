#pragma once
/// A Lagrangian that is not natural and a relative comparison, shared by the suites of
/// analysis/bseries/lagrangian_field.hpp and analysis/bseries/lagrangian_hamiltonian.hpp.
#include <cmath>
#include <limits>

#include "catch.hpp"
#include "geomint/linalg/types.hpp"

namespace bseries_lagrangians {

/// L = (1 + q^2) qdot^2 / 2 - q^4 / 4.
struct variable_mass {
  static constexpr int dof = 1;
  template <class S>
  S operator()(const geomint::vec<S, 1>& q, const geomint::vec<S, 1>& v) const {
    return S((S(1) + q[0] * q[0]) * v[0] * v[0] / S(2) - q[0] * q[0] * q[0] * q[0] / S(4));
  }
};

/// |value - expected| within 64 eps (1 + |expected|).
template <class T>
void check_close(const T& value, const T& expected) {
  using std::abs;
  CHECK(T(abs(T(value - expected))) <= T(64) * std::numeric_limits<T>::epsilon() * (T(1) + T(abs(expected))));
}

}  // namespace bseries_lagrangians
