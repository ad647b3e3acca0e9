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
///
/// Cost: everything fits the default evaluation limits of g++ 12 (-fconstexpr-ops-limit) and
/// clang++ 14 (-fconstexpr-steps); the largest evaluations are the one-colour trees of order 6
/// (counts), the order-5 series of the classical method and the two-colour trees of order 4.
#include "geomint/analysis/bseries/modified_equation.hpp"
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

}  // namespace
