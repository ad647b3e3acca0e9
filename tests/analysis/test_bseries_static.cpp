/// Compile-time checks of the B-/P-series of bseries/trees.hpp, series.hpp and
/// modified_equation.hpp over geomint::rational (exact; an overflow would be a compile error),
/// against published values. HLW: Hairer, Lubich & Wanner, Geometric Numerical Integration,
/// 2nd ed., Springer 2006. In HLW's normalisation (section III.1) one step is
/// y + sum_t h^|t| / sigma(t) a(t) F(t)(y) and the modified field is
/// sum_t h^(|t|-1) / sigma(t) b(t) F(t)(y), so the coefficient of an elementary differential in a
/// printed formula is a(t) / sigma(t) or b(t) / sigma(t).
/// - tree counts per order: one colour 1, 1, 2, 4, 9, 20 (OEIS A000081); two colours 2, 4, 14,
///   52, twice 1, 2, 7, 26 (OEIS A000151: the P-trees with a root of a given colour, HLW
///   section III.2.1);
/// - sigma and gamma of the trees of order <= 3 (HLW Table III.1.1);
/// - the implicit midpoint rule: order 2, Phi = 1/4 on both trees of order 3 (sum b_i c_i^2 and
///   sum b_i a_ij c_j with b = 1, a = c = 1/2); its modified equation
///   y' = f + h^2 (1/12 f'f'f - 1/24 f''(f,f)) + O(h^4) (HLW section IX.1, the modified equation
///   of the implicit midpoint rule);
/// - the classical Runge-Kutta method (Kutta 1901; Hairer, Norsett & Wanner, Solving ODEs I,
///   Table II.1.2: c = (0, 1/2, 1/2, 1), a_21 = a_32 = 1/2, a_43 = 1, b = (1/6, 1/3, 1/3, 1/6)):
///   order 4, i.e. a(t) = 1/gamma(t) for every tree of order <= 4 (series_order, whose
///   comparison with 1/gamma is checked on the exact flow above); at order 5, by hand: the
///   bushy tree [., ., ., .] has
///   Phi = sum b_i c_i^4 = 2/3 (1/2)^4 + 1/6 = 5/24, error 5/24 - 1/5 = 1/120, and the tall
///   tree [[[[.]]]] has Phi = b^T A^3 c = 0 (A strictly lower with one nonzero subdiagonal),
///   error -1/120;
/// - Stormer-Verlet as a Lobatto IIIA-IIIB pair (HLW section II.2.2), colour 0 = q with
///   f = T'(p), colour 1 = p with g = -U'(q), H = T(p) + U(q): order 2 in both variants. With
///   half steps in q (q by IIIB, p by IIIA: drift-kick-drift) HLW section IX.3 prints the
///   modified Hamiltonian
///     H~ = H + h^2 (-1/24 U''(T', T') + 1/12 T''(U', U')) + O(h^4);
///   with half steps in p (q by IIIA, p by IIIB: kick-drift-kick) the roles of T and U are
///   exchanged, H~ = H + h^2 (1/12 U''(T', T') - 1/24 T''(U', U')) + O(h^4) (the symmetric
///   Baker-Campbell-Hausdorff formula of HLW section III.4.2 for e^{h/2 U} e^{h T} e^{h/2 U};
///   on T = p^2/2, U = q^2/2 its ratio (1 - h^2/12)/(1 + h^2/6) = 1 - h^2/4 + O(h^4) of the
///   q^2 to the p^2 coefficient is that of the step's exact invariant p^2 + (1 - h^2/4) q^2).
///   q' = dH~/dp and p' = -dH~/dq, written with f''(g,g) = T''' U'^2, f'g'f = -T'' U'' T',
///   g''(f,f) = -U''' T'^2, g'f'g = U'' T'' U', give the coefficients b/sigma of these four
///   order-3 P-trees: kick-drift-kick -1/24, -1/6, 1/12, 1/12; drift-kick-drift 1/12, 1/12,
///   -1/24, -1/6.
/// - Runge-Kutta-Nystrom and Nystrom tableaux (bseries/nystrom_weights.hpp), on q' = v (colour
///   0), v' = F (colour 1); Nystrom trees are written with q for a colour-0 and p for a colour-1
///   vertex, p[q, q] = g''(f,f) in the pair's naming above:
///   - Stormer-Verlet as an RKN method (velocity Verlet, HLW section I.1.4: c = (0, 1),
///     a = [[0, 0], [1/2, 0]], bbar = (1/2, 0), b = (1/2, 1/2)): order 2, and on the rkn trees
///     the kick-drift-kick values above, q[p[q]] (f'g'f) -1/6, p[q, q] 1/12, p[q[p]] (g'f'g) 1/12
///     (HLW section IX.3, the same method);
///   - two half steps of it (the composition (1/2, 1/2)): order 2 and these values times 1/4
///     (the modified field of the step h/2 taken twice is the field of h/2, and its h^2 term
///     scales by (1/2)^2); the composition of steps (1/2, 2/3, 5/6, -1): order 3 by HLW Theorem
///     II.4.1 (sum gamma = 1, sum gamma^3 = (27 + 64 + 125 - 216)/216 = 0, with a symmetric
///     base of order 2), and not 4: by the Baker-Campbell-Hausdorff formula (HLW section III.4)
///     on steps exp(gamma h F1 + gamma^3 h^3 F3 + ...), its modified field is
///     F1 + h^3 c [F1, F3] + O(h^4), c = +-1/2 sum_{i<j} (gamma_i gamma_j^3 - gamma_i^3 gamma_j)
///     (the sign set by the order of the factors), and that sum is -11/18, not 0;
///   - the DEMP RKN4(3) pair (Dormand, El-Mikkawy & Prince 1987, IMA J. Numer. Anal. 7,
///     235-250, RKN4(3)4FM: c = (0, 1/4, 7/10, 1), a_21 = 1/32, a_31 = 7/1000, a_32 = 119/500,
///     a_4j = bbar_j, bbar = (1/14, 8/27, 25/189, 0), b = (1/14, 32/81, 250/567, 5/54); the
///     order-3 formula bbar = (-7/150, 67/150, 3/20, -1/20), b = (13/21, -20/27, 275/189, -1/3)):
///     orders 4 and 3. At order 5, by hand: A c = (0, 0, 119/2000, 1/6), so p[q, q[p[q]]]
///     (gamma 30) has sum b_i c_i (A c)_i = 250/567 7/10 119/2000 + 5/54 1/6 = 73/2160, error
///     1/2160, and q[p[q[p[q]]]] (gamma 120) has bbar^T A c = 25/189 119/2000 = 17/2160, error
///     -1/2160;
///   - Nystrom's classical method (Nystrom 1925; HNW: Hairer, Norsett & Wanner, Solving ODEs I,
///     section II.14: ap the classical RK4 matrix, a = (1/8; 1/8, 0; 0, 0, 1/2),
///     bbar = (1, 1, 1, 0)/6, b = (1, 2, 2, 1)/6): order 4 on q'' = F(q, q') and on q'' = f(q).
///     Its b, c and ap are those of the classical RK4 method, so at order 5 the bushy p[q, q, q, q]
///     has sum b_i c_i^4 - 1/5 = 1/120 and the tall p[p[p[p[p]]]] has b^T Ap^3 (Ap 1) - 1/120 =
///     -1/120 (Ap^4 = 0), as the classical method above; q[p[q, q, q]] has
///     bbar^T c^3 - 1/20 = (1/8 + 1/8)/6 - 1/20 = -1/120. Two half steps of it (a composition of
///     a nystrom tableau, 8 stages): order 4, and the errors of q'' = f(q) times 1/16 (HNW
///     section II.4, Richardson extrapolation: the local error of two steps h/2 is
///     2 C (h/2)^(p+1) + O(h^(p+2)));
///   - the classical RK4 method written as a Nystrom method for q'' = F(q, q') (HNW section
///     II.14: Runge-Kutta on the first-order system; methods/nystrom_form.hpp): a = A A
///     (a_31 = 1/4, a_42 = 1/2), ap = A, bbar = b^T A = (1/6, 1/6, 1/6, 0), b: order 4, and on
///     p[q, q, q, q] and p[p[p[p[p]]]] the errors 1/120 and -1/120 of the bushy and tall trees
///     of the classical method above (the same sums b_i c_i^4 and b^T A^3 (A 1)).
///
/// Cost: everything fits the default evaluation limits of g++ 12 (-fconstexpr-ops-limit) and
/// clang++ 14 (-fconstexpr-steps); the largest evaluations are the one-colour trees of order 6
/// (counts), the order-5 series of the classical method, the two-colour trees of order 4 and the
/// order-5 series on the nystrom class (building tree_set(5, tree_class::nystrom), 115 trees,
/// takes half of clang++ 14's default; with the series of a 4-stage tableau about 80 %, which is
/// why the 8-stage composition is checked on F(q, q') to order 4 only).
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/nystrom_weights.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/bseries/trees.hpp"
#include "geomint/core/rational.hpp"
#include "geomint/methods/tableau.hpp"

namespace {

using geomint::rational;
using geomint::analysis::bseries::tree_set;
namespace bs = geomint::analysis::bseries;
namespace methods = geomint::methods;

// ---- tree counts (OEIS A000081, A000151) ----
constexpr bool counts_are(int colours, int max_order, const int* expected) {
  const tree_set trees(max_order, colours);
  for (int n = 1; n <= max_order; ++n)
    if (trees.count(n) != expected[n - 1]) return false;
  return trees.size() == trees.first(max_order + 1);
}
constexpr int one_colour[] = {1, 1, 2, 4, 9, 20};
constexpr int two_colours[] = {2, 4, 14, 52};
static_assert(counts_are(1, 6, one_colour));
static_assert(counts_are(2, 4, two_colours));
static_assert(tree_set(4, 2).count(4, 0) == 26 && tree_set(4, 2).count(4, 1) == 26);

// ---- trees of order <= 3 by structure, sigma and gamma (HLW Table III.1.1) ----
struct small_trees {
  int leaf, pair, bushy, tall;  // ., [.], [., .], [[.]]
};
constexpr small_trees small_trees_of(const tree_set& t, int colour) {
  const int leaf = t.leaf(colour);
  const int pair = t.find(colour, {leaf});
  return {leaf, pair, t.find(colour, {leaf, leaf}), t.find(colour, {pair})};
}
constexpr bool sigma_gamma_order_3() {
  const tree_set t(3, 1);
  const small_trees s = small_trees_of(t, 0);
  return t[s.leaf].sigma == 1 && t[s.leaf].gamma == 1 && t[s.pair].sigma == 1 && t[s.pair].gamma == 2 &&
         t[s.bushy].sigma == 2 && t[s.bushy].gamma == 3 && t[s.tall].sigma == 1 && t[s.tall].gamma == 6 &&
         t.butcher_product(s.pair, s.leaf) == s.bushy && t.butcher_product(s.leaf, s.pair) == s.tall;
}
static_assert(sigma_gamma_order_3());

// ---- the exact flow: e(t) = 1/gamma(t), and its modified field is f itself ----
constexpr bool exact_flow_checks() {
  const tree_set t(5, 1);
  const auto e = bs::exact_flow_coefficients<rational>(t);
  const auto b = bs::modified_field(t, e);
  for (int k = 0; k < t.size(); ++k) {
    if (e[static_cast<std::size_t>(k)] != rational(1, t[k].gamma)) return false;
    if (b[static_cast<std::size_t>(k)] != (t[k].order == 1 ? rational(1) : rational(0))) return false;
  }
  return bs::series_order(t, e) == 5;
}
static_assert(exact_flow_checks());

// ---- the implicit midpoint rule ----
constexpr auto midpoint = methods::make_rk<rational>({rational(1, 2)}, {{rational(1, 2)}}, {rational(1)});
struct order_3_values {
  rational bushy, tall;
  int order;
};
constexpr order_3_values midpoint_weights() {
  const tree_set t(3, 1);
  const small_trees s = small_trees_of(t, 0);
  const auto a = bs::elementary_weights(t, midpoint);
  return {a[static_cast<std::size_t>(s.bushy)], a[static_cast<std::size_t>(s.tall)], bs::series_order(t, a)};
}
static_assert(midpoint_weights().order == 2);
static_assert(midpoint_weights().bushy == rational(1, 4) && midpoint_weights().tall == rational(1, 4));
/// b(t) / sigma(t) of the order-3 trees: f''(f,f) (bushy) and f'f'f (tall); b vanishes at order 2.
constexpr order_3_values midpoint_modified() {
  const tree_set t(3, 1);
  const small_trees s = small_trees_of(t, 0);
  const auto b = bs::modified_field(t, bs::elementary_weights(t, midpoint));
  if (b[static_cast<std::size_t>(s.leaf)] != rational(1) || b[static_cast<std::size_t>(s.pair)] != rational(0)) return {};
  return {b[static_cast<std::size_t>(s.bushy)] / rational(t[s.bushy].sigma),
          b[static_cast<std::size_t>(s.tall)] / rational(t[s.tall].sigma), 0};
}
static_assert(midpoint_modified().bushy == rational(-1, 24) && midpoint_modified().tall == rational(1, 12));

// ---- the classical Runge-Kutta method ----
constexpr rational half(1, 2);
constexpr auto rk4 = methods::make_rk<rational>({0, half, half, 1}, {{0, 0, 0, 0}, {half, 0, 0, 0}, {0, half, 0, 0}, {0, 0, 1, 0}},
                                                {rational(1, 6), rational(1, 3), rational(1, 3), rational(1, 6)});
struct order_5_values {
  int order;
  rational bushy_error, tall_error;
};
constexpr order_5_values rk4_series() {
  const tree_set t(5, 1);
  const auto a = bs::elementary_weights(t, rk4);
  const auto err = bs::local_error_coefficients(t, a);
  const int leaf = t.leaf(0);
  int tall = leaf;
  for (int k = 1; k < 5; ++k) tall = t.find(0, {tall});
  return {bs::series_order(t, a), err[static_cast<std::size_t>(t.find(0, {leaf, leaf, leaf, leaf}))],
          err[static_cast<std::size_t>(tall)]};
}
static_assert(rk4_series().order == 4);
static_assert(rk4_series().bushy_error == rational(1, 120) && rk4_series().tall_error == rational(-1, 120));

// ---- Stormer-Verlet, colour 0 = q, colour 1 = p ----
constexpr rational iiia[2][2] = {{0, 0}, {half, half}}, iiib[2][2] = {{half, 0}, {half, 0}};
constexpr auto kick_drift_kick = methods::make_prk<rational>({0, 1}, iiia, {half, half}, iiib, {half, half});
constexpr auto drift_kick_drift = methods::make_prk<rational>({0, 1}, iiib, {half, half}, iiia, {half, half});
struct verlet_values {
  int order;
  rational f_gg, f_g_f, g_ff, g_f_g;  // b / sigma of f''(g,g), f'g'f, g''(f,f), g'f'g
};
template <class Pair>
constexpr verlet_values verlet_series(const Pair& verlet) {
  const tree_set t(3, 2);
  const auto a = bs::elementary_weights(t, verlet);
  const auto b = bs::modified_field(t, a);
  const int f = t.leaf(0), g = t.leaf(1);
  const auto over_sigma = [&](int tree) { return b[static_cast<std::size_t>(tree)] / rational(t[tree].sigma); };
  return {bs::series_order(t, a), over_sigma(t.find(0, {g, g})), over_sigma(t.find(0, {t.find(1, {f})})),
          over_sigma(t.find(1, {f, f})), over_sigma(t.find(1, {t.find(0, {g})}))};
}
constexpr verlet_values kdk = verlet_series(kick_drift_kick), dkd = verlet_series(drift_kick_drift);
static_assert(kdk.order == 2 && dkd.order == 2);
static_assert(kdk.f_gg == rational(-1, 24) && kdk.f_g_f == rational(-1, 6) && kdk.g_ff == rational(1, 12) &&
              kdk.g_f_g == rational(1, 12));
static_assert(dkd.f_gg == rational(1, 12) && dkd.f_g_f == rational(1, 12) && dkd.g_ff == rational(-1, 24) &&
              dkd.g_f_g == rational(-1, 6));

// ---- Runge-Kutta-Nystrom and Nystrom tableaux: colour 0 = q (q' = v), colour 1 = v (v' = F) ----
using bs::tree_class;
/// Nystrom trees by structure: q[p[q]], p[q, q], p[q[p]] (q for colour 0, p for colour 1).
struct nystrom_order_3 {
  int q_p_q, p_qq, p_q_p;
};
constexpr nystrom_order_3 nystrom_order_3_of(const tree_set& t) {
  const int q = t.leaf(0), p = t.leaf(1);
  return {t.find(0, {t.find(1, {q})}), t.find(1, {q, q}), t.find(1, {t.find(0, {p})})};
}
struct rkn_verlet_values {
  int order;
  rational q_p_q, p_qq, p_q_p;  // b / sigma
};
template <class Method>
constexpr rkn_verlet_values rkn_order_3_series(const Method& method) {
  const tree_set t(3, tree_class::rkn);
  const auto a = bs::elementary_weights(t, method);
  const auto b = bs::modified_field(t, a);
  const nystrom_order_3 s = nystrom_order_3_of(t);
  const auto over_sigma = [&](int tree) { return b[static_cast<std::size_t>(tree)] / rational(t[tree].sigma); };
  // q[p, p] (f''(g,g)) is no Nystrom tree: f = v is linear.
  if (t.find(0, {t.leaf(1), t.leaf(1)}) != -1) return {};
  return {bs::series_order(t, a), over_sigma(s.q_p_q), over_sigma(s.p_qq), over_sigma(s.p_q_p)};
}
constexpr auto velocity_verlet = methods::make_rkn<rational>({0, 1}, {{0, 0}, {half, 0}}, {half, 0}, {half, half});
constexpr rkn_verlet_values verlet_rkn = rkn_order_3_series(velocity_verlet);
static_assert(verlet_rkn.order == 2);
static_assert(verlet_rkn.q_p_q == rational(-1, 6) && verlet_rkn.p_qq == rational(1, 12) && verlet_rkn.p_q_p == rational(1, 12));
static_assert(verlet_rkn.q_p_q == kdk.f_g_f && verlet_rkn.p_qq == kdk.g_ff && verlet_rkn.p_q_p == kdk.g_f_g);

// ---- compositions of Stormer-Verlet ----
constexpr methods::composition<methods::rkn<rational, 2>, 2> verlet_halves{velocity_verlet, {half, half}};
constexpr rkn_verlet_values halves = rkn_order_3_series(verlet_halves);
static_assert(halves.order == 2);
static_assert(halves.q_p_q == rational(-1, 24) && halves.p_qq == rational(1, 48) && halves.p_q_p == rational(1, 48));
constexpr methods::composition<methods::rkn<rational, 2>, 4> order_3_composition{
    velocity_verlet, {half, rational(2, 3), rational(5, 6), rational(-1)}};
constexpr int order_3_composition_order() {
  const tree_set t(5, tree_class::rkn);
  return bs::series_order(t, bs::elementary_weights(t, order_3_composition));
}
static_assert(order_3_composition_order() == 3);

// ---- DEMP RKN4(3) ----
constexpr auto demp4 = methods::make_rkn<rational>(
    {0, rational(1, 4), rational(7, 10), 1},
    {{0, 0, 0, 0}, {rational(1, 32), 0, 0, 0}, {rational(7, 1000), rational(119, 500), 0, 0},
     {rational(1, 14), rational(8, 27), rational(25, 189), 0}},
    {rational(1, 14), rational(8, 27), rational(25, 189), 0}, {rational(1, 14), rational(32, 81), rational(250, 567), rational(5, 54)});
/// The order-3 formula of the pair: the same c and a, other weights.
constexpr methods::rkn<rational, 4> demp3{demp4.c, demp4.a,
                                          {rational(-7, 150), rational(67, 150), rational(3, 20), rational(-1, 20)},
                                          {rational(13, 21), rational(-20, 27), rational(275, 189), rational(-1, 3)}};
struct demp_values {
  int order, embedded_order;
  rational p_q_q_p_q, q_p_q_p_q;  // local errors of p[q, q[p[q]]] and q[p[q[p[q]]]]
};
constexpr demp_values demp_series() {
  const tree_set t(5, tree_class::rkn);
  const auto a = bs::elementary_weights(t, demp4);
  const auto err = bs::local_error_coefficients(t, a);
  const int q = t.leaf(0), q_p_q = t.find(0, {t.find(1, {q})});
  return {bs::series_order(t, a), bs::series_order(t, bs::elementary_weights(t, demp3)),
          err[static_cast<std::size_t>(t.find(1, {q, q_p_q}))], err[static_cast<std::size_t>(t.find(0, {t.find(1, {q_p_q})}))]};
}
constexpr demp_values demp = demp_series();
static_assert(demp.order == 4 && demp.embedded_order == 3);
static_assert(demp.p_q_q_p_q == rational(1, 2160) && demp.q_p_q_p_q == rational(-1, 2160));

// ---- Nystrom's classical method, and RK4 as a Nystrom method ----
constexpr rational sixth(1, 6);
constexpr rational rk4_a[4][4] = {{0, 0, 0, 0}, {half, 0, 0, 0}, {0, half, 0, 0}, {0, 0, 1, 0}};
constexpr rational rk4_b[4] = {sixth, rational(1, 3), rational(1, 3), sixth};
constexpr auto nystrom4 = methods::make_nystrom<rational>(
    {0, half, half, 1}, {{0, 0, 0, 0}, {rational(1, 8), 0, 0, 0}, {rational(1, 8), 0, 0, 0}, {0, 0, half, 0}}, rk4_a,
    {sixth, sixth, sixth, 0}, rk4_b);
constexpr auto rk4_as_nystrom = methods::make_nystrom<rational>(
    {0, half, half, 1}, {{0, 0, 0, 0}, {0, 0, 0, 0}, {rational(1, 4), 0, 0, 0}, {0, half, 0, 0}}, rk4_a, {sixth, sixth, sixth, 0},
    rk4_b);
struct nystrom_values {
  int order;
  rational bushy_error, tall_error;  // p[q, q, q, q] and p[p[p[p[p]]]]
};
/// On the trees of q'' = F(q, q') to order 5.
template <class Method>
constexpr nystrom_values nystrom_series(const Method& method) {
  const tree_set t(5, tree_class::nystrom);
  const auto a = bs::elementary_weights(t, method);
  const auto err = bs::local_error_coefficients(t, a);
  const int q = t.leaf(0);
  int tall = t.leaf(1);
  for (int k = 1; k < 5; ++k) tall = t.find(1, {tall});
  return {bs::series_order(t, a), err[static_cast<std::size_t>(t.find(1, {q, q, q, q}))], err[static_cast<std::size_t>(tall)]};
}
struct velocity_free_values {
  int order;
  rational bushy_error, q_p_qqq_error;  // p[q, q, q, q] and q[p[q, q, q]]
};
/// On the trees of q'' = f(q) to order 5.
template <class Method>
constexpr velocity_free_values velocity_free_series(const Method& method) {
  const tree_set t(5, tree_class::rkn);
  const auto a = bs::elementary_weights(t, method);
  const auto err = bs::local_error_coefficients(t, a);
  const int q = t.leaf(0);
  return {bs::series_order(t, a), err[static_cast<std::size_t>(t.find(1, {q, q, q, q}))],
          err[static_cast<std::size_t>(t.find(0, {t.find(1, {q, q, q})}))]};
}
constexpr nystrom_values nystrom4_values = nystrom_series(nystrom4);
static_assert(nystrom4_values.order == 4);
static_assert(nystrom4_values.bushy_error == rational(1, 120) && nystrom4_values.tall_error == rational(-1, 120));
constexpr velocity_free_values nystrom4_velocity_free = velocity_free_series(nystrom4);
static_assert(nystrom4_velocity_free.order == 4);
static_assert(nystrom4_velocity_free.bushy_error == rational(1, 120) && nystrom4_velocity_free.q_p_qqq_error == rational(-1, 120));
// Two half steps (8 stages; on F(q, q') to order 4 only, to stay within clang++ 14's default
// evaluation limit).
constexpr methods::composition<methods::nystrom<rational, 4>, 2> nystrom4_halves{nystrom4, {half, half}};
constexpr int nystrom4_halves_order() {
  const tree_set t(4, tree_class::nystrom);
  return bs::series_order(t, bs::elementary_weights(t, nystrom4_halves));
}
static_assert(nystrom4_halves_order() == 4);
constexpr velocity_free_values nystrom4_halves_velocity_free = velocity_free_series(nystrom4_halves);
static_assert(nystrom4_halves_velocity_free.order == 4);
static_assert(nystrom4_halves_velocity_free.bushy_error == rational(1, 1920) &&
              nystrom4_halves_velocity_free.q_p_qqq_error == rational(-1, 1920));
// RK4 on the first-order system: on these two trees the classical method's own weights.
constexpr nystrom_values rk4_as_nystrom_values = nystrom_series(rk4_as_nystrom);
static_assert(rk4_as_nystrom_values.order == 4);
static_assert(rk4_as_nystrom_values.bushy_error == rational(1, 120) && rk4_as_nystrom_values.tall_error == rational(-1, 120));

}  // namespace
