#pragma once
/// Fixed-size vector and matrix aliases and finiteness checks, for every scalar type.

#include <cmath>
#include <cstddef>
#include <type_traits>

#include <Eigen/Core>

#include "geomint/core/scalar_traits.hpp"  // eigen_scalar_ready

namespace geomint {

template <class S, int N>
using vec = Eigen::Matrix<S, N, 1>;
template <class S, int N>
using mat = Eigen::Matrix<S, N, N>;

/// Bytes above which an N x N matrix of a compile-time size is kept on the heap (square_matrix):
/// half of Eigen's limit for a fixed-size object (EIGEN_STACK_ALLOCATION_LIMIT, 128 KiB), the
/// bound mechanics/lagrangian.hpp also uses. The Newton matrix of an implicit step of m (dof)
/// unknowns crosses it e.g. for the outer solar system (18 dof) from m = 6 in double and m = 2
/// in 50 digits; the pendulum and the Kepler problem stay below it at every m up to 16, in
/// double and in 50 digits.
inline constexpr std::size_t stack_matrix_bytes = std::size_t(64) * 1024;

/// Whether square_matrix<S, N> is on the heap.
template <class S, int N>
inline constexpr bool heap_matrix = sizeof(S) * static_cast<std::size_t>(N) * static_cast<std::size_t>(N) > stack_matrix_bytes;

/// An N x N matrix whose size is known at compile time: fixed-size (no allocation, loops of known
/// length) up to stack_matrix_bytes, above that a dynamic-size Eigen matrix of N x N on the heap,
/// so that large systems neither exceed Eigen's fixed-size limit nor fill the stack. Owners of a
/// large one allocate it once (e.g. with an engine's step memory) and reuse it.
template <class S, int N>
using square_matrix = std::conditional_t<heap_matrix<S, N>, Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>, mat<S, N>>;

/// A square_matrix<S, N> of N x N (allocated if it is on the heap), its entries unset.
template <class S, int N>
square_matrix<S, N> make_square_matrix() {
  if constexpr (heap_matrix<S, N>)
    return square_matrix<S, N>(N, N);
  else
    return square_matrix<S, N>();
}

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
