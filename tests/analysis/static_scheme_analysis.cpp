/// Compile-time facts of the exact scheme algebra (include/geomint/analysis: rkn_tableau,
/// nystrom_trees, order_conditions, scheme_structure, linear_stability). Every assertion is
/// evaluated by the compiler; a broken identity fails the build.
///
/// Independent sources of the expected values:
/// - tree counts: the generating function of the special Nystrom trees (HNW I, section II.14:
///   a fat root whose sons are meagre leaves or meagre vertices over a fat tree), counted by
///   multisets of sons, independently of the generator's enumeration;
/// - orders: collocation theory (an s-stage collocation method has the order of its quadrature,
///   Gauss: 2s; Hairer, Norsett, Wanner, Solving ODEs I, section II.7 and II.14), so LPF of
///   degree m on the Gauss interior nodes has order 2(m - 1), Galerkin (Gauss collocation with
///   m stages) 2m, and symmetric rational or Lobatto / Chebyshev interior nodes the quadrature
///   order 2 floor(m/2) (measured by geomint-order: docs/results/analysis.md);
/// - R(tau): the LPF paper's eq. (16) and (17) (Kong & Yang 2020);
/// - symplecticity: Suris' conditions hold for Gauss collocation and for the midpoint rule and
///   Stormer-Verlet (Hairer, Lubich, Wanner, Geometric Numerical Integration, VI.4);
/// - the P-series of the schemes' exact tableaux (bseries/rkn_series.hpp) and their modified
///   fields: the trapezoidal VI is Stormer-Verlet (velocity form, kick-drift-kick), whose
///   modified field at h^2 HLW section IX.3 prints (the values of tests/analysis/
///   test_bseries_static.cpp: f'g'f -1/6, g''(f, f) 1/12, g'f'g 1/12 as b(t)/sigma(t)); the
///   orders of the series are those of collocation theory above.
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/rkn_series.hpp"
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/order_conditions.hpp"
#include "geomint/analysis/scheme_structure.hpp"

namespace {

using namespace geomint;

// Tree counts by size against the generating function: with S_n the trees of size n and
// B_k = [k = 1] + S_{k-1} the sons of size k (a meagre leaf, or a meagre vertex over a tree of
// size k - 1), S_n is the number of multisets of sons of total size n - 1, the coefficient of
// x^(n-1) in prod_k (1 - x^k)^(-B_k). Up to 14 vertices here: 1, 1, 2, 3, 6, 10, 20, 36, 72,
// 137, 275, 541, 1098, 2208. (Not OEIS A001678, the series-reduced planted trees, which agrees for
// trees of up to 6 vertices and then has 19 where there are 20 special Nystrom trees of 7.)
constexpr bool tree_counts_match() {
  constexpr int n_max = 14;
  std::int64_t trees[n_max + 1]{}, sons[n_max + 1]{};
  trees[1] = 1;
  for (int n = 2; n <= n_max; ++n) {
    for (int k = 1; k < n; ++k) sons[k] = (k == 1 ? 1 : 0) + trees[k - 1];
    std::int64_t multisets[n_max + 1]{};
    multisets[0] = 1;
    for (int k = 1; k < n; ++k)
      for (std::int64_t copies = 0; copies < sons[k]; ++copies)  // times 1 / (1 - x^k)
        for (int j = k; j < n; ++j) multisets[j] += multisets[j - k];
    trees[n] = multisets[n - 1];
  }
  const nystrom_tree_table t = make_nystrom_trees(n_max);
  for (int n = 1; n <= n_max; ++n)
    if (t.count(n) != trees[n]) return false;
  return trees[7] == 20 && trees[14] == 2208;
}
static_assert(tree_counts_match());
// The printed list: Hairer, Norsett & Wanner, Solving ODEs I, 1st ed. (1987), section II.13,
// Table 13.3 ("SN-trees, elementary differentials and order conditions") lists t1..t13 with
// rho(t) = 1, 2, 3, 3, 4, 4, 4, 5 (six times): 1, 1, 2, 3, 6 trees of orders 1..5, with the
// densities gamma 1; 2; 3, 6; 4, 8, 24; 5, 10, 20, 30, 60, 120 (the same section is II.14 of the
// 2nd ed., whose Theorem 14.10 the analysis cites).
constexpr bool hnw_table_13_3() {
  const nystrom_tree_table t = make_nystrom_trees(5);
  if (t.count(1) != 1 || t.count(2) != 1 || t.count(3) != 2 || t.count(4) != 3 || t.count(5) != 6) return false;
  const std::int64_t expected[6][6] = {{}, {1}, {2}, {3, 6}, {4, 8, 24}, {5, 10, 20, 30, 60, 120}};
  for (int n = 1; n <= 5; ++n) {
    std::int64_t gammas[6]{};
    int k = 0;
    for (const auto& tree : t.trees)
      if (tree.size == n) gammas[k++] = tree.gamma;
    for (int i = 0; i < k; ++i)  // as a multiset: sort the (at most 6) densities
      for (int j = i + 1; j < k; ++j)
        if (gammas[j] < gammas[i]) {
          const std::int64_t x = gammas[i];
          gammas[i] = gammas[j];
          gammas[j] = x;
        }
    for (int i = 0; i < k; ++i)
      if (gammas[i] != expected[n][i]) return false;
  }
  return true;
}
static_assert(hnw_table_13_3());
// Densities and symmetries of the trees of size 3: f''(p, p) (gamma 3, sigma 2), f' f (gamma 6, sigma 1).
static_assert(make_nystrom_trees(3).trees[2].gamma == 3 && make_nystrom_trees(3).trees[2].sigma == 2);
static_assert(make_nystrom_trees(3).trees[3].gamma == 6 && make_nystrom_trees(3).trees[3].sigma == 1);

// LPF on Gauss-interior nodes has order 2(m - 1); on Gauss-Lobatto nodes it is symmetric but not
// symplectic: bbar_i = b_i (1 - c_i) holds, b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji) fails.
static_assert(tree_order(lpf_tableau<5, gauss_interior>()) == 8);
static_assert(symmetry(lpf_tableau<4, gauss_lobatto>()).symmetric);
static_assert(!symplecticity(lpf_tableau<4, gauss_lobatto>()).symplectic);
static_assert(symplecticity(lpf_tableau<4, gauss_lobatto>()).first_condition);  // bbar = b (1 - c) holds
static_assert(!symplecticity(lpf_tableau<4, gauss_lobatto>()).second_condition);

// Galerkin of degree m: order 2m by the trees (m = 1..4) and by the quadrature (m = 1..8).
static_assert(tree_order(galerkin_tableau<1>()) == 2 && tree_order(galerkin_tableau<2>()) == 4);
static_assert(tree_order(galerkin_tableau<3>()) == 6 && tree_order(galerkin_tableau<4>()) == 8);
template <int M>
constexpr bool galerkin_quadrature_orders() {
  constexpr exact_rkn_tableau t = galerkin_tableau<M>();  // evaluated once
  if (quadrature_order(t) != 2 * M) return false;
  if (!symplecticity(t).symplectic) return false;
  if (!symmetry(t).symmetric) return false;
  if constexpr (M < 8) return galerkin_quadrature_orders<M + 1>();
  return true;
}
static_assert(galerkin_quadrature_orders<1>());

// Every LPF family, m = 2..8: quadrature order; symplectic exactly for Gauss interior nodes and
// for m = 2.
template <class Family>
constexpr int expected_order(int m) {
  return std::is_same_v<Family, gauss_interior> ? 2 * (m - 1) : 2 * (m / 2);
}
template <class Family, int M>
constexpr bool lpf_family_facts() {
  constexpr exact_rkn_tableau t = lpf_tableau<M, Family>();
  static_assert(t.stages == M - 1);
  static_assert(quadrature_order(t) == expected_order<Family>(M));
  static_assert(symplecticity(t).symplectic == (std::is_same_v<Family, gauss_interior> || M == 2));
  // Every family's interior nodes are symmetric about 1/2, so every LPF scheme is symmetric
  // (a collocation method with symmetric nodes is symmetric: HLW, Theorem V.2.3).
  static_assert(symmetry(t).nodes_symmetric && symmetry(t).symmetric);
  if constexpr (M < max_exact_m) return lpf_family_facts<Family, M + 1>();
  return true;
}
static_assert(lpf_family_facts<equispaced, 2>());
static_assert(lpf_family_facts<gauss_interior, 2>());
static_assert(lpf_family_facts<gauss_lobatto, 2>());
static_assert(lpf_family_facts<chebyshev_lobatto, 2>());

// Tree order = quadrature order where the trees are cheap at compile time (order <= 6).
template <class Family, int M>
constexpr bool tree_orders_small() {
  static_assert(tree_order(lpf_tableau<M, Family>()) == expected_order<Family>(M));
  if constexpr (M < (std::is_same_v<Family, gauss_interior> ? 4 : 7)) return tree_orders_small<Family, M + 1>();
  return true;
}
static_assert(tree_orders_small<equispaced, 2>());
static_assert(tree_orders_small<gauss_interior, 2>());
static_assert(tree_orders_small<gauss_lobatto, 2>());
static_assert(tree_orders_small<chebyshev_lobatto, 2>());

// Midpoint and trapezoidal (Stormer-Verlet): order 2, symplectic, symmetric.
static_assert(tree_order(midpoint_tableau()) == 2 && tree_order(trapezoidal_tableau()) == 2);
static_assert(symplecticity(midpoint_tableau()).symplectic && symmetry(midpoint_tableau()).symmetric);
static_assert(symplecticity(trapezoidal_tableau()).symplectic && symmetry(trapezoidal_tableau()).symmetric);

// Principal error constant of the midpoint VI: C^2 = 1/64 (three trees of order 3).
static_assert(order_analysis(midpoint_tableau()).error_constant_squared == exact_number(rational(1, 64)));
// Per component, Stormer-Verlet (order 2) by Taylor expansion of one step, f = f(q), p = q':
//   q1 = q + tau p + tau^2/2 f,  exact q(tau) = q + tau p + tau^2/2 f + tau^3/6 f'p + ...,
//   so q1 - q(tau) = -(1/6) tau^3 f'p + ...:                                  C_q^2 = 1/36;
//   p1 = p + tau/2 (f + f(q + tau p + tau^2/2 f)) = p + tau f + tau^2/2 f'p + tau^3 (f''(p,p)/4
//   + f'f/4) + ..., exact p(tau) = ... + tau^3 (f''(p,p)/6 + f'f/6) + ...: coefficients 1/12 and
//   1/12,                                                                     C_p^2 = 1/72.
static_assert(order_analysis(trapezoidal_tableau()).position_error_constant_squared == exact_number(rational(1, 36)));
static_assert(order_analysis(trapezoidal_tableau()).velocity_error_constant_squared == exact_number(rational(1, 72)));
static_assert(order_analysis(trapezoidal_tableau()).error_constant_squared == exact_number(rational(1, 24)));

// Linear stability: eq. (16) R = (16 - 6 tau^2)/(8 + tau^2), eq. (17) R = (8 - 2 tau^2)/(4 + tau^2).
constexpr bool has_r(const linear_stability_result& r, std::int64_t p0, std::int64_t p1, std::int64_t q0, std::int64_t q1) {
  return r.numerator.degree == 1 && r.denominator.degree == 1 && r.numerator[0] == stability_integer(p0) &&
         r.numerator[1] == stability_integer(p1) && r.denominator[0] == stability_integer(q0) &&
         r.denominator[1] == stability_integer(q1);
}
static_assert(has_r(linear_stability(lpf_tableau<2, equispaced>()), 16, -6, 8, 1));
static_assert(has_r(linear_stability(midpoint_tableau()), 8, -2, 4, 1));
static_assert(linear_stability(midpoint_tableau()).leading_coefficient == exact_number(rational(1, 6)));
static_assert(linear_stability(lpf_tableau<3, gauss_interior>()).order == 4 &&
              linear_stability(lpf_tableau<3, gauss_interior>()).determinant_is_one);

// Stormer-Verlet: det M = 1 and R = tr M = 2 - tau^2 (one step of y'' = -y by hand), so
// |R| <= 2 exactly for tau <= 2: interval of periodicity (0, 2), z* = tau*^2 = 4.
constexpr stability_interval verlet_interval = linear_stability_interval(linear_stability(trapezoidal_tableau()));
static_assert(verlet_interval.kind == stability_kind::periodic && !verlet_interval.empty && !verlet_interval.unbounded);
static_assert(verlet_interval.compare_squared(exact_number(4)) == 0);
static_assert(verlet_interval.compare_squared(exact_number(rational(399, 100))) < 0);
// The midpoint VI and Gauss collocation (Galerkin) are P-stable: for the midpoint VI
// R = (8 - 2z)/(4 + z) and -2 (4 + z) < 8 - 2z < 2 (4 + z) for every z > 0; Gauss collocation
// applied to q' = p, p' = -q has the eigenvalues R(i tau), R(-i tau) of modulus 1 (its stability
// function is a diagonal Pade approximant of e^z, R(-z) R(z) = 1: Hairer and Wanner, Solving
// Ordinary Differential Equations II, chapter IV).
static_assert(linear_stability_interval(linear_stability(midpoint_tableau())).unbounded);
static_assert(linear_stability_interval(linear_stability(galerkin_tableau<2>())).unbounded);
static_assert(linear_stability_interval(linear_stability(galerkin_tableau<3>())).unbounded);

// Nystrom's classical explicit 3-stage order-4 method (E. J. Nystrom, Acta Soc. Sci. Fenn. 50
// (1925); Hairer, Norsett, Wanner, Solving ODEs I, section II.14): c = (0, 1/2, 1), a21 = 1/8,
// a32 = 1/2, bbar = (1/6, 1/3, 0), b = (1/6, 2/3, 1/6). Not symplectic (b1 (bbar2 - a12) = 1/18,
// b2 (bbar1 - a21) = 1/36), so det M != 1. By hand, one step of y'' = -y on (q, tau p), z = tau^2:
//   q1 = (1 - z/2 + z^2/24) q + (1 - z/6) tau p,
//   tau p1 = -(z - z^2/6 + z^3/96) q + (1 - z/2 + z^2/24) tau p,
// so t = tr M = 2 - z + z^2/12 and d = det M = 1 - z^3/288. Hence
// - dissipation 1 - sqrt(d) = tau^6/576 + ...: order r = 5, constant 1/576;
// - t / (2 sqrt d) = (1 - z/2 + z^2/24)(1 + z^3/576 + ...) = cos tau + (1/576 + 1/720) tau^6 + ...,
//   so phi(tau) = tau^5/320 + ...: phase-lag order q = 4, constant 1/320;
// - absolute stability: d <= 1 always; 1 + d - t = z (1 - z/12 - z^2/288) >= 0 up to
//   z = 12 (sqrt 3 - 1) = 8.78; 1 + d + t = (1152 - 288 z + 24 z^2 - z^3)/288 >= 0 up to its
//   only real root z* = 6.690..., so tau* = 2.586...; the trace alone (|t| <= 2 up to z = 12,
//   tau = 3.46) is not the stability condition.
constexpr exact_rkn_tableau nystrom4 = rational_rkn_tableau<3>(
    {rational(0), rational(1, 2), rational(1)},
    {{{rational(0), rational(0), rational(0)}, {rational(1, 8), rational(0), rational(0)}, {rational(0), rational(1, 2), rational(0)}}},
    {rational(1, 6), rational(1, 3), rational(0)}, {rational(1, 6), rational(2, 3), rational(1, 6)});
constexpr linear_stability_result nystrom4_stability = linear_stability(nystrom4);
static_assert(tree_order(nystrom4) == 4 && !symplecticity(nystrom4).symplectic);
static_assert(!nystrom4_stability.determinant_is_one);
static_assert(nystrom4_stability.dissipation_order == 5 && nystrom4_stability.dissipation_constant == exact_number(rational(1, 576)));
static_assert(nystrom4_stability.phase_lag_order == 4 && nystrom4_stability.phase_lag_constant == exact_number(rational(1, 320)));
constexpr stability_interval nystrom4_interval = linear_stability_interval(nystrom4_stability);
static_assert(nystrom4_interval.kind == stability_kind::absolute && !nystrom4_interval.empty && !nystrom4_interval.unbounded);
constexpr bool bound_is(const analysis::detail::wide_polynomial& p, std::initializer_list<std::int64_t> coefficients) {
  int k = 0;
  for (std::int64_t c : coefficients)
    if (!(p[k++] == analysis::detail::wide_integer(c))) return false;
  return p.degree == k - 1;
}
static_assert(bound_is(nystrom4_interval.bound.polynomial, {1152, -288, 24, -1}));
static_assert(nystrom4_interval.compare_squared(exact_number(rational(6689, 1000))) < 0);
static_assert(nystrom4_interval.compare_squared(exact_number(rational(6691, 1000))) > 0);

// Schemes of one's own: rational nodes, a node polynomial, an explicit tableau.
// Nodes 1/6, 1/2, 5/6 (symmetric): quadrature order 4, not symplectic.
constexpr exact_rkn_tableau own = collocation_tableau_from_nodes<3>({rational(1, 6), rational(1, 2), rational(5, 6)});
static_assert(quadrature_order(own) == 4 && tree_order(own) == 4 && symmetry(own).symmetric && !symplecticity(own).symplectic);
// x^2 - x + 1/6: the two Gauss points, the same tableau as lpf<3, gauss_interior>.
constexpr exact_rkn_tableau own_poly = collocation_tableau_from_polynomial<2>({rational(1, 6), rational(-1), rational(1)});
static_assert(own_poly == lpf_tableau<3, gauss_interior>() && tree_order(own_poly) == 4);
// Stormer-Verlet written out by hand.
static_assert(rational_rkn_tableau<2>({rational(0), rational(1)}, {{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}},
                                      {rational(1, 2), rational(0)}, {rational(1, 2), rational(1, 2)}) == trapezoidal_tableau());

}  // namespace

// Symmetry up to any permutation of stages. Phi: c = 1, a = 0, bbar = 1/3, b = 1 (explicit,
// not symmetric: its adjoint has c* = 0). Its adjoint (scheme_structure.hpp: c* = 1 - c,
// a* = (1 - c) b - bbar + a, bbar* = b - bbar) is c = 0, a = -1/3, bbar = 2/3, b = 1, and the
// composition Phi*_{tau/2} o Phi_{tau/2} is symmetric (Hairer, Lubich, Wanner, Geometric
// Numerical Integration, 2nd ed., section II.3). Composed by hand (h = tau/2): stage 1 at
// q + tau/2 p, stage 2 = q + tau/2 p + tau^2/12 (f1 - f2), q1 = q + tau p + tau^2 (f1/3 + f2/6),
// p1 = p + tau (f1 + f2)/2. Both nodes are 1/2; the adjoint swaps the two stages, so pairing
// them by c_i + c_j = 1 alone (the identity here) misses the symmetry.
constexpr exact_rkn_tableau adjoint_composition = rational_rkn_tableau<2>(
    {rational(1, 2), rational(1, 2)}, {{{rational(0), rational(0)}, {rational(1, 12), rational(-1, 12)}}},
    {rational(1, 3), rational(1, 6)}, {rational(1, 2), rational(1, 2)});
static_assert(symmetry(adjoint_composition).symmetric);
static_assert(symmetry(adjoint_composition).permutation[0] == 1 && symmetry(adjoint_composition).permutation[1] == 0);
// The same nodes and weights with a22 = 0: no permutation satisfies the adjoint conditions
// (the swap needs a11 = a*_00 = 1/4 - 1/3 = -1/12 in row 2; the identity needs bbar = b - bbar).
constexpr exact_rkn_tableau not_symmetric = rational_rkn_tableau<2>(
    {rational(1, 2), rational(1, 2)}, {{{rational(0), rational(0)}, {rational(1, 12), rational(0)}}},
    {rational(1, 3), rational(1, 6)}, {rational(1, 2), rational(1, 2)});
static_assert(symmetry(not_symmetric).nodes_symmetric && !symmetry(not_symmetric).symmetric);
// Stormer-Verlet as two half steps (c = 0, 1/2, 1/2, 1; the middle stages evaluate the same
// point): symmetric (HLW, section II.3). Nystrom's order-4 method (above) is not: the nodes force
// sigma = (3, 2, 1), and a*_13 = (1 - c_1) b_3 - bbar_3 + a_13 = 1/6 differs from a_31 = 0.
constexpr exact_rkn_tableau verlet_twice = rational_rkn_tableau<4>(
    {rational(0), rational(1, 2), rational(1, 2), rational(1)},
    {{{rational(0), rational(0), rational(0), rational(0)},
      {rational(1, 8), rational(0), rational(0), rational(0)},
      {rational(1, 8), rational(0), rational(0), rational(0)},
      {rational(1, 4), rational(1, 8), rational(1, 8), rational(0)}}},
    {rational(1, 4), rational(1, 8), rational(1, 8), rational(0)}, {rational(1, 4), rational(1, 4), rational(1, 4), rational(1, 4)});
static_assert(symmetry(verlet_twice).symmetric && tree_order(verlet_twice) == 2);
static_assert(!symmetry(nystrom4).symmetric);

// Stage order (order_conditions.hpp): an s-stage collocation method integrates q'' = g(t) exactly
// in its stages for g of degree s - 1 (HNW I, section II.14), stage order s + 1; Gauss RK (RK stage
// order s: A c^(j-1) = c^j / j, j <= s) as an RKN method, a = A^2, is exact for k <= s - 2: stage
// order s (Galerkin m = 3: 3); Stormer-Verlet's
// stages are q and q + tau p + tau^2 f/2 (exact for constant g: stage order 2); Nystrom's method
// has a31 + a32 = 1/2 = c3^2/2 but a32 c2 = 1/4 != c3^3/6: stage order 2.
static_assert(stage_order(lpf_tableau<4, gauss_lobatto>()) == 4 && stage_order(galerkin_tableau<3>()) == 3);
static_assert(stage_order(trapezoidal_tableau()) == 2 && stage_order(nystrom4) == 2);

// The P-series of the schemes at compile time (rkn trees: q' = v colour 0, v' = f(q) colour 1).
namespace {
namespace bs = geomint::analysis::bseries;
using geomint::exact_number;
using geomint::analysis::detail::fraction;
struct verlet_values {
  int order;
  exact_number f_g_f, g_ff, g_f_g;  // b / sigma of q[p[q]], p[q,q], p[q[p]]
};
constexpr verlet_values trapezoidal_series() {
  const bs::tree_set t(3, bs::tree_class::rkn);
  const auto a = bs::exact_elementary_weights(t, geomint::trapezoidal_tableau());
  const auto b = bs::modified_field(t, a);
  const int f = t.leaf(0), g = t.leaf(1);
  const auto over_sigma = [&](int tree) { return b[static_cast<std::size_t>(tree)] / exact_number(t[tree].sigma); };
  return {bs::series_order(t, a), over_sigma(t.find(0, {t.find(1, {f})})), over_sigma(t.find(1, {f, f})),
          over_sigma(t.find(1, {t.find(0, {g})}))};
}
constexpr verlet_values trapezoidal_values = trapezoidal_series();
static_assert(trapezoidal_values.order == 2);
static_assert(trapezoidal_values.f_g_f == fraction(-1, 6) && trapezoidal_values.g_ff == fraction(1, 12) &&
              trapezoidal_values.g_f_g == fraction(1, 12));
constexpr int series_order_of(const geomint::exact_rkn_tableau& method, int max_order) {
  const bs::tree_set t(max_order, bs::tree_class::rkn);
  return bs::series_order(t, bs::exact_elementary_weights(t, method));
}
static_assert(series_order_of(geomint::lpf_tableau<3, geomint::gauss_interior>(), 5) == 4);  // 2(m - 1)
static_assert(series_order_of(geomint::galerkin_tableau<2>(), 5) == 4);                    // 2m
}  // namespace
