// Compile-time checks of the catalogue's explicit methods (methods/catalogue.hpp) against their
// published properties: the constexpr exact analysis of analysis/ (order by the Nystrom trees,
// symplecticity by Suris' conditions, symmetry up to a permutation of stages, linear stability
// on y'' = -y) over the same constexpr tableaux the integrator runs, over geomint::rational
// and, for the compositions and McLachlan's splittings, over their number fields
// (methods/algebraic_number.hpp). The expected values are the sources' (cited per method) or
// exact mathematics (said where).
#include "geomint/analysis/bseries/nystrom_weights.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/analysis/order_conditions.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/analysis/scheme_structure.hpp"
#include "geomint/methods/catalogue.hpp"

namespace {

using namespace geomint;

/// An rkn<rational, S> as the analysis' exact tableau (values basis).
template <int S>
constexpr exact_rkn_tableau exact_of(const methods::rkn<rational, S>& t) {
  return rational_rkn_tableau(t.c, t.a, t.bbar, t.b);
}
/// The rkn part of a nystrom tableau (its restriction to q'' = f(q), where ap does not enter).
template <int S>
constexpr exact_rkn_tableau exact_of(const methods::nystrom<rational, S>& t) {
  return rational_rkn_tableau(t.c, t.a, t.bbar, t.b);
}

template <class Method>
constexpr exact_rkn_tableau exact_tableau = exact_of(Method::tableau());

template <class Method>
constexpr bool has_order(int p) {
  const order_summary s = order_analysis(exact_tableau<Method>);
  return s.order == p && !s.order_is_lower_bound;
}

// Stormer-Verlet: order 2, symplectic, symmetric (Hairer, Lubich & Wanner 2006, sections I.1.4,
// V.1, VI.3). On y'' = -y: q1 = (1 - h^2/2) q + h v, v1 = -h (1 - h^2/4) q + (1 - h^2/2) v, so
// tr M = 2 - h^2 and det M = 1 (exact mathematics): periodic exactly for h^2 < 4.
static_assert(has_order<methods::stormer_verlet>(2));
static_assert(symplecticity(exact_tableau<methods::stormer_verlet>).symplectic);
static_assert(symmetry(exact_tableau<methods::stormer_verlet>).symmetric);
static_assert(linear_stability(exact_tableau<methods::stormer_verlet>).determinant_is_one);
static_assert(linear_stability_interval(linear_stability(exact_tableau<methods::stormer_verlet>)).kind == stability_kind::periodic);
static_assert(linear_stability_interval(linear_stability(exact_tableau<methods::stormer_verlet>)).compare_squared(exact_number(4)) == 0);

// Ruth's method: order 3, symplectic (Ruth 1983; Forest & Ruth 1990); not symmetric (its
// adjoint has the kicks and drifts in reverse order, which is another method).
static_assert(has_order<methods::ruth3>(3));
static_assert(symplecticity(exact_tableau<methods::ruth3>).symplectic);
static_assert(!symmetry(exact_tableau<methods::ruth3>).symmetric);
static_assert(linear_stability(exact_tableau<methods::ruth3>).determinant_is_one);  // symplectic: det M = 1

// A splitting that starts with a drift (kick_drift_rkn's first_drift, as McLachlan's SB3A
// methods do; those have irrational drifts and are checked at run time, test_catalogue.cpp):
// drift h/2, kick h, drift h/2 is position Stormer-Verlet, c = 1/2, a = 0, bbar = 1/2, b = 1
// (Hairer, Lubich & Wanner 2006, section I.1.4): order 2, symplectic, symmetric.
constexpr auto position_verlet = methods::detail::kick_drift_rkn<rational, 1>({rational(1)}, {rational(1, 2)}, rational(1, 2));
static_assert(position_verlet.c[0] == rational(1, 2) && position_verlet.a[0][0] == rational(0));
static_assert(position_verlet.bbar[0] == rational(1, 2) && position_verlet.b[0] == rational(1));
static_assert(order_analysis(exact_of(position_verlet)).order == 2 && !order_analysis(exact_of(position_verlet)).order_is_lower_bound);
static_assert(symplecticity(exact_of(position_verlet)).symplectic);
static_assert(symmetry(exact_of(position_verlet)).symmetric);

// Dormand, El-Mikkawy & Prince 1987: RKN4(3)4FM has orders 4 and 3, RKN6(4)6FM 6 and 4;
// they are not constructed to be symplectic, and Suris' conditions fail, so det M != 1 on
// y'' = -y.
static_assert(has_order<methods::demp_rkn43>(4));
static_assert(has_order<methods::demp_rkn43_embedded>(3));
static_assert(has_order<methods::demp_rkn64>(6));
static_assert(has_order<methods::demp_rkn64_embedded>(4));
static_assert(!symplecticity(exact_tableau<methods::demp_rkn43>).symplectic);
static_assert(!symplecticity(exact_tableau<methods::demp_rkn64>).symplectic);
static_assert(!linear_stability(exact_tableau<methods::demp_rkn43>).determinant_is_one);
static_assert(!linear_stability(exact_tableau<methods::demp_rkn64>).determinant_is_one);

// Nystrom's method (Hairer, Norsett & Wanner I, section II.14): order 4; on q'' = f(q) its rkn
// part has order 4 too (the conditions there are a subset).
static_assert(has_order<methods::nystrom4>(4));
static_assert(!symplecticity(exact_tableau<methods::nystrom4>).symplectic);

// ---- over number fields: the tree order (Nystrom trees of q'' = f(q), series_order), Suris'
// conditions bbar_i = b_i (1 - c_i), b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji) (Hairer, Lubich &
// Wanner 2006, Theorem VI.4.10; sufficient), and symmetry up to a permutation of stages ----
template <class K, int S>
constexpr int rkn_tree_order(const methods::rkn<K, S>& t, int limit) {
  const analysis::bseries::tree_set trees(limit, analysis::bseries::tree_class::rkn);
  return analysis::bseries::series_order(trees, analysis::bseries::elementary_weights(trees, t));
}
template <class K, int S>
constexpr bool suris_conditions(const methods::rkn<K, S>& t) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    if (!(t.bbar[i] == t.b[i] * (K(1) - t.c[i]))) return false;
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j)
      if (!(t.b[i] * (t.bbar[j] - t.a[i][j]) == t.b[j] * (t.bbar[i] - t.a[j][i]))) return false;
  }
  return true;
}
/// The method's rkn tableau; a composition's is its composed tableau (with d = sum gamma = 1).
template <class Method>
constexpr auto field_tableau() {
  if constexpr (requires { methods::tableau_of(Method::tableau()); }) {
    const auto composed = methods::tableau_of(Method::tableau());
    if (!(composed.d == 1)) throw "the composition is not consistent";
    return composed.tableau;
  } else {
    return Method::tableau();
  }
}

// Forest & Ruth 1990, Yoshida 1990 (the triple jump), Suzuki 1990 (the fractal order 4): order 4
// (exactly: not 5), symplectic, symmetric. Over Q(2^(1/3)).
static_assert(rkn_tree_order(field_tableau<methods::forest_ruth>(), 5) == 4);
static_assert(rkn_tree_order(field_tableau<methods::yoshida_triple_jump>(), 5) == 4);
static_assert(rkn_tree_order(field_tableau<methods::suzuki4>(), 5) == 4);
static_assert(suris_conditions(field_tableau<methods::forest_ruth>()) && is_symmetric(field_tableau<methods::forest_ruth>()));
static_assert(suris_conditions(field_tableau<methods::yoshida_triple_jump>()) && is_symmetric(field_tableau<methods::yoshida_triple_jump>()));
static_assert(suris_conditions(field_tableau<methods::suzuki4>()) && is_symmetric(field_tableau<methods::suzuki4>()));

// McLachlan 1995, SB3A with m = 4 (over Q(sqrt 14)) and m = 5: order 4, symplectic, symmetric.
// The order of m = 5 is not here: its weights on the order-5 trees overflow the 512 bits of the
// exact numbers (a compile error); tests/methods/test_catalogue.cpp checks it at run time.
static_assert(rkn_tree_order(field_tableau<methods::mclachlan_sb3a4>(), 5) == 4);
static_assert(suris_conditions(field_tableau<methods::mclachlan_sb3a4>()) && is_symmetric(field_tableau<methods::mclachlan_sb3a4>()));
static_assert(suris_conditions(field_tableau<methods::mclachlan_sb3a5>()) && is_symmetric(field_tableau<methods::mclachlan_sb3a5>()));

}  // namespace
