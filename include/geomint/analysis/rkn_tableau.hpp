#pragma once
/// Exact Runge-Kutta-Nystrom tableaux of the library's schemes, at compile time.
///
/// For a natural system (L = 1/2 qdot^T M qdot - V(q), constant M; unit mass below, f = -grad V)
/// one step of every scheme of the library is an s-stage RKN method
///   Q_i = q + c_i tau p + tau^2 sum_j a_ij f(Q_j),
///   q1  = q + tau p + tau^2 sum_j bbar_j f(Q_j),   p1 = p + tau sum_j b_j f(Q_j):
/// - LPF of degree m on a node family (Kong & Yang 2020, eq. 10-12): the collocation RKN method
///   on the s = m - 1 interior nodes. With lt_j the Lagrange basis on the interior nodes,
///   a_ij = int_0^{c_i} (c_i - u) lt_j(u) du, bbar_j = int_0^1 (1 - u) lt_j(u) du,
///   b_j = int_0^1 lt_j(u) du (the path's second derivative, of degree m - 2, interpolates the
///   force at the interior nodes; eq. 12 and the momentum match, eq. 9-11).
/// - Galerkin VI of degree m with m-point Gauss quadrature: the partitioned RK method
///   a_ij = int_0^{c_i} l_j, ahat_ij = b_j (1 - a_ji / b_i) (Hairer, Lubich, Wanner, Geometric
///   Numerical Integration, 2nd ed., Theorem VI.6.4), which for Gauss nodes is the Gauss
///   collocation RK method; as an RKN method a = A Ahat = A^2, bbar = b^T A.
/// - Midpoint VI (scheme 17): s = 1, c = 1/2, a = 1/4, bbar = 1/2, b = 1.
/// - Trapezoidal VI: Stormer-Verlet, s = 2, c = (0, 1), a = [[0, 0], [1/2, 0]], bbar = (1/2, 0),
///   b = (1/2, 1/2).
///
/// Exact representation. When the stages are the roots of a polynomial N with rational
/// coefficients (every node family: shifted Legendre P_{m-1} for Gauss interior, P'_m for the
/// Lobatto interior, U_{m-1} for the Chebyshev-Lobatto interior, prod (x - c_i) for rational
/// nodes), a vector of stage values (v_1..v_s) is the polynomial V of degree < s with V(c_i) =
/// v_i, i.e. an element of Q[x]/(N); the componentwise product is the product modulo N, and
/// the tableau acts by rational matrices in the monomial basis 1, x, ..., x^{s-1}:
///   A: V -> int_0^x (x - u) V(u) du mod N,   bbar(V) = int_0^1 (1 - u) V(u) du,   b(V) = int_0^1 V
/// for collocation (exact: V is its own interpolant). An explicit rational tableau keeps the
/// stage values themselves (componentwise product). Either way every quantity derived from
/// the tableau (order conditions, symplecticity, symmetry, stability) is an exact rational
/// although the nodes may be irrational; `numeric_tableau` gives the usual (c, a, bbar, b) in
/// any scalar type from the exact data and the numerically computed nodes (core/nodes.hpp), as
/// the methods' run-time tableau (methods::tableau_data, methods/tableau.hpp).

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

#include "geomint/core/big_rational.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/core/rational.hpp"
#include "geomint/methods/collocation_rkn.hpp"
#include "geomint/methods/tableau.hpp"

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

namespace analysis::detail {

/// Polynomial coefficients (ascending) of up to degree 2 max_exact_stages + 2.
struct exact_poly_buffer {
  static constexpr int capacity = 2 * max_exact_stages + 3;
  exact_number c[capacity];  // default-initialised: see stage_vector
};

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

/// Monic version of a polynomial with rational coefficients (degree = the last nonzero one).
constexpr int make_monic(exact_number* p, int top) {
  while (top >= 0 && p[top].num.is_zero()) --top;
  if (top < 1) throw std::domain_error("geomint: a node polynomial must have degree >= 1");
  const exact_number lead = p[top];
  for (int k = 0; k <= top; ++k) p[k] = p[k] / lead;
  return top;
}

/// Legendre P_n(y) or Chebyshev U_n(y) with y = 2x - 1, as a polynomial in x (three-term
/// recurrences in exact arithmetic); derivative_of_legendre: P'_n(y) instead.
enum class orthogonal_kind { legendre, legendre_derivative, chebyshev_u };
constexpr int shifted_orthogonal(orthogonal_kind kind, int n, exact_number* out) {
  exact_number prev[max_exact_stages + 3], cur[max_exact_stages + 3];
  // P_0 = 1, P_1 = y (Legendre) / U_1 = 2y (Chebyshev); y = 2x - 1.
  // For P'_n: (n) P_n = ... use P'_{k+1} = (k+1) P_k + y P'_k: track P and P'.
  exact_number dprev[max_exact_stages + 3], dcur[max_exact_stages + 3];
  cur[0] = exact_number(1);
  auto times_y = [](const exact_number* v, exact_number* r, int deg) {
    for (int k = deg + 1; k >= 0; --k) {
      exact_number t = -v[k];
      if (k >= 1) t = t + exact_number(2) * v[k - 1];
      r[k] = t;
    }
  };
  for (int k = 0; k < n; ++k) {
    exact_number yc[max_exact_stages + 3], next[max_exact_stages + 3], dnext[max_exact_stages + 3];
    times_y(cur, yc, k);
    if (kind == orthogonal_kind::chebyshev_u) {
      for (int j = 0; j <= k + 1; ++j) next[j] = exact_number(2) * yc[j] - prev[j];
    } else {
      // (k+1) P_{k+1} = (2k+1) y P_k - k P_{k-1};  P'_{k+1} = (k+1) P_k + y P'_k.
      exact_number ydc[max_exact_stages + 3];
      times_y(dcur, ydc, k);
      for (int j = 0; j <= k + 1; ++j) {
        next[j] = (exact_number(2 * k + 1) * yc[j] - exact_number(k) * prev[j]) / exact_number(k + 1);
        dnext[j] = exact_number(k + 1) * cur[j] + ydc[j];
      }
    }
    for (int j = 0; j < max_exact_stages + 3; ++j) {
      prev[j] = cur[j];
      cur[j] = next[j];
      dprev[j] = dcur[j];
      dcur[j] = dnext[j];
    }
  }
  const exact_number* src = kind == orthogonal_kind::legendre_derivative ? dcur : cur;
  for (int j = 0; j <= n; ++j) out[j] = src[j];
  return n;
}

/// The monic polynomial whose roots are the m - 1 interior nodes of a family.
template <class Family, int M>
constexpr exact_poly_buffer interior_node_polynomial() {
  exact_poly_buffer p;
  constexpr int s = M - 1;
  if constexpr (std::is_same_v<Family, equispaced>) {
    p.c[0] = exact_number(1);
    for (int i = 1; i <= s; ++i) {
      const exact_number root = fraction(i, M);
      for (int k = i; k >= 0; --k) p.c[k] = (k >= 1 ? p.c[k - 1] : exact_number(0)) - root * p.c[k];
    }
  } else if constexpr (std::is_same_v<Family, gauss_interior>) {
    shifted_orthogonal(orthogonal_kind::legendre, s, p.c);
  } else if constexpr (std::is_same_v<Family, gauss_lobatto>) {
    shifted_orthogonal(orthogonal_kind::legendre_derivative, M, p.c);
  } else {
    static_assert(std::is_same_v<Family, chebyshev_lobatto>);
    shifted_orthogonal(orthogonal_kind::chebyshev_u, s, p.c);
  }
  make_monic(p.c, s);
  return p;
}

}  // namespace analysis::detail

/// The exact RKN tableau of LPF of degree m on a node family (collocation on the interior nodes).
template <int M, class Family = equispaced>
constexpr exact_rkn_tableau lpf_tableau() {
  static_assert(node_family<Family>,
                "geomint::lpf_tableau: Family must be equispaced, gauss_lobatto, chebyshev_lobatto or gauss_interior");
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
    analysis::detail::exact_poly_buffer n;
    analysis::detail::shifted_orthogonal(analysis::detail::orthogonal_kind::legendre, M, n.c);
    analysis::detail::make_monic(n.c, M);
    return analysis::detail::galerkin_tableau(n.c, M);
  } else {
    return {};
  }
}

/// An explicit rational RKN tableau with s stages (values basis): c (s nodes), a (s rows of s
/// entries), bbar and b (s weights each), all exact geomint::rational. Sizes and entry types are
/// deduced, so that a malformed tableau is a readable compile error.
template <class NodeEntry, std::size_t S, class MatrixEntry, std::size_t Columns, std::size_t Rows, class BbarEntry,
          std::size_t BbarSize, class BEntry, std::size_t BSize>
constexpr exact_rkn_tableau rational_rkn_tableau(const std::array<NodeEntry, S>& c,
                                                 const std::array<std::array<MatrixEntry, Columns>, Rows>& a,
                                                 const std::array<BbarEntry, BbarSize>& bbar,
                                                 const std::array<BEntry, BSize>& b) {
  static_assert(std::is_same_v<NodeEntry, rational> && std::is_same_v<MatrixEntry, rational> &&
                    std::is_same_v<BbarEntry, rational> && std::is_same_v<BEntry, rational>,
                "geomint::rational_rkn_tableau: every entry must be an exact geomint::rational (floating-point "
                "entries are not exact; write rational(1, 3), not 1.0 / 3)");
  static_assert(S >= 1 && S <= max_exact_stages, "geomint::rational_rkn_tableau: the number of stages must be in 1..8");
  static_assert(Rows == S, "geomint::rational_rkn_tableau: a must have one row per stage (as many rows as nodes c)");
  static_assert(Columns == S, "geomint::rational_rkn_tableau: every row of a must have one entry per stage");
  static_assert(BbarSize == S && BSize == S, "geomint::rational_rkn_tableau: bbar and b must have one weight per stage");
  exact_rkn_tableau t;
  t.stages = static_cast<int>(S);
  t.basis = stage_basis::values;
  for (std::size_t i = 0; i < S; ++i) {
    t.c[static_cast<int>(i)] = exact_number(c[i]);
    t.one[static_cast<int>(i)] = exact_number(1);
    t.b[i] = exact_number(b[i]);
    t.bbar[i] = exact_number(bbar[i]);
    for (std::size_t j = 0; j < S; ++j) t.a[i][j] = exact_number(a[i][j]);
  }
  return t;
}
namespace analysis::detail {
template <class>
inline constexpr bool dependent_false = false;
}  // namespace analysis::detail

/// One entry of a braced tableau list (`rational_rkn_tableau<S>({...}, ...)`): an exact rational
/// or an integer. A std::array (a row of a) filled from a shorter braced list value-initialises
/// the missing entries; here that default constructor is a static_assert, so that a left-out
/// entry is a compile error and never a silent 0.
struct tableau_entry {
  rational value;
  constexpr tableau_entry(const rational& v) : value(v) {}  // NOLINT(google-explicit-constructor)
  template <std::integral Int>
    requires(!std::is_same_v<Int, bool>)
  constexpr tableau_entry(Int n) : value(n) {}  // NOLINT(google-explicit-constructor)
  template <std::floating_point F>
  constexpr tableau_entry(F) : value() {  // NOLINT(google-explicit-constructor)
    static_assert(analysis::detail::dependent_false<F>,
                  "geomint::rational_rkn_tableau: every entry must be an exact geomint::rational (floating-point entries are "
                  "not exact; write rational(1, 3), not 1.0 / 3)");
  }
  template <class Missing = void>
  constexpr tableau_entry() : value() {
    static_assert(analysis::detail::dependent_false<Missing>,
                  "geomint::rational_rkn_tableau<S>: a braced list is shorter than the number of stages S (every row of a "
                  "needs S entries and a needs S rows; a left-out entry would be a silent 0)");
  }
};

/// The same with the number of stages given, for braced lists: `rational_rkn_tableau<2>({...}, ...)`.
/// Every list must have exactly S entries: the lengths of c, bbar and b are deduced and checked by
/// static_asserts; a short row of a is caught by tableau_entry, a long one by std::array.
template <int S, std::size_t NodeCount, std::size_t BbarCount, std::size_t BCount>
constexpr exact_rkn_tableau rational_rkn_tableau(const tableau_entry (&c)[NodeCount],
                                                 const std::array<std::array<tableau_entry, S>, S>& a,
                                                 const tableau_entry (&bbar)[BbarCount], const tableau_entry (&b)[BCount]) {
  static_assert(NodeCount == S, "geomint::rational_rkn_tableau<S>: the braced list c must have S entries (one node per stage)");
  static_assert(BbarCount == S, "geomint::rational_rkn_tableau<S>: the braced list bbar must have S entries (one weight per stage)");
  static_assert(BCount == S, "geomint::rational_rkn_tableau<S>: the braced list b must have S entries (one weight per stage)");
  std::array<rational, S> c_values{}, bbar_values{}, b_values{};
  std::array<std::array<rational, S>, S> a_values{};
  for (std::size_t i = 0; i < S && i < NodeCount && i < BbarCount && i < BCount; ++i) {
    c_values[i] = c[i].value;
    bbar_values[i] = bbar[i].value;
    b_values[i] = b[i].value;
    for (std::size_t j = 0; j < S; ++j) a_values[i][j] = a[i][j].value;
  }
  return rational_rkn_tableau<rational, S, rational, S, S, rational, S, rational, S>(c_values, a_values, bbar_values, b_values);
}

/// Integer literals of any length for tableau entries: `123456789012345678_q` is a
/// geomint::rational, and a literal that does not fit (|n| > 2^63 - 1) is a compile error. A plain
/// integer literal above 2^64 - 1 is truncated by GCC with only a warning ("integer constant is
/// too large for its type"; Clang rejects it) before any library code sees it: write large
/// numerators and denominators with _q, e.g. `9007199254740993_q / 3`.
namespace literals {
namespace detail {
__extension__ using unsigned_wide = unsigned __int128;
struct parsed_literal {
  bool decimal = true;
  bool fits = true;
  std::int64_t value = 0;
};
template <char... Digits>
consteval parsed_literal parse_literal() {
  parsed_literal out;
  constexpr char digits[] = {Digits...};
  if (sizeof...(Digits) > 1 && digits[0] == '0') out.decimal = false;  // 0x.., 0b.., octal
  unsigned_wide v = 0;
  for (char ch : digits) {
    if (ch == '\'') continue;
    if (ch < '0' || ch > '9') {
      out.decimal = false;
      break;
    }
    v = v * 10 + static_cast<unsigned>(ch - '0');
    if (v > static_cast<unsigned_wide>(std::numeric_limits<std::int64_t>::max())) {
      out.fits = false;
      break;
    }
  }
  if (out.decimal && out.fits) out.value = static_cast<std::int64_t>(v);
  return out;
}
}  // namespace detail

template <char... Digits>
consteval rational operator""_q() {
  constexpr detail::parsed_literal parsed = detail::parse_literal<Digits...>();
  static_assert(parsed.decimal, "geomint::literals::operator\"\"_q: write a decimal integer (no prefix, no leading 0)");
  static_assert(parsed.fits,
                "geomint::literals::operator\"\"_q: the integer literal does not fit geomint::rational (|n| <= 2^63 - 1 = "
                "9223372036854775807)");
  return rational(parsed.value);
}
}  // namespace literals

/// The midpoint VI (scheme 17) and the trapezoidal VI (Stormer-Verlet).
constexpr exact_rkn_tableau midpoint_tableau() {
  return rational_rkn_tableau<1>({rational(1, 2)}, {{{rational(1, 4)}}}, {rational(1, 2)}, {rational(1)});
}
constexpr exact_rkn_tableau trapezoidal_tableau() {
  return rational_rkn_tableau<2>({rational(0), rational(1)}, {{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}},
                                 {rational(1, 2), rational(0)}, {rational(1, 2), rational(1, 2)});
}

namespace analysis::detail {

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

}  // namespace analysis::detail

/// Collocation (LPF-type) tableau on user data: the s distinct rational interior nodes in [0, 1].
template <class NodeEntry, std::size_t S>
constexpr exact_rkn_tableau collocation_tableau_from_nodes(const std::array<NodeEntry, S>& nodes) {
  static_assert(std::is_same_v<NodeEntry, rational>,
                "geomint::collocation_tableau_from_nodes: the nodes must be exact geomint::rational (floating-point "
                "nodes are not exact; for irrational nodes pass their node polynomial)");
  static_assert(S >= 1 && S <= max_exact_stages, "geomint::collocation_tableau_from_nodes: 1..8 nodes");
  analysis::detail::exact_poly_buffer p;
  p.c[0] = exact_number(1);
  for (std::size_t i = 0; i < S; ++i) {
    if (nodes[i] < rational(0) || nodes[i] > rational(1))
      throw std::domain_error("geomint::collocation_tableau_from_nodes: the nodes must lie in [0, 1]");
    for (std::size_t j = 0; j < i; ++j)
      if (nodes[i] == nodes[j]) throw std::domain_error("geomint::collocation_tableau_from_nodes: the nodes must be distinct");
    const exact_number root(nodes[i]);
    for (int k = static_cast<int>(i) + 1; k >= 0; --k) p.c[k] = (k >= 1 ? p.c[k - 1] : exact_number(0)) - root * p.c[k];
  }
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
  // Simple roots: the Euclidean remainder sequence of N and N' ends in a nonzero constant.
  exact_number u[max_exact_stages + 1], w[max_exact_stages + 1];
  int du = S, dw = S - 1;
  for (int k = 0; k <= S; ++k) u[k] = p.c[k];
  for (int k = 1; k <= S; ++k) w[k - 1] = p.c[k] * exact_number(k);
  while (dw >= 1) {
    while (du >= dw) {
      const exact_number f = u[du] / w[dw];
      for (int j = 0; j <= dw; ++j) u[du - dw + j] = u[du - dw + j] - f * w[j];
      --du;
      while (du >= 0 && u[du].num.is_zero()) --du;
    }
    if (du < 0) throw std::domain_error("geomint::collocation_tableau_from_polynomial: the node polynomial has a multiple root");
    for (int k = 0; k <= max_exact_stages; ++k) {
      const exact_number t = u[k];
      u[k] = w[k];
      w[k] = t;
    }
    const int t = du;
    du = dw;
    dw = t;
  }
  if (analysis::detail::roots_in_unit_interval(p.c, S) != S)
    throw std::domain_error("geomint::collocation_tableau_from_polynomial: the roots must be real and lie in [0, 1]");
  return analysis::detail::collocation_tableau(p.c, S);
}
/// The same with the degree given, for braced lists: `collocation_tableau_from_polynomial<2>({...})`.
template <int S>
constexpr exact_rkn_tableau collocation_tableau_from_polynomial(const std::array<rational, S + 1>& coefficients) {
  return collocation_tableau_from_polynomial<rational, S + 1>(coefficients);
}

namespace analysis::detail {
template <class T>
T to_scalar(const exact_number& x) {
  return T(x.num.str()) / T(x.den().str());
}
template <class T>
  requires std::is_floating_point_v<T>
T to_scalar(const exact_number& x) {
  return static_cast<T>(std::stold(x.num.str())) / static_cast<T>(std::stold(x.den().str()));
}
}  // namespace analysis::detail

/// The usual tableau (c, a, bbar, b) in T from the exact one, as the methods' run-time form of
/// an RKN tableau (methods/tableau.hpp; kind rkn). For the monomial basis, with V_ik = c_i^k at
/// the numerically computed nodes c (ascending), a = V A V^{-1}, bbar = bbar V^{-1},
/// b = b V^{-1}. Accuracy: the Vandermonde solve loses about log10(cond V) digits (some 5 for
/// s = 8).
template <class T>
methods::tableau_data<T> numeric_tableau(const exact_rkn_tableau& t, const T* nodes_ascending) {
  const int s = t.stages;
  const auto n = static_cast<std::size_t>(s);
  methods::tableau_data<T> out;
  out.kind = methods::method_kind::rkn;
  out.stages = s;
  out.c.assign(n, T(0));
  out.bbar.assign(n, T(0));
  out.b.assign(n, T(0));
  out.a.assign(n, std::vector<T>(n, T(0)));
  T A[max_exact_stages][max_exact_stages], bb[max_exact_stages], b[max_exact_stages];
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) A[i][j] = analysis::detail::to_scalar<T>(t.a[i][j]);
    bb[i] = analysis::detail::to_scalar<T>(t.bbar[i]);
    b[i] = analysis::detail::to_scalar<T>(t.b[i]);
  }
  if (t.basis == stage_basis::values) {
    for (int i = 0; i < s; ++i) {
      out.c[static_cast<std::size_t>(i)] = analysis::detail::to_scalar<T>(t.c[i]);
      out.bbar[static_cast<std::size_t>(i)] = bb[i];
      out.b[static_cast<std::size_t>(i)] = b[i];
      for (int j = 0; j < s; ++j) out.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = A[i][j];
    }
    return out;
  }
  // W = V^{-1} by Gauss-Jordan with partial pivoting.
  T V[max_exact_stages][2 * max_exact_stages];
  for (int i = 0; i < s; ++i) {
    T p(1);
    for (int k = 0; k < s; ++k) {
      V[i][k] = p;
      p *= nodes_ascending[i];
      V[i][s + k] = T(i == k ? 1 : 0);
    }
  }
  for (int col = 0; col < s; ++col) {
    int pivot = col;
    for (int r = col + 1; r < s; ++r) {
      using std::abs;
      if (abs(V[r][col]) > abs(V[pivot][col])) pivot = r;
    }
    for (int k = 0; k < 2 * s; ++k) std::swap(V[col][k], V[pivot][k]);
    const T d = V[col][col];
    for (int k = 0; k < 2 * s; ++k) V[col][k] /= d;
    for (int r = 0; r < s; ++r) {
      if (r == col) continue;
      const T f = V[r][col];
      for (int k = 0; k < 2 * s; ++k) V[r][k] -= f * V[col][k];
    }
  }
  auto W = [&](int k, int j) -> const T& { return V[k][s + j]; };  // (V^{-1})_{kj}
  for (int i = 0; i < s; ++i) {
    out.c[static_cast<std::size_t>(i)] = nodes_ascending[i];
    for (int j = 0; j < s; ++j) {
      // (V A W)_{ij} = sum_k c_i^k (A W)_{kj}
      T sum(0), power(1);
      for (int k = 0; k < s; ++k) {
        T aw(0);
        for (int l = 0; l < s; ++l) aw += A[k][l] * W(l, j);
        sum += power * aw;
        power *= nodes_ascending[i];
      }
      out.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = sum;
    }
  }
  for (int j = 0; j < s; ++j) {
    T sb(0), sbb(0);
    for (int k = 0; k < s; ++k) {
      sb += b[k] * W(k, j);
      sbb += bb[k] * W(k, j);
    }
    out.b[static_cast<std::size_t>(j)] = sb;
    out.bbar[static_cast<std::size_t>(j)] = sbb;
  }
  return out;
}

/// The numeric tableau of LPF (m, Family) in T: the collocation method on the family's interior
/// nodes (core/nodes.hpp), by the construction the schemes use (methods/collocation_rkn.hpp; no
/// Vandermonde solve, every entry to a few ulps of T), in the run-time form numeric_tableau gives.
template <int M, class Family, class T>
methods::tableau_data<T> lpf_numeric_tableau() {
  static_assert(M >= 2 && M - 1 <= max_exact_stages, "geomint::lpf_numeric_tableau: m must be 2..9");
  constexpr int S = M - 1;
  const auto c = nodes<Family, M, T>();
  std::array<T, S> interior;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) interior[i] = c[i + 1];
  return methods::data_of(methods::collocation_rkn<T, S>(interior));
}
/// The numeric tableau of the Galerkin VI of degree m in T (Gauss nodes from core/nodes.hpp).
template <int M, class T>
methods::tableau_data<T> galerkin_numeric_tableau() {
  const auto c = nodes<gauss_interior, M + 1, T>();
  return numeric_tableau<T>(galerkin_tableau<M>(), c.data() + 1);
}

}  // namespace geomint
