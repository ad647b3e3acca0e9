/// Node families against independent computations in every scalar type:
/// - Chebyshev-Lobatto: the closed form c_a = sin^2(pi a / (2m)) (Boost's pi and the type's sin);
/// - Gauss interior: Boost.Math's legendre_p_zeros (Newton on P_n with its own starting values);
/// - Gauss-Lobatto: a Golub-Welsch eigen-solve of the Jacobi matrix of P^(1,1)_{m-1} (whose
///   roots are those of P'_m) with Eigen's SelfAdjointEigenSolver in the same scalar type.
#include <geomint/core/nodes.hpp>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/legendre.hpp>
#include <vector>

#include "catch.hpp"
#include "scalar_types.hpp"

using geomint::test::abs_diff;
using geomint::test::eps_tol;

namespace {

template <class T>
std::vector<T> chebyshev_reference(int m) {
  using std::sin;
  std::vector<T> c;
  for (int a = 0; a <= m; ++a) {
    const T s = sin(T(boost::math::constants::pi<T>() * T(a) / T(2 * m)));
    c.push_back(T(s * s));
  }
  return c;
}

template <class T>
std::vector<T> gauss_interior_reference(int m) {
  // legendre_p_zeros(n) returns the non-negative zeros x of P_n, ascending; c = (1 -+ x)/2.
  const std::vector<T> zeros = boost::math::legendre_p_zeros<T>(m - 1);
  std::vector<T> c{T(0), T(1)};
  for (const T& x : zeros) {
    c.push_back(T((T(1) - x) / T(2)));
    if (x != T(0)) c.push_back(T((T(1) + x) / T(2)));
  }
  std::sort(c.begin(), c.end());
  return c;
}

template <class T>
std::vector<T> gauss_lobatto_reference(int m) {
  std::vector<T> c{T(0), T(1)};
  const int n = m - 1;  // interior nodes = roots of P^(1,1)_{m-1}
  if (n >= 1) {
    Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> J = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>::Zero(n, n);
    for (int k = 1; k < n; ++k) {
      // monic Jacobi recurrence, alpha = beta = 1: b_k = k (k + 2) / ((2k + 1)(2k + 3))
      using std::sqrt;
      const T b = sqrt(T(T(k * (k + 2)) / T((2 * k + 1) * (2 * k + 3))));
      J(k - 1, k) = b;
      J(k, k - 1) = b;
    }
    Eigen::SelfAdjointEigenSolver<decltype(J)> solver(J);
    for (int i = 0; i < n; ++i) c.push_back(T((T(1) + solver.eigenvalues()(i)) / T(2)));
  }
  std::sort(c.begin(), c.end());
  return c;
}

template <class Family, int M, class T>
void check_against(const std::vector<T>& reference, int ulps) {
  const auto c = geomint::nodes<Family, M, T>();
  REQUIRE(reference.size() == c.size());
  for (std::size_t a = 0; a < c.size(); ++a) {
    INFO("family " << Family::name << ", m = " << M << ", node " << a);
    CHECK(abs_diff(c[a], reference[a]) <= eps_tol<T>(ulps));
  }
}

template <class T, int M>
void check_all_families() {
  check_against<geomint::chebyshev_lobatto, M, T>(chebyshev_reference<T>(M), 4);
  check_against<geomint::gauss_interior, M, T>(gauss_interior_reference<T>(M), 4);
  // Golub-Welsch eigenvalues carry an absolute error of a few eps times ||J|| (< 1) per
  // QL sweep; 16 ulps covers m <= 16.
  check_against<geomint::gauss_lobatto, M, T>(gauss_lobatto_reference<T>(M), 16);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("irrational node families reach the full precision of the scalar", "[core][nodes]",
                        geomint::test::scalar_types) {
  check_all_families<TestType, 1>();
  check_all_families<TestType, 2>();
  check_all_families<TestType, 3>();
  check_all_families<TestType, 6>();
  check_all_families<TestType, 9>();
  check_all_families<TestType, 12>();
  check_all_families<TestType, 16>();
}

TEMPLATE_LIST_TEST_CASE("equispaced nodes are a/m", "[core][nodes]", geomint::test::scalar_types) {
  const auto c = geomint::nodes<geomint::equispaced, 7, TestType>();
  for (int a = 0; a <= 7; ++a) CHECK(c[static_cast<std::size_t>(a)] == TestType(a) / TestType(7));
}

TEST_CASE("constexpr double nodes equal the 100-digit nodes rounded to double", "[core][nodes]") {
  // Relative accuracy near the ends. Newton stops at the evaluation error of the recurrence,
  // about m eps |f|, against a slope of order m^4 for the root nearest an end (c ~ 1/m^2):
  // the relative error of that node is of order m eps, hence the bound m eps c.
  constexpr auto lobatto = geomint::nodes_v<geomint::gauss_lobatto, 12, double>;
  constexpr auto interior = geomint::nodes_v<geomint::gauss_interior, 12, double>;
  const auto lobatto_100 = geomint::nodes<geomint::gauss_lobatto, 12, geomint::test::cpp_bin_float_100>();
  const auto interior_100 = geomint::nodes<geomint::gauss_interior, 12, geomint::test::cpp_bin_float_100>();
  for (std::size_t a = 0; a <= 12; ++a) {
    INFO("node " << a);
    const double eps = std::numeric_limits<double>::epsilon();
    CHECK(std::abs(lobatto[a] - static_cast<double>(lobatto_100[a])) <= 12 * eps * lobatto[a]);
    CHECK(std::abs(interior[a] - static_cast<double>(interior_100[a])) <= 12 * eps * interior[a]);
  }
}
