// Compile-time checks of methods/algebraic_number.hpp: the arithmetic of Q(r) against exact
// mathematics, and tableaux with irrational coefficients, typed as their sources print them,
// analysed in static_assert against the properties the sources publish:
// - Gauss, s = 2 (sqrt 3) and s = 3 (sqrt 15): Hairer, Norsett & Wanner, Solving ODEs I (HNW),
//   Tables II.7.3 and II.7.4; Radau IIA, s = 3 (sqrt 6): Hairer & Wanner, Solving ODEs II (HW),
//   Table IV.5.6. Published: order 2s (Gauss), 2s - 1 (Radau IIA) (HW section IV.5); stability
//   function the Pade approximant R_ss (Gauss), R_(s-1)s (Radau IIA) (HW Theorem IV.5.3 and the
//   Pade table of section IV.3), Gauss A-stable and not L-stable, Radau IIA L-stable (HW
//   section IV.4); Gauss symplectic, b_i a_ij + b_j a_ji = b_i b_j (Hairer, Lubich & Wanner,
//   Geometric Numerical Integration (HLW), Theorem VI.4.3), and symmetric (HLW Theorem V.2.3),
//   Radau IIA neither; stage order s (B(s), C(s); HW section IV.5).
// The catalogue's methods over Q(r) (compositions, McLachlan's splittings) are checked in
// static_catalogue.cpp.
#include <cstdint>

#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/analysis/rk_stability.hpp"
#include "geomint/methods/algebraic_number.hpp"
#include "geomint/methods/tableau.hpp"
#include "../pade.hpp"

namespace {

using geomint::rational;
using namespace geomint::methods;
namespace bs = geomint::analysis::bseries;

// ---- the arithmetic, against exact mathematics ----
constexpr field_polynomial<3> cube_root_of_two{{-2, 0, 0, 1}, 1, 2};
using C = algebraic_number<cube_root_of_two>;
constexpr C r = C::generator();
static_assert(r * r * r == C(2) && !(r == C(1)) && !(r * r == C(2)));
static_assert((C(1) / (C(2) - r)) * (C(2) - r) == C(1));
static_assert(C(1) / r == r * r / C(2));  // r^3 = 2
static_assert(!r.is_rational() && (r * r * r).is_rational() && (r * r * r).rational_value() == 2);

constexpr field_polynomial<2> sqrt3_field{{-3, 0, 1}, 1, 2};
using Q3 = algebraic_number<sqrt3_field>;
constexpr Q3 s3 = Q3::generator();
static_assert((Q3(1) + s3) * (Q3(1) - s3) == Q3(-2) && Q3(1) / s3 == s3 / Q3(3));

// A reducible polynomial: (r - 1)(r^2 - 2) with the bracket (1.2, 2] around sqrt 2; r - 1 is
// not zero there, r^2 - 2 is.
constexpr field_polynomial<3> reducible{{2, -2, -1, 1}, rational(6, 5), 2};
using Rd = algebraic_number<reducible>;
constexpr Rd x = Rd::generator();
static_assert(x * x == Rd(2) && !(x == Rd(1)) && (Rd(1) / (x - Rd(1))) * (x - Rd(1)) == Rd(1));
static_assert(Rd(1) / (x - Rd(1)) == x + Rd(1));  // 1/(sqrt 2 - 1) = sqrt 2 + 1

// ---- Pade approximants, the published stability functions (HW section IV.3) ----
/// R (unreduced, P(0) = Q(0) = 1) equals R_kj = P_kj / Q_kj (tests/pade.hpp) coefficient by
/// coefficient.
template <class F>
constexpr bool is_pade(const F& f, int k, int j) {
  using K = std::remove_cvref_t<decltype(f.numerator[0])>;
  for (int i = 0; i < static_cast<int>(f.numerator.size()); ++i)
    if (!(f.numerator[static_cast<std::size_t>(i)] == K(geomint::test::pade_numerator(k, j, i))) ||
        !(f.denominator[static_cast<std::size_t>(i)] == K(geomint::test::pade_denominator(k, j, i))))
      return false;
  return true;
}

/// b_i a_ij + b_j a_ji = b_i b_j for every i, j (HLW Theorem VI.4.3).
template <class K, int S>
constexpr bool symplectic_rk(const rk<K, S>& t) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i)
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j)
      if (!(t.b[i] * t.a[i][j] + t.b[j] * t.a[j][i] == t.b[i] * t.b[j])) return false;
  return true;
}

/// The order by the rooted trees up to `limit` (series_order: a(t) = 1/gamma(t)).
template <class K, int S>
constexpr int tree_order(const rk<K, S>& t, int limit) {
  const bs::tree_set trees(limit, 1);
  return bs::series_order(trees, bs::elementary_weights(trees, t));
}

// ---- Gauss, s = 2: c = 1/2 -+ sqrt 3/6, a = [[1/4, 1/4 - sqrt 3/6], [1/4 + sqrt 3/6, 1/4]] ----
constexpr Q3 q(std::int64_t n, std::int64_t d = 1) { return Q3(rational(n, d)); }
constexpr auto gauss2 = make_rk<Q3>({q(1, 2) - s3 / q(6), q(1, 2) + s3 / q(6)},
                                    {{q(1, 4), q(1, 4) - s3 / q(6)}, {q(1, 4) + s3 / q(6), q(1, 4)}}, {q(1, 2), q(1, 2)});
static_assert(tree_order(gauss2, 5) == 4);
static_assert(is_pade(geomint::stability_function(gauss2), 2, 2));
static_assert(geomint::rk_stability(gauss2).a_stable && !geomint::rk_stability(gauss2).l_stable);
static_assert(symplectic_rk(gauss2) && geomint::is_symmetric(gauss2) && geomint::stage_order(gauss2) == 2);

// ---- Gauss, s = 3 (sqrt 15) ----
constexpr field_polynomial<2> sqrt15_field{{-15, 0, 1}, 3, 4};
using Q15 = algebraic_number<sqrt15_field>;
constexpr Q15 s15 = Q15::generator();
constexpr Q15 f(std::int64_t n, std::int64_t d = 1) { return Q15(rational(n, d)); }
constexpr auto gauss3 = make_rk<Q15>({f(1, 2) - s15 / f(10), f(1, 2), f(1, 2) + s15 / f(10)},
                                     {{f(5, 36), f(2, 9) - s15 / f(15), f(5, 36) - s15 / f(30)},
                                      {f(5, 36) + s15 / f(24), f(2, 9), f(5, 36) - s15 / f(24)},
                                      {f(5, 36) + s15 / f(30), f(2, 9) + s15 / f(15), f(5, 36)}},
                                     {f(5, 18), f(4, 9), f(5, 18)});
static_assert(tree_order(gauss3, 7) == 6);
static_assert(is_pade(geomint::stability_function(gauss3), 3, 3));
static_assert(geomint::rk_stability(gauss3).a_stable && !geomint::rk_stability(gauss3).l_stable);
static_assert(symplectic_rk(gauss3) && geomint::is_symmetric(gauss3) && geomint::stage_order(gauss3) == 3);

// ---- Radau IIA, s = 3 (sqrt 6) ----
constexpr field_polynomial<2> sqrt6_field{{-6, 0, 1}, 2, 3};
using Q6 = algebraic_number<sqrt6_field>;
constexpr Q6 s6 = Q6::generator();
constexpr Q6 g(std::int64_t n, std::int64_t d = 1) { return Q6(rational(n, d)); }
constexpr auto radau_iia3 = make_rk<Q6>({(g(4) - s6) / g(10), (g(4) + s6) / g(10), g(1)},
                                        {{(g(88) - g(7) * s6) / g(360), (g(296) - g(169) * s6) / g(1800), (g(-2) + g(3) * s6) / g(225)},
                                         {(g(296) + g(169) * s6) / g(1800), (g(88) + g(7) * s6) / g(360), (g(-2) - g(3) * s6) / g(225)},
                                         {(g(16) - s6) / g(36), (g(16) + s6) / g(36), g(1, 9)}},
                                        {(g(16) - s6) / g(36), (g(16) + s6) / g(36), g(1, 9)});
static_assert(tree_order(radau_iia3, 6) == 5);
static_assert(is_pade(geomint::stability_function(radau_iia3), 2, 3));
static_assert(geomint::rk_stability(radau_iia3).l_stable);
static_assert(!symplectic_rk(radau_iia3) && !geomint::is_symmetric(radau_iia3) && geomint::stage_order(radau_iia3) == 3);

}  // namespace
