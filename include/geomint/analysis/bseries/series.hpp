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
/// The coefficient type T is a template parameter (exact: boost::multiprecision::cpp_rational;
/// later an algebraic number field); only +, *, / and construction from int are used.

#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/analysis/bseries/trees.hpp"

namespace geomint::analysis::bseries {

/// A Runge-Kutta tableau (c, A, b) with s stages: A is s x s (row i holds a_i1..a_is).
template <class T>
struct rk_tableau {
  std::vector<T> c;
  std::vector<std::vector<T>> A;
  std::vector<T> b;
  std::size_t stages() const { return b.size(); }
};

/// A partitioned Runge-Kutta pair: `first` integrates the colour-0 component y, `second` the
/// colour-1 component z; both have the same number of stages.
template <class T>
struct prk_tableau {
  rk_tableau<T> first;
  rk_tableau<T> second;
};

namespace detail {
template <class T>
void check_tableau(const rk_tableau<T>& m, std::size_t stages, const char* which) {
  const std::string name = std::string("geomint::analysis::bseries: the ") + which + " tableau ";
  if (m.b.empty()) throw std::invalid_argument(name + "has no stages (b is empty)");
  if (m.b.size() != stages) throw std::invalid_argument(name + "has a different number of stages than the other");
  if (m.c.size() != stages) throw std::invalid_argument(name + "has c of a different length than b");
  if (m.A.size() != stages) throw std::invalid_argument(name + "has A with a number of rows different from the length of b");
  for (const auto& row : m.A)
    if (row.size() != stages) throw std::invalid_argument(name + "has a row of A of a length different from the length of b");
}

/// Elementary weights with one tableau per colour (weights[colour]).
template <class T>
std::vector<T> elementary_weights(const tree_set& trees, const rk_tableau<T>* const* weights) {
  const std::size_t s = weights[0]->stages();
  const auto n = static_cast<std::size_t>(trees.size());
  // g[t][i] = g_i(t); fed[t][i] = sum_j a^{colour of t}_ij g_j(t), the factor t contributes
  // as a subtree.
  std::vector<std::vector<T>> g(n), fed(n);
  std::vector<T> phi(n);
  for (std::size_t t = 0; t < n; ++t) {
    const rooted_tree& tree = trees[static_cast<int>(t)];
    g[t].assign(s, T(1));
    for (int u : tree.subtrees)
      for (std::size_t i = 0; i < s; ++i) g[t][i] *= fed[static_cast<std::size_t>(u)][i];
    const rk_tableau<T>& own = *weights[tree.colour];
    fed[t].assign(s, T(0));
    phi[t] = T(0);
    for (std::size_t i = 0; i < s; ++i) {
      for (std::size_t j = 0; j < s; ++j) fed[t][i] += own.A[i][j] * g[t][j];
      phi[t] += own.b[i] * g[t][i];
    }
  }
  return phi;
}
}  // namespace detail

/// a(t) = Phi(t) for every tree of a one-colour tree_set: the B-series of one step of the
/// Runge-Kutta method (a(empty) = 1).
template <class T>
std::vector<T> elementary_weights(const tree_set& trees, const rk_tableau<T>& method) {
  if (trees.colours() != 1)
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: a Runge-Kutta tableau needs one-colour trees");
  detail::check_tableau(method, method.stages(), "Runge-Kutta");
  const rk_tableau<T>* weights[1] = {&method};
  return detail::elementary_weights(trees, weights);
}

/// a(t) = Phi(t) for every tree of a two-colour tree_set: the P-series of one step of the
/// partitioned Runge-Kutta pair (a(empty_y) = a(empty_z) = 1).
template <class T>
std::vector<T> elementary_weights(const tree_set& trees, const prk_tableau<T>& method) {
  if (trees.colours() != 2)
    throw std::invalid_argument("geomint::analysis::bseries::elementary_weights: a partitioned pair needs two-colour trees");
  detail::check_tableau(method.first, method.first.stages(), "first (colour 0)");
  detail::check_tableau(method.second, method.first.stages(), "second (colour 1)");
  const rk_tableau<T>* weights[2] = {&method.first, &method.second};
  return detail::elementary_weights(trees, weights);
}

/// e(t) = 1/gamma(t): the B-/P-series of the exact flow (HLW section III.1.2).
template <class T>
std::vector<T> exact_flow_coefficients(const tree_set& trees) {
  std::vector<T> e;
  e.reserve(static_cast<std::size_t>(trees.size()));
  for (const rooted_tree& t : trees.trees()) e.push_back(T(1) / T(t.gamma));
  return e;
}

/// a(t) - 1/gamma(t): the local error of one step per tree (the error term of tree t is
/// h^|t| / sigma(t) (a(t) - e(t)) F(t)(y)).
template <class T>
std::vector<T> local_error_coefficients(const tree_set& trees, const std::vector<T>& a) {
  if (a.size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::local_error_coefficients: one coefficient per tree is needed");
  std::vector<T> err = exact_flow_coefficients<T>(trees);
  for (std::size_t t = 0; t < err.size(); ++t) err[t] = a[t] - err[t];
  return err;
}

/// The order of the series a: the largest p <= max_order with a(t) = 1/gamma(t) for |t| <= p.
template <class T>
int series_order(const tree_set& trees, const std::vector<T>& a) {
  const std::vector<T> err = local_error_coefficients(trees, a);
  for (int n = 1; n <= trees.max_order(); ++n)
    for (int t = trees.first(n); t < trees.first(n + 1); ++t)
      if (err[static_cast<std::size_t>(t)] != T(0)) return n - 1;
  return trees.max_order();
}

}  // namespace geomint::analysis::bseries
