/// Linear stability over Q(r) (analysis/field_stability.hpp, method_verdicts.hpp): the
/// compositions over Q(2^(1/3)) against the product of their Stormer-Verlet step matrices in 50
/// digits (an independent code path: no tableau, no determinant, no Sturm sequence), growth of
/// their solutions of y'' = -y just inside and outside the interval; the rational path and the
/// field path agree on rational methods; an SDIRK method over Q(sqrt 3) against Hairer & Wanner.
#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/algebraic_stability.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/tableau_file.hpp"

// A named namespace: the suites of a folder are compiled as one unit (UNITY_BUILD).
namespace field_stability_test {

using namespace geomint;
using methods::field_element;
using T = boost::multiprecision::cpp_bin_float_50;

/// The step matrix on (q, p) of y'' = -y, row-major.
using matrix = std::array<T, 4>;
matrix operator*(const matrix& a, const matrix& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}
matrix drift(const T& s) { return {T(1), s, T(0), T(1)}; }   // q += s p
matrix kick(const T& s) { return {T(1), T(0), -s, T(1)}; }   // p -= s q
/// Position Stormer-Verlet (drift h/2, kick h, drift h/2) and velocity Stormer-Verlet.
matrix position_verlet(const T& h) { return drift(h / 2) * kick(h) * drift(h / 2); }
matrix velocity_verlet(const T& h) { return kick(h / 2) * drift(h) * kick(h / 2); }

/// The step matrix of a composition with steps gamma_k h (applied in turn).
matrix composed(matrix (*base)(const T&), const std::vector<T>& gamma, const T& h) {
  matrix m{T(1), T(0), T(0), T(1)};
  for (const T& g : gamma) m = base(g * h) * m;
  return m;
}

/// The first h > 0 where |tr M(h)| > 2 for the step matrix M(h) = step_matrix(h) (det M = 1 for
/// these methods): a scan in steps of 1/1024 and 200 bisections.
template <class StepMatrix>
T first_trace_exit(const StepMatrix& step_matrix) {
  using std::abs;
  auto outside = [&](const T& h) {
    const matrix m = step_matrix(h);
    return abs(m[0] + m[3]) > T(2);
  };
  T h(0);
  const T step = T(1) / 1024;
  while (!outside(h + step)) h += step;
  T a = h, b = h + step;
  for (int k = 0; k < 200; ++k) {
    const T mid = (a + b) / 2;
    (outside(mid) ? b : a) = mid;
  }
  return a;
}

T to_t(const exact_number& x) { return T(x.num.str()) / T(x.den().str()); }

/// tau* of a bounded interval, to about 2^-200.
T interval_end(const stability_interval& interval) {
  using std::sqrt;
  return sqrt(to_t(interval.refined(200).low()));
}

/// A verdict with a bounded, nonempty interval of the given kind.
void require_bounded_interval(const method_verdicts& v, stability_verdict kind) {
  CHECK(v.stability == kind);
  REQUIRE_FALSE(v.interval.unbounded);
  REQUIRE_FALSE(v.interval.empty);
}

/// max(|q|, |p|) over `steps` steps of y'' = -y from (1, 0) with an explicit rkn tableau (its
/// coefficients in 50 digits; Q_i = q + c_i h p + h^2 sum_j a_ij F_j, F_j = -Q_j).
T explicit_rkn_amplitude(const methods::tableau_data<field_element>& t, const T& h, int steps) {
  const auto s = static_cast<std::size_t>(t.stages);
  T r(0);  // the field's generator once, in 50 digits
  for (const auto* v : {&t.c, &t.bbar, &t.b})
    for (const field_element& x : *v)
      if (x.field()) r = x.field()->root_in<T>();
  auto value = [&](const field_element& x) { return x.to<T>(r); };
  std::vector<T> c(s), bbar(s), b(s);
  std::vector<std::vector<T>> a(s, std::vector<T>(s));
  for (std::size_t i = 0; i < s; ++i) {
    c[i] = value(t.c[i]);
    bbar[i] = value(t.bbar[i]);
    b[i] = value(t.b[i]);
    for (std::size_t j = 0; j < s; ++j) {
      if (j >= i) REQUIRE(t.a[i][j].is_zero());
      a[i][j] = value(t.a[i][j]);
    }
  }
  T q(1), p(0), largest(1);
  std::vector<T> force(s);
  for (int n = 0; n < steps; ++n) {
    T q1 = q + h * p, p1 = p;
    for (std::size_t i = 0; i < s; ++i) {
      T stage = q + c[i] * h * p;
      for (std::size_t j = 0; j < i; ++j) stage += h * h * a[i][j] * force[j];
      force[i] = -stage;
      q1 += h * h * bbar[i] * force[i];
      p1 += h * b[i] * force[i];
    }
    q = q1;
    p = p1;
    using std::abs;
    largest = std::max({largest, T(abs(q)), T(abs(p))});
  }
  return largest;
}

methods::tableau_data<field_element> catalogue_tableau(const char* name) {
  const methods::catalogue_entry* e = methods::find_in_catalogue(name);
  REQUIRE(e != nullptr);
  return e->tableau();
}

TEST_CASE("Forest-Ruth, Yoshida, Suzuki over Q(2^(1/3)): the interval of periodicity of the Verlet matrix products", "[field_stability]") {
  using std::cbrt;
  const T r = cbrt(T(2)), theta = 1 / (2 - r), p = 1 / (4 - r * r);
  struct expected {
    const char* name;
    matrix (*base)(const T&);
    std::vector<T> gamma;
  };
  // Forest & Ruth 1990: position Verlet with theta, 1 - 2 theta, theta; Yoshida 1990: velocity
  // Verlet with w1, w0 = -2^(1/3) w1, w1 (w1 = theta); Suzuki 1990: velocity Verlet with p, p,
  // 1 - 4p, p, p, p = 1/(4 - 4^(1/3)).
  for (const expected& e : {expected{"forest-ruth", position_verlet, {theta, 1 - 2 * theta, theta}},
                            expected{"yoshida-triple-jump", velocity_verlet, {theta, -r * theta, theta}},
                            expected{"suzuki-4", velocity_verlet, {p, p, 1 - 4 * p, p, p}}}) {
    INFO(e.name);
    const auto t = catalogue_tableau(e.name);
    const method_verdicts v = verdicts(t);
    REQUIRE(v.oscillator_in_field);
    CHECK(v.field_oscillator.determinant_is_one);  // symplectic: det M = 1
    require_bounded_interval(v, stability_verdict::periodic);
    const T tau = interval_end(v.interval), reference = first_trace_exit([&](const T& h) { return composed(e.base, e.gamma, h); });
    using std::abs;
    CHECK(abs(tau - reference) < T(1) / T("1e40"));
    // Order 4: R - 2 cos tau = c tau^6 + O(tau^8), phase-lag order 4; c against the Verlet
    // matrix product, (tr M(h) - 2 cos h) / h^6 at h = 1/1000 (to O(h^2)).
    CHECK(v.field_oscillator.order == 4);
    CHECK(v.field_oscillator.phase_lag_order == 4);
    const T h = T(1) / 1000, c = v.field_oscillator.leading_coefficient.to<T>();
    const matrix m = composed(e.base, e.gamma, h);
    using std::cos;
    CHECK(abs((m[0] + m[3] - 2 * cos(h)) / (h * h * h * h * h * h) - c) < abs(c) / 10000);
    // The solution of y'' = -y from (1, 0): bounded 0.2 % inside, growing 0.2 % outside.
    CHECK(explicit_rkn_amplitude(t, tau * T(998) / 1000, 2000) < T(100));
    CHECK(explicit_rkn_amplitude(t, tau * T(1002) / 1000, 2000) > T(1000000));
  }
}

/// The step matrix of the splitting drift d_0 h, kick k_1 h, drift d_1 h, ..., kick k_s h, drift d_s h.
matrix kick_drift(const std::vector<T>& drifts, const std::vector<T>& kicks, const T& h) {
  matrix m = drift(drifts[0] * h);
  for (std::size_t i = 0; i < kicks.size(); ++i) m = drift(drifts[i + 1] * h) * kick(kicks[i] * h) * m;
  return m;
}

TEST_CASE("McLachlan's SB3A over quadratic fields: the interval of periodicity of the kick-drift products", "[field_stability]") {
  // McLachlan 1995 (SIAM J. Sci. Comput. 16, 151-168), SB3A with m = 4 and 5: the drifts as
  // printed to 20 digits in Principia (integrators/methods.hpp, McLachlan1995SB3A4) and in
  // Boost.Odeint (symplectic_rkn_sb3a_mclachlan.hpp), the kicks' fractions. SB3A-5's norm
  // polynomial has a Sturm sequence beyond 3072-bit integers (the field path forms it over Q).
  struct expected {
    const char* name;
    std::vector<T> drifts, kicks;
  };
  const T a4(T("0.18819521776883821787")), b4(T("-0.021528551102171551201"));
  const T a5(T("0.40518861839525227722")), b5(T("-0.28714404081652408900")), c5 = T(1) / 2 - a5 - b5;
  const T k1 = T(-3) / 73, k2 = T(17) / 59, k3 = 1 - 2 * (k1 + k2);
  for (const expected& e : {expected{"mclachlan-sb3a-4", {a4, b4, T(2) / 3, b4, a4}, {T(1), T(-1) / 2, T(-1) / 2, T(1)}},
                            expected{"mclachlan-sb3a-5", {a5, b5, c5, c5, b5, a5}, {k1, k2, k3, k2, k1}}}) {
    INFO(e.name);
    const auto t = catalogue_tableau(e.name);
    const method_verdicts v = verdicts(t);
    INFO(v.oscillator_reason);
    REQUIRE(v.oscillator_in_field);
    CHECK(v.field_oscillator.determinant_is_one);
    require_bounded_interval(v, stability_verdict::periodic);
    // The first exit of |tr M| from [-2, 2] of the printed coefficients' matrices.
    using std::abs;
    const T tau = interval_end(v.interval), reference = first_trace_exit([&](const T& h) { return kick_drift(e.drifts, e.kicks, h); });
    CHECK(abs(tau - reference) < T(1) / T("1e16"));  // the printed drifts' 20 digits
    CHECK(explicit_rkn_amplitude(t, tau * T(998) / 1000, 2000) < T(100));
    CHECK(explicit_rkn_amplitude(t, tau * T(1002) / 1000, 2000) > T(1000000));
  }
}

TEST_CASE("The field path agrees with the rational path on rational methods", "[field_stability]") {
  // Stormer-Verlet (periodic, tau* = 2) and RKN4(3)4FM (det M != 1: absolute stability, its
  // dissipation and phase lag) through field_linear_stability and the constexpr rational analysis.
  for (const char* name : {"stormer-verlet", "demp-rkn43", "ruth-3"}) {
    INFO(name);
    const auto t = catalogue_tableau(name);
    const linear_stability_result exact = linear_stability(t);
    const stability_interval exact_interval = linear_stability_interval(exact);
    const field_linear_stability_result field = field_linear_stability(t);
    CHECK(field.determinant_is_one == exact.determinant_is_one);
    CHECK(field.order == exact.order);
    CHECK(field.phase_lag_order == exact.phase_lag_order);
    CHECK(field.dissipation_order == exact.dissipation_order);
    auto same = [](const field_element& a, const exact_number& b) {
      return a == field_element(methods::exact_rational(b.num.str()) / methods::exact_rational(b.den().str()));
    };
    CHECK(same(field.phase_lag_constant, exact.phase_lag_constant));
    CHECK(same(field.leading_coefficient, exact.leading_coefficient));
    if (!exact.determinant_is_one) CHECK(same(field.dissipation_constant, exact.dissipation_constant));
    REQUIRE(field.interval.empty == exact_interval.empty);
    REQUIRE(field.interval.unbounded == exact_interval.unbounded);
    if (!exact_interval.empty && !exact_interval.unbounded) {
      // The same algebraic number: each bracket's ends lie on the right sides of the other root.
      const stability_interval a = field.interval.refined(100), b = exact_interval.refined(100);
      CHECK(b.compare_squared(a.low()) <= 0);
      CHECK(b.compare_squared(a.high()) >= 0);
      CHECK(a.compare_squared(b.low()) <= 0);
      CHECK(a.compare_squared(b.high()) >= 0);
    }
  }
  CHECK(field_linear_stability(catalogue_tableau("stormer-verlet")).interval.compare_squared(exact_number(4)) == 0);
}

/// The constexpr analysis over algebraic_number (algebraic_stability.hpp), run at run time on a
/// typed method, against the field path on the catalogue's run-time tableau.
template <class Method>
void check_algebraic_path(const char* name) {
  INFO(name);
  const auto typed = [] {
    if constexpr (requires { methods::tableau_of(Method::tableau()); }) return methods::tableau_of(Method::tableau()).tableau;
    else return Method::tableau();
  }();
  const algebraic_linear_stability_result a = algebraic_linear_stability(typed);
  const field_linear_stability_result f = field_linear_stability(catalogue_tableau(name));
  CHECK(a.determinant_is_one == f.determinant_is_one);
  CHECK(a.order == f.order);
  CHECK(a.phase_lag_order == f.phase_lag_order);
  CHECK(a.dissipation_order == f.dissipation_order);
  REQUIRE(a.interval.empty == f.interval.empty);
  REQUIRE(a.interval.unbounded == f.interval.unbounded);
  if (!a.interval.empty && !a.interval.unbounded) {
    const stability_interval x = a.interval.refined(100), y = f.interval.refined(100);
    CHECK(y.compare_squared(x.low()) <= 0);
    CHECK(y.compare_squared(x.high()) >= 0);
    CHECK(x.compare_squared(y.low()) <= 0);
    CHECK(x.compare_squared(y.high()) >= 0);
  }
}

TEST_CASE("The constexpr path over algebraic_number agrees with the field path", "[field_stability]") {
  // Two implementations of the same analysis (fixed-size constexpr types against run-time field
  // elements); the values themselves are checked against the matrix products above and, for
  // Forest-Ruth, against an 80-digit computation outside the library
  // (static_algebraic_stability.cpp).
  check_algebraic_path<methods::forest_ruth>("forest-ruth");
  check_algebraic_path<methods::yoshida_triple_jump>("yoshida-triple-jump");
  check_algebraic_path<methods::mclachlan_sb3a4>("mclachlan-sb3a-4");
}

methods::tableau_data<field_element> tableau_from(const std::string& text) {
  std::istringstream in(text);
  return methods::read_tableau(in, "test");
}

/// Complex numbers in 50 digits (the few operations one SDIRK step needs).
struct complex50 {
  T re, im;
};
complex50 operator+(const complex50& a, const complex50& b) { return {a.re + b.re, a.im + b.im}; }
complex50 operator*(const complex50& a, const complex50& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
complex50 operator/(const complex50& a, const complex50& b) {
  const T n = b.re * b.re + b.im * b.im;
  return {(a.re * b.re + a.im * b.im) / n, (a.im * b.re - a.re * b.im) / n};
}
complex50 scaled(const T& s, const complex50& a) { return {s * a.re, s * a.im}; }
T modulus_squared(const complex50& a) { return a.re * a.re + a.im * a.im; }

/// One step of y' = lambda y (z = h lambda) from y = 1 with the 2-stage SDIRK tableau
/// (gamma, 0; 1 - 2 gamma, gamma), b = (1/2, 1/2): the stage equations solved directly.
complex50 sdirk_step(const T& gamma, const complex50& z) {
  const complex50 one{T(1), T(0)}, denominator = one + scaled(-gamma, z);
  const complex50 k1 = z / denominator;
  const complex50 k2 = z * (one + scaled(1 - 2 * gamma, k1)) / denominator;
  return one + scaled(T(1) / 2, k1 + k2);
}

TEST_CASE("SDIRK of order 3 over Q(sqrt 3): A-stable for gamma = (3 + sqrt 3)/6 only", "[field_stability]") {
  // Hairer & Wanner II, section IV.6 (SDIRK methods): the 2-stage SDIRK method of order 3 has
  // gamma = (3 +- sqrt 3)/6 and is A-stable for the + sign only; R(inf) = 1 - sqrt 3 != 0 for it,
  // so it is not L-stable. Its stability function has irrational coefficients.
  const auto plus = tableau_from(
      "kind rk\nstages 2\nfield r^2-3\nc 1/2+1/6*r 1/2-1/6*r\na 1/2+1/6*r 0 -1/3*r 1/2+1/6*r\nb 1/2 1/2\n");
  const auto minus = tableau_from(
      "kind rk\nstages 2\nfield r^2-3\nc 1/2-1/6*r 1/2+1/6*r\na 1/2-1/6*r 0 1/3*r 1/2-1/6*r\nb 1/2 1/2\n");
  const method_verdicts vp = verdicts(plus), vm = verdicts(minus);
  REQUIRE(vp.rk_in_field);
  REQUIRE(vm.rk_in_field);
  CHECK(vp.field_rk.a_stable);
  CHECK_FALSE(vp.field_rk.l_stable);
  CHECK(vp.stability == stability_verdict::a_stable);
  CHECK_FALSE(vm.field_rk.a_stable);
  CHECK(vm.field_rk.poles_in_right_half_plane);  // the pole 1/gamma > 0
  CHECK(vm.field_rk.imaginary_axis.empty);        // |R(iy)| > 1 for every y > 0
  CHECK(vm.stability == stability_verdict::none);
  // Measured: |R(iy)| <= 1 for the + sign, > 1 for the - sign, at y = 1/10, 1, 10; R(-10^6) tends
  // to 1 - sqrt 3 for the + sign.
  using std::sqrt;
  const T gp = (3 + sqrt(T(3))) / 6, gm = (3 - sqrt(T(3))) / 6;
  for (const T& y : {T(T(1) / 10), T(1), T(10)}) {
    CHECK(modulus_squared(sdirk_step(gp, {T(0), y})) <= T(1));
    CHECK(modulus_squared(sdirk_step(gm, {T(0), y})) > T(1));
  }
  using std::abs;
  CHECK(abs(sdirk_step(gp, {T(-1000000), T(0)}).re - (1 - sqrt(T(3)))) < T(1) / 100000);
  // R(z) reduced over Q(sqrt 3) with Q(0) = 1: Q = (1 - gamma z)^2, so Q_2 = gamma^2 = (2 + sqrt 3)/6.
  REQUIRE(vp.field_rk.denominator.size() == 3);
  const field_element r = field_element(6) * (plus.c[0] - field_element(methods::exact_rational(1, 2)));  // sqrt 3, of the file's field
  CHECK(r * r == field_element(3));
  CHECK(vp.field_rk.denominator[2] == (field_element(2) + r) / field_element(6));
}

TEST_CASE("An explicit rk method over Q(sqrt 2): its finite imaginary-axis interval from |R(iy)|^2", "[field_stability]") {
  // a_21 = sqrt 2, b = (1/2, 1/2): R(z) = 1 + z + g z^2 with g = b_2 a_21 = sqrt 2 / 2 (the
  // stability function of an explicit method, HW II section IV.2). |R(iy)|^2 = (1 - g y^2)^2 + y^2
  // = 1 - (2 g - 1) y^2 + g^2 y^4 <= 1 exactly for y^2 <= (2 g - 1) / g^2 = 2 sqrt 2 - 2.
  const auto t = tableau_from("kind rk\nstages 2\nfield r^2-2\nc 0 r\na 0 0 r 0\nb 1/2 1/2\n");
  const method_verdicts v = verdicts(t);
  REQUIRE(v.rk_in_field);
  CHECK_FALSE(v.field_rk.a_stable);
  require_bounded_interval(v, stability_verdict::absolute);
  using std::abs;
  using std::sqrt;
  CHECK(abs(interval_end(v.interval) - sqrt(2 * sqrt(T(2)) - 2)) < T(1) / T("1e40"));
}

}  // namespace field_stability_test
