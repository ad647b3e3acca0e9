#pragma once
/// A composition of a base method as data: the steps gamma_1 h, ..., gamma_k h of the base
/// method in turn (Yoshida 1990, Phys. Lett. A 150, 262-268; Hairer, Lubich & Wanner 2006,
/// section II.4; docs/references.md). It runs through the same integrator as any tableau: its
/// stages are those of the k sub-steps (methods/nystrom_form.hpp, nystrom_form_of).
///
///   auto r = field_element::generator(algebraic_field::make({-2, 0, 0, 1}));  // 2^(1/3)
///   composition<rkn<field_element, 2>, 3> triple_jump{verlet, {1 / (2 - r), -r / (2 - r), 1 / (2 - r)}};
///
/// The coefficients of the composed method (compose_coefficients below) are written here once,
/// constexpr over fixed-size tableaux and over the run-time form of nystrom_form.hpp alike:
/// tableau_of gives a composition of an rkn or nystrom tableau as one fixed-size tableau, so its
/// series is exact at compile time (analysis/bseries/nystrom_weights.hpp).

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

template <class Base, int K>
struct composition {
  static_assert(K >= 1, "geomint::methods::composition: at least one sub-step");
  using base_type = Base;
  using coefficient = typename Base::coefficient;
  static constexpr int steps = K;
  Base base;
  std::array<coefficient, static_cast<std::size_t>(K)> gamma{};
};

namespace detail {
/// The steps gamma_1 h .. gamma_k h of a Nystrom method (c, a, bbar, b, and ap if it has
/// velocity stages; d of q1 = q + d h v + h^2 sum_j bbar_j F_j) as one method of s k stages,
/// written into `out`, whose c, a, bbar, b (and ap, if it has one) hold s k entries of zero on
/// entry; returns the composed d. With sub-step l starting at (q_l, v_l),
/// G_l = gamma_1 + ... + gamma_{l-1}:
///   v_l = v + h sum_{m<l} gamma_m sum_j b_j F_mj,
///   q_l = q + d G_l h v + h^2 sum_{m<l} (gamma_m^2 bbar_j + d gamma_m (G_l - G_{m+1}) b_j) F_mj,
/// and the stages of sub-step l are the base's from (q_l, v_l) with step gamma_l h. Indexing
/// only, so std::array (fixed-size tableaux) and std::vector (nystrom_form) alike.
template <class K, class Base, class Gamma, class Out>
constexpr K compose_coefficients(const Base& base, const K& d, const Gamma& gamma, Out& out) {
  const std::size_t s = base.c.size(), k = gamma.size();
  std::vector<K> G(k + 1, K(0));
  for (std::size_t l = 0; l < k; ++l) G[l + 1] = G[l] + gamma[l];
  // The coefficient of h^2 F_mj in q_l (m < l).
  const auto in_position = [&](std::size_t l, std::size_t m, std::size_t j) {
    const K& g = gamma[m];
    return K(g * g * base.bbar[j] + d * g * (G[l] - G[m + 1]) * base.b[j]);
  };
  for (std::size_t l = 0; l < k; ++l) {
    const K& gl = gamma[l];
    for (std::size_t i = 0; i < s; ++i) {
      const std::size_t row = l * s + i;
      const K& ci = base.c[i];
      out.c[row] = d * G[l] + ci * gl;
      for (std::size_t m = 0; m < l; ++m)
        for (std::size_t j = 0; j < s; ++j) {
          const std::size_t col = m * s + j;
          const K gb = gamma[m] * base.b[j];
          out.a[row][col] = in_position(l, m, j) + ci * gl * gb;
          if constexpr (requires(Out& o) { o.ap; }) out.ap[row][col] = gb;
        }
      for (std::size_t j = 0; j < s; ++j) {
        const std::size_t col = l * s + j;
        out.a[row][col] = gl * gl * base.a[i][j];
        if constexpr (requires(const Base& b) { b.ap; }) out.ap[row][col] = gl * base.ap[i][j];
      }
    }
  }
  for (std::size_t m = 0; m < k; ++m)
    for (std::size_t j = 0; j < s; ++j) {
      out.bbar[m * s + j] = in_position(k, m, j);
      out.b[m * s + j] = gamma[m] * base.b[j];
    }
  return d * G[k];
}

/// Every coefficient of a fixed-size tableau set to zero (K(0), not K{}: a coefficient type
/// need not be zero when default-constructed).
template <class Tableau>
constexpr Tableau zero_tableau() {
  using K = typename Tableau::coefficient;
  Tableau t{};
  const auto clear = [](auto& x) {
    for (auto& e : x) e = K(0);
  };
  clear(t.c);
  clear(t.bbar);
  clear(t.b);
  for (auto& row : t.a) clear(row);
  if constexpr (requires(Tableau& x) { x.ap; })
    for (auto& row : t.ap) clear(row);
  return t;
}

/// The tableau type of the same kind with N stages (rkn and nystrom).
template <class Tableau, int N>
struct with_stages;
template <class K, int S, int N>
struct with_stages<rkn<K, S>, N> {
  using type = rkn<K, N>;
};
template <class K, int S, int N>
struct with_stages<nystrom<K, S>, N> {
  using type = nystrom<K, N>;
};
}  // namespace detail

/// A composition as one fixed-size tableau, with the coefficient d of q1 = q + d h v + ...
/// (d = gamma_1 + ... + gamma_k: 1 for a consistent composition; the tableau types fix d = 1).
template <class Tableau>
struct composed_tableau {
  Tableau tableau;
  typename Tableau::coefficient d;
};

/// The tableau of s M stages of a composition of M steps of an rkn or nystrom tableau of s
/// stages (an rkn stays rkn; a nystrom tableau's velocity stages ap are composed too); see
/// detail::compose_coefficients. constexpr over geomint::rational.
template <class Base, int M>
  requires(Base::kind == method_kind::rkn || Base::kind == method_kind::nystrom)
constexpr auto tableau_of(const composition<Base, M>& t) {
  using K = typename Base::coefficient;
  using Tableau = typename detail::with_stages<std::remove_cv_t<Base>, Base::stages * M>::type;
  composed_tableau<Tableau> out{detail::zero_tableau<Tableau>(), K(1)};
  out.d = detail::compose_coefficients(t.base, K(1), t.gamma, out.tableau);
  return out;
}

}  // namespace geomint::methods
