#pragma once
/// Small dense linear algebra: LU with complete pivoting for fixed sizes, solve and inverse.

#include <limits>

#include <Eigen/Core>
#include "geomint/linalg/types.hpp"

namespace geomint {

/// LU factorisation with complete pivoting (P A Q = L U) of a small fixed-size matrix, kept for
/// reuse (e.g. across Newton iterations); singular to working precision when the largest
/// remaining pivot is <= N eps max|A|. Written out instead of Eigen::FullPivLU: same algorithm,
/// but a fraction of the compile time per matrix size, which matters for the many (m, n) sizes
/// a program instantiates.
template <class T, int N>
class lu_small {
 public:
  /// False if A is singular to working precision or not finite.
  bool factor(const mat<T, N>& A) {
    using std::abs;
    if (!all_finite(A)) return false;  // a NaN would slip through the pivot comparisons
    lu_ = A;
    T scale(0);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        if (abs(lu_(i, j)) > scale) scale = abs(lu_(i, j));
    if (!is_finite(scale)) return false;
    const T tiny = T(N) * std::numeric_limits<T>::epsilon() * scale;
    for (int k = 0; k < N; ++k) {
      int pr = k, pc = k;
      T best(-1);
      for (int i = k; i < N; ++i)
        for (int j = k; j < N; ++j)
          if (abs(lu_(i, j)) > best) {
            best = abs(lu_(i, j));
            pr = i;
            pc = j;
          }
      if (!(best > tiny)) return false;
      row_[static_cast<std::size_t>(k)] = pr;
      col_[static_cast<std::size_t>(k)] = pc;
      if constexpr (N > 1) {
        if (pr != k)
          for (int j = 0; j < N; ++j) std::swap(lu_(k, j), lu_(pr, j));
        if (pc != k)
          for (int i = 0; i < N; ++i) std::swap(lu_(i, k), lu_(i, pc));
      }
      const T inv = T(1) / lu_(k, k);
      for (int i = k + 1; i < N; ++i) {
        const T f = lu_(i, k) * inv;
        lu_(i, k) = f;
        if (f == T(0)) continue;
        for (int j = k + 1; j < N; ++j) lu_(i, j) -= f * lu_(k, j);
      }
    }
    return true;
  }
  /// x = A^{-1} b; false if x is not finite.
  bool solve(vec<T, N> b, vec<T, N>& x) const {
    // The multipliers were swapped with their rows, so all row swaps come first (P b).
    if constexpr (N > 1) {
      for (int k = 0; k < N; ++k) {
        const int r = row_[static_cast<std::size_t>(k)];
        if (r != k) std::swap(b[k], b[r]);
      }
    }
    for (int k = 0; k < N; ++k)
      for (int i = k + 1; i < N; ++i) b[i] -= lu_(i, k) * b[k];
    for (int k = N - 1; k >= 0; --k) {
      T sum = b[k];
      for (int j = k + 1; j < N; ++j) sum -= lu_(k, j) * b[j];
      b[k] = sum / lu_(k, k);
    }
    if constexpr (N > 1) {
      for (int k = N - 1; k >= 0; --k) {
        const int c = col_[static_cast<std::size_t>(k)];
        if (c != k) std::swap(b[k], b[c]);
      }
    }
    x = b;
    return all_finite(x);
  }

 private:
  mat<T, N> lu_ = mat<T, N>::Zero();
  std::array<int, N> row_{}, col_{};
};

/// Solves A x = b for a small fixed-size A (lu_small); false if A is singular to working
/// precision (x = 0) or not finite (x = NaN), or if x is not finite.
template <class T, int N>
bool solve_small(const mat<T, N>& A, const vec<T, N>& b, vec<T, N>& x) {
  lu_small<T, N> lu;
  if (!lu.factor(A)) {
    x.setConstant(all_finite(A) ? T(0) : std::numeric_limits<T>::quiet_NaN());
    return false;
  }
  return lu.solve(b, x);
}

/// Inverse of a small fixed-size matrix (columns solved one by one); false if singular.
template <class T, int N>
bool invert_small(const mat<T, N>& A, mat<T, N>& inv) {
  for (int j = 0; j < N; ++j) {
    vec<T, N> e = vec<T, N>::Zero(), x;
    e[j] = T(1);
    if (!solve_small<T, N>(A, e, x)) return false;
    inv.col(j) = x;
  }
  return true;
}

}  // namespace geomint
