/// The exact RKN tableaux (include/geomint/analysis/rkn_tableau.hpp) against the integrators.
///
/// Independent source: the integrators (include/geomint/schemes) solve their own defining
/// equations (LPF: eq. 10-12 by Newton on the path's control points; Galerkin: stationarity of
/// the quadrature action; midpoint and trapezoidal: their discrete Lagrangians) and never form a
/// tableau. One step of the RKN method built from the exact tableau (converted to
/// cpp_bin_float_50 with the family's nodes) must reproduce one step of the integrator on the
/// pendulum (f = -sin q) to the precision of cpp_bin_float_50, for each family and m = 2..8.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <string>

#include "catch.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_50;

namespace {

using T = cpp_bin_float_50;

/// One RKN step for q'' = -sin q: stages by fixed-point iteration until they stop changing
/// (contraction factor ~ tau^2 max|a| < 1/10 at tau = 1/4).
std::pair<T, T> rkn_step(const numeric_rkn_tableau<T>& t, const T& q, const T& p, const T& tau) {
  using std::abs;
  using std::sin;
  const int s = t.stages;
  std::array<T, max_exact_stages> Q{}, F{};
  for (int i = 0; i < s; ++i) Q[static_cast<std::size_t>(i)] = q + t.c[static_cast<std::size_t>(i)] * tau * p;
  for (int iteration = 0; iteration < 400; ++iteration) {
    for (int j = 0; j < s; ++j) F[static_cast<std::size_t>(j)] = -sin(Q[static_cast<std::size_t>(j)]);
    T change(0);
    for (int i = 0; i < s; ++i) {
      T sum(0);
      for (int j = 0; j < s; ++j) sum += t.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * F[static_cast<std::size_t>(j)];
      const T next = q + t.c[static_cast<std::size_t>(i)] * tau * p + tau * tau * sum;
      change = std::max(change, T(abs(next - Q[static_cast<std::size_t>(i)])));
      Q[static_cast<std::size_t>(i)] = next;
    }
    if (change == T(0)) break;
  }
  for (int j = 0; j < s; ++j) F[static_cast<std::size_t>(j)] = -sin(Q[static_cast<std::size_t>(j)]);
  T sb(0), sbb(0);
  for (int j = 0; j < s; ++j) {
    sb += t.b[static_cast<std::size_t>(j)] * F[static_cast<std::size_t>(j)];
    sbb += t.bbar[static_cast<std::size_t>(j)] * F[static_cast<std::size_t>(j)];
  }
  return {q + tau * p + tau * tau * sbb, p + tau * sb};
}

template <class Scheme>
void check_step(const numeric_rkn_tableau<T>& t, const std::string& label) {
  using std::abs;
  const T tau = T(1) / T(4);
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto st = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1) / T(2)));
  const T q = st.q[0], p = st.p[0];
  I.step(st);
  const auto [q1, p1] = rkn_step(t, q, p, tau);
  INFO(label << ": integrator (" << st.q[0] << ", " << st.p[0] << "), tableau (" << q1 << ", " << p1 << ")");
  // The Vandermonde conversion of the monomial-basis tableau loses up to ~5 digits for s = 8.
  const T tol = T(1000000) * std::numeric_limits<T>::epsilon();
  CHECK(abs(st.q[0] - q1) <= tol);
  CHECK(abs(st.p[0] - p1) <= tol);
}

template <class Family, int M>
void check_lpf() {
  check_step<lpf<M, Family>>(lpf_numeric_tableau<M, Family, T>(), "lpf m=" + std::to_string(M) + " " + std::string(Family::name));
  if constexpr (M < max_exact_m) check_lpf<Family, M + 1>();
}

template <int M>
void check_galerkin() {
  check_step<galerkin_vi<M>>(galerkin_numeric_tableau<M, T>(), "galerkin m=" + std::to_string(M));
  if constexpr (M < max_exact_m) check_galerkin<M + 1>();
}

}  // namespace

TEST_CASE("rkn tableau: one step equals the LPF integrator's step (50 digits)", "[analysis][tableau]") {
  check_lpf<equispaced, 2>();
  check_lpf<gauss_interior, 2>();
  check_lpf<gauss_lobatto, 2>();
  check_lpf<chebyshev_lobatto, 2>();
}

TEST_CASE("rkn tableau: one step equals the classical VIs' step (50 digits)", "[analysis][tableau]") {
  check_step<midpoint_vi>(numeric_tableau<T>(midpoint_tableau(), nullptr), "midpoint");
  check_step<trapezoidal_vi>(numeric_tableau<T>(trapezoidal_tableau(), nullptr), "trapezoidal");
  check_galerkin<1>();
}
