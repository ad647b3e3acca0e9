#pragma once
/// Numerical values of the elementary differentials F(t)(y) of one- and two-colour trees
/// (trees.hpp) for a vector field given as a functor templated on its scalar, with the field's
/// own derivatives by automatic differentiation (ad/multilinear_jet.hpp, ad/dual.hpp), in any
/// scalar T (double, Boost.Multiprecision).
///
/// HLW (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006), section III.1.2
/// (one colour): F(single vertex) = f(y), F([t_1, ..., t_m]) = f^(m)(y)[F(t_1), ..., F(t_m)];
/// section III.2.1 (two colours, y = (y_0, y_1), y_0' = f_0(y), y_1' = f_1(y)): F(t) of a tree
/// whose root has colour c is the block c of f^(m)(y)[F(t_1), ..., F(t_m)], each F(t_i) being
/// zero outside the block of its own root's colour; so the derivative in y_0 or y_1 that the
/// colour of a child asks for is the directional derivative along F(t_i) as a full vector.
///
/// The k-th mixed directional derivative f^(k)(y)[u_1, ..., u_k] is the coefficient of
/// e_1 e_2 ... e_k in f(y + e_1 u_1 + ... + e_k u_k), evaluated once in the multilinear jet
/// scalar jet<T> with k directions (ad/multilinear_jet.hpp): exact, with no truncation error
/// (only the rounding of T), one instantiation of the field for every order, 3^k
/// multiplications per product.
///
/// A field is a type with `static constexpr int dimension` (the length of y),
/// `static constexpr int colour_split` (the length of the colour-0 block y_0; the whole y for
/// one colour) and `template <class S> geomint::vec<S, dimension> operator()(const
/// geomint::vec<S, dimension>& y) const`. Two adapters: natural_field (q' = M^{-1} p,
/// p' = -grad V(q) from a natural system of mechanics/lagrangian.hpp) and hamiltonian_field
/// (y' = J^{-1} grad H(y)).

#include <cstddef>
#include <stdexcept>
#include <string>
#include <algorithm>
#include <type_traits>
#include <vector>

#include "geomint/ad/dual.hpp"
#include "geomint/ad/multilinear_jet.hpp"
#include "geomint/analysis/bseries/trees.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/mechanics/lagrangian.hpp"

namespace geomint::analysis::bseries {

/// The largest derivative order evaluated (a vertex with at most this many children): every
/// tree the generators accept (the rkn class to order 16, the others below). Repeated children
/// share one jet direction (directional_derivative), so the cost of a vertex is
/// prod (m_j + 1)(m_j + 2)/2 over its distinct children of multiplicities m_j, not 3^k.
inline constexpr int max_derivative_order = 15;

namespace detail {
/// grad V(q) of a scalar functor V at q in the scalar S, by one dual level of n directions.
template <int n, class S, class Potential>
vec<S, n> gradient(const Potential& potential, const vec<S, n>& q) {
  using G = dual<S, n>;
  vec<G, n> x;
  for (int i = 0; i < n; ++i) x[i] = G::variable(q[i], i);
  const G v = potential(x);
  vec<S, n> g;
  for (int i = 0; i < n; ++i) g[i] = v.d[static_cast<std::size_t>(i)];
  return g;
}
}  // namespace detail

/// f^(k)(y)[u_1, ..., u_k], k = u.size() <= max_derivative_order (k = 0: f(y)). Equal
/// directions (the same pointer, as repeated subtrees give) are one direction of the jet with
/// their multiplicity as its degree (ad/multilinear_jet.hpp): the coefficient of
/// s_1^(m_1) ... s_J^(m_J) times m_1! ... m_J!.
template <class Field, class T>
vec<T, Field::dimension> directional_derivative(const Field& f, const vec<T, Field::dimension>& y,
                                                const std::vector<const vec<T, Field::dimension>*>& u) {
  constexpr int D = Field::dimension;
  if (u.size() > static_cast<std::size_t>(max_derivative_order))
    throw std::invalid_argument("geomint::analysis::bseries::directional_derivative: derivative order " +
                                std::to_string(u.size()) + " above " + std::to_string(max_derivative_order));
  if (u.empty()) return f.template operator()<T>(y);
  std::vector<const vec<T, D>*> distinct;
  std::vector<int> degrees;
  for (const vec<T, D>* d : u) {
    const auto same = std::find(distinct.begin(), distinct.end(), d);
    if (same == distinct.end()) {
      distinct.push_back(d);
      degrees.push_back(1);
    } else {
      ++degrees[static_cast<std::size_t>(same - distinct.begin())];
    }
  }
  using S = jet<T>;
  vec<S, D> x;
  std::vector<T> directions(distinct.size());
  for (int i = 0; i < D; ++i) {
    for (std::size_t k = 0; k < distinct.size(); ++k) directions[k] = (*distinct[k])[i];
    x[i] = S::variable(y[i], directions, degrees);
  }
  const vec<S, D> fx = f.template operator()<S>(x);
  T multiplicities(1);  // m_1! ... m_J!
  for (int m : degrees)
    for (int j = 2; j <= m; ++j) multiplicities *= T(j);
  std::size_t top = 1;  // the index of s_1^(m_1) ... s_J^(m_J): the last coefficient
  for (int m : degrees) top *= static_cast<std::size_t>(m + 1);
  vec<T, D> out;
  for (int i = 0; i < D; ++i) out[i] = T(fx[i].coefficient(top - 1) * multiplicities);
  return out;
}

/// F(t)(y) for every tree t of `trees` (the whole vector y; for two colours zero outside the
/// block of the root's colour). With `wanted` (one entry per tree, closed under taking
/// subtrees) only the marked trees are evaluated, the others are zero. A tree with a child whose
/// differential is exactly zero is zero (multilinearity) without evaluation.
template <class Field, class T>
std::vector<vec<T, Field::dimension>> elementary_differentials(const tree_set& trees, const Field& f,
                                                               const vec<T, Field::dimension>& y,
                                                               const std::vector<bool>* wanted = nullptr) {
  constexpr int D = Field::dimension;
  static_assert(Field::colour_split >= 1 && Field::colour_split <= D,
                "geomint::analysis::bseries: a field's colour_split is the length of the colour-0 block, 1..dimension");
  if (trees.colours() == 2 && Field::colour_split == D)
    throw std::invalid_argument("geomint::analysis::bseries::elementary_differentials: two-colour trees need a field with two blocks");
  if (wanted && wanted->size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::elementary_differentials: `wanted` needs one entry per tree");
  std::vector<vec<T, D>> F(static_cast<std::size_t>(trees.size()), vec<T, D>::Zero());
  std::vector<bool> zero(static_cast<std::size_t>(trees.size()), true);
  const vec<T, D> fy = f.template operator()<T>(y);
  for (int t = 0; t < trees.size(); ++t) {
    if (wanted && !(*wanted)[static_cast<std::size_t>(t)]) continue;
    const rooted_tree& tree = trees[t];
    std::vector<const vec<T, D>*> u;
    bool vanishes = false;
    for (int s : tree.subtrees) {
      vanishes = vanishes || zero[static_cast<std::size_t>(s)];
      u.push_back(&F[static_cast<std::size_t>(s)]);
    }
    if (vanishes) continue;
    vec<T, D> value = u.empty() ? fy : directional_derivative(f, y, u);
    if (trees.colours() == 2) {  // keep the block of the root's colour
      if (tree.colour == 0) value.tail(D - Field::colour_split).setZero();
      else value.head(Field::colour_split).setZero();
    }
    zero[static_cast<std::size_t>(t)] = value.isZero(0);
    F[static_cast<std::size_t>(t)] = value;
  }
  return F;
}

/// q' = M^{-1} p (colour 0), p' = -grad V(q) (colour 1) for a natural system Sys
/// (`Sys::potential<S>`, `Sys::mass_matrix<S>`: mechanics/lagrangian.hpp), y = (q, p); grad V
/// from the system's `potential_gradient<S>` if it supplies one, else by one dual level of dof
/// directions over S (dual<jet<T>, dof> inside a directional derivative); M^{-1} computed once
/// in T.
template <class Sys, class T>
struct natural_field {
  static constexpr int dof = Sys::dof;
  static constexpr int dimension = 2 * dof;
  static constexpr int colour_split = dof;
  mat<T, dof> inverse_mass = Sys::template mass_matrix<T>().inverse();

  template <class S>
  vec<S, dimension> operator()(const vec<S, dimension>& y) const {
    const vec<S, dof> q = y.head(dof);
    vec<S, dof> grad;
    if constexpr (mechanics::detail::supplies_potential_gradient<Sys, S>)
      grad = Sys::template potential_gradient<S>(q);
    else
      grad = detail::gradient<dof, S>([](const auto& x) { return Sys::template potential<typename std::decay_t<decltype(x)>::Scalar>(x); }, q);
    vec<S, dimension> out;
    for (int i = 0; i < dof; ++i) {
      S v(0);
      for (int j = 0; j < dof; ++j) v += S(inverse_mass(i, j)) * y[dof + j];
      out[i] = v;
      out[dof + i] = -grad[i];
    }
    return out;
  }
};

/// y' = J^{-1} grad H(y), y = (q, p) with n = dimension / 2: q' = H_p, p' = -H_q; H a functor
/// templated on its scalar, `template <class S> S operator()(const geomint::vec<S, 2n>& y) const`.
/// Colour 0 is q, colour 1 is p. grad H from the Hamiltonian's own
/// `template <class S> vec<S, 2n> gradient(const vec<S, 2n>& y) const` if it supplies one, else
/// by one dual level over S.
template <class Hamiltonian, int n>
struct hamiltonian_field {
  static constexpr int dimension = 2 * n;
  static constexpr int colour_split = n;
  Hamiltonian hamiltonian{};

  template <class S>
  vec<S, dimension> operator()(const vec<S, dimension>& y) const {
    vec<S, dimension> g;
    if constexpr (requires { hamiltonian.template gradient<S>(y); })
      g = hamiltonian.template gradient<S>(y);
    else
      g = detail::gradient<dimension, S>(
          [this](const auto& x) { return hamiltonian.template operator()<typename std::decay_t<decltype(x)>::Scalar>(x); }, y);
    vec<S, dimension> out;
    for (int i = 0; i < n; ++i) {
      out[i] = g[n + i];
      out[n + i] = -g[i];
    }
    return out;
  }
};

/// omega(u, v) = u_q . v_p - u_p . v_q on y = (q, p) (the first `n` entries are q). For a
/// Hamiltonian field f = J^{-1} grad H: grad H(y) . v = omega(f(y), v).
template <class T, int D>
T symplectic_pairing(const vec<T, D>& u, const vec<T, D>& v) {
  constexpr int n = D / 2;
  T s(0);
  for (int i = 0; i < n; ++i) s += u[i] * v[n + i] - u[n + i] * v[i];
  return s;
}

}  // namespace geomint::analysis::bseries
