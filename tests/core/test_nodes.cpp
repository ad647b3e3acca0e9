/// Node families against independent computations in every scalar type:
/// - Chebyshev-Lobatto: the closed form c_a = sin^2(pi a / (2m)) (Boost's pi and the type's sin);
/// - Gauss interior: Boost.Math's legendre_p_zeros (Newton on P_n with its own starting values);
/// - Gauss-Lobatto: a Golub-Welsch eigen-solve of the Jacobi matrix of P^(1,1)_{m-1} (whose
///   roots are those of P'_m) with Eigen's SelfAdjointEigenSolver in the same scalar type;
/// - Radau right (the Radau IIA points): Golub-Welsch for P^(1,0)_{m-1}, the free nodes of the
///   Gauss-Radau rule with the node 1 (weight 1 - y); Radau left (Radau IA) reflected; and the
///   published points of m = 3 (closed form) and m = 5 (Hairer & Wanner's RADAU code).
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

/// Boost.Math's legendre_p_zeros in T; for a sum of doubles (libqd's types, which Boost.Math
/// cannot take), in 150 digits and rounded term by term to T.
template <class T>
std::vector<T> legendre_zeros(int n) {
  if constexpr (geomint::double_expansion<T>::value) {
    using H = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<150>>;
    std::vector<T> out;
    for (const H& x : boost::math::legendre_p_zeros<H>(n)) out.push_back(geomint::narrow<T>(x));
    return out;
  } else {
    return boost::math::legendre_p_zeros<T>(n);
  }
}

template <class T>
std::vector<T> gauss_interior_reference(int m) {
  // legendre_p_zeros(n) returns the non-negative zeros x of P_n, ascending; c = (1 -+ x)/2.
  const std::vector<T> zeros = legendre_zeros<T>(m - 1);
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

/// The eigenvalues y of the symmetric tridiagonal Jacobi matrix of the monic recurrence
/// p_{k+1} = (y - a_k) p_k - b_k p_{k-1} (diagonal a_0..a_{n-1}, off-diagonal sqrt b_1..b_{n-1}),
/// mapped to c = (1 + y)/2, with the ends 0 and 1.
template <class T, class A, class B>
std::vector<T> golub_welsch_nodes(int n, A a, B b) {
  std::vector<T> c{T(0), T(1)};
  if (n >= 1) {
    Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> J = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>::Zero(n, n);
    for (int k = 0; k < n; ++k) J(k, k) = a(k);
    for (int k = 1; k < n; ++k) {
      using std::sqrt;
      const T s = sqrt(b(k));
      J(k - 1, k) = s;
      J(k, k - 1) = s;
    }
    Eigen::SelfAdjointEigenSolver<decltype(J)> solver(J);
    for (int i = 0; i < n; ++i) c.push_back(T((T(1) + solver.eigenvalues()(i)) / T(2)));
  }
  std::sort(c.begin(), c.end());
  return c;
}

/// Jacobi P^(1,0): a_k = (beta^2 - alpha^2)/((2k+1)(2k+3)) = -1/((2k+1)(2k+3)),
/// b_k = 4k(k+1)k(k+1)/((2k+1)^2 (2k+2)(2k)) = k(k+1)/(2k+1)^2.
template <class T>
std::vector<T> radau_right_reference(int m) {
  return golub_welsch_nodes<T>(
      m - 1, [](int k) { return T(T(-1) / T((2 * k + 1) * (2 * k + 3))); }, [](int k) { return T(T(k * (k + 1)) / T((2 * k + 1) * (2 * k + 1))); });
}
template <class T>
std::vector<T> radau_left_reference(int m) {
  std::vector<T> c = radau_right_reference<T>(m);
  for (T& x : c) x = T(1) - x;
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
  check_against<geomint::radau_right, M, T>(radau_right_reference<T>(M), 16);
  check_against<geomint::radau_left, M, T>(radau_left_reference<T>(M), 16);
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

TEST_CASE("Radau nodes: the published Radau IIA and IA points", "[core][nodes]") {
  using T = geomint::test::cpp_bin_float_50;
  using std::sqrt;
  // s = 3: (4 - sqrt 6)/10, (4 + sqrt 6)/10, 1 (Radau IIA) and 0, (6 - sqrt 6)/10, (6 + sqrt 6)/10
  // (Radau IA): Hairer & Wanner II, section IV.5, Tables 5.5 and 5.6.
  const T r6 = sqrt(T(6));
  const auto right3 = geomint::nodes<geomint::radau_right, 3, T>();
  const auto left3 = geomint::nodes<geomint::radau_left, 3, T>();
  const T right3_expected[] = {T(0), (4 - r6) / 10, (4 + r6) / 10, T(1)};
  const T left3_expected[] = {T(0), (6 - r6) / 10, (6 + r6) / 10, T(1)};
  for (std::size_t a = 0; a < 4; ++a) {
    CHECK(abs_diff(right3[a], right3_expected[a]) <= eps_tol<T>(8));
    CHECK(abs_diff(left3[a], left3_expected[a]) <= eps_tol<T>(8));
  }
  // s = 5 (order 9): the nodes of Hairer & Wanner's RADAU code (radau.f, its 5-stage constants;
  // Hairer & Wanner, J. Comput. Appl. Math. 111 (1999) 93-111), as printed to 22 digits there and
  // in OrdinaryDiffEq.jl's RadauIIA9Tableau.
  const auto right5 = geomint::nodes<geomint::radau_right, 5, T>();
  const T right5_expected[] = {T("5.710419611451768219312e-2"), T("2.768430136381238276800e-1"), T("5.835904323689168200567e-1"),
                               T("8.602401356562194478479e-1")};
  for (std::size_t a = 0; a < 4; ++a) CHECK(abs_diff(right5[a + 1], right5_expected[a]) <= T("1e-21"));
  CHECK(right5[5] == T(1));
}
