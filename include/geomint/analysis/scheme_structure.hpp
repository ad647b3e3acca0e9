#pragma once
/// Exact symplecticity and symmetry of an RKN tableau (analysis/rkn_tableau.hpp).
///
/// Symplecticity (Suris 1989; Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed.,
/// Theorem VI.4.10): an RKN method is symplectic for every q'' = -grad V(q) iff
///   bbar_i = b_i (1 - c_i)                                   (all i),
///   b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji)                (all i, j).
/// In the stage algebra both are forms: the linear form d1(v) = bbar(v) - b((1 - x) v) and the
/// antisymmetric bilinear form
///   d2(u, v) = b(u) bbar(v) - b(u A v) - b(v) bbar(u) + b(v A u)
/// (u A v: product of u and A v), which in the stage-values basis are exactly the left-hand
/// minus right-hand sides above. The defect matrices reported are these forms on the basis of
/// the tableau (monomials 1..x^{s-1} modulo N, or stage values); they vanish iff the
/// conditions hold (the change of basis is invertible).
///
/// Symmetry: the adjoint of (c, a, bbar, b) is (1 - c, a*, b - bbar, b) with
/// a*_ij = (1 - c_i) b_j - bbar_j + a_ij (one step backwards with -tau, solved for the new
/// point). The method is symmetric iff the adjoint equals the method up to the permutation of
/// stages c_i -> 1 - c_i (HLW, section V.2). In the monomial basis that permutation is
/// P: V(x) -> V(1 - x) mod N, which exists iff N(1 - x) = (-1)^s N(x); the defects are
/// A* - P A P, bbar* - bbar P and b - b P.

#include "geomint/analysis/rkn_tableau.hpp"

namespace geomint {

/// Exact symplecticity verdict with its defects. Structural.
struct symplecticity_result {
  bool symplectic = false;
  bool first_condition = false;   ///< bbar_i = b_i (1 - c_i)
  bool second_condition = false;  ///< b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji)
  exact_number first_defect[max_exact_stages];                     ///< d1 on the basis
  exact_number second_defect[max_exact_stages][max_exact_stages];  ///< d2 on the basis
  friend constexpr bool operator==(const symplecticity_result&, const symplecticity_result&) = default;
};

/// Exact symmetry verdict with its defects. Structural.
struct symmetry_result {
  bool symmetric = false;
  bool nodes_symmetric = false;  ///< the stage permutation c -> 1 - c exists
  exact_number a_defect[max_exact_stages][max_exact_stages];  ///< A* - P A P
  exact_number bbar_defect[max_exact_stages];                 ///< bbar* - bbar P
  exact_number b_defect[max_exact_stages];                    ///< b - b P
  friend constexpr bool operator==(const symmetry_result&, const symmetry_result&) = default;
};

/// Both forms need b of a product e_k * w only. In the values basis that is b_k w_k; in the
/// monomial basis it is sum_j w_j b(x^(k+j) mod N), so the quadrature values b(x^n mod N),
/// n <= 2s - 1, are computed once (O(s^3) in all, instead of one product modulo N per pair).
constexpr symplecticity_result symplecticity(const exact_rkn_tableau& t) {
  symplecticity_result r;
  const int s = t.stages;
  exact_number moment[2 * max_exact_stages];  // b(x^n mod N), monomial basis only
  if (t.basis == stage_basis::monomial) {
    stage_vector power = t.one;
    for (int n = 0; n < 2 * s; ++n) {
      moment[n] = t.apply_b(power);
      if (n + 1 < 2 * s) power = t.multiply_by_nodes(power);
    }
  }
  auto b_of_product = [&](int k, auto&& w_entry) {  // b(e_k * w), w_entry(j) = w_j
    if (t.basis == stage_basis::values) return t.b[k] * w_entry(k);
    exact_number sum;
    for (int j = 0; j < s; ++j) {
      const exact_number w = w_entry(j);
      if (!w.num.is_zero() && !moment[k + j].num.is_zero()) sum = sum + w * moment[k + j];
    }
    return sum;
  };
  r.first_condition = true;
  r.second_condition = true;
  for (int k = 0; k < s; ++k) {
    // d1(e_k) = bbar(e_k) - b(e_k) + b(e_k * x)
    r.first_defect[k] = t.bbar[k] - t.b[k] + b_of_product(k, [&](int j) { return t.c[j]; });
    if (!r.first_defect[k].num.is_zero()) r.first_condition = false;
  }
  // d2(e_k, e_l) = b_k bbar_l - b(e_k * A e_l) - b_l bbar_k + b(e_l * A e_k); (A e_l)_j = a_jl.
  for (int k = 0; k < s; ++k)
    for (int l = k + 1; l < s; ++l) {
      const exact_number d = t.b[k] * t.bbar[l] - b_of_product(k, [&](int j) { return t.a[j][l]; }) - t.b[l] * t.bbar[k] +
                             b_of_product(l, [&](int j) { return t.a[j][k]; });
      r.second_defect[k][l] = d;
      r.second_defect[l][k] = -d;  // antisymmetric; the diagonal is 0
      if (!d.num.is_zero()) r.second_condition = false;
    }
  r.symplectic = r.first_condition && r.second_condition;
  return r;
}

namespace analysis::detail {
/// The stage permutation c -> 1 - c as a matrix on the tableau's basis; false if none exists.
constexpr bool reflection_matrix(const exact_rkn_tableau& t, exact_number (&P)[max_exact_stages][max_exact_stages]) {
  const int s = t.stages;
  if (t.basis == stage_basis::values) {
    bool used[max_exact_stages]{};
    for (int i = 0; i < s; ++i) {
      int match = -1;
      for (int j = 0; j < s && match < 0; ++j)
        if (!used[j] && t.c[i] + t.c[j] == exact_number(1)) match = j;
      if (match < 0) return false;
      used[match] = true;
      P[i][match] = exact_number(1);  // (P v)_i = v_match
    }
    return true;
  }
  // N(1 - x) = (-1)^s N(x)?  N(1 - x) = sum_k n_k (1 - x)^k.
  exact_number reflected[max_exact_stages + 1];
  for (int k = 0; k <= s; ++k) {
    exact_number binom(1);  // C(k, j) (-1)^j
    for (int j = 0; j <= k; ++j) {
      reflected[j] = reflected[j] + t.node_polynomial[k] * binom;
      binom = binom * exact_number(-(k - j)) / exact_number(j + 1);
    }
  }
  for (int k = 0; k <= s; ++k) {
    const exact_number expected = (s % 2 == 0) ? t.node_polynomial[k] : -t.node_polynomial[k];
    if (!(reflected[k] == expected)) return false;
  }
  // Column l: (1 - x)^l mod N (degree l < s, no reduction needed).
  for (int l = 0; l < s; ++l) {
    exact_number binom(1);
    for (int j = 0; j <= l; ++j) {
      P[j][l] = binom;
      binom = binom * exact_number(-(l - j)) / exact_number(j + 1);
    }
  }
  return true;
}
}  // namespace analysis::detail

constexpr symmetry_result symmetry(const exact_rkn_tableau& t) {
  symmetry_result r;
  const int s = t.stages;
  exact_number P[max_exact_stages][max_exact_stages];
  r.nodes_symmetric = analysis::detail::reflection_matrix(t, P);
  if (!r.nodes_symmetric) return r;
  auto matrix_times = [s](const exact_number (&X)[max_exact_stages][max_exact_stages],
                          const exact_number (&Y)[max_exact_stages][max_exact_stages],
                          exact_number (&Z)[max_exact_stages][max_exact_stages]) {
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        exact_number sum;
        for (int k = 0; k < s; ++k)
          if (!X[i][k].num.is_zero() && !Y[k][j].num.is_zero()) sum = sum + X[i][k] * Y[k][j];
        Z[i][j] = sum;
      }
  };
  exact_number AP[max_exact_stages][max_exact_stages], PAP[max_exact_stages][max_exact_stages];
  matrix_times(t.a, P, AP);
  matrix_times(P, AP, PAP);
  r.symmetric = true;
  for (int l = 0; l < s; ++l) {
    // A* e_l = (1 - x) b(e_l) - bbar(e_l) 1 + A e_l.
    const stage_vector e = t.unit(l);
    const stage_vector Ae = t.apply_a(e);
    const stage_vector xe = t.c;
    for (int i = 0; i < s; ++i) {
      const exact_number star = (t.one[i] - xe[i]) * t.b[l] - t.bbar[l] * t.one[i] + Ae[i];
      r.a_defect[i][l] = star - PAP[i][l];
      if (!r.a_defect[i][l].num.is_zero()) r.symmetric = false;
    }
    // Functionals on e_l: bbar*(e_l) = b_l - bbar_l against bbar(P e_l); b against b(P e_l).
    exact_number bbar_p, b_p;
    for (int k = 0; k < s; ++k) {
      bbar_p = bbar_p + t.bbar[k] * P[k][l];
      b_p = b_p + t.b[k] * P[k][l];
    }
    r.bbar_defect[l] = t.b[l] - t.bbar[l] - bbar_p;
    r.b_defect[l] = t.b[l] - b_p;
    if (!r.bbar_defect[l].num.is_zero() || !r.b_defect[l].num.is_zero()) r.symmetric = false;
  }
  return r;
}

}  // namespace geomint
