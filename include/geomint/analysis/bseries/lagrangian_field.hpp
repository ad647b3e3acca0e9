#pragma once
/// The Euler-Lagrange equations of any Lagrangian system as a first-order field in (q, v), for
/// the elementary differentials of elementary_differentials.hpp, and its energy.
///
/// For L(q, qdot) with L_vv regular the Euler-Lagrange equations are q'' = F(q, q'),
///   F = L_vv^{-1} (L_q - L_vq qdot)
/// (mechanics/lagrangian.hpp, lagrangian_derivatives; docs/results/schemes.md, "LPF as a
/// Nystrom method", item 1), so y = (q, v) obeys q' = v (colour 0), v' = F(q, v) (colour 1): the
/// first-order form on which a Nystrom method is a partitioned method (partitioned_form.hpp).
/// The derivatives of L are by two levels of AD over the field's scalar S, and the linear solve
/// is done in S, so the field can itself be differentiated (S a dual or jet type). The energy
/// E(q, v) = v . L_v - L is what LPF's H(q_n, p_n) is at v_n = the inverse Legendre map of p_n.

#include <cmath>
#include <stdexcept>
#include <utility>

#include "geomint/ad/dual.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/mechanics/lagrangian.hpp"

namespace geomint::analysis::bseries {

namespace detail {
/// x with A x = b by Gaussian elimination with partial pivoting in the scalar S itself, whose
/// comparisons look at values only (a dual or jet: the derivatives of x follow); false at an
/// exactly zero pivot. (linalg/lu_small.hpp solves in double-backed or plain scalars only.)
template <class S, int n>
bool solve_in_scalar(mat<S, n> A, vec<S, n> b, vec<S, n>& x) {
  using std::abs;
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    for (int i = k + 1; i < n; ++i)
      if (abs(A(i, k)) > abs(A(pivot, k))) pivot = i;
    if (A(pivot, k) == S(0)) return false;
    if (pivot != k) {
      A.row(k).swap(A.row(pivot));
      std::swap(b[k], b[pivot]);
    }
    for (int i = k + 1; i < n; ++i) {
      const S factor = A(i, k) / A(k, k);
      for (int j = k + 1; j < n; ++j) A(i, j) -= factor * A(k, j);
      b[i] -= factor * b[k];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    S sum = b[i];
    for (int j = i + 1; j < n; ++j) sum -= A(i, j) * x[j];
    x[i] = sum / A(i, i);
  }
  return true;
}
}  // namespace detail

/// q' = v, v' = F(q, v) for the Lagrangian system Sys (a field of elementary_differentials.hpp
/// with colour_split dof). std::domain_error where L_vv is singular.
template <lagrangian_system Sys>
struct lagrangian_field {
  static constexpr int dof = Sys::dof;
  static constexpr int dimension = 2 * dof;
  static constexpr int colour_split = dof;
  Sys system{};

  template <class S>
  vec<S, dimension> operator()(const vec<S, dimension>& y) const {
    const vec<S, dof> q = y.head(dof), v = y.tail(dof);
    const hessian_data<S, dof> h = lagrangian_derivatives<Sys, S>::hessian(system, q, v);
    vec<S, dof> a;
    if (!detail::solve_in_scalar<S, dof>(h.Lvv, vec<S, dof>(h.Lq - h.Lvq * v), a))
      throw std::domain_error("geomint::analysis::bseries::lagrangian_field: L_vv is singular at the state");
    vec<S, dimension> out;
    out << v, a;
    return out;
  }

  /// E(q, v) = v . L_v - L at y = (q, v).
  template <class T>
  T energy(const vec<T, dimension>& y) const {
    return energy_qv<Sys, T>(system, vec<T, dof>(y.head(dof)), vec<T, dof>(y.tail(dof)));
  }

  /// grad E at y = (q, v), by one level of AD over the 2 dof coordinates.
  template <class T>
  vec<T, dimension> energy_gradient(const vec<T, dimension>& y) const {
    using D = dual<T, dimension>;
    vec<D, dimension> x;
    for (int i = 0; i < dimension; ++i) x[i] = D::variable(y[i], i);
    const D e = energy<D>(x);
    vec<T, dimension> g;
    for (int i = 0; i < dimension; ++i) g[i] = e.d[static_cast<std::size_t>(i)];
    return g;
  }
};

}  // namespace geomint::analysis::bseries
