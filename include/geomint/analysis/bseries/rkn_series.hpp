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

#include <stdexcept>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/trees.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/methods/number_field.hpp"

namespace geomint::analysis::bseries {

/// The Nystrom trees of a two-colour tree_set for F = F(q) (is_nystrom_tree, velocity_free).
inline std::vector<bool> nystrom_trees(const tree_set& trees) {
  std::vector<bool> wanted(static_cast<std::size_t>(trees.size()));
  for (int t = 0; t < trees.size(); ++t) wanted[static_cast<std::size_t>(t)] = is_nystrom_tree(trees, t, true);
  return wanted;
}

/// a(t) of one step of the exact RKN tableau on every Nystrom tree of `trees` (two colours),
/// 0 on the others; exact rationals.
inline std::vector<methods::exact_rational> elementary_weights(const tree_set& trees, const exact_rkn_tableau& method) {
  if (trees.colours() != 2)
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: an RKN tableau needs two-colour trees");
  const std::vector<bool> wanted = nystrom_trees(trees);
  const auto n = static_cast<std::size_t>(trees.size());
  std::vector<stage_vector> psi(n), fed(n);  // fed[t] = Y(t) for a colour-0 tree t
  std::vector<exact_number> a(n);
  for (std::size_t t = 0; t < n; ++t) {
    if (!wanted[t]) continue;
    const rooted_tree& tree = trees[static_cast<int>(t)];
    if (tree.colour == 1) {
      psi[t] = method.one;
      for (int w : tree.subtrees) psi[t] = method.multiply(psi[t], fed[static_cast<std::size_t>(w)]);
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
  std::vector<methods::exact_rational> out(n, methods::exact_rational(0));
  for (std::size_t t = 0; t < n; ++t)
    if (wanted[t])
      out[t] = methods::exact_rational(boost::multiprecision::cpp_int(a[t].num.str()),
                                       boost::multiprecision::cpp_int(a[t].den().str()));
  return out;
}

}  // namespace geomint::analysis::bseries
