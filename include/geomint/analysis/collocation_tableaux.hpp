#pragma once
/// Builders of the exact RKN tableaux of collocation type (analysis/stage_algebra.hpp, monomial
/// basis on the roots of the node polynomial N): LPF of degree m on a node family (the
/// collocation RKN method on the m - 1 interior nodes; Kong & Yang 2020, eq. 10-12), the
/// Galerkin VI (the Gauss collocation RK method as an RKN method; Hairer, Lubich & Wanner 2006,
/// Theorem VI.6.4), and collocation on a user's rational nodes or node polynomial.

#include <array>
#include <cstddef>
#include <stdexcept>
#include <type_traits>

#include "geomint/analysis/node_polynomial.hpp"
#include "geomint/analysis/stage_algebra.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/core/rational.hpp"

namespace geomint {

namespace analysis::detail {

/// The collocation tableau (LPF interior nodes) on the roots of a monic N of degree s.
constexpr exact_rkn_tableau collocation_tableau(const exact_number* monic_n, int s) {
  exact_rkn_tableau t;
  t.stages = s;
  t.basis = stage_basis::monomial;
  for (int k = 0; k <= s; ++k) t.node_polynomial[k] = monic_n[k];
  for (int k = 0; k < s; ++k) {
    // x^k -> int_0^x (x - u) u^k du = x^{k+2} / ((k+1)(k+2)), reduced modulo N.
    exact_number p[2 * max_exact_stages + 2];
    p[k + 2] = analysis::detail::fraction(1, (k + 1) * (k + 2));
    t.reduce(p, k + 2);
    for (int i = 0; i < s; ++i) t.a[i][k] = p[i];
    t.b[k] = analysis::detail::fraction(1, k + 1);
    t.bbar[k] = analysis::detail::fraction(1, (k + 1) * (k + 2));
  }
  t.one[0] = exact_number(1);
  if (s == 1) {
    t.c[0] = -monic_n[0];  // x mod (x + n0)
  } else {
    t.c[1] = exact_number(1);
  }
  return t;
}

/// The Gauss collocation RK method on the roots of N (the Galerkin VI), as an RKN tableau:
/// A_rk: V -> int_0^x V mod N; a = A_rk^2, bbar = b A_rk, b(V) = int_0^1 V.
constexpr exact_rkn_tableau galerkin_tableau(const exact_number* monic_n, int s) {
  exact_rkn_tableau t;
  t.stages = s;
  t.basis = stage_basis::monomial;
  for (int k = 0; k <= s; ++k) t.node_polynomial[k] = monic_n[k];
  exact_number rk[max_exact_stages][max_exact_stages];
  for (int k = 0; k < s; ++k) {
    exact_number p[2 * max_exact_stages + 2];
    p[k + 1] = analysis::detail::fraction(1, k + 1);
    t.reduce(p, k + 1);
    for (int i = 0; i < s; ++i) rk[i][k] = p[i];
    t.b[k] = analysis::detail::fraction(1, k + 1);
  }
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) {
      exact_number sum;
      for (int k = 0; k < s; ++k) sum = sum + rk[i][k] * rk[k][j];
      t.a[i][j] = sum;
    }
  for (int j = 0; j < s; ++j) {
    exact_number sum;
    for (int k = 0; k < s; ++k) sum = sum + t.b[k] * rk[k][j];
    t.bbar[j] = sum;
  }
  t.one[0] = exact_number(1);
  if (s == 1) t.c[0] = -monic_n[0];
  else t.c[1] = exact_number(1);
  return t;
}

}  // namespace analysis::detail

/// The exact RKN tableau of LPF of degree m on a node family (collocation on the interior nodes).
template <int M, class Family = equispaced>
constexpr exact_rkn_tableau lpf_tableau() {
  static_assert(node_family<Family>,
                "geomint::lpf_tableau: Family must be a node family (geomint::node_family, core/nodes.hpp)");
  static_assert(M >= 2 && M <= max_exact_m, "geomint::lpf_tableau: m must be in 2..8");
  if constexpr (node_family<Family> && M >= 2 && M <= max_exact_m) {
    const auto n = analysis::detail::interior_node_polynomial<Family, M>();
    return analysis::detail::collocation_tableau(n.c, M - 1);
  } else {
    return {};
  }
}

/// The Galerkin VI of degree m (m-point Gauss quadrature) as an exact RKN tableau.
template <int M>
constexpr exact_rkn_tableau galerkin_tableau() {
  static_assert(M >= 1 && M <= max_exact_stages, "geomint::galerkin_tableau: m must be in 1..8");
  if constexpr (M >= 1 && M <= max_exact_stages) {
    const auto n = analysis::detail::monic_shifted_orthogonal(shifted_orthogonal_kind::legendre, M);
    return analysis::detail::galerkin_tableau(n.c, M);
  } else {
    return {};
  }
}

/// Collocation (LPF-type) tableau on user data: the s distinct rational interior nodes in [0, 1].
template <class NodeEntry, std::size_t S>
constexpr exact_rkn_tableau collocation_tableau_from_nodes(const std::array<NodeEntry, S>& nodes) {
  static_assert(std::is_same_v<NodeEntry, rational>,
                "geomint::collocation_tableau_from_nodes: the nodes must be exact geomint::rational (floating-point "
                "nodes are not exact; for irrational nodes pass their node polynomial)");
  static_assert(S >= 1 && S <= max_exact_stages, "geomint::collocation_tableau_from_nodes: 1..8 nodes");
  exact_number roots[S];
  for (std::size_t i = 0; i < S; ++i) {
    if (nodes[i] < rational(0) || nodes[i] > rational(1))
      throw std::domain_error("geomint::collocation_tableau_from_nodes: the nodes must lie in [0, 1]");
    for (std::size_t j = 0; j < i; ++j)
      if (nodes[i] == nodes[j]) throw std::domain_error("geomint::collocation_tableau_from_nodes: the nodes must be distinct");
    roots[i] = exact_number(nodes[i]);
  }
  const auto p = analysis::detail::monic_from_roots(roots, static_cast<int>(S));
  return analysis::detail::collocation_tableau(p.c, static_cast<int>(S));
}
/// The same with the number of nodes given, for braced lists: `collocation_tableau_from_nodes<3>({...})`.
template <int S>
constexpr exact_rkn_tableau collocation_tableau_from_nodes(const std::array<rational, S>& nodes) {
  return collocation_tableau_from_nodes<rational, S>(nodes);
}

/// Collocation tableau on the roots of a node polynomial with rational coefficients (ascending:
/// degree + 1 coefficients, degree 1..8). Checked: the leading coefficient is nonzero, the roots
/// are simple (the Euclidean remainder sequence of N and N' ends in a nonzero constant) and all
/// real in [0, 1] (Sturm's theorem, exactly).
template <class CoefficientEntry, std::size_t K>
constexpr exact_rkn_tableau collocation_tableau_from_polynomial(const std::array<CoefficientEntry, K>& coefficients) {
  static_assert(std::is_same_v<CoefficientEntry, rational>,
                "geomint::collocation_tableau_from_polynomial: the coefficients must be exact geomint::rational");
  static_assert(K >= 2 && K <= max_exact_stages + 1,
                "geomint::collocation_tableau_from_polynomial: the node polynomial must have degree 1..8 (pass degree + 1 "
                "coefficients, ascending powers)");
  constexpr int S = static_cast<int>(K) - 1;
  analysis::detail::exact_poly_buffer p;
  for (int k = 0; k <= S; ++k) p.c[k] = exact_number(coefficients[static_cast<std::size_t>(k)]);
  if (p.c[S].num.is_zero())
    throw std::domain_error("geomint::collocation_tableau_from_polynomial: the leading coefficient is zero (the degree is "
                            "the number of coefficients minus one)");
  analysis::detail::make_monic(p.c, S);
  if (!analysis::detail::has_simple_roots(p.c, S))
    throw std::domain_error("geomint::collocation_tableau_from_polynomial: the node polynomial has a multiple root");
  if (analysis::detail::roots_in_unit_interval(p.c, S) != S)
    throw std::domain_error("geomint::collocation_tableau_from_polynomial: the roots must be real and lie in [0, 1]");
  return analysis::detail::collocation_tableau(p.c, S);
}
/// The same with the degree given, for braced lists: `collocation_tableau_from_polynomial<2>({...})`.
template <int S>
constexpr exact_rkn_tableau collocation_tableau_from_polynomial(const std::array<rational, S + 1>& coefficients) {
  return collocation_tableau_from_polynomial<rational, S + 1>(coefficients);
}

}  // namespace geomint
