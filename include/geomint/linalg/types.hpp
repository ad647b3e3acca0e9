#pragma once
/// Fixed-size vector and matrix aliases and finiteness checks, for every scalar type.

#include <cmath>

#include <Eigen/Core>
#include "geomint/core/multiprecision.hpp"

namespace geomint {

template <class S, int N>
using vec = Eigen::Matrix<S, N, 1>;
template <class S, int N>
using mat = Eigen::Matrix<S, N, N>;
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
