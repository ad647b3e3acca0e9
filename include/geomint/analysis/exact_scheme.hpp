#pragma once
/// Exact two-step schemes of the harmonic oscillator, derived at compile time.
///
/// For L = xdot^2/2 - x^2/2 (eq. 15) every scheme of the library reduces to
///   x^{k+1} = R(tau) x^k - x^{k-1},   R = P(s) / Q(s),   s = tau^2,
/// with P, Q integer polynomials: eq. (16) for m = 2, (18) for m = 3, (19) for m = 4 (LPF,
/// equispaced nodes) and (17) for the midpoint variational integrator. This header derives P and
/// Q exactly for the LPF scheme (include/geomint/schemes/lpf.hpp) with m = 2..8 on an exact node
/// family, and for the midpoint VI, and expands R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4))
/// for the exact leading local error term and the order p.
///
///   constexpr auto r = geomint::exact_two_step<4>();     // eq. (19)
///   static_assert(r.numerator[0] == 294912 && r.order == 4);
///   r.leading_coefficient.str();                         // "-7/7680"
///
/// Derivation (LPF, one step, nodes 0 = c_0 < ... < c_m = 1, x(c) = sum_j l_j(c) X_j): the
/// interior Euler-Lagrange rows (eq. 12) sum_j D2[i][j] X_j + s X_i = 0 (i = 1..m-1) fix the
/// interior values; the end momentum (eq. 10, times tau) is sum_j D1[m][j] X_j = A(s) X_0 +
/// B(s) X_m; by the symmetry of the nodes the start momentum is -(B X_0 + A X_m), and momentum
/// matching (eq. 11) gives R = -2 B / A. With the Schur complement, A and B are the bordered
/// determinants det[[M(s), D2[I][0]], [D1[m][I], D1[m][0]]] / det M(s) (and the same with
/// column m), M(s) = D2[I][I] + s Id; both are computed by one fraction-free (Bareiss)
/// elimination over Z[s]. All arithmetic is exact (include/geomint/core/big_integer.hpp,
/// big_rational.hpp, integer_polynomial.hpp): overflow throws (a compile error in a constant
/// expression, never a wrong value).

#include <numeric>
#include <array>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "geomint/core/big_integer.hpp"
#include "geomint/core/big_rational.hpp"
#include "geomint/core/differentiation.hpp"
#include "geomint/core/integer_polynomial.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/core/rational.hpp"

namespace geomint {

namespace analysis::detail {

// ---------------------------------------------------------------------------------------------
// The scheme's R = P / Q from the momentum coefficients A, B; reduction; error series.
// ---------------------------------------------------------------------------------------------

/// Limbs of the elimination and of the leading error coefficient: 384 bits. The largest
/// intermediate (m = 8) has 199 bits.
inline constexpr int exact_limbs = 12;

}  // namespace analysis::detail

/// The exact leading error coefficient: a reduced big rational (to_string: `str()`), comparable
/// with geomint::rational.
using exact_rational = big_rational<analysis::detail::exact_limbs>;

/// x^{k+1} = R(tau) x^k - x^{k-1} for L = xdot^2/2 - x^2/2 (eq. 15), R = P(s)/Q(s), s = tau^2,
/// in lowest terms (gcd(P, Q) = 1 in Z[s], integer content 1, Q(0) > 0), and its local error
/// R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4)), so the scheme has order p. Structural.
struct exact_two_step_scheme {
  static constexpr int capacity = max_exact_m + 1;
  int m = 0;  ///< interpolation degree of the LPF scheme; 0 for the midpoint VI (17)
  int numerator_degree = -1;
  int denominator_degree = -1;
  std::array<std::int64_t, capacity> numerator{};    ///< P, ascending powers of s = tau^2
  std::array<std::int64_t, capacity> denominator{};  ///< Q, ascending powers of s = tau^2
  int order = 0;                                     ///< p
  exact_rational leading_coefficient{};              ///< c

  /// Power of tau in the leading error term: p + 2.
  constexpr int leading_power() const { return order + 2; }

  /// R(tau) in T (Horner in s; one conversion per integer coefficient).
  template <class T>
  constexpr T R(const T& tau) const {
    const T s = tau * tau;
    T p(0), q(0);
    for (int k = numerator_degree; k >= 0; --k) p = p * s + T(numerator[static_cast<std::size_t>(k)]);
    for (int k = denominator_degree; k >= 0; --k) q = q * s + T(denominator[static_cast<std::size_t>(k)]);
    return p / q;
  }

  friend constexpr bool operator==(const exact_two_step_scheme&, const exact_two_step_scheme&) = default;
};

namespace analysis::detail {

template <int D>
using exact_poly = integer_polynomial<exact_limbs, D>;

/// n! as a big integer.
constexpr big_integer<exact_limbs> big_factorial(int n) {
  big_integer<exact_limbs> f(1);
  for (int k = 2; k <= n; ++k) f *= big_integer<exact_limbs>(k);
  return f;
}

/// Reduces R = -2 B / A, narrows it to int64 coefficients and expands R - 2 cos(tau).
template <int D>
constexpr exact_two_step_scheme finish_two_step(int m, const exact_poly<D>& A, const exact_poly<D>& B) {
  using big = big_integer<exact_limbs>;
  exact_poly<D> P = big(-2) * B;
  exact_poly<D> Q = A;
  if (Q.is_zero()) throw std::domain_error("geomint::exact_two_step: degenerate scheme (A = 0)");
  const exact_poly<D> G = polynomial_gcd(P, Q);
  if (G.degree > 0) {
    P = exact_quotient(P, G);
    Q = exact_quotient(Q, G);
  }
  const big g = gcd(content(P), content(Q));
  for (int k = 0; k <= P.degree; ++k) P[k] = exact_quotient(P[k], g);
  for (int k = 0; k <= Q.degree; ++k) Q[k] = exact_quotient(Q[k], g);
  if (Q[0].is_zero()) throw std::domain_error("geomint::exact_two_step: R has a pole at tau = 0");
  if (Q[0].negative) {
    P = big(-1) * P;
    Q = big(-1) * Q;
  }

  exact_two_step_scheme out;
  out.m = m;
  if (P.degree >= exact_two_step_scheme::capacity || Q.degree >= exact_two_step_scheme::capacity)
    throw std::overflow_error("geomint::exact_two_step: degree exceeds the result's capacity");
  out.numerator_degree = P.degree;
  out.denominator_degree = Q.degree;
  for (int k = 0; k <= P.degree; ++k) out.numerator[static_cast<std::size_t>(k)] = P[k].to_int64();
  for (int k = 0; k <= Q.degree; ++k) out.denominator[static_cast<std::size_t>(k)] = Q[k].to_int64();

  // R - 2 cos = (P - Q C) / Q with C = 2 cos(tau) = sum_k 2 (-1)^k s^k / (2k)!. The coefficient
  // of s^k of (P - Q C) times (2k)! is the integer
  //   E_k = (2k)! P_k - sum_i Q_i 2 (-1)^(k-i) (2k)! / (2(k-i))!.
  // P - Q C cannot vanish beyond s^(deg P + deg Q + 1) (else P/Q = 2 cos), so that bounds the
  // search; the first nonzero E_j gives c = E_j / ((2j)! Q_0) and p = 2j - 2.
  const int last = P.degree + Q.degree + 1;
  for (int k = 0; k <= last; ++k) {
    big E = k <= P.degree ? big_factorial(2 * k) * P[k] : big(0);
    for (int i = 0; i <= k && i <= Q.degree; ++i) {
      big ratio(2);  // 2 (2k)! / (2(k-i))!
      for (int f = 2 * (k - i) + 1; f <= 2 * k; ++f) ratio *= big(f);
      if ((k - i) % 2 == 0) E -= Q[i] * ratio;
      else E += Q[i] * ratio;
    }
    if (!E.is_zero()) {
      out.order = 2 * k - 2;
      out.leading_coefficient = exact_rational(E, big_factorial(2 * k) * Q[0]);
      return out;
    }
  }
  throw std::domain_error("geomint::exact_two_step: R(tau) - 2 cos(tau) has no nonzero term");
}

/// LCM of the denominators of a range of rationals (int64; the weights for m <= 8 are small).
template <class Range>
constexpr std::int64_t denominator_lcm(const Range& values) {
  std::int64_t l = 1;
  for (const rational& v : values) l = l / std::gcd(l, v.den) * v.den;
  return l;
}

/// The LPF derivation (eqs. 10-12 on the harmonic oscillator): see the header comment.
template <int M, class Family>
constexpr exact_two_step_scheme lpf_two_step() {
  using big = big_integer<exact_limbs>;
  constexpr int D = 2 * M;  // Bareiss products of k-minors have degree <= 2(m-1)
  using poly = exact_poly<D>;
  const auto D1 = differentiation_weights<1, Family, M, rational>();
  const auto D2 = differentiation_weights<2, Family, M, rational>();

  // Integer scales: the interior rows of D2 by L2, the momentum row D1[m] by L1; both bordered
  // determinants get the same factor L2^(m-1) L1, which cancels in R.
  std::int64_t L2 = 1;
  for (int i = 1; i < M; ++i) L2 = L2 / std::gcd(L2, denominator_lcm(D2[static_cast<std::size_t>(i)])) *
                                   denominator_lcm(D2[static_cast<std::size_t>(i)]);
  const std::int64_t L1 = denominator_lcm(D1[static_cast<std::size_t>(M)]);
  auto integer = [](const rational& v, std::int64_t scale) {
    const rational scaled = v * rational(scale);
    if (scaled.den != 1) throw std::logic_error("geomint::exact_two_step: weight scaling is not integral");
    return scaled.num;
  };
  // The start momentum is -(B X_0 + A X_m) only for nodes symmetric about 1/2.
  const auto c = nodes<Family, M, rational>();
  for (int i = 0; i <= M; ++i)
    if (c[static_cast<std::size_t>(i)] + c[static_cast<std::size_t>(M - i)] != rational(1))
      throw std::logic_error("geomint::exact_two_step: the derivation needs nodes symmetric about 1/2");

  // Rows 0..m-2: interior nodes 1..m-1; row m-1: the end momentum. Columns 0..m-2: interior
  // nodes; column m-1: node 0; column m: node m.
  poly a[M][M + 1]{};
  auto node_of_column = [](int col) { return col < M - 1 ? col + 1 : (col == M - 1 ? 0 : M); };
  for (int row = 0; row < M - 1; ++row)
    for (int col = 0; col <= M; ++col) {
      const int i = row + 1, j = node_of_column(col);
      poly& e = a[row][col];
      e[0] = big(integer(D2[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], L2));
      if (i == j) e[1] = big(L2);  // + s X_i (the potential's force, times tau^2)
      e.trim();
    }
  for (int col = 0; col <= M; ++col) {
    poly& e = a[M - 1][col];
    e[0] = big(integer(D1[static_cast<std::size_t>(M)][static_cast<std::size_t>(node_of_column(col))], L1));
    e.trim();
  }

  // Fraction-free elimination (Bareiss): after step k the entry (i, j) is the minor on rows
  // 0..k, i and columns 0..k, j. The pivots are the leading principal minors of M(s), whose
  // leading term is (L2 s)^(k+1), so none vanishes and the divisions are exact.
  poly previous(big(1));
  for (int k = 0; k < M - 1; ++k) {
    for (int i = k + 1; i < M; ++i)
      for (int j = k + 1; j <= M; ++j) a[i][j] = exact_quotient(a[k][k] * a[i][j] - a[i][k] * a[k][j], previous);
    previous = a[k][k];
  }
  // A det M = det(bordered with column 0), B det M = det(bordered with column m).
  const poly& A = a[M - 1][M - 1];
  const poly& B = a[M - 1][M];
  return finish_two_step<D>(M, A, B);
}

/// The midpoint VI (scheme 17): L_d(x0, x1) = tau L(x(1/2), x'(1/2)) on the linear path
/// x(c) = (1 - c) x0 + c x1. Its end momentum (times tau) is
///   A x0 + B x1,  A = phi0'(b) phi1'(b) - s phi0(b) phi1(b),  B = phi1'(b)^2 - s phi1(b)^2,
/// at b = 1/2 with phi0 = 1 - c, phi1 = c; scaled by 4 to integers.
constexpr exact_two_step_scheme midpoint_two_step() {
  using big = big_integer<exact_limbs>;
  using poly = exact_poly<2>;
  const rational b(1, 2), phi0 = rational(1) - b, phi1 = b, dphi0(-1), dphi1(1);
  const rational a0 = dphi0 * dphi1, a1 = -(phi0 * phi1), b0 = dphi1 * dphi1, b1 = -(phi1 * phi1);
  const std::int64_t scale = denominator_lcm(std::array<rational, 4>{a0, a1, b0, b1});
  poly A, B;
  A[0] = big((a0 * rational(scale)).num);
  A[1] = big((a1 * rational(scale)).num);
  B[0] = big((b0 * rational(scale)).num);
  B[1] = big((b1 * rational(scale)).num);
  A.trim();
  B.trim();
  return finish_two_step<2>(0, A, B);
}

}  // namespace analysis::detail

/// The LPF scheme's exact two-step form for the harmonic oscillator (eq. 15) on an exact node
/// family: eq. (16) for m = 2, (18) for m = 3, (19) for m = 4 (equispaced), m up to 8.
template <int M, class Family = equispaced>
constexpr exact_two_step_scheme exact_two_step() {
  static_assert(node_family<Family>,
                "geomint::exact_two_step: Family must be a node family (geomint::node_family, core/nodes.hpp)");
  static_assert(M >= 2 && M <= max_exact_m, "geomint::exact_two_step: m must be in 2..8");
  if constexpr (node_family<Family>) {
    static_assert(Family::is_rational,
                  "geomint::exact_two_step: the node family must be exact (rational nodes, e.g. equispaced)");
    if constexpr (Family::is_rational && M >= 2 && M <= max_exact_m) return analysis::detail::lpf_two_step<M, Family>();
  }
  return {};
}

/// The midpoint variational integrator's exact two-step form: eq. (17), R = (8 - 2s)/(4 + s).
constexpr exact_two_step_scheme exact_midpoint_two_step() { return analysis::detail::midpoint_two_step(); }

/// The results as constexpr variables (each evaluated once per program).
template <int M, class Family = equispaced>
inline constexpr exact_two_step_scheme exact_two_step_v = exact_two_step<M, Family>();
inline constexpr exact_two_step_scheme exact_midpoint_two_step_v = exact_midpoint_two_step();

}  // namespace geomint