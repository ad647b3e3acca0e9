#pragma once
/// The exact RKN tableaux (analysis/stage_algebra.hpp) as numeric tableaux (c, a, bbar, b) in a
/// scalar type T, in the methods' run-time form of a tableau (methods::tableau_data,
/// methods/tableau.hpp), with the nodes computed numerically (core/nodes.hpp).

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "geomint/analysis/collocation_tableaux.hpp"
#include "geomint/analysis/stage_algebra.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/methods/collocation_rkn.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint {

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
