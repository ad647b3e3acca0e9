#pragma once
/// Small dense linear algebra: LU with complete pivoting for fixed sizes, solve and inverse.

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>
#include <Eigen/LU>
#include "geomint/core/elementary.hpp"
#include "geomint/core/mantissa.hpp"
#include "geomint/linalg/types.hpp"

namespace geomint {

namespace linalg {
/// The pivot search of an LU factorisation: complete (the largest remaining element; the
/// default) or partial (the largest in the pivot column; O(n^2) comparisons instead of O(n^3),
/// for matrices near the identity such as implicit stage matrices I - h A J).
enum class pivoting { complete, partial };
}  // namespace linalg

namespace linalg::detail {
/// lu_factor for one pivot search, fixed at compile time (the complete search's loops stay
/// those of the rows; see lu_factor).
template <bool Partial, class T, class Size>
bool lu_factor_with(T* a, Size size, int* row, int* col) {
  using std::abs;
  const int n = static_cast<int>(size);
  auto at = [&](int i, int j) -> T& { return a[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)]; };
  T scale(0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (!is_finite(at(i, j))) return false;  // a NaN would slip through the pivot comparisons
      if (abs(at(i, j)) > scale) scale = abs(at(i, j));
    }
  const T tiny = T(n) * std::numeric_limits<T>::epsilon() * scale;
  for (int k = 0; k < n; ++k) {
    int pr = k, pc = k;
    T best(-1);
    const int last_column = Partial ? k + 1 : n;
    for (int i = k; i < n; ++i)
      for (int j = k; j < last_column; ++j)
        if (abs(at(i, j)) > best) {
          best = abs(at(i, j));
          pr = i;
          pc = j;
        }
    if (!(best > tiny)) return false;
    row[k] = pr;
    col[k] = pc;
    if (n > 1) {  // (for a constant n = 1, no swap code for GCC's bounds warnings to see)
      if (pr != k)
        for (int j = 0; j < n; ++j) std::swap(at(k, j), at(pr, j));
      if (pc != k)
        for (int i = 0; i < n; ++i) std::swap(at(i, k), at(i, pc));
    }
    const T inv = T(1) / at(k, k);
    if constexpr (Partial) {
      // By columns (contiguous, vectorised for the run-time sizes of lu_in_double): the same
      // products and differences as the rows below, in another order.
      for (int i = k + 1; i < n; ++i) at(i, k) *= inv;
      for (int j = k + 1; j < n; ++j) {
        const T u = at(k, j);
        if (u == T(0)) continue;
        T* column = &at(0, j);
        const T* multipliers = &at(0, k);
        for (int i = k + 1; i < n; ++i) column[i] -= multipliers[i] * u;
      }
    } else {
      // By rows: faster for the small compile-time sizes complete pivoting serves.
      for (int i = k + 1; i < n; ++i) {
        const T f = at(i, k) * inv;
        at(i, k) = f;
        if (f == T(0)) continue;
        for (int j = k + 1; j < n; ++j) at(i, j) -= f * at(k, j);
      }
    }
  }
  return true;
}

/// LU with complete pivoting (P A Q = L U; with pivoting::partial, Q = I) in place on a
/// column-major n x n array: false if the largest remaining pivot is <= n eps max|A| (singular
/// to working precision) or A is not finite. `Size` is int (the size known at run time: one
/// instantiation per scalar serves every size) or std::integral_constant<int, N> (loops of
/// known length, unrolled where small): see lu_extent.
template <class T, class Size>
bool lu_factor(T* a, Size size, int* row, int* col, pivoting search = pivoting::complete) {
  return search == pivoting::partial ? lu_factor_with<true>(a, size, row, col) : lu_factor_with<false>(a, size, row, col);
}

/// b <- A^{-1} b from lu_factor's factors. The multipliers were swapped with their rows, so all
/// row swaps come first (P b).
template <class T, class Size>
void lu_solve(const T* a, Size size, const int* row, const int* col, T* b) {
  const int n = static_cast<int>(size);
  auto at = [&](int i, int j) -> const T& { return a[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)]; };
  if (n > 1)
    for (int k = 0; k < n; ++k)
      if (row[k] != k) std::swap(b[k], b[row[k]]);
  for (int k = 0; k < n; ++k)
    for (int i = k + 1; i < n; ++i) b[i] -= at(i, k) * b[k];
  for (int k = n - 1; k >= 0; --k) {
    T sum = b[k];
    for (int j = k + 1; j < n; ++j) sum -= at(k, j) * b[j];
    b[k] = sum / at(k, k);
  }
  if (n > 1)
    for (int k = n - 1; k >= 0; --k)
      if (col[k] != k) std::swap(b[k], b[col[k]]);
}

/// The size argument of lu_factor and lu_solve for an N x N matrix of T: a compile-time constant
/// for the built-in types, whose small solves gain from loops of known length, and a run-time
/// int for the others, whose arithmetic dominates either way and for which one instantiation
/// then serves every size of a translation unit.
template <class T, int N>
using lu_extent = std::conditional_t<std::is_floating_point_v<T>, std::integral_constant<int, N>, int>;
template <class T, int N>
constexpr lu_extent<T, N> lu_size() {
  if constexpr (std::is_floating_point_v<T>) return {};
  else return N;
}
}  // namespace linalg::detail

/// LU factorisation with complete pivoting (P A Q = L U) of a matrix of compile-time size, kept
/// for reuse (e.g. across Newton iterations); singular to working precision when the largest
/// remaining pivot is <= N eps max|A| (linalg::detail::lu_factor). Written out instead of
/// Eigen::FullPivLU: same algorithm, but a fraction of the compile time per matrix size, which
/// matters for the many (m, n) sizes a program instantiates. The factors are a square_matrix:
/// on the heap, allocated with the object, when they are large.
template <class T, int N>
class lu_small {
 public:
  /// False if A is singular to working precision or not finite.
  template <class Derived>
  bool factor(const Eigen::MatrixBase<Derived>& A) {
    lu_ = A;
    return linalg::detail::lu_factor_with<false, T>(lu_.data(), linalg::detail::lu_size<T, N>(), row_.data(), col_.data());
  }
  /// x = A^{-1} b; false if x is not finite.
  bool solve(vec<T, N> b, vec<T, N>& x) const {
    linalg::detail::lu_solve<T>(lu_.data(), linalg::detail::lu_size<T, N>(), row_.data(), col_.data(), b.data());
    x = b;
    return all_finite(x);
  }

 private:
  square_matrix<T, N> lu_ = square_matrix<T, N>::Zero(N, N);
  std::array<int, N> row_{}, col_{};
};

/// An N x N matrix of any scalar rounded to double and factorised there (linalg::detail::
/// lu_factor<double>), to solve for corrections in double from residuals in the scalar
/// (newton_options::double_jacobian). From 64 unknowns on (the stage matrices of many degrees
/// of freedom: the outer solar system's 270 at m = 16) the matrix lives on the heap, and a
/// partial-pivoting factorisation is Eigen's blocked PartialPivLU (half the time of the
/// unblocked loops at 270), with the same test for a singular matrix.
template <int N>
class lu_in_double {
  static constexpr bool large = N >= 64;
  using storage = std::conditional_t<large, Eigen::MatrixXd, std::array<double, static_cast<std::size_t>(N) * N>>;

 public:
  /// False if A does not round to a finite double matrix or is singular in double.
  template <class Derived>
  bool factor(const Eigen::MatrixBase<Derived>& A) {
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) at(i, j) = to_double(A(i, j));
    return factor_in_place();
  }
  /// Element (i, j) of the matrix to factorise, for callers that fill it in double directly.
  double& at(int i, int j) { return a_.data()[static_cast<std::size_t>(j) * N + static_cast<std::size_t>(i)]; }
  /// Factorises the matrix filled through at(); false if it is not finite or singular.
  bool factor_in_place(linalg::pivoting search = linalg::pivoting::complete) {
    blocked_ = false;
    if constexpr (large) {
      if (search == linalg::pivoting::partial) {
        // lu_factor's test: not finite, or a pivot <= N eps max|A|.
        if (!a_.allFinite()) return false;
        const double size = a_.cwiseAbs().maxCoeff();
        blocked_lu_.compute(a_);
        const double smallest = blocked_lu_.matrixLU().diagonal().cwiseAbs().minCoeff();
        blocked_ = true;
        return smallest > double(N) * std::numeric_limits<double>::epsilon() * size;
      }
    }
    return linalg::detail::lu_factor<double, int>(a_.data(), N, row_.data(), col_.data(), search);
  }
  /// x = A^{-1} b with b rounded to double and x converted back to T; false if b or x is not
  /// finite in double.
  template <class T>
  bool solve(const vec<T, N>& b, vec<T, N>& x) const {
    std::array<double, N> y;
    for (int i = 0; i < N; ++i) {
      y[static_cast<std::size_t>(i)] = to_double(b[i]);
      if (!std::isfinite(y[static_cast<std::size_t>(i)])) return false;
    }
    if constexpr (large) {
      if (blocked_) {
        Eigen::Map<Eigen::VectorXd> v(y.data(), N);
        v = blocked_lu_.solve(v);
      } else {
        linalg::detail::lu_solve<double, int>(a_.data(), N, row_.data(), col_.data(), y.data());
      }
    } else {
      linalg::detail::lu_solve<double, int>(a_.data(), N, row_.data(), col_.data(), y.data());
    }
    for (int i = 0; i < N; ++i) {
      if (!std::isfinite(y[static_cast<std::size_t>(i)])) return false;
      x[i] = from_double<T>(y[static_cast<std::size_t>(i)]);
    }
    return true;
  }

 private:
  static storage make_storage() {
    if constexpr (large) return Eigen::MatrixXd::Zero(N, N);
    else return storage{};
  }
  storage a_ = make_storage();
  std::array<int, N> row_{}, col_{};
  struct none {};
  [[no_unique_address]] std::conditional_t<large, Eigen::PartialPivLU<Eigen::MatrixXd>, none> blocked_lu_{};
  bool blocked_ = false;
};

/// Solves A x = b for an N x N matrix A (mat or square_matrix; lu_small); false if A is singular
/// to working precision (x = 0) or not finite (x = NaN), or if x is not finite.
template <class T, int N, class Matrix>
bool solve_small(const Matrix& A, const vec<T, N>& b, vec<T, N>& x) {
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
