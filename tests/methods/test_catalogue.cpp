/// The catalogue of published methods (methods/catalogue.hpp, methods/collocation_families.hpp):
/// every entry's published order, symplecticity and symmetry against the exact analysis of its
/// coefficients (analysis/bseries/method_analysis.hpp, analysis/method_verdicts.hpp), the order
/// of the rkn and nystrom entries by their N-trees against the route through the partitioned
/// form, the generated collocation families against tableaux printed in the literature and (s =
/// 4, 5) against their defining polynomials and simplifying assumptions, and orders observed on
/// the one integrator from global errors in 50 digits against exact solutions. These are run-time
/// checks: the coefficients in Q(r) (field_element, Boost's cpp_rational) are not literal types,
/// so only the rational methods have compile-time checks (static_catalogue.cpp).
#include <algorithm>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

#include "catch.hpp"
#include "geomint/analysis/bseries/method_analysis.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/collocation_algebra.hpp"
#include "geomint/methods/tableau_method.hpp"
#include "field_numbers.hpp"
#include "scalar_types.hpp"

namespace catalogue_test {

using namespace geomint;
using methods::exact_rational;
using methods::field_element;
using geomint::test::field_numbers::q;
using T50 = geomint::test::cpp_bin_float_50;

/// Observed order from the global errors at t = 1 with N and 2N steps (log2 of their ratio) on
/// the pendulum from rest at 1 rad, exact solution by Jacobi elliptic functions.
template <class Method>
double observed_order_pendulum(int steps) {
  using T = T50;
  auto error = [](int count) {
    integrator<methods::tableau_method<Method>, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(count));
    auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
    I.advance(s, count);
    const auto exact = analysis::pendulum_from_rest(T(1), T(1));
    using std::abs;
    return std::max<T>(T(abs(T(s.q[0] - exact.q[0]))), T(abs(T(s.p[0] - exact.p[0]))));
  };
  using std::log2;
  return static_cast<double>(log2(error(steps) / error(2 * steps)));
}


TEST_CASE("catalogue: every entry's published order, symplecticity and symmetry are those of its exact coefficients", "[methods]") {
  // Published values: each entry's `source` (methods/catalogue.hpp). Orders are exact (the
  // first nonzero tree defect), not a lower bound. One-colour trees (rk) go two orders beyond
  // the published order: the rk symplecticity verdict is one of the modified field up to that
  // order, and for Lobatto IIIC the first non-Hamiltonian term has trees of order p + 2 (with
  // trees to p + 1, IIIC of s = 2..5 still looks symplectic). Bi-coloured trees (prk) and N-trees
  // (rkn, nystrom) go one order beyond, at most to 7: the IIIA-IIIB pair
  // costs 13 s (s = 4) and 16 s (s = 5) at order 8 in this build, so its s = 5 order is a
  // lower bound here (its exact order: the observed-order test case; its symplecticity: the
  // exact condition of the next test case).
  // The Gauss (s = 4, 5) and Radau (s = 4) methods have coefficients in fields of degree 8 and
  // 6 (collocation_families.hpp), where the series cost about 4 ms per tree (Gauss s = 4: 2.1 s
  // for the 486 trees up to order 9 at -O1): Radau s = 4 goes one order beyond its own (its
  // non-symplecticity shows at order 8), and Gauss s = 4, 5 are left to the exact conditions
  // (orders: Butcher's simplifying assumptions, the next test case but one; symplecticity:
  // b_i a_ij + b_j a_ji = b_i b_j, the test case after it).
  for (const methods::catalogue_entry& e : methods::catalogue()) {
    INFO(e.name << " (" << e.source << ")");
    if (!e.tableau) {  // Radau s = 5 over its stage algebra: test_collocation_algebra.cpp
      CHECK(static_cast<bool>(e.algebra));
      continue;
    }
    const auto t = e.tableau();
    CHECK(t.kind == e.kind);
    CHECK(t.stages == e.stages);
    CHECK(is_symmetric(t) == e.symmetric);
    const bool large_field =
        std::any_of(t.c.begin(), t.c.end(), [](const field_element& x) { return x.field() && x.field()->degree() > 2; });
    if (large_field && e.order + 1 > 8) continue;
    const int one_colour = large_field ? e.order + 1 : e.order + 2;
    const int two_colours = std::min(e.order + 1, 7);
    const auto r = analysis::bseries::analyse_method(t, one_colour, two_colours);
    if (e.order < (e.kind == methods::method_kind::rk ? one_colour : two_colours)) {
      CHECK(r.order == e.order);
      CHECK_FALSE(r.order_is_lower_bound);
    } else {
      CHECK(r.order == (e.kind == methods::method_kind::rk ? one_colour : two_colours));
      CHECK(r.order_is_lower_bound);
    }
    CHECK(r.symplectic == e.symplectic);
  }
}

TEST_CASE("catalogue: the order of every rkn and nystrom entry from its N-trees is the one from its partitioned form", "[methods]") {
  // Two routes to the same order conditions (analysis/bseries/nystrom_tree_set.hpp): the
  // N-trees with the Nystrom coefficients (analyse_method), and the bi-coloured trees that
  // is_nystrom_tree selects with the (2s + 2)-stage partitioned form (partitioned_form.hpp).
  using namespace analysis::bseries;
  for (const methods::catalogue_entry& e : methods::catalogue()) {
    if (e.kind != methods::method_kind::rkn && e.kind != methods::method_kind::nystrom) continue;
    INFO(e.name);
    const auto form = methods::nystrom_form_of(e.tableau());
    const int order = std::min(e.order + 1, 7);
    const tree_set trees(order, 2);
    std::vector<bool> wanted(static_cast<std::size_t>(trees.size()));
    for (int t = 0; t < trees.size(); ++t) wanted[static_cast<std::size_t>(t)] = is_nystrom_tree(trees, t, !form.has_velocity_stages);
    const auto err = local_error_coefficients(trees, elementary_weights(trees, partitioned_form_of(form), &wanted));
    int reference = order;
    for (int t = 0; t < trees.size() && reference == order; ++t)
      if (wanted[static_cast<std::size_t>(t)] && !(err[static_cast<std::size_t>(t)] == field_element(0))) reference = trees[t].order - 1;
    CHECK(analyse_method(form, order).order == reference);
  }
}

TEST_CASE("catalogue: names are unique and found by find_in_catalogue", "[methods]") {
  for (const methods::catalogue_entry& e : methods::catalogue()) CHECK(methods::find_in_catalogue(e.name) == &e);
  CHECK(methods::find_in_catalogue("gauss-6") == nullptr);
  CHECK(methods::find_in_catalogue("") == nullptr);
}

TEST_CASE("catalogue: the generated families are the tableaux printed by Hairer & Wanner II, section IV.5", "[methods]") {
  // Radau IIA, s = 2: c = (1/3, 1), A = (5/12, -1/12; 3/4, 1/4), b = (3/4, 1/4).
  const auto radau = methods::collocation_family_tableau(methods::collocation_family::radau_iia, 2);
  CHECK(radau.a[0][0] == q(5, 12));
  CHECK(radau.a[0][1] == q(-1, 12));
  CHECK(radau.a[1][0] == q(3, 4));
  CHECK(radau.a[1][1] == q(1, 4));
  CHECK(radau.b[0] == q(3, 4));
  // Radau IA, s = 2: c = (0, 2/3), A = (1/4, -1/4; 1/4, 5/12), b = (1/4, 3/4).
  const auto radau_ia = methods::collocation_family_tableau(methods::collocation_family::radau_ia, 2);
  CHECK(radau_ia.a[0][0] == q(1, 4));
  CHECK(radau_ia.a[0][1] == q(-1, 4));
  CHECK(radau_ia.a[1][0] == q(1, 4));
  CHECK(radau_ia.a[1][1] == q(5, 12));
  // Lobatto IIIA, s = 3: A = (0, 0, 0; 5/24, 1/3, -1/24; 1/6, 2/3, 1/6);
  // IIIB, s = 3: A = (1/6, -1/6, 0; 1/6, 1/3, 0; 1/6, 5/6, 0);
  // IIIC, s = 3: A = (1/6, -1/3, 1/6; 1/6, 5/12, -1/12; 1/6, 2/3, 1/6).
  using F = methods::collocation_family;
  const auto iiia = methods::collocation_family_tableau(F::lobatto_iiia, 3);
  const auto iiib = methods::collocation_family_tableau(F::lobatto_iiib, 3);
  const auto iiic = methods::collocation_family_tableau(F::lobatto_iiic, 3);
  const field_element A[3][3] = {{q(0), q(0), q(0)}, {q(5, 24), q(1, 3), q(-1, 24)}, {q(1, 6), q(2, 3), q(1, 6)}};
  const field_element B[3][3] = {{q(1, 6), q(-1, 6), q(0)}, {q(1, 6), q(1, 3), q(0)}, {q(1, 6), q(5, 6), q(0)}};
  const field_element C[3][3] = {{q(1, 6), q(-1, 3), q(1, 6)}, {q(1, 6), q(5, 12), q(-1, 12)}, {q(1, 6), q(2, 3), q(1, 6)}};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      CHECK(iiia.a[i][j] == A[i][j]);
      CHECK(iiib.a[i][j] == B[i][j]);
      CHECK(iiic.a[i][j] == C[i][j]);
    }
  // Gauss, s = 2: a_11 = 1/4, a_12 = 1/4 - sqrt 3/6, so (1/4 - a_12)^2 = 1/12.
  const auto gauss = methods::collocation_family_tableau(F::gauss, 2);
  const field_element d = q(1, 4) - gauss.a[0][1];
  CHECK(d * d == q(1, 12));
  CHECK(gauss.a[0][0] == q(1, 4));
  // Every node is a root of its family's polynomial: right Radau s = 3, 10 x^2 - 8 x + 1 (with
  // x = 1); Lobatto s = 5 interior, 28 x^2 - 28 x + 4 (x (1 - x) = 1/7 at 1/2 +- sqrt 21/14) and 1/2.
  const auto r3 = methods::collocation_family_tableau(F::radau_iia, 3);
  for (std::size_t i = 0; i < 2; ++i) CHECK((q(10) * r3.c[i] * r3.c[i] - q(8) * r3.c[i] + q(1)).is_zero());
  const auto l5 = methods::collocation_family_tableau(F::lobatto_iiia, 5);
  CHECK((q(28) * l5.c[1] * l5.c[1] - q(28) * l5.c[1] + q(4)).is_zero());
  CHECK((q(28) * l5.c[3] * l5.c[3] - q(28) * l5.c[3] + q(4)).is_zero());
}

field_element power(const field_element& x, int k) {
  field_element out = q(1);
  for (int i = 0; i < k; ++i) out *= x;
  return out;
}

/// P_n(2x - 1) at x by Bonnet's recurrence (k + 1) P_{k+1} = (2k + 1) y P_k - k P_{k-1}.
field_element legendre(int n, const field_element& x) {
  const field_element y = q(2) * x - q(1);
  field_element previous = q(1), current = y;
  if (n == 0) return previous;
  for (int k = 1; k < n; ++k) {
    field_element next = (q(2 * k + 1) * y * current - q(k) * previous) * q(1, k + 1);
    previous = current;
    current = next;
  }
  return current;
}

/// The largest k <= limit with C(k): sum_j a_ij c_j^(m-1) = c_i^m / m for m <= k (and D(k):
/// sum_i b_i c_i^(m-1) a_ij = b_j (1 - c_j^m) / m).
int simplifying_c(const methods::tableau_data<field_element>& t, int limit) {
  const std::size_t s = t.c.size();
  for (int m = 1; m <= limit; ++m)
    for (std::size_t i = 0; i < s; ++i) {
      field_element sum = q(0);
      for (std::size_t j = 0; j < s; ++j) sum += t.a[i][j] * power(t.c[j], m - 1);
      if (!(sum == power(t.c[i], m) * q(1, m))) return m - 1;
    }
  return limit;
}
int simplifying_d(const methods::tableau_data<field_element>& t, int limit) {
  const std::size_t s = t.c.size();
  for (int m = 1; m <= limit; ++m)
    for (std::size_t j = 0; j < s; ++j) {
      field_element sum = q(0);
      for (std::size_t i = 0; i < s; ++i) sum += t.b[i] * power(t.c[i], m - 1) * t.a[i][j];
      if (!(sum == t.b[j] * (q(1) - power(t.c[j], m)) * q(1, m))) return m - 1;
    }
  return limit;
}

TEST_CASE("catalogue: Gauss s = 4, 5 and Radau s = 4 have the nodes and orders of their definitions", "[methods]") {
  // Hairer & Wanner II, section IV.5: Gauss nodes are the roots of P_s(2x - 1), right Radau
  // (IIA) of P_s - P_{s-1}, left Radau (IA) of P_s + P_{s-1}; the quadrature (b, c) has order 2s
  // (Gauss) and 2s - 1 (Radau): B(k), sum_i b_i c_i^(k-1) = 1/k, for k <= that order, beyond
  // the s conditions that define b. Gauss has C(s) and D(s), Radau IIA C(s) and D(s - 1), Radau
  // IA C(s - 1) and D(s); by Butcher's theorem (B(p), C(eta), D(zeta) with p <= eta + zeta + 1
  // and p <= 2 eta + 2 give order p; Hairer & Wanner II, Theorem IV.5.1) the orders are 2s and
  // 2s - 1, and not more: the condition of the bushy tree of order p + 1 is B(p + 1).
  using F = methods::collocation_family;
  const struct {
    F family;
    int s;
    int sign;  // the nodes are the roots of P_s + sign P_{s-1}
    int quadrature_order, c_order, d_order;
  } cases[] = {{F::gauss, 4, 0, 8, 4, 4}, {F::gauss, 5, 0, 10, 5, 5}, {F::radau_iia, 4, -1, 7, 4, 3}, {F::radau_ia, 4, 1, 7, 3, 4}};
  for (const auto& c : cases) {
    INFO("family " << static_cast<int>(c.family) << ", s = " << c.s);
    const auto t = methods::collocation_family_tableau(c.family, c.s);
    REQUIRE(t.c.size() == static_cast<std::size_t>(c.s));
    for (std::size_t i = 0; i < t.c.size(); ++i) {
      CHECK((legendre(c.s, t.c[i]) + q(c.sign) * legendre(c.s - 1, t.c[i])).is_zero());
      if (i > 0) CHECK(t.c[i - 1].to<double>() < t.c[i].to<double>());
    }
    for (int k = 1; k <= c.quadrature_order + 1; ++k) {
      field_element sum = q(0);
      for (std::size_t i = 0; i < t.c.size(); ++i) sum += t.b[i] * power(t.c[i], k - 1);
      CHECK((sum == q(1, k)) == (k <= c.quadrature_order));
    }
    CHECK(simplifying_c(t, c.s) == c.c_order);
    CHECK(simplifying_d(t, c.s) == c.d_order);
  }
}

TEST_CASE("catalogue: the IIIA-IIIB pair and Gauss satisfy the symplecticity condition exactly", "[methods]") {
  // b_i ahat_ij + b_j a_ji = b_i b_j, for Gauss with ahat = a (Hairer, Lubich & Wanner 2006,
  // section VI.4).
  for (int s = 2; s <= 5; ++s) {
    const auto t = methods::collocation_family_tableau(methods::collocation_family::lobatto_iiia_iiib, s);
    for (std::size_t i = 0; i < static_cast<std::size_t>(s); ++i)
      for (std::size_t j = 0; j < static_cast<std::size_t>(s); ++j) CHECK(t.b[i] * t.ahat[i][j] + t.b[j] * t.a[j][i] == t.b[i] * t.b[j]);
  }
  for (int s = 2; s <= 5; ++s) {
    const auto t = methods::collocation_family_tableau(methods::collocation_family::gauss, s);
    for (std::size_t i = 0; i < static_cast<std::size_t>(s); ++i)
      for (std::size_t j = 0; j < static_cast<std::size_t>(s); ++j) CHECK(t.b[i] * t.a[i][j] + t.b[j] * t.a[j][i] == t.b[i] * t.b[j]);
  }
}

TEST_CASE("catalogue: orders observed on the pendulum in 50 digits are the published ones", "[methods]") {
  // Global errors at t = 1 against the exact solution; log2 of the ratio for N and 2N steps.
  CHECK(std::lround(observed_order_pendulum<methods::gauss<3>>(8)) == 6);
  CHECK(std::lround(observed_order_pendulum<methods::radau_iia<3>>(16)) == 5);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiic<3>>(16)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiia_iiib<4>>(8)) == 6);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiia_iiib<5>>(8)) == 8);
  CHECK(std::lround(observed_order_pendulum<methods::ruth3>(32)) == 3);
  CHECK(std::lround(observed_order_pendulum<methods::forest_ruth>(16)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::suzuki4>(16)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::gauss<4>>(8)) == 8);
  CHECK(std::lround(observed_order_pendulum<methods::mclachlan_sb3a4>(16)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::demp_rkn43>(16)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::demp_rkn64>(8)) == 6);
  CHECK(std::lround(observed_order_pendulum<methods::nystrom4>(16)) == 4);
  // The rest of the catalogue, each at its published order (Hairer & Wanner II, section IV.5:
  // Gauss 2s, Radau IA and IIA 2s - 1, Lobatto IIIA, IIIB, IIIC and the IIIA-IIIB pair 2s - 2;
  // Yoshida 1990; McLachlan 1995; Dormand, El-Mikkawy & Prince 1987 for the embedded formulas;
  // Hairer, Lubich & Wanner 2006, section I.1.4 for Stormer-Verlet). Measured, not computed
  // here: the ratios are within 0.03 of these orders at these N (0.05 for Radau IA s = 4 at 16).
  CHECK(std::lround(observed_order_pendulum<methods::gauss<2>>(8)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::gauss<5>>(8)) == 10);
  CHECK(std::lround(observed_order_pendulum<methods::radau_iia<2>>(8)) == 3);
  CHECK(std::lround(observed_order_pendulum<methods::radau_iia<4>>(8)) == 7);
  CHECK(std::lround(observed_order_pendulum<methods::radau_ia<2>>(8)) == 3);
  CHECK(std::lround(observed_order_pendulum<methods::radau_ia<3>>(8)) == 5);
  CHECK(std::lround(observed_order_pendulum<methods::radau_ia<4>>(16)) == 7);
  CHECK(std::lround(observed_order_pendulum<methods::radau_iia<5>>(8)) == 9);
  CHECK(std::lround(observed_order_pendulum<methods::radau_ia<5>>(8)) == 9);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiia<3>>(8)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiia<4>>(8)) == 6);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiia<5>>(8)) == 8);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiib<3>>(8)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiib<4>>(8)) == 6);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiic<4>>(16)) == 6);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiia_iiib<2>>(8)) == 2);
  CHECK(std::lround(observed_order_pendulum<methods::lobatto_iiia_iiib<3>>(8)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::stormer_verlet>(8)) == 2);
  CHECK(std::lround(observed_order_pendulum<methods::yoshida_triple_jump>(8)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::mclachlan_sb3a5>(8)) == 4);
  CHECK(std::lround(observed_order_pendulum<methods::demp_rkn43_embedded>(16)) == 3);
  CHECK(std::lround(observed_order_pendulum<methods::demp_rkn64_embedded>(8)) == 4);
}

}  // namespace catalogue_test
