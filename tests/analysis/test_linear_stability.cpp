/// The exact linear stability verdicts (analysis/linear_stability.hpp) against iteration.
///
/// Independent source: one step of the RKN method on y'' = -y computed numerically in
/// cpp_bin_float_50 from its tableau (the stage equations (I + tau^2 A) Q = q 1 + tau p c solved
/// by Gaussian elimination), never through the exact step matrix. Iterated inside the reported
/// interval the solution stays bounded; outside it grows. The phase lag and dissipation are
/// measured from the numerical step matrix (its columns are the steps of (1, 0) and (0, 1)) by
/// van der Houwen and Sommeijer's definitions (SIAM J. Numer. Anal. 24 (1987) 595-617):
/// phi(H) = H - arccos(tr / (2 sqrt det)), d(H) = 1 - sqrt(det), against c H^(order+1).
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <string>

#include "catch.hpp"
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/methods/catalogue.hpp"

using namespace geomint;
using T = boost::multiprecision::cpp_bin_float_50;

namespace {

/// Nystrom's classical explicit 3-stage order-4 method (E. J. Nystrom, Acta Soc. Sci. Fenn. 50
/// (1925); Hairer, Norsett, Wanner, Solving ODEs I, section II.14).
exact_rkn_tableau nystrom4() {
  return rational_rkn_tableau<3>(
      {rational(0), rational(1, 2), rational(1)},
      {{{rational(0), rational(0), rational(0)}, {rational(1, 8), rational(0), rational(0)}, {rational(0), rational(1, 2), rational(0)}}},
      {rational(1, 6), rational(1, 3), rational(0)}, {rational(1, 6), rational(2, 3), rational(1, 6)});
}

T to_t(const exact_number& x) { return T(x.num.str()) / T(x.den().str()); }

/// One step of y'' = -y: (q, tau p) -> (q1, tau p1).
std::pair<T, T> harmonic_step(const methods::tableau_data<T>& t, const T& q, const T& tau_p, const T& tau) {
  const int s = t.stages;
  const T z = tau * tau;
  // (I + z A) Q = q + c tau p, Gaussian elimination with partial pivoting.
  T m[max_exact_stages][max_exact_stages + 1];
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) m[i][j] = T(i == j ? 1 : 0) + z * t.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    m[i][s] = q + t.c[static_cast<std::size_t>(i)] * tau_p;
  }
  using std::abs;
  for (int k = 0; k < s; ++k) {
    int pivot = k;
    for (int i = k + 1; i < s; ++i)
      if (abs(m[i][k]) > abs(m[pivot][k])) pivot = i;
    for (int j = 0; j <= s; ++j) std::swap(m[k][j], m[pivot][j]);
    for (int i = k + 1; i < s; ++i) {
      const T f = m[i][k] / m[k][k];
      for (int j = k; j <= s; ++j) m[i][j] -= f * m[k][j];
    }
  }
  T Q[max_exact_stages];
  for (int i = s - 1; i >= 0; --i) {
    T sum = m[i][s];
    for (int j = i + 1; j < s; ++j) sum -= m[i][j] * Q[j];
    Q[i] = sum / m[i][i];
  }
  T q1 = q + tau_p, p1 = tau_p;
  for (int j = 0; j < s; ++j) {
    q1 -= z * t.bbar[static_cast<std::size_t>(j)] * Q[j];
    p1 -= z * t.b[static_cast<std::size_t>(j)] * Q[j];
  }
  return {q1, p1};
}

/// max |(q_n, tau p_n)|, n <= steps, from (1, 0).
T largest_amplitude(const methods::tableau_data<T>& t, const T& tau, int steps) {
  using std::abs;
  T q(1), p(0), largest(1);
  for (int n = 0; n < steps; ++n) {
    std::tie(q, p) = harmonic_step(t, q, p, tau);
    largest = std::max(largest, T(std::max(abs(q), abs(p))));
  }
  return largest;
}

/// Bounded at 9 points inside (0, tau*), growth just outside (at z = (1 + 1/10) z*).
void check_interval(const exact_rkn_tableau& exact, const methods::tableau_data<T>& t, const std::string& label) {
  using std::sqrt;
  const stability_interval iv = linear_stability_interval(linear_stability(exact)).refined(120);
  REQUIRE(!iv.empty);
  REQUIRE(!iv.unbounded);
  const T z_star = to_t(iv.low());
  INFO(label << ": tau* = " << sqrt(z_star));
  for (int k = 1; k <= 9; ++k) {
    const T tau = sqrt(z_star * T(k) / T(10));
    INFO("inside, tau = " << tau);
    CHECK(largest_amplitude(t, tau, 4000) < T(10));
  }
  const T tau_out = sqrt(z_star * T(11) / T(10));
  INFO("outside, tau = " << tau_out);
  CHECK(largest_amplitude(t, tau_out, 4000) > T(1000000));
}

}  // namespace

TEST_CASE("linear stability: Nystrom's order-4 method is stable exactly on its interval of absolute stability",
          "[analysis][stability]") {
  const exact_rkn_tableau exact = nystrom4();
  const methods::tableau_data<T> t = numeric_tableau<T>(exact, nullptr);
  check_interval(exact, t, "nystrom4");
  // The trace alone (|tr M| <= 2 up to tau = sqrt 12) is not the stability condition: at tau = 3
  // the solution grows.
  CHECK(largest_amplitude(t, T(3), 200) > T(1000000));
  CHECK(linear_stability_interval(linear_stability(exact)).compare_squared(exact_number(9)) > 0);
}

TEST_CASE("linear stability: the Dormand-El-Mikkawy-Prince pairs on their intervals, or none", "[analysis][stability]") {
  // RKN4(3)4FM, both formulas: absolute stability (det M != 1) on their intervals (3.7678 and
  // 2.4823), bounded inside and growing outside.
  const auto rkn43 = methods::demp_rkn43::tableau(), embedded = methods::demp_rkn43_embedded::tableau();
  const exact_rkn_tableau e43 = rational_rkn_tableau(rkn43.c, rkn43.a, rkn43.bbar, rkn43.b);
  const exact_rkn_tableau e43e = rational_rkn_tableau(embedded.c, embedded.a, embedded.bbar, embedded.b);
  CHECK_FALSE(linear_stability(e43).determinant_is_one);
  check_interval(e43, numeric_tableau<T>(e43, nullptr), "demp rkn43");
  check_interval(e43e, numeric_tableau<T>(e43e, nullptr), "demp rkn43 embedded");
  // RKN6(4)6FM: an empty interval, its dissipation constant negative: the step matrix's
  // spectral radius sqrt(det M) (complex eigenvalues for small tau) exceeds 1 already at small
  // tau, measured from the numerical step.
  const auto rkn64 = methods::demp_rkn64::tableau();
  const exact_rkn_tableau e64 = rational_rkn_tableau(rkn64.c, rkn64.a, rkn64.bbar, rkn64.b);
  CHECK(linear_stability_interval(linear_stability(e64)).empty);
  const methods::tableau_data<T> t64 = numeric_tableau<T>(e64, nullptr);
  for (const T& tau : {T(1) / T(4), T(1) / T(2), T(1)}) {
    const auto [m11, m21] = harmonic_step(t64, T(1), T(0), tau);
    const auto [m12, m22] = harmonic_step(t64, T(0), T(1), tau);
    const T trace = m11 + m22, det = m11 * m22 - m12 * m21;
    INFO("tau = " << tau << ", det M - 1 = " << T(det - T(1)));
    CHECK(trace * trace < T(4) * det);  // complex pair: spectral radius sqrt(det)
    CHECK(det > T(1));
  }
}

TEST_CASE("linear stability: Stormer-Verlet and LPF m = 4 are periodic exactly on their intervals", "[analysis][stability]") {
  check_interval(trapezoidal_tableau(), numeric_tableau<T>(trapezoidal_tableau(), nullptr), "stormer-verlet");
  check_interval(lpf_tableau<4, equispaced>(), lpf_numeric_tableau<4, equispaced, T>(), "lpf m=4 equispaced");
}

TEST_CASE("linear stability: phase lag and dissipation measured from the numerical step matrix", "[analysis][stability]") {
  using std::acos;
  using std::pow;
  using std::sqrt;
  const exact_rkn_tableau exact = nystrom4();
  const linear_stability_result r = linear_stability(exact);
  const methods::tableau_data<T> t = numeric_tableau<T>(exact, nullptr);
  // phi(H) / H^(q+1) -> c_phi and d(H) / H^(r+1) -> c_d with relative corrections O(H^2).
  const T H = T(1) / T(1000);
  const auto [m11, m21] = harmonic_step(t, T(1), T(0), H);
  const auto [m12, m22] = harmonic_step(t, T(0), T(1), H);
  const T trace = m11 + m22, det = m11 * m22 - m12 * m21;
  const T phase_lag = H - acos(trace / (T(2) * sqrt(det)));
  const T dissipation = T(1) - sqrt(det);
  INFO("phi(H) = " << phase_lag << ", d(H) = " << dissipation);
  const T phase_ratio = phase_lag / pow(H, r.phase_lag_order + 1) / to_t(r.phase_lag_constant);
  const T dissipation_ratio = dissipation / pow(H, r.dissipation_order + 1) / to_t(r.dissipation_constant);
  CHECK(abs(phase_ratio - T(1)) < T(1) / T(1000));
  CHECK(abs(dissipation_ratio - T(1)) < T(1) / T(1000));
}
