#pragma once
/// The classical implicit Runge-Kutta families, generated exactly in one place from their nodes
/// and the simplifying assumptions that define them (Hairer & Wanner, Solving ODEs II, section
/// IV.5; Hairer, Lubich & Wanner 2006, section II.1.4; docs/references.md):
///
/// - B(s): sum_j b_j c_j^(k-1) = 1/k;  C(s): sum_j a_ij c_j^(k-1) = c_i^k / k;
///   D(s): sum_i b_i c_i^(k-1) a_ij = b_j (1 - c_j^k) / k  (k = 1..s);
/// - Gauss (Butcher 1964): Gauss nodes, C(s); order 2s;
/// - Radau IIA (Ehle 1969): right Radau nodes (c_s = 1), C(s); order 2s - 1;
/// - Radau IA (Ehle 1969): left Radau nodes (c_1 = 0), D(s); order 2s - 1;
/// - Lobatto IIIA: Lobatto nodes, C(s); IIIB: Lobatto nodes, D(s); order 2s - 2;
/// - Lobatto IIIC (Chipman 1971): a_i1 = b_1 and C(s - 1); order 2s - 2;
/// - the Lobatto IIIA-IIIB pair: the prk with (A, b) = IIIA and (Ahat, b) = IIIB; order 2s - 2,
///   symplectic (b_i ahat_ij + b_j a_ji = b_i b_j).
///
/// A D(s) method is the symplectic complement of the C(s) method on its nodes:
/// ahat_ij = b_j (1 - a_ji / b_i) satisfies D(s) when a satisfies C(s) and b B(s), and D(s)
/// determines A given the nodes (a Vandermonde system per column), so Radau IA and Lobatto IIIB
/// are the complements of collocation on their nodes.
///
/// The nodes of s = 2..5 lie in Q or in a quadratic field Q(sqrt d) for every family but Gauss
/// with s = 4, 5 and Radau with s = 4. There the irrational nodes are the roots x_1 < x_2 < ...
/// of an irreducible quartic (Gauss; Galois group D4) or cubic (Radau; S3), and every entry of
/// the tableau lies in their splitting field, of degree 8 (Gauss) or 6 (Radau): Q(theta) with
/// theta = x_1 + 2 x_2, whose minimal polynomial is given where family_nodes uses it (computed
/// once with SymPy's minimal_polynomial; tests/methods/test_catalogue.cpp checks every node
/// against its family's polynomial, and the quadrature and simplifying conditions of the
/// tableau). The nodes are found exactly in Q(theta): x_2 is the one common root of N(z) and
/// N(theta - 2 z) (a gcd over Q(theta)), x_1 = theta - 2 x_2, and the others follow from the
/// symmetry x -> 1 - x of the Gauss nodes or from the sum of the roots of the cubic. Radau with
/// s = 5 is not here: the splitting field of its quartic has Galois group S4 and degree 24 (the
/// series of Gauss s = 5, in degree 8, already cost seconds per tree order); it is analysed over
/// its stage algebra Q[x]/(N) instead (methods/collocation_algebra.hpp). The Gauss methods of
/// any s as RKN tableaux over their stage algebra are `galerkin_tableau<s>` of
/// analysis/collocation_tableaux.hpp.
/// The coefficients are field_element over that one field (methods/number_field.hpp), solved
/// from the conditions above in exact arithmetic.

#include <stdexcept>
#include <string>
#include <type_traits>
#include <tuple>
#include <utility>
#include <vector>

#include "geomint/core/nodes.hpp"
#include "geomint/core/orthogonal_polynomials.hpp"
#include "geomint/methods/number_field.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

/// The collocation-type families of this header.
enum class collocation_family { gauss, radau_iia, radau_ia, lobatto_iiia, lobatto_iiib, lobatto_iiic, lobatto_iiia_iiib };

namespace detail {

using field_vector = std::vector<field_element>;
using field_matrix = std::vector<field_vector>;

/// Solves M x = y exactly (Gaussian elimination with an exactly nonzero pivot) over an exact K
/// (field_element, exact_rational); std::logic_error when M is singular.
template <class K>
std::vector<K> solve_exact(std::vector<std::vector<K>> m, std::vector<K> y) {
  const std::size_t n = y.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    while (p < n && m[p][k].is_zero()) ++p;
    if (p == n) throw std::logic_error("collocation_families: singular system (repeated nodes?)");
    std::swap(m[p], m[k]);
    std::swap(y[p], y[k]);
    for (std::size_t i = k + 1; i < n; ++i) {
      if (m[i][k].is_zero()) continue;
      const K f = m[i][k] / m[k][k];
      for (std::size_t j = k; j < n; ++j) m[i][j] -= f * m[k][j];
      y[i] -= f * y[k];
    }
  }
  std::vector<K> x(n);
  for (std::size_t i = n; i-- > 0;) {
    K s = y[i];
    for (std::size_t j = i + 1; j < n; ++j) s -= m[i][j] * x[j];
    x[i] = s / m[i][i];
  }
  return x;
}

/// The shifted Legendre polynomial P_n(2x - 1) over Q (constant first), n <= 8
/// (core/orthogonal_polynomials.hpp).
inline poly shifted_legendre(int n) {
  const auto p = shifted_orthogonal_polynomial<exact_rational, 9>(shifted_orthogonal_kind::legendre, n);
  return poly(p.begin(), p.begin() + n + 1);
}

/// Polynomials in z over Q(theta) (constant first, no zero leading coefficient).
using field_poly = std::vector<field_element>;
inline void trim(field_poly& p) {
  while (!p.empty() && p.back().is_zero()) p.pop_back();
}
/// p mod q (q with a nonzero leading coefficient).
inline field_poly remainder(field_poly p, const field_poly& q) {
  trim(p);
  while (p.size() >= q.size()) {
    const std::size_t shift = p.size() - q.size();
    const field_element f = p.back() / q.back();
    for (std::size_t i = 0; i < q.size(); ++i) p[shift + i] -= f * q[i];
    p.pop_back();
    trim(p);
  }
  return p;
}

/// The splitting field Q(theta) of the irreducible part of a family's node polynomial: theta =
/// x_1 + 2 x_2 (x_1 < x_2 the two smallest roots), the root of `minimal` (integers, constant
/// first) nearest `near`.
struct splitting_field {
  std::vector<long> minimal;
  exact_rational near;
};

/// x_1 and x_2 of the irreducible polynomial n (over Q, constant first) in Q(theta): x_2 is the
/// common root of n(z) and n(theta - 2 z), the last nonzero remainder of Euclid's algorithm.
inline std::pair<field_element, field_element> two_smallest_roots(const poly& n, const splitting_field& f) {
  std::vector<exact_rational> m;
  for (long k : f.minimal) m.push_back(exact_rational(k));
  const field_element theta = field_element::generator(algebraic_field::make(m, f.near));
  field_poly a, b{field_element(0)};
  for (const auto& x : n) a.push_back(field_element(x));
  // n(theta - 2 z) by Horner's rule in z.
  const field_poly shift{theta, field_element(-2)};
  for (std::size_t k = n.size(); k-- > 0;) {
    field_poly next(b.size() + 1, field_element(0));
    for (std::size_t i = 0; i < b.size(); ++i)
      for (std::size_t j = 0; j < 2; ++j) next[i + j] += b[i] * shift[j];
    next[0] += field_element(n[k]);
    b = std::move(next);
  }
  trim(b);
  while (!b.empty()) {
    field_poly r = remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  if (a.size() != 2) throw std::logic_error("collocation_families: the splitting field does not single out x_2");
  const field_element x2 = -a[0] / a[1];
  return {theta - field_element(2) * x2, x2};
}

inline field_element power(const field_element& x, int k) {
  field_element out(1);
  for (int i = 0; i < k; ++i) out *= x;
  return out;
}

/// b from B(s).
inline field_vector quadrature_weights(const field_vector& c) {
  const std::size_t s = c.size();
  field_matrix m(s, field_vector(s));
  field_vector y(s);
  for (std::size_t k = 0; k < s; ++k) {
    for (std::size_t j = 0; j < s; ++j) m[k][j] = power(c[j], static_cast<int>(k));
    y[k] = field_element(exact_rational(1, static_cast<long>(k + 1)));
  }
  return solve_exact(m, y);
}

/// Row i of A from sum_j a_ij c_j^(k-1) = c_i^k / k for k = 1..s (C(s)), or, with the first
/// entry fixed to `first`, for k = 1..s-1 on the other entries (a_i1 = b_1 and C(s - 1)).
inline field_vector collocation_row(const field_vector& c, std::size_t i, const field_element* first = nullptr) {
  const std::size_t s = c.size(), off = first ? 1 : 0, n = s - off;
  field_matrix m(n, field_vector(n));
  field_vector y(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t j = 0; j < n; ++j) m[k][j] = power(c[j + off], static_cast<int>(k));
    y[k] = power(c[i], static_cast<int>(k + 1)) * field_element(exact_rational(1, static_cast<long>(k + 1)));
    if (first) y[k] -= *first * power(c[0], static_cast<int>(k));
  }
  field_vector row = solve_exact(m, y);
  if (first) row.insert(row.begin(), *first);
  return row;
}

/// The symplectic complement ahat_ij = b_j (1 - a_ji / b_i).
inline field_matrix complement(const field_matrix& a, const field_vector& b) {
  const std::size_t s = b.size();
  field_matrix out(s, field_vector(s));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) out[i][j] = b[j] * (field_element(1) - a[j][i] / b[i]);
  return out;
}

/// The three roots below 1 of P_4(2x - 1) - P_3(2x - 1) (the right Radau nodes of s = 4, the
/// roots of an irreducible cubic: radau_right's interior polynomial, core/nodes.hpp) in its
/// splitting field; theta = x_1 + 2 x_2 = 0.90752168...
inline std::tuple<field_element, field_element, field_element> right_radau_4_interior() {
  const auto interior = radau_right::interior_polynomial<exact_rational, 4>(4);
  const poly cubic(interior.begin(), interior.end());
  const splitting_field field{{163593, -911250, 2031075, -2324700, 1444275, -463050, 60025}, exact_rational(907522, 1000000)};
  const auto [x1, x2] = two_smallest_roots(cubic, field);
  const field_element sum = field_element(-cubic[2] / cubic[3]);
  return {x1, x2, sum - x1 - x2};
}

/// The nodes of a family with s stages (ascending), over Q, Q(sqrt d) or the splitting field
/// above (Hairer & Wanner II, section IV.5): the roots of the shifted Legendre polynomial P_s
/// (Gauss), of P_s - P_{s-1} (right Radau, c_s = 1), P_s + P_{s-1} (left Radau, c_1 = 0), and
/// x (1 - x) P'_{s-1} (Lobatto). std::invalid_argument for s outside the catalogue.
inline field_vector family_nodes(collocation_family f, int s) {
  auto q = [](long n, long d) { return field_element(exact_rational(n, d)); };
  auto sqrt_of = [](long d) { return field_element::generator(algebraic_field::make({exact_rational(-d), 0, 1})); };
  switch (f) {
    case collocation_family::gauss:
      if (s == 2) {
        const field_element r = sqrt_of(3);
        return {q(1, 2) - r / q(6, 1), q(1, 2) + r / q(6, 1)};
      }
      if (s == 3) {
        const field_element r = sqrt_of(15);
        return {q(1, 2) - r / q(10, 1), q(1, 2), q(1, 2) + r / q(10, 1)};
      }
      if (s == 4) {
        // The roots of P_4(2x - 1); theta = x_1 + 2 x_2 = 0.72945080...
        const splitting_field field{{375021, -2763936, 8420076, -13889736, 13613376, -8149680, 2922360, -576240, 48020},
                                    exact_rational(729451, 1000000)};
        const auto [x1, x2] = two_smallest_roots(shifted_legendre(4), field);
        return {x1, x2, q(1, 1) - x2, q(1, 1) - x1};
      }
      if (s == 5) {
        // The roots of P_5(2x - 1) / (x - 1/2); theta = x_1 + 2 x_2 = 0.50844076...
        poly quartic, rest;
        divide(shifted_legendre(5), {exact_rational(-1, 2), exact_rational(1)}, quartic, rest);
        const splitting_field field{
            {5851441, -51417072, 178740828, -323775144, 338158800, -210896784, 77443128, -15431472, 1285956},
            exact_rational(508441, 1000000)};
        const auto [x1, x2] = two_smallest_roots(quartic, field);
        return {x1, x2, q(1, 2), q(1, 1) - x2, q(1, 1) - x1};
      }
      break;
    case collocation_family::radau_iia:
      if (s == 2) return {q(1, 3), q(1, 1)};
      if (s == 3) {
        const field_element r = sqrt_of(6);
        return {(q(4, 1) - r) / q(10, 1), (q(4, 1) + r) / q(10, 1), q(1, 1)};
      }
      if (s == 4) {
        const auto [x1, x2, x3] = right_radau_4_interior();
        return {x1, x2, x3, q(1, 1)};
      }
      break;
    case collocation_family::radau_ia:
      if (s == 2) return {q(0, 1), q(2, 3)};
      if (s == 3) {
        const field_element r = sqrt_of(6);
        return {q(0, 1), (q(6, 1) - r) / q(10, 1), (q(6, 1) + r) / q(10, 1)};
      }
      if (s == 4) {
        // Left Radau nodes are 1 - the right Radau nodes (P_s(-y) = (-1)^s P_s(y)).
        const auto [x1, x2, x3] = right_radau_4_interior();
        return {q(0, 1), q(1, 1) - x3, q(1, 1) - x2, q(1, 1) - x1};
      }
      break;
    case collocation_family::lobatto_iiia:
    case collocation_family::lobatto_iiib:
    case collocation_family::lobatto_iiic:
    case collocation_family::lobatto_iiia_iiib:
      if (s == 2) return {q(0, 1), q(1, 1)};
      if (s == 3) return {q(0, 1), q(1, 2), q(1, 1)};
      if (s == 4) {
        const field_element r = sqrt_of(5);
        return {q(0, 1), q(1, 2) - r / q(10, 1), q(1, 2) + r / q(10, 1), q(1, 1)};
      }
      if (s == 5) {
        const field_element r = sqrt_of(21);
        return {q(0, 1), q(1, 2) - r / q(14, 1), q(1, 2), q(1, 2) + r / q(14, 1), q(1, 1)};
      }
      break;
  }
  throw std::invalid_argument("collocation_families: no such family member in the catalogue (s = " + std::to_string(s) + ")");
}

}  // namespace detail

/// The tableau of a family with s stages (rk; prk for the IIIA-IIIB pair), exact.
inline tableau_data<field_element> collocation_family_tableau(collocation_family f, int s) {
  const detail::field_vector c = detail::family_nodes(f, s);
  const detail::field_vector b = detail::quadrature_weights(c);
  const auto n = static_cast<std::size_t>(s);
  detail::field_matrix collocation(n);
  if (f != collocation_family::lobatto_iiic)
    for (std::size_t i = 0; i < n; ++i) collocation[i] = detail::collocation_row(c, i);
  tableau_data<field_element> t;
  t.kind = method_kind::rk;
  t.stages = s;
  t.c = c;
  t.b = b;
  switch (f) {
    case collocation_family::gauss:
    case collocation_family::radau_iia:
    case collocation_family::lobatto_iiia: t.a = collocation; break;
    case collocation_family::radau_ia:
    case collocation_family::lobatto_iiib: t.a = detail::complement(collocation, b); break;
    case collocation_family::lobatto_iiic:
      for (std::size_t i = 0; i < n; ++i) t.a.push_back(detail::collocation_row(c, i, &b[0]));
      break;
    case collocation_family::lobatto_iiia_iiib:
      t.kind = method_kind::prk;
      t.a = collocation;
      t.ahat = detail::complement(collocation, b);
      t.bhat = b;
      break;
  }
  return t;
}

namespace detail {
template <class Fixed>
Fixed fixed_size(const tableau_data<field_element>& d) {
  Fixed t;
  constexpr auto S = static_cast<std::size_t>(Fixed::stages);
  for (std::size_t i = 0; i < S; ++i) {
    t.c[i] = d.c[i];
    t.b[i] = d.b[i];
    for (std::size_t j = 0; j < S; ++j) t.a[i][j] = d.a[i][j];
    if constexpr (Fixed::kind == method_kind::prk) {
      t.bhat[i] = d.bhat[i];
      for (std::size_t j = 0; j < S; ++j) t.ahat[i][j] = d.ahat[i][j];
    }
  }
  return t;
}
}  // namespace detail

/// The families as schemes of the one integrator: integrator<tableau_method<gauss<3>>, Sys, T>.
template <collocation_family F, int S>
struct collocation_method {
  static auto tableau() {
    using fixed = std::conditional_t<F == collocation_family::lobatto_iiia_iiib, prk<field_element, S>, rk<field_element, S>>;
    return detail::fixed_size<fixed>(collocation_family_tableau(F, S));
  }
};
template <int S>
using gauss = collocation_method<collocation_family::gauss, S>;
// radau_iia<S> and radau_ia<S>: methods/collocation_algebra.hpp (s = 5 over its stage algebra).
template <int S>
using lobatto_iiia = collocation_method<collocation_family::lobatto_iiia, S>;
template <int S>
using lobatto_iiib = collocation_method<collocation_family::lobatto_iiib, S>;
template <int S>
using lobatto_iiic = collocation_method<collocation_family::lobatto_iiic, S>;
template <int S>
using lobatto_iiia_iiib = collocation_method<collocation_family::lobatto_iiia_iiib, S>;

}  // namespace geomint::methods
