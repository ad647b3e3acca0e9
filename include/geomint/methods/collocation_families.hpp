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
/// and Radau with s = 4, 5 (their nodes generate fields of degree 8 and more; not here; the
/// Gauss methods of any s as RKN tableaux are `galerkin_tableau<s>` of analysis/rkn_tableau.hpp).
/// The coefficients are field_element over that one field (methods/number_field.hpp), solved
/// from the conditions above in exact arithmetic.

#include <stdexcept>
#include <type_traits>
#include <string>
#include <vector>

#include "geomint/methods/number_field.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

/// The collocation-type families of this header.
enum class collocation_family { gauss, radau_iia, radau_ia, lobatto_iiia, lobatto_iiib, lobatto_iiic, lobatto_iiia_iiib };

namespace detail {

using field_vector = std::vector<field_element>;
using field_matrix = std::vector<field_vector>;

/// Solves M x = y exactly (Gaussian elimination with an exactly nonzero pivot).
inline field_vector solve_exact(field_matrix m, field_vector y) {
  const std::size_t n = y.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    while (p < n && m[p][k].is_zero()) ++p;
    if (p == n) throw std::logic_error("collocation_families: singular system (repeated nodes?)");
    std::swap(m[p], m[k]);
    std::swap(y[p], y[k]);
    for (std::size_t i = k + 1; i < n; ++i) {
      if (m[i][k].is_zero()) continue;
      const field_element f = m[i][k] / m[k][k];
      for (std::size_t j = k; j < n; ++j) m[i][j] -= f * m[k][j];
      y[i] -= f * y[k];
    }
  }
  field_vector x(n);
  for (std::size_t i = n; i-- > 0;) {
    field_element s = y[i];
    for (std::size_t j = i + 1; j < n; ++j) s -= m[i][j] * x[j];
    x[i] = s / m[i][i];
  }
  return x;
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

/// The nodes of a family with s stages (ascending), over Q or Q(sqrt d) (Hairer & Wanner II,
/// section IV.5): the roots of the shifted Legendre polynomial P_s (Gauss), of
/// P_s - P_{s-1} (right Radau, c_s = 1), P_s + P_{s-1} (left Radau, c_1 = 0), and
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
      break;
    case collocation_family::radau_iia:
      if (s == 2) return {q(1, 3), q(1, 1)};
      if (s == 3) {
        const field_element r = sqrt_of(6);
        return {(q(4, 1) - r) / q(10, 1), (q(4, 1) + r) / q(10, 1), q(1, 1)};
      }
      break;
    case collocation_family::radau_ia:
      if (s == 2) return {q(0, 1), q(2, 3)};
      if (s == 3) {
        const field_element r = sqrt_of(6);
        return {q(0, 1), (q(6, 1) - r) / q(10, 1), (q(6, 1) + r) / q(10, 1)};
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
template <int S>
using radau_iia = collocation_method<collocation_family::radau_iia, S>;
template <int S>
using radau_ia = collocation_method<collocation_family::radau_ia, S>;
template <int S>
using lobatto_iiia = collocation_method<collocation_family::lobatto_iiia, S>;
template <int S>
using lobatto_iiib = collocation_method<collocation_family::lobatto_iiib, S>;
template <int S>
using lobatto_iiic = collocation_method<collocation_family::lobatto_iiic, S>;
template <int S>
using lobatto_iiia_iiib = collocation_method<collocation_family::lobatto_iiia_iiib, S>;

}  // namespace geomint::methods
