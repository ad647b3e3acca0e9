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
  constexpr symplecticity_result() {  // every element assigned explicitly: see stage_vector
    for (int i = 0; i < max_exact_stages; ++i) {
      first_defect[i] = exact_number(0);
      for (int j = 0; j < max_exact_stages; ++j) second_defect[i][j] = exact_number(0);
    }
  }
  friend constexpr bool operator==(const symplecticity_result&, const symplecticity_result&) = default;
};

/// Exact symmetry verdict with its defects. Structural.
struct symmetry_result {
  bool symmetric = false;
  bool nodes_symmetric = false;  ///< the stage permutation c -> 1 - c exists
  exact_number a_defect[max_exact_stages][max_exact_stages];  ///< A* - P A P
  exact_number bbar_defect[max_exact_stages];                 ///< bbar* - bbar P
  exact_number b_defect[max_exact_stages];                    ///< b - b P
  constexpr symmetry_result() {  // every element assigned explicitly: see stage_vector
    for (int i = 0; i < max_exact_stages; ++i) {
      bbar_defect[i] = exact_number(0);
      b_defect[i] = exact_number(0);
      for (int j = 0; j < max_exact_stages; ++j) a_defect[i][j] = exact_number(0);
    }
  }
  friend constexpr bool operator==(const symmetry_result&, const symmetry_result&) = default;
};

constexpr symplecticity_result symplecticity(const exact_rkn_tableau& t) {
  symplecticity_result r;
  const int s = t.stages;
  r.first_condition = true;
  r.second_condition = true;
  for (int k = 0; k < s; ++k) {
    const stage_vector e = t.unit(k);
    stage_vector one_minus_x_e = e;
    const stage_vector xe = t.multiply(t.c, e);
    for (int i = 0; i < s; ++i) one_minus_x_e[i] = e[i] - xe[i];
    r.first_defect[k] = t.apply_bbar(e) - t.apply_b(one_minus_x_e);
    if (!r.first_defect[k].num.is_zero()) r.first_condition = false;
  }
  for (int k = 0; k < s; ++k)
    for (int l = 0; l < s; ++l) {
      const stage_vector u = t.unit(k), v = t.unit(l);
      const exact_number d = t.apply_b(u) * t.apply_bbar(v) - t.apply_b(t.multiply(u, t.apply_a(v))) -
                             t.apply_b(v) * t.apply_bbar(u) + t.apply_b(t.multiply(v, t.apply_a(u)));
      r.second_defect[k][l] = d;
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
