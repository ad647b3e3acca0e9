#pragma once
/// The collocation RKN and Nystrom methods on s given nodes, in a numeric scalar T at T's full
/// precision: the one construction of the numeric coefficients of LPF on a natural system
/// (schemes/lpf.hpp, schemes/gauss_fixed_point.hpp) and of its numeric tableau in the analysis
/// (analysis/numeric_tableau.hpp, lpf_numeric_tableau); on a Lagrangian that is not natural LPF
/// is the collocation Nystrom method on its interior nodes for q'' = F(q, q') composed with the
/// Legendre maps (docs/results/schemes.md, "LPF as a Nystrom method").
///
/// With l_j the Lagrange polynomials on the nodes c_1..c_s (Hairer, Lubich & Wanner 2006,
/// section II.1.4, collocation; docs/references.md):
///   a_ij  = int_0^{c_i} (c_i - u) l_j(u) du = c_i^2 int_0^1 (1 - u) l_j(c_i u) du,
///   bbar_j = int_0^1 (1 - u) l_j(u) du,      b_j = int_0^1 l_j(u) du,
/// and for q'' = F(q, q') also ap_ij = int_0^{c_i} l_j(u) du = c_i int_0^1 l_j(c_i u) du (the
/// collocation Runge-Kutta matrix; Hairer, Norsett & Wanner I, section II.14),
/// each integral by the s-point Gauss-Legendre rule, exact for the integrands of degree s. The
/// Lagrange values are barycentric (core/basis.hpp): no monomial coefficients, no Vandermonde
/// solve, so every entry is good to a few ulps of T for any s up to max_floating_m.

#include <array>
#include <cstddef>

#include "geomint/core/basis.hpp"
#include "geomint/core/quadrature.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

/// The collocation RKN tableau (c, a, bbar, b) on the distinct nodes c (see the top of the file).
template <class T, int S>
rkn<T, S> collocation_rkn(const stage_vector<T, S>& c) {
  const auto rule = gauss_legendre_rule<S, T>();
  rkn<T, S> t;
  t.c = c;
  t.b.fill(T(0));
  t.bbar.fill(T(0));
  for (std::size_t r = 0; r < static_cast<std::size_t>(S); ++r) {
    const T& u = rule.points[r];
    const T w = rule.weights[r];
    const auto l = lagrange_values_at(c, u);
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) {
      t.b[j] += w * l[j];
      t.bbar[j] += w * (T(1) - u) * l[j];
    }
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    const T& ci = c[i];
    stage_vector<T, S> sum;
    sum.fill(T(0));
    for (std::size_t r = 0; r < static_cast<std::size_t>(S); ++r) {
      const T& u = rule.points[r];
      const auto l = lagrange_values_at(c, T(ci * u));
      const T w = rule.weights[r] * (T(1) - u);
      for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) sum[j] += w * l[j];
    }
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) t.a[i][j] = ci * ci * sum[j];
  }
  return t;
}

/// The collocation Nystrom tableau (c, a, ap, bbar, b) on the distinct nodes c: collocation_rkn's
/// (c, a, bbar, b) and the collocation Runge-Kutta matrix ap (see the top of the file).
template <class T, int S>
nystrom<T, S> collocation_nystrom(const stage_vector<T, S>& c) {
  const rkn<T, S> positions = collocation_rkn<T, S>(c);
  const auto rule = gauss_legendre_rule<S, T>();
  nystrom<T, S> t{positions.c, positions.a, {}, positions.bbar, positions.b};
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    t.ap[i].fill(T(0));
    for (std::size_t r = 0; r < static_cast<std::size_t>(S); ++r) {
      const auto l = lagrange_values_at(c, T(c[i] * rule.points[r]));
      for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) t.ap[i][j] += c[i] * rule.weights[r] * l[j];
    }
  }
  return t;
}

/// The Nystrom collocation method at the s Gauss-Legendre points on [0, 1]: LPF of degree s + 1
/// on Gauss-interior nodes on a natural system, order 2s. (Not the Gauss Runge-Kutta method
/// applied to q'' = f, whose RKN matrix is A^2: the same nodes and weights, another a.)
template <class T, int S>
rkn<T, S> gauss_collocation_rkn() {
  return collocation_rkn<T, S>(gauss_legendre_rule<S, T>().points);
}

}  // namespace geomint::methods
