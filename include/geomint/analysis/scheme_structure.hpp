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
/// Symmetry: the adjoint Phi*_tau = Phi_{-tau}^{-1} (HLW, section II.3) of (c, a, bbar, b) is
/// (1 - c, a*, b - bbar, b) with a*_ij = (1 - c_i) b_j - bbar_j + a_ij: from (q1, p1) one step
/// with -tau gives p = p1 - tau b^T f, q = q1 - tau p1 + tau^2 bbar^T f and the stages
/// Q_i = q1 - c_i tau p1 + tau^2 a_i^T f; solved for (q1, p1) that is p1 = p + tau b^T f,
/// q1 = q + tau p + tau^2 (b - bbar)^T f, Q_i = q + (1 - c_i) tau p + tau^2 a*_i^T f. The method
/// is symmetric iff its adjoint is the method with the stages permuted (HLW, section V.2; for RK,
/// Theorem V.2.3 with sigma(i) = s + 1 - i): some permutation sigma with
///   c_sigma(i) = 1 - c_i,   a_sigma(i)sigma(j) = a*_ij,   bbar_sigma(j) = b_j - bbar_j,   b_sigma(j) = b_j.
/// Stage values (explicit tableaux): sigma is searched among all permutations (backtracking over
/// the stages, the conditions on the stages assigned so far pruning), so a symmetric method whose
/// adjoint swaps two stages with equal nodes (a composition Phi*_{tau/2} o Phi_{tau/2}) is found.
/// Monomial basis: the nodes are the distinct roots of N, so sigma is the reflection
/// P: V(x) -> V(1 - x) mod N, which exists iff N(1 - x) = (-1)^s N(x). The defects are
/// A* - P A P^{-1}, bbar* - bbar P^{-1} and b - b P^{-1} for sigma (for stage values without a
/// permutation satisfying everything: for the first one matching the nodes).

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
  bool nodes_symmetric = false;  ///< a stage permutation sigma with c_sigma(i) = 1 - c_i exists
  int permutation[max_exact_stages]{};  ///< sigma (stage values; the reflection for the monomial basis: unused)
  exact_number a_defect[max_exact_stages][max_exact_stages];  ///< A* - P A P^{-1}
  exact_number bbar_defect[max_exact_stages];                 ///< bbar* - bbar P^{-1}
  exact_number b_defect[max_exact_stages];                    ///< b - b P^{-1}
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
/// The adjoint's a*_ij = (1 - c_i) b_j - bbar_j + a_ij (stage values).
constexpr exact_number adjoint_a(const exact_rkn_tableau& t, int i, int j) {
  return (exact_number(1) - t.c[i]) * t.b[j] - t.bbar[j] + t.a[i][j];
}

/// Extends sigma(0..i-1) to a permutation with the adjoint conditions (backtracking).
constexpr bool extend_symmetry_permutation(const exact_rkn_tableau& t, int i, int* sigma, bool* used, bool nodes_only) {
  const int s = t.stages;
  if (i == s) return true;
  for (int k = 0; k < s; ++k) {
    if (used[k] || !(t.c[k] == exact_number(1) - t.c[i])) continue;
    bool ok = true;
    if (!nodes_only) {
      ok = t.b[k] == t.b[i] && t.bbar[k] == t.b[i] - t.bbar[i] && t.a[k][k] == adjoint_a(t, i, i);
      for (int j = 0; j < i && ok; ++j)
        ok = t.a[k][sigma[j]] == adjoint_a(t, i, j) && t.a[sigma[j]][k] == adjoint_a(t, j, i);
    }
    if (!ok) continue;
    sigma[i] = k;
    used[k] = true;
    if (extend_symmetry_permutation(t, i + 1, sigma, used, nodes_only)) return true;
    used[k] = false;
  }
  return false;
}

/// The stage permutation sigma as a matrix P on the tableau's basis and its inverse; false if
/// none maps the nodes.
constexpr bool reflection_matrix(const exact_rkn_tableau& t, exact_number (&P)[max_exact_stages][max_exact_stages],
                                 exact_number (&P_inverse)[max_exact_stages][max_exact_stages], int (&sigma)[max_exact_stages]) {
  const int s = t.stages;
  if (t.basis == stage_basis::values) {
    bool used[max_exact_stages]{};
    if (!extend_symmetry_permutation(t, 0, sigma, used, false)) {
      for (int k = 0; k < s; ++k) used[k] = false;
      if (!extend_symmetry_permutation(t, 0, sigma, used, true)) return false;
    }
    for (int i = 0; i < s; ++i) {
      P[i][sigma[i]] = exact_number(1);  // (P v)_i = v_sigma(i)
      P_inverse[sigma[i]][i] = exact_number(1);
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
  for (int i = 0; i < s; ++i)  // V(1 - (1 - x)) = V(x): P is an involution
    for (int l = 0; l < s; ++l) P_inverse[i][l] = P[i][l];
  return true;
}
}  // namespace analysis::detail

constexpr symmetry_result symmetry(const exact_rkn_tableau& t) {
  symmetry_result r;
  const int s = t.stages;
  exact_number P[max_exact_stages][max_exact_stages], P_inverse[max_exact_stages][max_exact_stages];
  r.nodes_symmetric = analysis::detail::reflection_matrix(t, P, P_inverse, r.permutation);
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
  matrix_times(t.a, P_inverse, AP);
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
      bbar_p = bbar_p + t.bbar[k] * P_inverse[k][l];
      b_p = b_p + t.b[k] * P_inverse[k][l];
    }
    r.bbar_defect[l] = t.b[l] - t.bbar[l] - bbar_p;
    r.b_defect[l] = t.b[l] - b_p;
    if (!r.bbar_defect[l].num.is_zero() || !r.b_defect[l].num.is_zero()) r.symmetric = false;
  }
  return r;
}

}  // namespace geomint
