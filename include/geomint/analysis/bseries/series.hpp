#pragma once
/// Exact B-series (Runge-Kutta) and P-series (partitioned Runge-Kutta) coefficients of one step.
///
/// Normalisation of HLW (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006),
/// section III.1: B(a, y) = a(empty) y + sum_t h^|t| / sigma(t) a(t) F(t)(y), so that the exact
/// flow has e(t) = 1/gamma(t) and a Runge-Kutta method has a(t) = Phi(t), its
/// elementary weight: Phi(t) = sum_i b_i g_i(t), g_i(t) = prod over the subtrees u of the root
/// of (sum_j a_ij g_j(u)), g_i(single vertex) = 1 (HLW section III.1.2).
/// For a partitioned method (HLW section III.2.1; the pair (A, b) for y' = f(y,z), colour 0, and
/// (Ahat, bhat) for z' = g(y,z), colour 1) the root's colour picks b or bhat and each subtree's
/// root colour picks A or Ahat in the factor sum_j a_ij g_j(u). A Runge-Kutta-Nystrom method
/// written as q' = v, v' = f(q) is such a pair.
///
/// The tableaux are those the integrator runs (geomint::methods::tableau_data, methods/tableau.hpp).
/// The coefficient type T is a template parameter (exact: boost::multiprecision::cpp_rational, or
/// methods::field_element for Q(r)); only +, *, /, == and construction from int are used.
/// Every function is constexpr: with geomint::rational (core/rational.hpp, whose overflow is a
/// compile error in a constant expression) the coefficients of a constexpr tableau
/// (methods::make_rk, make_prk) are exact at compile time; see tests/analysis/test_bseries_static.cpp.
/// Fixed-size rkn and nystrom tableaux and their compositions: nystrom_weights.hpp (constexpr
/// too); their run-time data (tableau_data, nystrom_form): partitioned_form.hpp.

#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/analysis/bseries/trees.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::analysis::bseries {

using methods::tableau_data;

/// The partitioned pair (first on colour 0, second on colour 1) of two Runge-Kutta tableaux of
/// the same number of stages, as one `prk` tableau (c from the first).
template <class T>
constexpr tableau_data<T> pair_of(const tableau_data<T>& first, const tableau_data<T>& second) {
  if (first.kind != methods::method_kind::rk || second.kind != methods::method_kind::rk)
    throw std::invalid_argument("geomint::analysis::bseries::pair_of: both parts must be Runge-Kutta tableaux");
  tableau_data<T> d = first;
  d.kind = methods::method_kind::prk;
  d.ahat = second.a;
  d.bhat = second.b;
  return d;
}

namespace detail {
/// One colour's (A, b).
template <class T>
struct weights_of_colour {
  const std::vector<std::vector<T>>* a;
  const std::vector<T>* b;
};

template <class T>
constexpr void check_tableau(const weights_of_colour<T>& m, std::size_t stages, std::size_t c_size, const char* which) {
  // The message is built only on failure (Clang 14 cannot build a libstdc++ 12 std::string in a
  // constant expression).
  const auto fail = [which](const char* what) {
    throw std::invalid_argument(std::string("geomint::analysis::bseries: the ") + which + " tableau " + what);
  };
  if (m.b->empty()) fail("has no stages (b is empty)");
  if (m.b->size() != stages) fail("has a different number of stages than the other");
  if (c_size != stages) fail("has c of a different length than b");
  if (m.a->size() != stages) fail("has A with a number of rows different from the length of b");
  for (const auto& row : *m.a)
    if (row.size() != stages) fail("has a row of A of a length different from the length of b");
}

/// Elementary weights with one (A, b) per colour (weights[colour]); with `wanted`, only for the
/// trees it marks (a set closed under taking subtrees), zero for the others.
template <class T>
constexpr std::vector<T> elementary_weights(const tree_set& trees, const weights_of_colour<T>* weights,
                                            const std::vector<bool>* wanted = nullptr) {
  const std::size_t s = weights[0].b->size();
  const auto n = static_cast<std::size_t>(trees.size());
  // g_i(t) (per tree, not kept); fed[t][i] = sum_j a^{colour of t}_ij g_j(t), the factor t
  // contributes as a subtree.
  std::vector<std::vector<T>> fed(n);
  std::vector<T> g;
  std::vector<T> phi(n, T(0));
  for (std::size_t t = 0; t < n; ++t) {
    if (wanted && !(*wanted)[t]) continue;
    const rooted_tree& tree = trees[static_cast<int>(t)];
    // g_i(t) = prod over the subtrees u of fed_i(u); zero factors and zero entries of A and b
    // are skipped (known_zero), exactly.
    if (tree.subtrees.empty()) g.assign(s, T(1));
    else g = fed[static_cast<std::size_t>(tree.subtrees[0])];
    for (std::size_t k = 1; k < tree.subtrees.size(); ++k)
      for (std::size_t i = 0; i < s; ++i)
        if (!known_zero(g[i])) g[i] *= fed[static_cast<std::size_t>(tree.subtrees[k])][i];
    const weights_of_colour<T>& own = weights[tree.colour];
    fed[t].assign(s, T(0));
    for (std::size_t j = 0; j < s; ++j) {
      if (known_zero(g[j])) continue;
      for (std::size_t i = 0; i < s; ++i)
        if (!known_zero((*own.a)[i][j])) fed[t][i] += (*own.a)[i][j] * g[j];
      if (!known_zero((*own.b)[j])) phi[t] += (*own.b)[j] * g[j];
    }
  }
  return phi;
}

/// The checks and the weights of elementary_weights below, on one (A, b) per colour.
template <class T>
constexpr std::vector<T> checked_elementary_weights(const tree_set& trees, methods::method_kind kind,
                                                    const weights_of_colour<T>* weights, std::size_t c_size,
                                                    const std::vector<bool>* wanted) {
  const std::size_t stages = weights[0].b->size();
  if (kind == methods::method_kind::rk) {
    if (trees.colours() != 1)
      throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: a Runge-Kutta tableau needs one-colour trees");
    check_tableau(weights[0], stages, c_size, "Runge-Kutta");
  } else if (kind == methods::method_kind::prk) {
    if (trees.colours() != 2)
      throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: a partitioned pair needs two-colour trees");
    check_tableau(weights[0], stages, c_size, "first (colour 0)");
    check_tableau(weights[1], stages, c_size, "second (colour 1)");
  } else {
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: an rk or prk tableau is needed (rkn and nystrom: partitioned_form_of)");
  }
  if (wanted && wanted->size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: `wanted` needs one entry per tree");
  return elementary_weights(trees, weights, wanted);
}
}  // namespace detail

/// a(t) = Phi(t) for every tree: the B-series of one step of a Runge-Kutta tableau (kind rk,
/// one-colour trees) or the P-series of a partitioned pair (kind prk, two-colour trees; (A, b)
/// on colour 0, (Ahat, bhat) on colour 1); a(empty) = 1. Other kinds: see
/// bseries/partitioned_form.hpp. With `wanted` (one entry per tree, a set closed under taking
/// subtrees), only the marked trees are computed; the others are zero.
template <class T>
constexpr std::vector<T> elementary_weights(const tree_set& trees, const tableau_data<T>& method,
                                            const std::vector<bool>* wanted = nullptr) {
  const detail::weights_of_colour<T> weights[2] = {{&method.a, &method.b}, {&method.ahat, &method.bhat}};
  return detail::checked_elementary_weights(trees, method.kind, weights, method.c.size(), wanted);
}

/// The same for a fixed-size methods:: tableau (rk or prk). These are the compile-time entry
/// points: they do not go through tableau_data, whose std::string name Clang 14 cannot build in a
/// constant expression with libstdc++ 12 (GCC 12 can).
template <class K, int S>
constexpr std::vector<K> elementary_weights(const tree_set& trees, const methods::rk<K, S>& method) {
  const std::vector<std::vector<K>> a = methods::detail::to_vector<K, S>(method.a);
  const std::vector<K> b = methods::detail::to_vector<K, S>(method.b);
  const detail::weights_of_colour<K> weights[2] = {{&a, &b}, {&a, &b}};
  return detail::checked_elementary_weights(trees, methods::method_kind::rk, weights, method.c.size(), nullptr);
}
template <class K, int S>
constexpr std::vector<K> elementary_weights(const tree_set& trees, const methods::prk<K, S>& method) {
  const std::vector<std::vector<K>> a = methods::detail::to_vector<K, S>(method.a), ahat = methods::detail::to_vector<K, S>(method.ahat);
  const std::vector<K> b = methods::detail::to_vector<K, S>(method.b), bhat = methods::detail::to_vector<K, S>(method.bhat);
  const detail::weights_of_colour<K> weights[2] = {{&a, &b}, {&ahat, &bhat}};
  return detail::checked_elementary_weights(trees, methods::method_kind::prk, weights, method.c.size(), nullptr);
}

/// e(t) = 1/gamma(t): the B-/P-series of the exact flow (HLW section III.1.2).
template <class T>
constexpr std::vector<T> exact_flow_coefficients(const tree_set& trees) {
  std::vector<T> e;
  e.reserve(static_cast<std::size_t>(trees.size()));
  for (const rooted_tree& t : trees.trees()) e.push_back(T(1) / T(t.gamma));
  return e;
}

/// a(t) - 1/gamma(t): the local error of one step per tree (the error term of tree t is
/// h^|t| / sigma(t) (a(t) - e(t)) F(t)(y)).
template <class T>
constexpr std::vector<T> local_error_coefficients(const tree_set& trees, const std::vector<T>& a) {
  if (a.size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::local_error_coefficients: one coefficient per tree is needed");
  std::vector<T> err = exact_flow_coefficients<T>(trees);
  for (std::size_t t = 0; t < err.size(); ++t) err[t] = a[t] - err[t];
  return err;
}

/// The order of the series a: the largest p <= max_order with a(t) = 1/gamma(t) for |t| <= p.
template <class T>
constexpr int series_order(const tree_set& trees, const std::vector<T>& a) {
  const std::vector<T> err = local_error_coefficients(trees, a);
  for (int n = 1; n <= trees.max_order(); ++n)
    for (int t = trees.first(n); t < trees.first(n + 1); ++t)
      if (err[static_cast<std::size_t>(t)] != T(0)) return n - 1;
  return trees.max_order();
}

}  // namespace geomint::analysis::bseries
