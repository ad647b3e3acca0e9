/// Differentiation weights and basis evaluation in every scalar type. Expected values:
/// - exact mathematics: derivatives of monomials, partition of unity, Kronecker delta at nodes;
/// - the exact rational weights (equispaced) converted to the scalar;
/// - the closed-form Gauss-Lobatto differentiation matrix (Canuto et al., Spectral Methods,
///   eq. 2.4.34): D_ij = P_m(x_i) / (P_m(x_j) (x_i - x_j)), D_00 = -m(m+1)/4 = -D_mm, others 0,
///   on x in [-1, 1], evaluated with Boost.Math's legendre_p; on c = (1 + x)/2 it doubles.
#include <geomint/core/differentiation.hpp>

#include <boost/math/special_functions/legendre.hpp>

#include "catch.hpp"
#include "scalar_types.hpp"

using geomint::test::abs_diff;
using geomint::test::eps_tol;

namespace {

template <class T, std::size_t N>
T max_abs(const geomint::square_array<T, N>& D) {
  T out(0);
  for (const auto& row : D)
    for (const T& v : row) {
      using std::abs;
      const T a = abs(v);
      if (a > out) out = a;
    }
  return out;
}

/// D_1 and D_2 reproduce the derivatives of t^k, k <= m. The rounding error of a weight row
/// applied to values in [0, 1] is at most (m + 1) * eps * max|D| per product-sum, and the
/// weights themselves carry a few eps * max|D|: the bound is 8 (m + 1) eps max|D|.
template <class Family, int M, class T>
void check_monomials() {
  const auto c = geomint::nodes<Family, M, T>();
  const auto D1 = geomint::differentiation_weights<1, Family, M, T>();
  const auto D2 = geomint::differentiation_weights<2, Family, M, T>();
  const T tol1 = eps_tol<T>(8 * (M + 1)) * max_abs(D1);
  const T tol2 = eps_tol<T>(8 * (M + 1)) * max_abs(D2);
  for (int k = 0; k <= M; ++k) {
    for (std::size_t i = 0; i <= M; ++i) {
      T first(0), second(0);
      for (std::size_t j = 0; j <= M; ++j) {
        using std::pow;
        const T value = k == 0 ? T(1) : T(pow(c[j], k));
        first += D1[i][j] * value;
        second += D2[i][j] * value;
      }
      using std::pow;
      const T expected1 = k >= 1 ? T(T(k) * (k == 1 ? T(1) : T(pow(c[i], k - 1)))) : T(0);
      const T expected2 = k >= 2 ? T(T(k * (k - 1)) * (k == 2 ? T(1) : T(pow(c[i], k - 2)))) : T(0);
      INFO("family " << Family::name << ", m = " << M << ", k = " << k << ", node " << i);
      CHECK(abs_diff(first, expected1) <= tol1);
      CHECK(abs_diff(second, expected2) <= tol2);
    }
  }
}

template <int M, class T>
void check_lobatto_closed_form() {
  const auto c = geomint::nodes<geomint::gauss_lobatto, M, T>();
  const auto D1 = geomint::differentiation_weights<1, geomint::gauss_lobatto, M, T>();
  const T tol = eps_tol<T>(8 * (M + 1)) * max_abs(D1);
  for (std::size_t i = 0; i <= M; ++i) {
    for (std::size_t j = 0; j <= M; ++j) {
      const T xi = T(2) * c[i] - T(1), xj = T(2) * c[j] - T(1);
      T expected(0);
      if (i != j)
        expected = boost::math::legendre_p(M, xi) / (boost::math::legendre_p(M, xj) * (xi - xj));
      else if (i == 0)
        expected = -T(M * (M + 1)) / T(4);
      else if (i == M)
        expected = T(M * (M + 1)) / T(4);
      expected *= T(2);  // d/dc = 2 d/dx
      INFO("m = " << M << ", D1[" << i << "][" << j << "]");
      CHECK(abs_diff(D1[i][j], expected) <= tol);
    }
  }
}

template <int M, class T>
void check_equispaced_against_exact() {
  const auto exact1 = geomint::differentiation_weights<1, geomint::equispaced, M, geomint::rational>();
  const auto exact2 = geomint::differentiation_weights<2, geomint::equispaced, M, geomint::rational>();
  const auto D1 = geomint::differentiation_weights<1, geomint::equispaced, M, T>();
  const auto D2 = geomint::differentiation_weights<2, geomint::equispaced, M, T>();
  for (std::size_t i = 0; i <= M; ++i)
    for (std::size_t j = 0; j <= M; ++j) {
      INFO("m = " << M << ", entry [" << i << "][" << j << "]");
      CHECK(abs_diff(D1[i][j], exact1[i][j].template to<T>()) <= eps_tol<T>(8 * (M + 1)) * max_abs(D1));
      CHECK(abs_diff(D2[i][j], exact2[i][j].template to<T>()) <= eps_tol<T>(8 * (M + 1)) * max_abs(D2));
    }
}

template <class Basis, class Family, int M, class T>
void check_basis_values() {
  const auto c = geomint::nodes<Family, M, T>();
  for (int s = 0; s <= 20; ++s) {
    const T t = T(s) / T(20);
    const auto phi = geomint::basis_values<Basis, Family, M, T>(t);
    const auto dphi = geomint::basis_derivatives<1, Basis, Family, M, T>(t);
    T sum(0), slope(0), dsum(0);
    for (std::size_t j = 0; j <= M; ++j) {
      sum += phi[j];
      dsum += dphi[j];
      // Lagrange: node values of t reproduce t; Bernstein: control points j/m reproduce t.
      const T coordinate = std::is_same_v<Basis, geomint::lagrange> ? c[j] : T(T(int(j)) / T(M));
      slope += dphi[j] * coordinate;
    }
    INFO("basis " << Basis::name << ", family " << Family::name << ", m = " << M << ", t = " << t);
    // Exact identities (partition of unity, its derivative, reproduction of t), to rounding:
    // the barycentric evaluation keeps O(m^2) eps (the monomial form of the Lagrange basis it
    // replaced lost some 2^(2m) eps, 1e-6 at m = 16 in double); Bernstein sums positive terms.
    const T tol = eps_tol<T>(16) * T((M + 1) * (M + 1));
    CHECK(abs_diff(sum, T(1)) <= tol);
    CHECK(abs_diff(dsum, T(0)) <= tol * T(M * M));
    CHECK(abs_diff(slope, T(1)) <= tol * T(M * M));
  }
  if constexpr (std::is_same_v<Basis, geomint::lagrange>) {
    for (std::size_t i = 0; i <= M; ++i) {
      const auto phi = geomint::basis_values<Basis, Family, M, T>(c[i]);
      for (std::size_t j = 0; j <= M; ++j)
        CHECK(phi[j] == T(i == j ? 1 : 0));  // exact at the nodes
    }
  }
}

template <class T, int M>
void check_all() {
  check_monomials<geomint::equispaced, M, T>();
  check_monomials<geomint::gauss_lobatto, M, T>();
  check_monomials<geomint::chebyshev_lobatto, M, T>();
  check_monomials<geomint::gauss_interior, M, T>();
  check_lobatto_closed_form<M, T>();
  check_basis_values<geomint::lagrange, geomint::gauss_lobatto, M, T>();
  check_basis_values<geomint::bernstein, geomint::equispaced, M, T>();
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("differentiation weights in every scalar type", "[core][differentiation]",
                        geomint::test::scalar_types) {
  check_all<TestType, 2>();
  check_all<TestType, 5>();
  check_all<TestType, 12>();
  // The highest degree of the schemes (max_floating_m): Galerkin and dense output evaluate the
  // basis off the nodes.
  check_basis_values<geomint::lagrange, geomint::gauss_lobatto, 16, TestType>();
  check_basis_values<geomint::lagrange, geomint::gauss_interior, 16, TestType>();
  check_equispaced_against_exact<2, TestType>();
  check_equispaced_against_exact<8, TestType>();
}
