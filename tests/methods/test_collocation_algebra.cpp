/// Runge-Kutta methods over their stage algebra (methods/collocation_algebra.hpp,
/// analysis/collocation_algebra_analysis.hpp). Independent sources:
/// - a second construction: for s = 2..4 the exact tableaux of collocation_families.hpp (nodes
///   and C(s), D(s) solved in a number field) have the same elementary weights, R(z), stage
///   order, symplecticity, symmetry and error constant as the operators on Q[x]/(N);
/// - the published properties of Radau IIA and IA with s = 5 (Ehle 1969; Hairer & Wanner, Solving
///   ODEs II, section IV.5, Radau IA and IIA methods): order 2s - 1 = 9, stage
///   order s (IIA: C(s)) and s - 1 (IA: C(s - 1)), R(z) the (s - 1, s) Pade approximant of e^z,
///   A- and L-stable, neither symplectic nor symmetric; Gauss (Butcher 1964) symplectic and
///   symmetric, Lobatto IIIB symmetric (Hairer, Lubich & Wanner 2006, sections II.1.4 and VI.4);
/// - the Pade approximant's coefficients from their closed form (Hairer & Wanner II, section
///   IV.3, Pade approximations to the exponential function);
/// - the numeric tableau in 50 digits (nodes by Newton in that type, barycentric Lagrange
///   integrals) against the exact elementary weights, and its step's symplecticity defect.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

#include "catch.hpp"
#include "pade.hpp"
#include "geomint/analysis/collocation_algebra_analysis.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/collocation_algebra.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/methods/tableau_method.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/methods/tableau_stepper.hpp"
#include "scalar_types.hpp"

namespace collocation_algebra_test {

using namespace geomint;
using methods::exact_rational;
using methods::field_element;
using methods::rk_stage_algebra;
using T50 = geomint::test::cpp_bin_float_50;
namespace bs = geomint::analysis::bseries;

rk_stage_algebra algebra_of(methods::collocation_family f, int s) {
  using F = methods::collocation_family;
  switch (f) {
    case F::gauss: return methods::collocation_algebra(methods::detail::monic(methods::detail::shifted_legendre(s)));
    case F::radau_iia: return methods::radau_iia_algebra(s);
    case F::radau_ia: return methods::radau_ia_algebra(s);
    default: {
      // Lobatto IIIA (collocation) and IIIB (its complement) on x (1 - x) P*'_(s-1).
      methods::detail::poly n = methods::detail::multiply({exact_rational(0), exact_rational(1), exact_rational(-1)},
                                                          methods::detail::derivative(methods::detail::shifted_legendre(s - 1)));
      const rk_stage_algebra a = methods::collocation_algebra(methods::detail::monic(n));
      return f == F::lobatto_iiia ? a : methods::symplectic_complement(a);
    }
  }
}

TEST_CASE("collocation algebra: the operators on Q[x]/(N) are the families' exact tableaux (s = 2..4)", "[methods]") {
  using F = methods::collocation_family;
  for (F f : {F::gauss, F::radau_iia, F::radau_ia, F::lobatto_iiia, F::lobatto_iiib})
    for (int s = 2; s <= 4; ++s) {
      if ((f == F::gauss || f == F::radau_iia || f == F::radau_ia) && s == 4) continue;  // fields of degree 6 and 8: slow series
      INFO("family " << static_cast<int>(f) << ", s = " << s);
      const auto t = methods::collocation_family_tableau(f, s);
      const rk_stage_algebra a = algebra_of(f, s);
      const bs::tree_set trees(7, 1);
      CHECK(bs::elementary_weights(trees, a) == bs::elementary_weights(trees, t));
      const auto va = analysis::verdicts(a);
      const auto vt = verdicts(t);
      CHECK(va.symmetric == vt.symmetric);
      CHECK(va.stage_order == stage_order(t));
      REQUIRE(va.has_rk);
      REQUIRE(vt.has_rk);
      CHECK(va.rk.numerator == vt.rk.numerator);
      CHECK(va.rk.denominator == vt.rk.denominator);
      CHECK(va.rk.a_stable == vt.rk.a_stable);
      CHECK(va.rk.l_stable == vt.rk.l_stable);
      REQUIRE(va.has_oscillator);
      CHECK(va.oscillator.phase_lag_order == vt.oscillator.phase_lag_order);
      CHECK(va.oscillator.dissipation_order == vt.oscillator.dissipation_order);
      const auto conditions = analysis::symplecticity_conditions(a);
      if (f == F::lobatto_iiib && s == 2) {
        // Reducible (both stages solve K = f(y + h K / 2): the implicit midpoint rule, symplectic;
        // Hairer, Lubich & Wanner, section VI.3), with A 1 = (1/2, 1/2) != c: not decided here.
        CHECK_FALSE(conditions.irreducible);
        CHECK_THROWS_AS(bs::analyse_method(a), std::domain_error);
      } else {
        CHECK(conditions.irreducible);
        CHECK(conditions.symplectic == analysis::symplecticity_conditions(t).symplectic);
      }
    }
}

TEST_CASE("collocation algebra: Gauss s = 5 and 6 are symplectic and symmetric, Lobatto IIIB s = 5 symmetric", "[methods]") {
  using F = methods::collocation_family;
  for (int s : {5, 6}) {
    const rk_stage_algebra g = algebra_of(F::gauss, s);
    CHECK(analysis::symplecticity_conditions(g).symplectic);
    CHECK(analysis::is_symmetric(g));
    CHECK(analysis::stage_order(g) == s);
  }
  const rk_stage_algebra iiib = algebra_of(F::lobatto_iiib, 5);
  CHECK(analysis::is_symmetric(iiib));
  CHECK_FALSE(analysis::symplecticity_conditions(iiib).symplectic);  // IIIB alone is not (only the pair is)
}

/// The (k, j) Pade approximant of e^z (tests/pade.hpp) over exact rationals.
std::pair<std::vector<exact_rational>, std::vector<exact_rational>> pade(int k, int j) {
  auto exact = [](const rational& x) { return exact_rational(x.num, x.den); };
  std::vector<exact_rational> p, q;
  for (int i = 0; i <= k; ++i) p.push_back(exact(test::pade_numerator(k, j, i)));
  for (int i = 0; i <= j; ++i) q.push_back(exact(test::pade_denominator(k, j, i)));
  return {p, q};
}

TEST_CASE("collocation algebra: Radau IIA and IA, s = 5, have their published properties", "[methods]") {
  const auto [p, q] = pade(4, 5);
  for (bool right : {true, false}) {
    const rk_stage_algebra m = right ? methods::radau_iia_algebra(5) : methods::radau_ia_algebra(5);
    INFO(m.name);
    const auto r = bs::analyse_method(m);
    CHECK(r.order == 9);
    CHECK_FALSE(r.order_is_lower_bound);
    CHECK_FALSE(r.symplectic);
    const auto v = analysis::verdicts(m);
    CHECK_FALSE(v.symmetric);
    CHECK(v.stage_order == (right ? 5 : 4));
    REQUIRE(v.has_rk);
    // R = P / Q in lowest terms over Z (rk_stability.hpp): compared after dividing by Q(0).
    REQUIRE(v.rk.numerator.degree == static_cast<int>(p.size()) - 1);
    REQUIRE(v.rk.denominator.degree == static_cast<int>(q.size()) - 1);
    const exact_rational q0(v.rk.denominator[0].str());
    for (std::size_t i = 0; i < p.size(); ++i) CHECK(exact_rational(v.rk.numerator[static_cast<int>(i)].str()) / q0 == p[i]);
    for (std::size_t i = 0; i < q.size(); ++i) CHECK(exact_rational(v.rk.denominator[static_cast<int>(i)].str()) / q0 == q[i]);
    CHECK(v.rk.a_stable);
    CHECK(v.rk.l_stable);
    CHECK(v.stability == stability_verdict::a_stable);
    // R - e^z = C z^10 + ...: on the imaginary axis phase lag of order 10, dissipation of order 9.
    CHECK(v.oscillator.phase_lag_order == 10);
    CHECK(v.oscillator.dissipation_order == 9);
    const auto ec = bs::principal_error_constants(m, r.order);
    CHECK(ec.squared.rational_value() > 0);
  }
}

TEST_CASE("collocation algebra: the numeric Radau tableaux of s = 5 in 50 digits have the exact weights", "[methods]") {
  const T50 tolerance = T50(1000) * std::numeric_limits<T50>::epsilon();
  const bs::tree_set trees(9, 1);
  auto check = [&](const auto& numeric, const rk_stage_algebra& exact) {
    const auto phi = bs::elementary_weights(trees, numeric);
    const auto phi_exact = bs::elementary_weights(trees, exact);
    for (std::size_t t = 0; t < phi.size(); ++t) {
      const T50 e = methods::rational_to<T50>(phi_exact[t].rational_value());
      using std::abs;
      CHECK(abs(phi[t] - e) <= tolerance);
    }
  };
  check(methods::radau_iia<5>::numeric_tableau<T50>(), methods::radau_iia_algebra(5));
  check(methods::radau_ia<5>::numeric_tableau<T50>(), methods::radau_ia_algebra(5));
  // The nodes, from their exact brackets, against core/nodes.hpp's (sign-change scan and Newton on
  // the Legendre recurrence in T50): radau_right is 0 and the Radau IIA points, radau_left the
  // Radau IA points and 1.
  const auto right = nodes<radau_right, 5, T50>(), left = nodes<radau_left, 5, T50>();
  const auto iia = methods::radau_iia<5>::numeric_tableau<T50>(), ia = methods::radau_ia<5>::numeric_tableau<T50>();
  for (std::size_t i = 0; i < 5; ++i) {
    using std::abs;
    CHECK(abs(iia.c[i] - right[i + 1]) <= tolerance);
    CHECK(abs(ia.c[i] - left[i]) <= tolerance);
  }
}

TEST_CASE("collocation algebra: the step of Radau s = 5 has a symplecticity defect far above the noise", "[methods]") {
  // As tests/analysis/test_tableau_symplecticity.cpp for the other entries: one step of
  // tau = 1/2 on the pendulum in 50 digits, the Jacobian by central differences (noise about
  // eps^(4/5)); not symplectic, so the defect is far above it.
  using std::pow;
  const T50 noise = T50(1024) * pow(std::numeric_limits<T50>::epsilon(), T50(4) / T50(5));
  analysis::phase_vector<T50> z(2);
  z << T50(1), T50(1) / T50(2);
  for (bool right : {true, false}) {
    const auto form = methods::nystrom_form_of(right ? methods::radau_iia<5>::numeric_tableau<T50>() : methods::radau_ia<5>::numeric_tableau<T50>());
    const auto stepper = make_tableau_stepper<systems::pendulum, T50>(form);
    CHECK(analysis::symplectic_defect(analysis::one_step_jacobian<T50>(*stepper, T50(1) / T50(2), z)) > noise * T50(1000000));
  }
}

TEST_CASE("collocation algebra: the catalogue's Gauss s = 4, 5 and Radau s = 4 are their field tableaux", "[methods]") {
  // The catalogue analyses these over the stage algebra and runs their tableaux over fields of
  // degree 8 and 6 (collocation_families.hpp): the same method, by the weights to order 5 (the
  // field's series cost milliseconds per tree) and by R(z) (rational for these methods). Gauss has order 2s (Butcher 1964),
  // decided with the rooted trees to 2s + 1.
  for (const char* name : {"gauss-4", "gauss-5", "radau-iia-4", "radau-ia-4"}) {
    INFO(name);
    const methods::catalogue_entry* e = methods::find_in_catalogue(name);
    REQUIRE(e);
    REQUIRE(static_cast<bool>(e->algebra));
    REQUIRE(static_cast<bool>(e->tableau));
    const rk_stage_algebra m = e->algebra();
    const auto t = e->tableau();
    const bs::tree_set trees(5, 1);
    CHECK(bs::elementary_weights(trees, m) == bs::elementary_weights(trees, t));
    const auto va = analysis::verdicts(m);
    const auto vt = rk_stability(t);
    REQUIRE(va.has_rk);
    CHECK(va.rk.numerator == vt.numerator);
    CHECK(va.rk.denominator == vt.denominator);
    const auto r = bs::analyse_method(m);
    CHECK(r.order == e->order);
    CHECK_FALSE(r.order_is_lower_bound);
    CHECK(r.symplectic == e->symplectic);
    CHECK(va.symmetric == e->symmetric);
  }
}

TEST_CASE("collocation algebra: the catalogue's Radau s = 5 entries are these methods", "[methods]") {
  for (const char* name : {"radau-iia-5", "radau-ia-5"}) {
    const methods::catalogue_entry* e = methods::find_in_catalogue(name);
    REQUIRE(e);
    REQUIRE(static_cast<bool>(e->algebra));
    CHECK_FALSE(static_cast<bool>(e->tableau));
    const rk_stage_algebra m = e->algebra();
    CHECK(m.name == name);
    CHECK(bs::analyse_method(m).order == e->order);
    CHECK(m.a == (std::string(name) == "radau-iia-5" ? methods::radau_iia_algebra(5) : methods::radau_ia_algebra(5)).a);
  }
}

}  // namespace collocation_algebra_test
