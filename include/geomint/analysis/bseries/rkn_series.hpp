#pragma once
/// The P-series of one step of a library scheme from its exact RKN tableau
/// (analysis/rkn_tableau.hpp: lpf on every node family, galerkin, midpoint, trapezoidal), on
/// the Nystrom trees of a two-colour tree_set, exactly: the bridge from the schemes' exact
/// tableaux to the series of this folder (modified_equation.hpp takes its result as it takes
/// elementary_weights of series.hpp).
///
/// Why not a tableau_data: the stages of lpf and galerkin are roots of a node polynomial N of
/// degree up to 8 (Legendre, Chebyshev), which need not lie in one field Q(r) of
/// methods/number_field.hpp (the four Gauss points lie in Q(r) for no single root r). The
/// tableau's stage algebra Q[x]/(N) needs no field: a vector of stage values is a polynomial
/// mod N, the componentwise product is the product mod N, and A, bbar, b act rationally
/// (rkn_tableau.hpp). Every series coefficient is a rational, computed exactly there.
///
/// On q' = v (colour 0), v' = F(q) (colour 1), with Psi(u) the stage vector of a colour-1 tree
/// u (the expansion f(Q_i) = sum_u h^(|u| - 1)/sigma(u) Psi_i(u) F(u)):
///   Psi(u) = prod over the children w of u of Y(w),  Y(colour-0 leaf) = c,  Y([v]) = A Psi(v);
///   a(u) = b(Psi(u)),   a(colour-0 leaf) = 1,   a([v]) = bbar(Psi(v)),
/// the colour-0 trees being the leaf and [v] with one colour-1 child v (HNW: Hairer, Norsett &
/// Wanner, Solving ODEs I, section II.14; the same weights as order_conditions.hpp, there as
/// conditions). The other trees (not is_nystrom_tree with velocity_free) get 0: their elementary
/// differentials vanish on such a system, and the coefficients of the Nystrom trees depend on
/// Nystrom trees only, also in the modified field (an edge cut of a Nystrom tree gives Nystrom
/// trees). tests/analysis/test_bseries_elementary_differentials.cpp checks the result against
/// elementary_weights of the partitioned form of the same method read from a tableau file.
///
/// LPF on a Lagrangian that is not natural (docs/results/schemes.md, "LPF as a Nystrom
/// method"): the same collocation tableau is the Nystrom method for q'' = F(q, q') with the
/// velocity stages V_i = v + h sum_j ap_ij F_j, ap_ij = int_0^{c_i} l_j(u) du, i.e. on stage
/// vectors Ap: V -> int_0^x V(u) du mod N. Its series (collocation_nystrom_weights) is the one
/// above on the Nystrom trees of F(q, q') (is_nystrom_tree, not velocity_free), with one more
/// rule: a colour-1 child w of a colour-1 vertex feeds Ap Psi(w) (the direction V_i - v).

#include <stdexcept>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/trees.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/methods/number_field.hpp"

namespace geomint::analysis::bseries {

/// The Nystrom trees of a two-colour tree_set for F = F(q) (velocity_free) or F(q, q')
/// (is_nystrom_tree).
inline std::vector<bool> nystrom_trees(const tree_set& trees, bool velocity_free = true) {
  std::vector<bool> wanted(static_cast<std::size_t>(trees.size()));
  for (int t = 0; t < trees.size(); ++t) wanted[static_cast<std::size_t>(t)] = is_nystrom_tree(trees, t, velocity_free);
  return wanted;
}

namespace detail {
/// Ap of a collocation tableau in the monomial basis: x^k -> x^(k+1) / (k + 1) mod N.
constexpr stage_vector collocation_velocity_stages(const exact_rkn_tableau& method, const stage_vector& u) {
  exact_number p[max_exact_stages + 1];
  for (int k = 0; k < method.stages; ++k) p[k + 1] = u[k] * geomint::analysis::detail::fraction(1, k + 1);
  method.reduce(p, method.stages);
  stage_vector r;
  for (int i = 0; i < method.stages; ++i) r[i] = p[i];
  return r;
}

/// The exact numbers a[t] as rationals where `wanted`, 0 elsewhere.
inline std::vector<methods::exact_rational> to_rationals(const std::vector<exact_number>& a, const std::vector<bool>& wanted) {
  std::vector<methods::exact_rational> out(a.size(), methods::exact_rational(0));
  for (std::size_t t = 0; t < a.size(); ++t)
    if (wanted[t])
      out[t] = methods::exact_rational(boost::multiprecision::cpp_int(a[t].num.str()),
                                       boost::multiprecision::cpp_int(a[t].den().str()));
  return out;
}

/// a(t) on the Nystrom trees of F(q) (velocity_free) or of F(q, q') (Ap: the method's velocity
/// stages), 0 on the others; exact numbers of the stage algebra (constexpr).
constexpr std::vector<exact_number> exact_nystrom_weights(const tree_set& trees, const exact_rkn_tableau& method,
                                                          bool velocity_free) {
  if (trees.colours() != 2)
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: an RKN tableau needs two-colour trees");
  const auto n = static_cast<std::size_t>(trees.size());
  std::vector<stage_vector> psi(n), fed(n);  // fed[t] = Y(t) for a colour-0 tree t
  std::vector<exact_number> a(n);
  for (std::size_t t = 0; t < n; ++t) {
    if (!is_nystrom_tree(trees, static_cast<int>(t), velocity_free)) continue;  // (no vector<bool>: Clang 14 constexpr)
    const rooted_tree& tree = trees[static_cast<int>(t)];
    if (tree.colour == 1) {
      psi[t] = method.one;
      for (int w : tree.subtrees) {
        const auto child = static_cast<std::size_t>(w);
        psi[t] = method.multiply(psi[t], trees[w].colour == 0 ? fed[child] : collocation_velocity_stages(method, psi[child]));
      }
      a[t] = method.apply_b(psi[t]);
    } else if (tree.subtrees.empty()) {
      fed[t] = method.c;
      a[t] = exact_number(1);
    } else {
      const auto v = static_cast<std::size_t>(tree.subtrees.front());
      fed[t] = method.apply_a(psi[v]);
      a[t] = method.apply_bbar(psi[v]);
    }
  }
  return a;
}

/// The same as exact rationals (cpp_rational).
inline std::vector<methods::exact_rational> nystrom_weights(const tree_set& trees, const exact_rkn_tableau& method,
                                                            bool velocity_free) {
  return to_rationals(exact_nystrom_weights(trees, method, velocity_free), nystrom_trees(trees, velocity_free));
}
}  // namespace detail

/// a(t) of one step of the exact RKN tableau of a library scheme on every Nystrom tree of
/// `trees` (two colours, F = F(q)), 0 on the others, in the tableau's own exact numbers: constexpr,
/// so the series and the modified field (modified_equation.hpp) of lpf, galerkin, midpoint and
/// trapezoidal reach static_assert (tests/analysis/test_bseries_static.cpp).
constexpr std::vector<exact_number> exact_elementary_weights(const tree_set& trees, const exact_rkn_tableau& method) {
  return detail::exact_nystrom_weights(trees, method, true);
}

/// a(t) of one step of the exact RKN tableau on every Nystrom tree of `trees` (two colours,
/// F = F(q)), 0 on the others; exact rationals.
inline std::vector<methods::exact_rational> elementary_weights(const tree_set& trees, const exact_rkn_tableau& method) {
  return detail::nystrom_weights(trees, method, true);
}

/// a(t) of the collocation Nystrom method of a collocation tableau (lpf_tableau, monomial basis)
/// on q'' = F(q, q'): every Nystrom tree of F(q, q'), 0 on the others; exact rationals.
/// std::invalid_argument for a tableau that is not a collocation tableau.
inline std::vector<methods::exact_rational> collocation_nystrom_weights(const tree_set& trees, const exact_rkn_tableau& method) {
  if (method.basis != stage_basis::monomial)
    throw std::invalid_argument("geomint::analysis::bseries::collocation_nystrom_weights: a collocation tableau (monomial basis) is needed");
  return detail::nystrom_weights(trees, method, false);
}

/// a(t) = Phi(t) of one step of the collocation Runge-Kutta method on the nodes of a collocation
/// tableau (monomial basis; galerkin_tableau: the Gauss method), on every tree of a one-colour
/// tree_set (its B-series, series.hpp): g(leaf) = 1, g([t_1..t_k]) = prod_j A g(t_j) with
/// A: V -> int_0^x V(u) du mod N (the collocation coefficients a_ij = int_0^{c_i} l_j), and
/// Phi(t) = b(g(t)) (HLW section III.1.2). A partitioned pair with Ahat = A, bhat = b has these
/// coefficients on every colouring of t. std::invalid_argument for two-colour trees or a tableau
/// that is not a collocation tableau.
inline std::vector<methods::exact_rational> collocation_rk_weights(const tree_set& trees, const exact_rkn_tableau& method) {
  if (trees.colours() != 1)
    throw std::invalid_argument("geomint::analysis::bseries::collocation_rk_weights: a Runge-Kutta method's B-series needs one-colour trees");
  if (method.basis != stage_basis::monomial)
    throw std::invalid_argument("geomint::analysis::bseries::collocation_rk_weights: a collocation tableau (monomial basis) is needed");
  const auto n = static_cast<std::size_t>(trees.size());
  std::vector<stage_vector> g(n);
  std::vector<exact_number> a(n);
  for (std::size_t t = 0; t < n; ++t) {
    g[t] = method.one;
    for (int w : trees[static_cast<int>(t)].subtrees)
      g[t] = method.multiply(g[t], detail::collocation_velocity_stages(method, g[static_cast<std::size_t>(w)]));
    a[t] = method.apply_b(g[t]);
  }
  return detail::to_rationals(a, std::vector<bool>(n, true));
}

}  // namespace geomint::analysis::bseries
