/// The numeric collocation RKN tableau (methods/collocation_rkn.hpp), the one construction behind
/// LPF's coefficients, against independent sources: the two-stage Gauss method in closed form, and the
/// exact analysis' tableau (analysis/rkn_tableau.hpp: exact arithmetic in the stage algebra
/// Q[x]/(N), then a Vandermonde solve) on every node family.
#include <cmath>
#include <string>

#include "catch.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/methods/collocation_rkn.hpp"
#include "scalar_types.hpp"

namespace collocation_rkn_test {

using namespace geomint;

TEMPLATE_LIST_TEST_CASE("collocation rkn: the two-stage Gauss method in closed form", "[methods][collocation_rkn]",
                        geomint::test::integrator_scalar_types) {
  // Exact mathematics: the Gauss points c = 1/2 -+ sqrt 3 / 6 and weights b = (1/2, 1/2)
  // (Hairer, Lubich & Wanner 2006, Table II.1.1), the Lagrange polynomials l_1 = (c_2 - u) / d,
  // l_2 = (u - c_1) / d (d = c_2 - c_1), and the integrals a_ij = int_0^{c_i} (c_i - u) l_j(u) du
  // in closed form: int_0^c (c - u)(x - u) du = c^2 (3 x - c) / 6, so
  // a_i1 = c_i^2 (3 c_2 - c_i) / (6 d), a_i2 = c_i^2 (c_i - 3 c_1) / (6 d), and bbar_j = a_j at
  // c = 1 = b_j (1 - c_j).
  using T = TestType;
  using std::abs;
  using std::sqrt;
  const T r3 = sqrt(T(3));
  const methods::rkn<T, 2> t = methods::gauss_collocation_rkn<T, 2>();
  const T c[2] = {T(1) / T(2) - r3 / T(6), T(1) / T(2) + r3 / T(6)};
  const T d = c[1] - c[0];
  const T tol = geomint::test::eps_tol<T>(8);
  for (std::size_t i = 0; i < 2; ++i) {
    const T a[2] = {c[i] * c[i] * (T(3) * c[1] - c[i]) / (T(6) * d), c[i] * c[i] * (c[i] - T(3) * c[0]) / (T(6) * d)};
    CHECK(abs(T(t.c[i] - c[i])) <= tol);
    CHECK(abs(T(t.b[i] - T(1) / T(2))) <= tol);
    CHECK(abs(T(t.bbar[i] - (T(1) - c[i]) / T(2))) <= tol);
    for (std::size_t j = 0; j < 2; ++j) CHECK(abs(T(t.a[i][j] - a[j])) <= tol);
  }
}

TEMPLATE_LIST_TEST_CASE("collocation nystrom: the velocity matrix on two nodes in closed form", "[methods][collocation_rkn]",
                        geomint::test::integrator_scalar_types) {
  // Exact mathematics, ap_ij = int_0^{c_i} l_j(u) du. Gauss points: the Gauss Runge-Kutta matrix
  // (1/4, 1/4 - sqrt 3/6; 1/4 + sqrt 3/6, 1/4) (Hairer, Lubich & Wanner 2006, Table II.1.1).
  // Nodes 1/3, 2/3: l_1 = 2 - 3u, l_2 = 3u - 1, so ap = (1/2, -1/6; 2/3, 0). Both keep the
  // position part of collocation_rkn (the rows of a sum to c_i^2 / 2 there, as here a to c).
  using T = TestType;
  using std::abs;
  using std::sqrt;
  const T tol = geomint::test::eps_tol<T>(8);
  const T r3 = sqrt(T(3));
  const methods::stage_vector<T, 2> gauss{T(1) / T(2) - r3 / T(6), T(1) / T(2) + r3 / T(6)};
  const methods::nystrom<T, 2> g = methods::collocation_nystrom<T, 2>(gauss);
  const T ap[2][2] = {{T(1) / T(4), T(1) / T(4) - r3 / T(6)}, {T(1) / T(4) + r3 / T(6), T(1) / T(4)}};
  const methods::rkn<T, 2> positions = methods::collocation_rkn<T, 2>(gauss);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j) {
      CHECK(abs(T(g.ap[i][j] - ap[i][j])) <= tol);
      CHECK(g.a[i][j] == positions.a[i][j]);
    }
  const methods::nystrom<T, 2> e = methods::collocation_nystrom<T, 2>({T(1) / T(3), T(2) / T(3)});
  const T thirds[2][2] = {{T(1) / T(2), T(-1) / T(6)}, {T(2) / T(3), T(0)}};
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j) CHECK(abs(T(e.ap[i][j] - thirds[i][j])) <= tol);
}

/// The tableau on the interior nodes of (m, Family) against the exact analysis' one in 50 digits.
template <int M, class Family>
void check_family() {
  using T = geomint::test::cpp_bin_float_50;
  using std::abs;
  constexpr int S = M - 1;
  const auto nodes_of = nodes<Family, M, T>();
  std::array<T, S> interior;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) interior[i] = nodes_of[i + 1];
  const methods::rkn<T, S> t = methods::collocation_rkn<T, S>(interior);
  const methods::tableau_data<T> e = numeric_tableau<T>(lpf_tableau<M, Family>(), nodes_of.data() + 1);
  INFO("m = " << M << ", " << Family::name);
  // The Vandermonde solve of the exact route loses up to about 5 digits at s = 7.
  const T tol = geomint::test::eps_tol<T>(1000000);
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    CHECK(abs(T(t.b[i] - e.b[i])) <= tol);
    CHECK(abs(T(t.bbar[i] - e.bbar[i])) <= tol);
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) CHECK(abs(T(t.a[i][j] - e.a[i][j])) <= tol);
  }
}

TEST_CASE("collocation rkn: the exact analysis' tableau on every node family (50 digits)", "[methods][collocation_rkn]") {
  check_family<3, equispaced>();
  check_family<8, equispaced>();
  check_family<5, gauss_interior>();
  check_family<8, gauss_interior>();
  check_family<6, gauss_lobatto>();
  check_family<8, chebyshev_lobatto>();
  check_family<5, radau_right>();
  check_family<4, radau_left>();
}

}  // namespace collocation_rkn_test
