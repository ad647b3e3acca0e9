#pragma once
/// Node polynomials N of the exact RKN tableaux (analysis/stage_algebra.hpp), in exact numbers:
/// the monic N of each node family's interior nodes (from the family's defining polynomial,
/// core/orthogonal_polynomials.hpp), and the exact checks on a user's N: simple roots
/// (Euclid) and the number of roots in [0, 1] (Sturm's theorem).

#include <cstddef>
#include <stdexcept>
#include <type_traits>

#include "geomint/analysis/stage_algebra.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/core/orthogonal_polynomials.hpp"

namespace geomint::analysis::detail {

/// Polynomial coefficients (ascending) of up to degree 2 max_exact_stages + 2.
struct exact_poly_buffer {
  static constexpr int capacity = 2 * max_exact_stages + 3;
  exact_number c[capacity];  // default-initialised: see stage_vector
};

/// Monic version of a polynomial with rational coefficients (degree = the last nonzero one).
constexpr int make_monic(exact_number* p, int top) {
  while (top >= 0 && p[top].num.is_zero()) --top;
  if (top < 1) throw std::domain_error("geomint: a node polynomial must have degree >= 1");
  const exact_number lead = p[top];
  for (int k = 0; k <= top; ++k) p[k] = p[k] / lead;
  return top;
}

/// The monic polynomial `kind` of index n (degree n, or n - 1 for the Legendre derivative),
/// from core/orthogonal_polynomials.hpp.
constexpr exact_poly_buffer monic_shifted_orthogonal(shifted_orthogonal_kind kind, int n) {
  const auto q = shifted_orthogonal_polynomial<exact_number, max_exact_stages + 3>(kind, n);
  const int degree = kind == shifted_orthogonal_kind::legendre_derivative ? n - 1 : n;
  exact_poly_buffer p;
  for (int k = 0; k <= degree; ++k) p.c[k] = q[static_cast<std::size_t>(k)];
  make_monic(p.c, degree);
  return p;
}

/// The monic polynomial prod (x - r_i) on the s given roots.
constexpr exact_poly_buffer monic_from_roots(const exact_number* roots, int s) {
  exact_poly_buffer p;
  p.c[0] = exact_number(1);
  for (int i = 0; i < s; ++i)
    for (int k = i + 1; k >= 0; --k) p.c[k] = (k >= 1 ? p.c[k - 1] : exact_number(0)) - roots[i] * p.c[k];
  return p;
}

/// The monic polynomial whose roots are the m - 1 interior nodes of a family (its
/// interior_polynomial, core/nodes.hpp).
template <class Family, int M>
constexpr exact_poly_buffer interior_node_polynomial() {
  const auto q = Family::template interior_polynomial<exact_number, max_exact_stages + 3>(M);
  exact_poly_buffer p;
  for (int k = 0; k < M; ++k) p.c[k] = q[static_cast<std::size_t>(k)];
  make_monic(p.c, M - 1);
  return p;
}

/// Whether the monic p of degree s >= 1 has simple roots: the Euclidean remainder sequence of p
/// and p' ends in a nonzero constant.
constexpr bool has_simple_roots(const exact_number* p, int s) {
  exact_number u[max_exact_stages + 1], w[max_exact_stages + 1];
  int du = s, dw = s - 1;
  for (int k = 0; k <= s; ++k) u[k] = p[k];
  for (int k = 1; k <= s; ++k) w[k - 1] = p[k] * exact_number(k);
  while (dw >= 1) {
    while (du >= dw) {
      const exact_number f = u[du] / w[dw];
      for (int j = 0; j <= dw; ++j) u[du - dw + j] = u[du - dw + j] - f * w[j];
      --du;
      while (du >= 0 && u[du].num.is_zero()) --du;
    }
    if (du < 0) return false;
    for (int k = 0; k <= max_exact_stages; ++k) {
      const exact_number t = u[k];
      u[k] = w[k];
      w[k] = t;
    }
    const int t = du;
    du = dw;
    dw = t;
  }
  return true;
}

/// Sign (-1, 0, 1) of the polynomial p (ascending, degree deg) at x = 0 and x = 1.
constexpr int sign_at(const exact_number* p, int deg, bool at_one) {
  if (!at_one) return p[0].sign();
  exact_number sum;
  for (int k = 0; k <= deg; ++k) sum = sum + p[k];
  return sum.sign();
}

/// Number of distinct real roots in (0, 1] of a squarefree p (degree deg >= 1) with p(0) != 0,
/// by Sturm's theorem: V(0) - V(1), V the sign changes of the Sturm sequence p, p', -rem, ...
constexpr int sturm_roots_in_half_open_unit_interval(const exact_number* p, int deg) {
  exact_number chain[max_exact_stages + 1][max_exact_stages + 1];
  int degree[max_exact_stages + 1]{};
  for (int k = 0; k <= deg; ++k) chain[0][k] = p[k];
  degree[0] = deg;
  for (int k = 1; k <= deg; ++k) chain[1][k - 1] = p[k] * exact_number(k);
  degree[1] = deg - 1;
  int length = 2;
  while (degree[length - 1] > 0) {
    // chain[length] = -(chain[length - 2] mod chain[length - 1])
    exact_number r[max_exact_stages + 1];
    const int dr0 = degree[length - 2], dd = degree[length - 1];
    for (int k = 0; k <= dr0; ++k) r[k] = chain[length - 2][k];
    int dr = dr0;
    while (dr >= dd && dr >= 0) {
      const exact_number f = r[dr] / chain[length - 1][dd];
      for (int j = 0; j <= dd; ++j) r[dr - dd + j] = r[dr - dd + j] - f * chain[length - 1][j];
      --dr;
      while (dr >= 0 && r[dr].num.is_zero()) --dr;
    }
    if (dr < 0) throw std::domain_error("geomint: the node polynomial has a multiple root");
    for (int k = 0; k <= dr; ++k) chain[length][k] = -r[k];
    degree[length] = dr;
    ++length;
  }
  auto changes = [&](bool at_one) {
    int count = 0, last = 0;
    for (int i = 0; i < length; ++i) {
      const int sg = sign_at(chain[i], degree[i], at_one);
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++count;
      last = sg;
    }
    return count;
  };
  return changes(false) - changes(true);
}

/// Number of distinct roots of a squarefree p (degree deg >= 1) in the closed interval [0, 1].
constexpr int roots_in_unit_interval(const exact_number* p, int deg) {
  if (!p[0].num.is_zero()) return sturm_roots_in_half_open_unit_interval(p, deg);
  if (deg == 1) return 1;  // p = c x
  // x = 0 is a simple root: count it and the roots of p / x in (0, 1].
  return 1 + sturm_roots_in_half_open_unit_interval(p + 1, deg - 1);
}

}  // namespace geomint::analysis::detail
