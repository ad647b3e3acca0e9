#pragma once
/// Exactly symplectic rounding of an RKN tableau in a binary floating-point scalar T (as
/// RungeKutta.jl's `symplecticize`, and the coefficients of IRKGL16: Antonana, Makazaga & Murua
/// 2017; docs/references.md).
///
/// An RKN method (c, a, bbar, b) for q'' = f(q) with all b_j != 0 is symplectic if and only if
/// bbar_i = b_i (1 - c_i) and b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji) (Suris 1989; Hairer,
/// Lubich & Wanner 2006, Theorem VI.4.3). With e_i = 1 - c_i and mu_ij = a_ij / b_j these read
///   bbar_i = b_i e_i,   mu_ji - mu_ij = e_i - e_j,
/// and b drops out. Rounded one by one, the stored coefficients miss these relations by an ulp,
/// and a step then leaves the symplectic manifold by that much every step. `symplecticize`
/// stores the method as (c, e, b, mu) with the relations exact in T: every c, e and mu a
/// multiple of a common grid g = 2^k eps (2^k >= every |c|, |e|, |mu|), on which the sums and
/// differences below are exact; c rounded to the grid, e_i = 1 - c_i, mu_ij (i <= j) rounded
/// and mu_ji = mu_ij + (e_i - e_j). The weights b are rounded as they are: any b keeps the
/// relations. The method this stores, a_ij = mu_ij b_j and bbar_i = e_i b_i with the products
/// taken exactly, satisfies Suris's conditions with no residual at all.
///
/// A symmetric method (c_i' = 1 - c_i, b_i' = b_i, mu_i'j' = mu_ij + c_j - c_i for the mirror
/// stage i' = s-1-i, within a few ulps in the input) keeps its symmetry exactly as well: c_i'
/// is set to 1 - c_i and each orbit {(i, j), (j, i), (i', j'), (j', i')} of mu comes from one
/// rounded value (`mirrored`; the fixed-point form of LPF relies on it,
/// schemes/gauss_fixed_point.hpp). An explicit method stays explicit: the zeros of mu_ij
/// (i <= j) are kept.

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

/// An RKN method stored with its symplecticity relations exact in T (see the top of the file).
template <class T, int S>
struct symplectic_rkn {
  stage_vector<T, S> c{}, e{}, b{};
  /// mu_ij = a_ij / b_j.
  stage_matrix<T, S> mu{};
  /// The grid every c, e and mu is a multiple of.
  T grid{};
  /// Whether the method's symmetry holds exactly too: c_i' = 1 - c_i, mu_i'j' = mu_ij + c_j - c_i.
  bool mirrored = false;

  /// The usual tableau: a_ij = mu_ij b_j and bbar_i = e_i b_i, each product rounded once (the
  /// relations hold exactly for the products taken in exact arithmetic, which is how a step
  /// that scales the forces by tau b_j first uses them).
  rkn<T, S> tableau() const {
    rkn<T, S> t;
    t.c = c;
    t.b = b;
    for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
      t.bbar[i] = e[i] * b[i];
      for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) t.a[i][j] = mu[i][j] * b[j];
    }
    return t;
  }
};

/// The exactly symplectic rounding of the symplectic RKN tableau t (computed in T, e.g. by
/// methods/coefficients.hpp from exact data, to a few ulps). std::domain_error if some b_j = 0
/// (the relations need a_ij / b_j) or if t is not symplectic to within 64 ulps of its largest
/// coefficient.
template <class T, int S>
symplectic_rkn<T, S> symplecticize(const rkn<T, S>& t) {
  static_assert(std::numeric_limits<T>::radix == 2 && !std::numeric_limits<T>::is_exact,
                "geomint::methods::symplecticize: T must be a binary floating-point scalar (the grid is a power of two)");
  using std::abs;
  using std::round;
  constexpr auto s = static_cast<std::size_t>(S);
  const T eps = std::numeric_limits<T>::epsilon();
  symplectic_rkn<T, S> k;
  stage_matrix<T, S> mu_in{};
  T largest(1);
  auto widen = [&](const T& x) {
    if (abs(x) > largest) largest = abs(x);
  };
  for (std::size_t i = 0; i < s; ++i) {
    if (t.b[i] == T(0))
      throw std::domain_error("geomint::methods::symplecticize: b_" + std::to_string(i + 1) +
                              " = 0 (the symplecticity relations divide by b)");
    widen(t.c[i]);
    widen(T(T(1) - t.c[i]));
  }
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      mu_in[i][j] = t.a[i][j] / t.b[j];
      widen(mu_in[i][j]);
    }
  // The input must be symplectic (and, for `mirrored`, symmetric) up to its own rounding.
  const T tol = T(64) * eps * largest;
  T largest_b(0);
  for (std::size_t i = 0; i < s; ++i)
    if (abs(t.b[i]) > largest_b) largest_b = abs(t.b[i]);
  for (std::size_t i = 0; i < s; ++i) {
    if (abs(T(t.bbar[i] - t.b[i] * (T(1) - t.c[i]))) > tol * largest_b)
      throw std::domain_error("geomint::methods::symplecticize: bbar_i = b_i (1 - c_i) fails: the tableau is not symplectic");
    for (std::size_t j = 0; j < s; ++j)
      if (abs(T((mu_in[j][i] - mu_in[i][j]) - (t.c[j] - t.c[i]))) > tol)
        throw std::domain_error(
            "geomint::methods::symplecticize: b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji) fails: the tableau is not symplectic");
  }
  k.mirrored = true;
  for (std::size_t i = 0; i < s && k.mirrored; ++i) {
    const std::size_t im = s - 1 - i;
    k.mirrored = abs(T(t.c[i] + t.c[im] - T(1))) <= tol && abs(T(t.b[i] - t.b[im])) <= tol * largest_b;
    for (std::size_t j = 0; j < s && k.mirrored; ++j)
      k.mirrored = abs(T(mu_in[im][s - 1 - j] - mu_in[i][j] - (t.c[j] - t.c[i]))) <= tol;
  }
  // The grid g = 2^k eps with 2^k >= every |value|: a multiple of g below 2^(k+1) in magnitude
  // has at most `digits` significant bits, so sums and differences of them that stay below
  // 2^(k+1) are exact.
  T scale(1);
  while (scale < largest) scale *= T(2);
  k.grid = scale * eps;
  auto on_grid = [&](const T& x) { return T(T(round(T(x / k.grid))) * k.grid); };
  for (std::size_t i = 0; i < s; ++i) {
    const std::size_t im = s - 1 - i;
    if (!k.mirrored || i >= im) k.c[i] = on_grid(t.c[i]);
  }
  if (k.mirrored)
    for (std::size_t i = 0; i < s; ++i)
      if (i < s - 1 - i) k.c[i] = T(1) - k.c[s - 1 - i];
  for (std::size_t i = 0; i < s; ++i) {
    k.e[i] = T(1) - k.c[i];
    k.b[i] = t.b[i];
  }
  // Each orbit from one rounded value: the transpose by mu_ji = mu_ij + e_i - e_j (symplectic),
  // and if mirrored the mirror by mu_i'j' = mu_ij + c_j - c_i (the symmetry) and mu_j'i' = mu_ij
  // (both).
  stage_matrix<bool, S> done{};
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = i; j < s; ++j) {
      if (done[i][j]) continue;
      const T m = on_grid(mu_in[i][j]);
      k.mu[i][j] = m;
      k.mu[j][i] = m + (k.e[i] - k.e[j]);
      done[i][j] = done[j][i] = true;
      if (k.mirrored) {
        const std::size_t im = s - 1 - i, jm = s - 1 - j;
        k.mu[im][jm] = m + (k.c[j] - k.c[i]);
        k.mu[jm][im] = m;
        done[im][jm] = done[jm][im] = true;
      }
    }
  return k;
}

}  // namespace geomint::methods
