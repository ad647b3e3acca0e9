/// The small LU with complete pivoting, and partial pivoting in double (linalg/lu_small.hpp).
///
/// Independent sources of the expected values: the residual A x - b, which is zero for the exact
/// solution (a backward-error check, exact mathematics); Eigen's FullPivLU in cpp_bin_float_100
/// (a second method in higher precision); matrices that are singular by construction.
#include <limits>
#include <random>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <Eigen/LU>

#include "catch.hpp"
#include "geomint/linalg/lu_small.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_100;

namespace {
/// A reproducible matrix with entries in [-1, 1] plus `shift` on the diagonal.
template <class T, int N>
mat<T, N> sample_matrix(unsigned seed, int shift) {
  std::mt19937 gen(seed);
  std::uniform_int_distribution<int> d(-1000, 1000);
  mat<T, N> A;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) A(i, j) = T(d(gen)) / T(1000);
  for (int i = 0; i < N; ++i) A(i, i) += T(shift);
  return A;
}
template <class T, int N>
vec<T, N> sample_vector(unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_int_distribution<int> d(-1000, 1000);
  vec<T, N> b;
  for (int i = 0; i < N; ++i) b[i] = T(d(gen)) / T(1000);
  return b;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("lu_small solves to a backward error of a few eps", "[linalg]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  constexpr int N = 6;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const mat<T, N> A = sample_matrix<T, N>(seed, static_cast<int>(seed % 3));
    const vec<T, N> b = sample_vector<T, N>(seed + 100);
    vec<T, N> x;
    REQUIRE(solve_small<T, N>(A, b, x));
    // |A x - b| <= c N eps |A| |x| (Wilkinson's bound for LU with pivoting, c small).
    const T residual = (A * x - b).template lpNorm<Eigen::Infinity>();
    const T bound = T(4 * N) * std::numeric_limits<T>::epsilon() * A.template lpNorm<Eigen::Infinity>() *
                    x.template lpNorm<Eigen::Infinity>();
    CHECK(residual <= bound);
    // Against Eigen's full-pivoting LU in 100 digits: forward error within cond(A) eps.
    const mat<cpp_bin_float_100, N> A100 = A.template cast<cpp_bin_float_100>();
    const vec<cpp_bin_float_100, N> x100 = A100.fullPivLu().solve(b.template cast<cpp_bin_float_100>());
    const cpp_bin_float_100 cond = A100.norm() * A100.inverse().norm();
    const cpp_bin_float_100 error = (x.template cast<cpp_bin_float_100>() - x100).template lpNorm<Eigen::Infinity>();
    CHECK(error <= cpp_bin_float_100(16 * N) * cond * cpp_bin_float_100(std::numeric_limits<T>::epsilon()) *
                       x100.template lpNorm<Eigen::Infinity>());
  }
}

TEMPLATE_LIST_TEST_CASE("lu_small: the inverse, and a factorisation reused for several right-hand sides", "[linalg]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  constexpr int N = 4;
  const mat<T, N> A = sample_matrix<T, N>(7, 2);
  mat<T, N> inv;
  REQUIRE(invert_small<T, N>(A, inv));
  const T off = (A * inv - mat<T, N>::Identity()).template lpNorm<Eigen::Infinity>();
  CHECK(off <= geomint::test::eps_tol<T>(64) * A.template lpNorm<Eigen::Infinity>() * inv.template lpNorm<Eigen::Infinity>());
  lu_small<T, N> lu;
  REQUIRE(lu.factor(A));
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const vec<T, N> b = sample_vector<T, N>(seed);
    vec<T, N> x;
    REQUIRE(lu.solve(b, x));
    CHECK((x - inv * b).template lpNorm<Eigen::Infinity>() <= geomint::test::eps_tol<T>(256) * (T(1) + x.template lpNorm<Eigen::Infinity>()));
  }
}

TEMPLATE_LIST_TEST_CASE("lu_small refuses singular and non-finite matrices", "[linalg]",
                        geomint::test::integrator_scalar_types) {
  using T = TestType;
  constexpr int N = 3;
  // Row 2 = row 0 + row 1: singular by construction (exactly representable entries).
  mat<T, N> A;
  A << T(1), T(2), T(3), T(4), T(5), T(6), T(5), T(7), T(9);
  lu_small<T, N> lu;
  CHECK_FALSE(lu.factor(A));
  vec<T, N> x;
  CHECK_FALSE(solve_small<T, N>(A, vec<T, N>::Ones(), x));
  CHECK(x.isZero());  // a singular but finite matrix gives x = 0, never garbage
  mat<T, N> Z = mat<T, N>::Zero();
  CHECK_FALSE(lu.factor(Z));
  mat<T, N> B = mat<T, N>::Identity();
  B(1, 2) = std::numeric_limits<T>::quiet_NaN();
  CHECK_FALSE(lu.factor(B));
  CHECK_FALSE(solve_small<T, N>(B, vec<T, N>::Ones(), x));
  CHECK_FALSE(all_finite(x));  // NaN input: the solution says so
  mat<T, N> inv;
  CHECK_FALSE(invert_small<T, N>(A, inv));
}

/// The partial-pivoting checks below for one size (from 64 on, lu_in_double's blocked path).
template <int N>
void check_partial_pivoting() {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const mat<double, N> A = sample_matrix<double, N>(seed, seed % 2 == 0 ? 8 : 0);
    const vec<double, N> b = sample_vector<double, N>(seed + 100);
    lu_in_double<N> lu;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) lu.at(i, j) = A(i, j);
    REQUIRE(lu.factor_in_place(linalg::pivoting::partial));
    vec<double, N> x;
    REQUIRE(lu.solve(b, x));
    const double residual = (A * x - b).template lpNorm<Eigen::Infinity>();
    CHECK(residual <= 4 * N * std::numeric_limits<double>::epsilon() * A.template lpNorm<Eigen::Infinity>() *
                          x.template lpNorm<Eigen::Infinity>());
  }
  // Singular by construction (the last row the sum of the first two, in binary fractions so
  // that the sum is exact), and not finite: refused.
  lu_in_double<N> singular, infinite;
  const mat<double, N> A = sample_matrix<double, N>(7, 0);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const double a = std::ldexp(std::round(std::ldexp(A(i, j), 10)), -10);
      singular.at(i, j) = i == N - 1 ? singular.at(0, j) + singular.at(1, j) : a;
      infinite.at(i, j) = A(i, j);
    }
  CHECK_FALSE(singular.factor_in_place(linalg::pivoting::partial));
  infinite.at(N / 2, N / 3) = std::numeric_limits<double>::infinity();
  CHECK_FALSE(infinite.factor_in_place(linalg::pivoting::partial));
}

TEST_CASE("lu_in_double: partial pivoting solves to a backward error of a few eps", "[linalg]") {
  // The double factorisation with the pivot searched in its column only (linalg::pivoting::
  // partial, for stage matrices near the identity): Wilkinson's backward-error bound for the
  // residual (exact mathematics), for matrices dominated by the diagonal and for general ones.
  // A row of zeros left after elimination (singular by construction) is refused as with
  // complete pivoting. N = 12: the unblocked loops; N = 96: Eigen's blocked PartialPivLU.
  check_partial_pivoting<12>();
  check_partial_pivoting<96>();
  lu_in_double<3> singular;
  const double rows[3][3] = {{1, 2, 3}, {4, 5, 6}, {5, 7, 9}};  // row 2 = row 0 + row 1
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) singular.at(i, j) = rows[i][j];
  CHECK_FALSE(singular.factor_in_place(linalg::pivoting::partial));
}
