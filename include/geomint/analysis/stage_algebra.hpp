#pragma once
/// The exact model of an RKN tableau (analysis/rkn_tableau.hpp): its numbers, its stage vectors
/// and the tableau acting on them over the stage algebra.
///
/// When the stages are the roots of a polynomial N with rational coefficients (every node
/// family: shifted Legendre P_{m-1} for Gauss interior, P'_m for the Lobatto interior, U_{m-1}
/// for the Chebyshev-Lobatto interior, prod (x - c_i) for rational nodes), a vector of stage values (v_1..v_s) is the polynomial V of degree < s with V(c_i) =
/// v_i, i.e. an element of Q[x]/(N); the componentwise product is the product modulo N, and
/// the tableau acts by rational matrices in the monomial basis 1, x, ..., x^{s-1}:
///   A: V -> int_0^x (x - u) V(u) du mod N,   bbar(V) = int_0^1 (1 - u) V(u) du,   b(V) = int_0^1 V
/// for collocation (exact: V is its own interpolant). An explicit rational tableau keeps the
/// stage values themselves (componentwise product). Either way every quantity derived from
/// the tableau (order conditions, symplecticity, symmetry, stability) is an exact rational
/// although the nodes may be irrational (analysis/numeric_tableau.hpp gives the usual
/// (c, a, bbar, b) in a scalar type).

#include <cstdint>

#include "geomint/core/big_rational.hpp"
#include "geomint/core/rational.hpp"

namespace geomint {

/// Largest number of stages of an exact tableau (Galerkin of degree 8).
inline constexpr int max_exact_stages = 8;
/// Limbs of the exact numbers of the scheme algebra (512 bits; overflow throws).
inline constexpr int exact_algebra_limbs = 16;
/// The exact numbers of the scheme algebra.
using exact_number = big_rational<exact_algebra_limbs>;

namespace analysis::detail {
/// n / d as an exact number.
constexpr exact_number fraction(std::int64_t n, std::int64_t d) { return exact_number(rational(n, d)); }
}  // namespace analysis::detail

/// How stage vectors are represented.
enum class stage_basis {
  monomial,  ///< coordinates of V in 1, x, ..., x^{s-1} modulo the node polynomial N
  values     ///< the stage values themselves (explicit rational tableaux)
};

/// A stage vector: s exact coordinates.
///
/// Arrays of exact numbers need no initialiser: the default (and the zero-filled) exact number
/// is 0, bit for bit (big_rational stores its denominator minus one). That is what makes them
/// safe from GCC 12, which zero-fills such arrays on two paths: a copied element of a partly
/// assigned value-initialised array in constant evaluation (`symmetry` of lpf m >= 5 threw
/// "zero denominator" after m = 4 had been evaluated), and the folded default-initialisation of a
/// local array at run time, which ran the constructor on the first two elements only (a
/// collocation tableau built at run time threw). With a denominator stored as is, both gave 0/0.
struct stage_vector {
  exact_number v[max_exact_stages];
  friend constexpr bool operator==(const stage_vector&, const stage_vector&) = default;
  constexpr const exact_number& operator[](int k) const { return v[k]; }
  constexpr exact_number& operator[](int k) { return v[k]; }
};

/// An exact RKN tableau over its stage algebra (see the header comment). Structural.
struct exact_rkn_tableau {
  int stages = 0;                                        ///< s
  stage_basis basis = stage_basis::values;
  exact_number node_polynomial[max_exact_stages + 1];  ///< monic N, ascending (monomial basis only)
  exact_number a[max_exact_stages][max_exact_stages];  ///< the operator A on coordinates: (A v)_i = sum_j a[i][j] v_j
  exact_number bbar[max_exact_stages];                 ///< the functional bbar: bbar(v) = sum_k bbar[k] v_k
  exact_number b[max_exact_stages];                    ///< the functional b
  stage_vector c;                                      ///< the vector of nodes (x mod N, or c itself)
  stage_vector one;                                    ///< the vector of ones

  /// Componentwise product of stage vectors (product modulo N in the monomial basis).
  constexpr stage_vector multiply(const stage_vector& u, const stage_vector& w) const {
    stage_vector r;
    if (basis == stage_basis::values) {
      for (int i = 0; i < stages; ++i) r[i] = u[i] * w[i];
      return r;
    }
    exact_number p[2 * max_exact_stages];
    for (int i = 0; i < stages; ++i) {
      if (u[i].num.is_zero()) continue;
      for (int j = 0; j < stages; ++j)
        if (!w[j].num.is_zero()) p[i + j] = p[i + j] + u[i] * w[j];
    }
    reduce(p, 2 * stages - 2);
    for (int i = 0; i < stages; ++i) r[i] = p[i];
    return r;
  }
  /// The product u * c with the vector of nodes: in the monomial basis x u mod N, a shift and
  /// one reduction step (O(s) instead of the O(s^2) general product).
  constexpr stage_vector multiply_by_nodes(const stage_vector& u) const {
    if (basis == stage_basis::values) return multiply(u, c);
    stage_vector r;
    for (int i = stages - 1; i >= 1; --i) r[i] = u[i - 1];
    const exact_number& top = u[stages - 1];  // x^s = -(n_0 + ... + n_{s-1} x^{s-1}) mod N
    if (!top.num.is_zero())
      for (int i = 0; i < stages; ++i) r[i] = r[i] - top * node_polynomial[i];
    return r;
  }
  /// p (degree <= top) modulo the monic N, in place: p[0..s-1] hold the remainder.
  constexpr void reduce(exact_number* p, int top) const {
    for (int k = top; k >= stages; --k) {
      if (p[k].num.is_zero()) continue;
      const exact_number t = p[k];
      for (int j = 0; j <= stages; ++j) p[k - stages + j] = p[k - stages + j] - t * node_polynomial[j];
    }
  }
  constexpr stage_vector apply_a(const stage_vector& u) const {
    stage_vector r;
    for (int i = 0; i < stages; ++i) {
      exact_number sum;
      for (int j = 0; j < stages; ++j)
        if (!a[i][j].num.is_zero() && !u[j].num.is_zero()) sum = sum + a[i][j] * u[j];
      r[i] = sum;
    }
    return r;
  }
  static constexpr exact_number dot(const exact_number* f, const stage_vector& u, int s) {
    exact_number sum;
    for (int k = 0; k < s; ++k)
      if (!f[k].num.is_zero() && !u[k].num.is_zero()) sum = sum + f[k] * u[k];
    return sum;
  }
  constexpr exact_number apply_b(const stage_vector& u) const { return dot(b, u, stages); }
  constexpr exact_number apply_bbar(const stage_vector& u) const { return dot(bbar, u, stages); }
  /// The basis vector e_k (x^k in the monomial basis).
  constexpr stage_vector unit(int k) const {
    stage_vector e;
    e[k] = exact_number(1);
    return e;
  }

  friend constexpr bool operator==(const exact_rkn_tableau&, const exact_rkn_tableau&) = default;
};

}  // namespace geomint
