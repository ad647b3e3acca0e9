#pragma once
/// Runge-Kutta methods of collocation type over their stage algebra Q[x]/(N), exactly, for the
/// family members whose entries need too large a number field: Radau IIA and Radau IA with
/// s = 5, whose quartic's splitting field has Galois group S4 and degree 24
/// (methods/collocation_families.hpp).
///
/// On the simple roots c_1..c_s of a monic N with rational coefficients, a vector of stage values
/// (v_1..v_s) is the polynomial u of degree < s with u(c_i) = v_i, an element of Q[x]/(N),
/// written in the monomial basis 1, x, ..., x^(s-1) (analysis/stage_algebra.hpp does the same for
/// RKN tableaux). The componentwise product is the product modulo N, the vector of ones is 1 and
/// the vector of nodes is x. With V_ik = c_i^k (v = V u) and W = diag(b) (Hairer & Wanner,
/// Solving ODEs II, section IV.5; Hairer, Lubich & Wanner 2006, section II.1.4):
/// - b(u) = sum_i b_i u(c_i) = int_0^1 u (B(s), exact for degree < s): b_k = 1 / (k + 1);
/// - collocation, C(s): (A u)(c_i) = int_0^(c_i) u, so A u = int_0^x u mod N;
/// - the D(s) method on the same nodes is the symplectic complement ahat_ij = b_j (1 - a_ji / b_i)
///   of collocation (collocation_families.hpp): Ahat = 1 b^T - W^(-1) A^T W, in the monomial basis
///   e_0 b^T - G^(-1) A^T G with the Gram matrix G = V^T W V, G_kl = b(x^(k+l) mod N).
/// Every coordinate is rational although the nodes are not; analysis/collocation_algebra_analysis.hpp
/// analyses such a method exactly, and `numeric_tableau<T>(m)` gives the usual (c, A, b) in a
/// scalar T from the nodes in T without a Vandermonde solve.

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "geomint/methods/collocation_families.hpp"
#include "geomint/methods/collocation_rkn.hpp"
#include "geomint/methods/number_field.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

/// An rk method on the roots of N over Q[x]/(N) (see the top of the file).
struct rk_stage_algebra {
  using vector = std::vector<exact_rational>;
  using matrix = std::vector<vector>;
  std::string name;
  int stages = 0;
  vector node_polynomial;  ///< monic N, ascending (stages + 1 coefficients)
  matrix a;                ///< the operator A on coordinates: (A u)_k = sum_l a[k][l] u_l
  vector b;                ///< the functional b: b(u) = sum_k b[k] u_k
  /// How the operators were made (numeric_tableau computes the same in T): collocation on the
  /// roots of N, or its symplectic complement (the D(s) method on those nodes).
  bool complement = false;

  /// The basis vector x^k (k < stages).
  vector unit(int k) const {
    vector e(static_cast<std::size_t>(stages), exact_rational(0));
    e[static_cast<std::size_t>(k)] = 1;
    return e;
  }
  vector one() const { return unit(0); }
  /// x^k mod N for any k >= 0.
  vector power(int k) const {
    vector p(static_cast<std::size_t>(k + 1), exact_rational(0));
    p.back() = 1;
    return reduce(std::move(p));
  }
  /// The nodes: x mod N.
  vector nodes() const { return power(1); }
  /// p (ascending, any degree) modulo the monic N, as stages coordinates.
  vector reduce(vector p) const {
    const auto s = static_cast<std::size_t>(stages);
    for (std::size_t k = p.size(); k-- > s;) {
      if (p[k].is_zero()) continue;
      const exact_rational t = p[k];
      for (std::size_t j = 0; j <= s; ++j) p[k - s + j] -= t * node_polynomial[j];
    }
    p.resize(s, exact_rational(0));
    return p;
  }
  /// The componentwise product of stage vectors: u w mod N.
  vector multiply(const vector& u, const vector& w) const {
    const auto s = static_cast<std::size_t>(stages);
    vector p(2 * s - 1, exact_rational(0));
    for (std::size_t i = 0; i < s; ++i) {
      if (u[i].is_zero()) continue;
      for (std::size_t j = 0; j < s; ++j)
        if (!w[j].is_zero()) p[i + j] += u[i] * w[j];
    }
    return reduce(std::move(p));
  }
  vector apply_a(const vector& u) const {
    const auto s = static_cast<std::size_t>(stages);
    vector r(s, exact_rational(0));
    for (std::size_t k = 0; k < s; ++k)
      for (std::size_t l = 0; l < s; ++l)
        if (!a[k][l].is_zero() && !u[l].is_zero()) r[k] += a[k][l] * u[l];
    return r;
  }
  exact_rational apply_b(const vector& u) const {
    exact_rational sum = 0;
    for (std::size_t k = 0; k < u.size(); ++k) sum += b[k] * u[k];
    return sum;
  }
  /// G_kl = b(x^(k+l) mod N) = sum_i b_i c_i^(k+l).
  matrix gram() const {
    const auto s = static_cast<std::size_t>(stages);
    matrix g(s, vector(s));
    for (std::size_t k = 0; k < s; ++k)
      for (std::size_t l = 0; l < s; ++l) g[k][l] = apply_b(power(static_cast<int>(k + l)));
    return g;
  }
};


/// The collocation method (C(s), B(s)) on the roots of the monic N of degree s >= 1
/// (ascending; std::invalid_argument otherwise). The roots are taken simple and real (the
/// families below are).
inline rk_stage_algebra collocation_algebra(detail::poly monic_n, std::string name = {}) {
  detail::trim(monic_n);
  if (monic_n.size() < 2 || monic_n.back() != 1)
    throw std::invalid_argument("geomint::methods::collocation_algebra: N must be monic of degree 1 or more");
  rk_stage_algebra m;
  m.name = std::move(name);
  m.stages = static_cast<int>(monic_n.size()) - 1;
  m.node_polynomial = std::move(monic_n);
  const auto s = static_cast<std::size_t>(m.stages);
  m.a.assign(s, rk_stage_algebra::vector(s, exact_rational(0)));
  m.b.assign(s, exact_rational(0));
  for (std::size_t k = 0; k < s; ++k) {
    // x^k -> x^(k+1) / (k + 1), reduced modulo N.
    rk_stage_algebra::vector p(k + 2, exact_rational(0));
    p[k + 1] = exact_rational(1, static_cast<long>(k + 1));
    const rk_stage_algebra::vector column = m.reduce(std::move(p));
    for (std::size_t i = 0; i < s; ++i) m.a[i][k] = column[i];
    m.b[k] = exact_rational(1, static_cast<long>(k + 1));
  }
  return m;
}

/// The symplectic complement of a method on the same nodes (the D(s) method of a collocation
/// method): e_0 b^T - G^(-1) A^T G (see the top of the file).
inline rk_stage_algebra symplectic_complement(const rk_stage_algebra& m, std::string name = {}) {
  const auto s = static_cast<std::size_t>(m.stages);
  const rk_stage_algebra::matrix g = m.gram();
  rk_stage_algebra::matrix at_g(s, rk_stage_algebra::vector(s, exact_rational(0)));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j)
      for (std::size_t k = 0; k < s; ++k) at_g[i][j] += m.a[k][i] * g[k][j];
  if (m.complement) throw std::invalid_argument("geomint::methods::symplectic_complement: the method is a complement already");
  rk_stage_algebra out = m;
  out.name = std::move(name);
  out.complement = true;
  for (std::size_t j = 0; j < s; ++j) {  // column j of G^(-1) A^T G
    rk_stage_algebra::vector column(s);
    for (std::size_t i = 0; i < s; ++i) column[i] = at_g[i][j];
    const rk_stage_algebra::vector x = detail::solve_exact(g, column);
    for (std::size_t i = 0; i < s; ++i) out.a[i][j] = (i == 0 ? m.b[j] : exact_rational(0)) - x[i];
  }
  return out;
}

/// The monic node polynomial of the Radau nodes of s stages: P*_s - P*_(s-1) (right, Radau IIA,
/// c_s = 1) or P*_s + P*_(s-1) (left, Radau IA, c_1 = 0), P*_n(x) = P_n(2x - 1) (Hairer &
/// Wanner II, section IV.5).
inline detail::poly radau_node_polynomial(int s, bool right) {
  if (s < 1 || s > 8) throw std::invalid_argument("geomint::methods::radau_node_polynomial: s must be 1..8");
  detail::poly n = detail::shifted_legendre(s), lower = detail::shifted_legendre(s - 1);
  n = right ? detail::subtract(n, lower) : detail::add(n, lower);
  return detail::monic(n);
}

/// Radau IIA (collocation on the right Radau nodes) and Radau IA (the D(s) method on the left
/// Radau nodes) with s stages over their stage algebra.
inline rk_stage_algebra radau_iia_algebra(int s) {
  return collocation_algebra(radau_node_polynomial(s, true), "radau-iia-" + std::to_string(s));
}
inline rk_stage_algebra radau_ia_algebra(int s) {
  return symplectic_complement(collocation_algebra(radau_node_polynomial(s, false)), "radau-ia-" + std::to_string(s));
}

/// The collocation Runge-Kutta method (c, A, b) on the distinct nodes c in T: A = the matrix
/// ap_ij = int_0^(c_i) l_j and b_j = int_0^1 l_j of collocation_nystrom (methods/collocation_rkn.hpp:
/// barycentric Lagrange values, Gauss-Legendre quadrature, a few ulps of T).
template <class T, int S>
rk<T, S> collocation_rk(const stage_vector<T, S>& c) {
  const nystrom<T, S> n = collocation_nystrom<T, S>(c);
  rk<T, S> t;
  t.c = c;
  t.a = n.ap;
  t.b = n.b;
  return t;
}

/// The symplectic complement ahat_ij = b_j (1 - a_ji / b_i) of a method in T.
template <class T, int S>
rk<T, S> symplectic_complement(const rk<T, S>& m) {
  rk<T, S> t = m;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i)
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) t.a[i][j] = m.b[j] * (T(1) - m.a[j][i] / m.b[i]);
  return t;
}

namespace detail {
/// f.template operator()<S>() for the run-time s in 1..8.
template <int S = 1, class F>
decltype(auto) with_stage_count(int s, F&& f) {
  if constexpr (S < 8) {
    if (s != S) return with_stage_count<S + 1>(s, std::forward<F>(f));
  }
  if (s != S) throw std::invalid_argument("geomint::methods: a method over its stage algebra has 1..8 stages");
  return f.template operator()<S>();
}
}  // namespace detail

/// The method with S = m.stages stages in the scalar T (std::invalid_argument otherwise): its
/// nodes, the roots of N, each to T's full precision from its exact bracket
/// (algebraic_field::root_in), then collocation_rk and, for a complement, symplectic_complement
/// in T: no Vandermonde solve, every entry to a few ulps of T.
template <class T, int S>
tableau_data<T> numeric_tableau(const rk_stage_algebra& m) {
  if (m.stages != S)
    throw std::invalid_argument("geomint::methods::numeric_tableau: the method has " + std::to_string(m.stages) + " stages, not " +
                                std::to_string(S));
  const auto brackets = algebraic_field::real_root_brackets(m.node_polynomial);
  if (static_cast<int>(brackets.size()) != S)
    throw std::invalid_argument("geomint::methods::numeric_tableau: N must have " + std::to_string(S) + " real roots");
  stage_vector<T, S> c;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    const auto& [a, b] = brackets[i];
    c[i] = a == b ? rational_to<T>(a) : algebraic_field::make(m.node_polynomial, exact_rational((a + b) / 2))->template root_in<T>();
  }
  const rk<T, S> collocation = collocation_rk<T, S>(c);
  tableau_data<T> out = data_of(m.complement ? symplectic_complement<T, S>(collocation) : collocation);
  out.name = m.name;
  return out;
}

/// The same for any number of stages, 1..8, known at run time (every S instantiated: where the
/// count is known, numeric_tableau<T, S> compiles one).
template <class T>
tableau_data<T> numeric_tableau(const rk_stage_algebra& m) {
  return detail::with_stage_count(m.stages, [&]<int S>() { return numeric_tableau<T, S>(m); });
}

/// Radau IIA and Radau IA with S stages as schemes of the one integrator
/// (integrator<tableau_method<radau_iia<5>>, Sys, T>, methods/tableau_method.hpp): `algebra()`
/// the exact method the analysis takes, `numeric_tableau<T>()` the same in T.
template <int S, bool Right>
struct radau_numeric {
  static_assert(S >= 1 && S <= 8, "geomint::methods::radau_numeric: S must be 1..8");
  static std::string name() { return (Right ? "radau-iia-" : "radau-ia-") + std::to_string(S); }
  static rk_stage_algebra algebra() { return Right ? radau_iia_algebra(S) : radau_ia_algebra(S); }
  template <class T>
  static tableau_data<T> numeric_tableau() {
    return methods::numeric_tableau<T, S>(algebra());
  }
  /// The type the integrator reads the kind from (never evaluated).
  static rk<exact_rational, S> tableau();
};
/// Radau IIA and IA with S stages as schemes: s = 2..4 from their exact tableaux
/// (collocation_families.hpp), s >= 5 from radau_numeric.
template <int S>
using radau_iia = std::conditional_t<(S >= 5), radau_numeric<S, true>, collocation_method<collocation_family::radau_iia, S>>;
template <int S>
using radau_ia = std::conditional_t<(S >= 5), radau_numeric<S, false>, collocation_method<collocation_family::radau_ia, S>>;

}  // namespace geomint::methods
