/// The verdicts of analysis/rk_stability.hpp and method_verdicts.hpp on tableaux over Q(r) and
/// of every kind, against the published values, and one verdict against a measurement.
///
/// Expected values: the Gauss s = 2, 3 and Radau IIA s = 3 stability functions are the Pade
/// approximants R_22, R_33 and R_23 of exp (Hairer & Wanner, Solving ODEs II, sections IV.3 and
/// IV.5); Gauss A-stable and not L-stable, Radau IIA L-stable (ibid., sections IV.4 and IV.5);
/// stage orders Gauss s, Radau IIA s (ibid., section IV.5: B(2s), C(s) and B(2s-1), C(s));
/// Gauss symmetric, Radau not (Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd
/// ed., Theorem V.2.3). Measurements: each method stepped numerically in cpp_bin_float_50 from
/// its tableau (the stage equations solved by Gaussian elimination), never through R.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/analysis/rk_stability.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "pade.hpp"

// A named namespace: the suites of a folder are compiled as one unit (UNITY_BUILD).
namespace rk_stability_test {

using namespace geomint;
using methods::exact_rational;
using methods::field_element;
using T = boost::multiprecision::cpp_bin_float_50;

methods::tableau_data<field_element> test_tableau(const std::string& file) {
  return methods::read_tableau_file(std::string(GEOMINT_SOURCE_DIR) + "/tests/analysis/tableaux/" + file);
}
methods::tableau_data<field_element> tableau_from(const std::string& text) {
  std::istringstream in(text);
  return methods::read_tableau(in, "test");
}

exact_rational exact(const rational& x) { return exact_rational(x.num, x.den); }

/// Whether R = P / Q (unreduced, P(0) = Q(0) = 1) is the Pade approximant R_kj of exp
/// (tests/pade.hpp).
bool is_pade(const rational_function<std::vector<field_element>>& f, int k, int j) {
  for (std::size_t n = 0; n < f.numerator.size(); ++n) {
    const int i = static_cast<int>(n);
    if (!(f.numerator[n] == field_element(exact(geomint::test::pade_numerator(k, j, i)))) ||
        !(f.denominator[n] == field_element(exact(geomint::test::pade_denominator(k, j, i)))))
      return false;
  }
  return true;
}

/// An rk tableau's coefficients in T (the field's root at T's precision).
struct numeric_rk {
  std::size_t s = 0;
  std::vector<std::vector<T>> a;
  std::vector<T> b;
};
numeric_rk numeric(const methods::tableau_data<field_element>& t) {
  numeric_rk n;
  n.s = static_cast<std::size_t>(t.stages);
  for (const auto& row : t.a) {
    n.a.emplace_back();
    for (const auto& x : row) n.a.back().push_back(x.to<T>());
  }
  for (const auto& x : t.b) n.b.push_back(x.to<T>());
  return n;
}

/// Solves m x = r (Gaussian elimination, partial pivoting).
std::vector<T> solve(std::vector<std::vector<T>> m, std::vector<T> r) {
  const std::size_t n = r.size();
  using std::abs;
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (abs(m[i][k]) > abs(m[pivot][k])) pivot = i;
    std::swap(m[k], m[pivot]);
    std::swap(r[k], r[pivot]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const T f = m[i][k] / m[k][k];
      for (std::size_t j = k; j < n; ++j) m[i][j] -= f * m[k][j];
      r[i] -= f * r[k];
    }
  }
  std::vector<T> x(n);
  for (std::size_t i = n; i-- > 0;) {
    T sum = r[i];
    for (std::size_t j = i + 1; j < n; ++j) sum -= m[i][j] * x[j];
    x[i] = sum / m[i][i];
  }
  return x;
}

/// One step of the RK method on y' = lambda y with real z = h lambda: the stage increments
/// k = h f(Y) solve (I - z A) k = z y 1, y1 = y + b^T k.
T real_step(const numeric_rk& t, const T& y, const T& z) {
  std::vector<std::vector<T>> m(t.s, std::vector<T>(t.s));
  for (std::size_t i = 0; i < t.s; ++i)
    for (std::size_t j = 0; j < t.s; ++j) m[i][j] = T(i == j ? 1 : 0) - z * t.a[i][j];
  const std::vector<T> k = solve(m, std::vector<T>(t.s, z * y));
  T y1 = y;
  for (std::size_t i = 0; i < t.s; ++i) y1 += t.b[i] * k[i];
  return y1;
}

/// |(q, p)| after n steps of the RK method on q' = p, p' = -q from (1, 0) with step h: the stage
/// increments (kq, kp) solve kq_i = h (p + sum_j a_ij kp_j), kp_i = -h (q + sum_j a_ij kq_j).
T oscillator_growth(const numeric_rk& t, const T& h, int steps) {
  const std::size_t s = t.s;
  std::vector<std::vector<T>> m(2 * s, std::vector<T>(2 * s, T(0)));
  for (std::size_t i = 0; i < s; ++i) {
    m[i][i] = m[s + i][s + i] = T(1);
    for (std::size_t j = 0; j < s; ++j) {
      m[i][s + j] = -h * t.a[i][j];
      m[s + i][j] = h * t.a[i][j];
    }
  }
  T q(1), p(0);
  for (int n = 0; n < steps; ++n) {
    std::vector<T> r(2 * s);
    for (std::size_t i = 0; i < s; ++i) {
      r[i] = h * p;
      r[s + i] = -h * q;
    }
    const std::vector<T> k = solve(m, r);
    for (std::size_t i = 0; i < s; ++i) {
      q += t.b[i] * k[i];
      p += t.b[i] * k[s + i];
    }
  }
  using std::sqrt;
  return sqrt(q * q + p * p);
}

const char* rk4_text = "kind rk\nstages 4\nname rk4\nc 0 1/2 1/2 1\na 0 0 0 0  1/2 0 0 0  0 1/2 0 0  0 0 1 0\nb 1/6 1/3 1/3 1/6\n";

TEST_CASE("Gauss and Radau IIA over Q(r): Pade approximants, A- and L-stability, symmetry, stage order", "[rk_stability]") {
  struct expected {
    const char* file;
    int k, j;
    bool l_stable, symmetric;
    int stage_order;
  };
  for (const expected& e : {expected{"gauss2_rk.tableau", 2, 2, false, true, 2}, expected{"gauss3_rk.tableau", 3, 3, false, true, 3},
                            expected{"radau_iia3.tableau", 2, 3, true, false, 3}}) {
    INFO(e.file);
    const auto t = test_tableau(e.file);
    CHECK(is_pade(stability_function(t), e.k, e.j));
    const rk_stability_result r = rk_stability(t);
    CHECK(r.a_stable);
    CHECK(r.l_stable == e.l_stable);
    CHECK(r.imaginary_axis.unbounded);
    const method_verdicts v = verdicts(t);
    CHECK(v.symmetric == e.symmetric);
    CHECK(v.stage_order == e.stage_order);
    CHECK(v.stability == stability_verdict::a_stable);
    // On y'' = -y through the Nystrom form: Gauss has |R(iy)| = 1 (det M = 1), Radau IIA damps.
    REQUIRE(v.has_oscillator);
    CHECK(v.oscillator.determinant_is_one == e.symmetric);
  }
}

TEST_CASE("Rationals of any size: a coefficient above 2^64 is exact", "[rk_stability]") {
  // Implicit Euler scaled: A = 1, b = 1 written as huge / huge.
  const auto t = tableau_from(
      "kind rk\nstages 1\nc 1\na 123456789012345678901234567890/123456789012345678901234567890\n"
      "b 98765432109876543210987654321/98765432109876543210987654321\n");
  CHECK(rk_stability(t).l_stable);
  // theta method with theta = 1/2 + 2^-70 (HW II, section IV.3: A-stable iff theta >= 1/2,
  // R(inf) = (theta - 1) / theta != 0): A-stable, not L-stable; theta = 1/2 - 2^-70: not A-stable.
  const std::string big = "1180591620717411303424";  // 2^70
  const auto above = tableau_from("kind rk\nstages 1\nc 1\na 1/2+1/" + big + "\nb 1\n");
  const auto below = tableau_from("kind rk\nstages 1\nc 1\na 1/2-1/" + big + "\nb 1\n");
  CHECK(rk_stability(above).a_stable);
  CHECK_FALSE(rk_stability(above).l_stable);
  CHECK_FALSE(rk_stability(below).a_stable);
  CHECK_FALSE(rk_stability(below).bounded_on_imaginary_axis);
  CHECK(rk_stability(below).poles_in_right_half_plane);
}

TEST_CASE("RK4's imaginary-axis interval 2 sqrt 2 agrees with its interval on y'' = -y and with growth", "[rk_stability]") {
  const auto t = tableau_from(rk4_text);
  const method_verdicts v = verdicts(t);
  CHECK(v.stability == stability_verdict::absolute);
  CHECK(v.interval.compare_squared(exact_number(8)) == 0);
  // The same bound from the step matrix of the Nystrom form (A A, b^T A, b): other polynomials,
  // Jury's conditions instead of E(y).
  REQUIRE(v.has_oscillator);
  const stability_interval oscillator = linear_stability_interval(v.oscillator);
  CHECK(oscillator.kind == stability_kind::absolute);
  CHECK(oscillator.compare_squared(exact_number(8)) == 0);
  // |R(iy)|^2 = 1 - y^6/72 + y^8/576 (exact): dissipation 1 - |R| = y^6/144 + ..., order 5.
  CHECK(v.oscillator.dissipation_order == 5);
  // Measured: inside (h = 2.82) the oscillator's amplitude does not grow in 400 steps, outside
  // (h = 2.84, |R|^2 = 1.0595...) it grows by more than 1e5.
  const numeric_rk n = numeric(t);
  CHECK(oscillator_growth(n, T(282) / 100, 400) <= T(1));
  CHECK(oscillator_growth(n, T(284) / 100, 400) > T(100000));
}

TEST_CASE("L-stability measured: stiff decay of implicit Euler and Radau IIA, not of the trapezoidal rule", "[rk_stability]") {
  const auto euler = tableau_from("kind rk\nstages 1\nc 1\na 1\nb 1\n");
  const auto trapezoidal = tableau_from("kind rk\nstages 2\nc 0 1\na 0 0 1/2 1/2\nb 1/2 1/2\n");
  const auto radau = test_tableau("radau_iia3.tableau");
  CHECK(rk_stability(euler).l_stable);
  CHECK(rk_stability(radau).l_stable);
  CHECK(rk_stability(trapezoidal).a_stable);
  CHECK_FALSE(rk_stability(trapezoidal).l_stable);
  // One step of y' = lambda y with z = -10^6: |R(z)| -> 0 for the L-stable methods, -> 1 for the
  // trapezoidal rule ((1 + z/2) / (1 - z/2) = -0.999996...).
  const T z(-1000000);
  using std::abs;
  CHECK(abs(real_step(numeric(euler), T(1), z)) < T(1) / 100000);
  CHECK(abs(real_step(numeric(radau), T(1), z)) < T(1) / 100000);
  CHECK(abs(real_step(numeric(trapezoidal), T(1), z)) > T(99) / 100);
  // A-stability measured on the oscillator with a large step: Radau IIA damps, Gauss keeps |y|.
  CHECK(oscillator_growth(numeric(radau), T(10), 50) < T(1));
  const T gauss = oscillator_growth(numeric(test_tableau("gauss3_rk.tableau")), T(10), 50);
  CHECK(abs(gauss - T(1)) < T(1) / 1000000000);
}

TEST_CASE("prk, rkn and nystrom tableaux: symmetry up to stage permutation, stage order, y'' = -y", "[rk_stability]") {
  // Lobatto IIIA-IIIB s = 2 is Stormer-Verlet (HLW section II.2): symmetric, interval of
  // periodicity (0, 2) (|tr M| = |2 - tau^2| <= 2); Lobatto IIIB has c != A 1, so C(1) fails:
  // stage order 0 (HW II section IV.5: Lobatto IIIB stage order s - 2).
  const auto pair2 = tableau_from("kind prk\nstages 2\nc 0 1\na 0 0 1/2 1/2\nb 1/2 1/2\nahat 1/2 0 1/2 0\nbhat 1/2 1/2\n");
  const method_verdicts v2 = verdicts(pair2);
  CHECK(v2.symmetric);
  CHECK(v2.stage_order == 0);
  CHECK(v2.stability == stability_verdict::periodic);
  CHECK(v2.interval.compare_squared(exact_number(4)) == 0);
  const method_verdicts v3 = verdicts(test_tableau("lobatto_iiia_iiib3.tableau"));
  CHECK(v3.symmetric);  // HLW Theorem V.2.3 for each of IIIA and IIIB with the same sigma
  CHECK(v3.stage_order == 1);  // min(IIIA: 3, IIIB: s - 2 = 1)
  CHECK(v3.stability == stability_verdict::periodic);
  // The Nystrom form of the implicit midpoint rule: symmetric; stage order (RKN definition) 1:
  // the position stage q + h/2 v + h^2/4 F misses the exact h^2/8 F (a 1 = 1/4 != c^2/2 = 1/8).
  const method_verdicts vm = verdicts(test_tableau("midpoint_nystrom.tableau"));
  CHECK(vm.symmetric);
  CHECK(vm.stage_order == 1);
  CHECK(vm.stability == stability_verdict::periodic);
  CHECK(vm.interval.unbounded);
  // Changing ap breaks the symmetry of a nystrom tableau only through ap.
  const auto skewed = tableau_from("kind nystrom\nstages 1\nc 1/2\na 1/4\nap 1/3\nbbar 1/2\nb 1\n");
  CHECK_FALSE(verdicts(skewed).symmetric);
  // Implicit Euler over h/2, then explicit Euler over h/2 (Phi*_{h/2} o Phi_{h/2}, symmetric by
  // HLW section II.3): two stages of the equal node 1/2, which the adjoint exchanges
  // (a_11 = 1/2 != b_1 - a_11 = 0, so only the swap fits).
  const auto split = tableau_from("kind rk\nstages 2\nc 1/2 1/2\na 1/2 0 1/2 0\nb 1/2 1/2\n");
  const method_verdicts vs = verdicts(split);
  CHECK(vs.symmetric);
  CHECK(vs.permutation.sigma[0] == 1);
  CHECK(vs.permutation.sigma[1] == 0);
}

TEST_CASE("Irrational stability polynomials are decided over Q(r), not by the rational path", "[rk_stability]") {
  const auto t = methods::read_tableau_file(std::string(GEOMINT_SOURCE_DIR) + "/examples/tableaux/forest_ruth.tableau");
  const method_verdicts v = verdicts(t);
  CHECK(v.symmetric);  // Forest & Ruth, Physica D 43 (1990): a symmetric composition
  CHECK_FALSE(v.has_oscillator);  // the constexpr rational analysis refuses Q(2^(1/3))
  CHECK(v.oscillator_in_field);   // field_stability.hpp decides it (tests/analysis/test_field_stability.cpp)
  CHECK(v.has_stability);
  CHECK(v.stability == stability_verdict::periodic);
}

}  // namespace rk_stability_test
