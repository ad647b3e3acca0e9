#pragma once
/// Fixed-size vector and matrix aliases and finiteness checks, for every scalar type.

#include <cmath>
#include <type_traits>

#include <Eigen/Core>

namespace geomint {

template <class S, int N>
using vec = Eigen::Matrix<S, N, 1>;
template <class S, int N>
using mat = Eigen::Matrix<S, N, N>;

/// Whether Eigen has the traits of scalar S: true for built-in types; for a Boost.Multiprecision
/// number (a type with a backend_type) only once core/multiprecision.hpp is included, which
/// specialises this trait. The integrators assert it with a message naming the include.
template <class S>
struct eigen_scalar_ready : std::true_type {};
template <class S>
  requires requires { typename S::backend_type; }
struct eigen_scalar_ready<S> : std::false_type {};

/// A vector whose size is known at run time only (type-erased steppers, studies).
template <class S>
using dynamic_vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;

template <class T>
bool is_finite(const T& x) {
  using std::isfinite;
  return static_cast<bool>(isfinite(x));
}
template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& m) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (!is_finite(m(i, j))) return false;
  return true;
}

}  // namespace geomint

// Boost.Multiprecision's Eigen traits (core/multiprecision.hpp) are parsed only when
// Boost.Multiprecision is already in use (its number.hpp was included before this header): a
// file with built-in scalars only then does not parse Boost.Multiprecision, about 1.2 s of
// GCC 12 time per file (docs/results/compile_time.md). geomint/geomint.hpp includes them always.
#if defined(BOOST_MATH_EXTENDED_REAL_HPP) || defined(BOOST_MP_NUMBER_HPP)
#include "geomint/core/multiprecision.hpp"
#endif
