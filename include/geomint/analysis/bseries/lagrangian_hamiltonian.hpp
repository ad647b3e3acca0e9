#pragma once
/// The Hamiltonian H(q, p) = p . v - L(q, v) of any Lagrangian system, v the inverse Legendre
/// map of p, as a functor templated on its scalar: the field y' = J^{-1} grad H of
/// hamiltonian_field (elementary_differentials.hpp) on y = (q, p), on which the Galerkin
/// variational integrator is the Gauss collocation Runge-Kutta method (HLW: Hairer, Lubich &
/// Wanner, Geometric Numerical Integration, 2nd ed. 2006, Theorem VI.6.4).
///
/// v solves L_v(q, v) = p by Newton's method in the scalar S itself (start v = 0; one step is
/// exact for L quadratic in v), with the linear solve of lagrangian_field.hpp, so for S a dual
/// or jet the derivatives of the implicitly defined v(q, p) are carried by the iteration: the
/// derivative parts are the Taylor coefficients of the Newton error, which converge with the
/// value. The iteration stops when the value part of the update is below 16 eps (1 + |v|), eps
/// of the base scalar. grad H = (-L_q(q, v), v) (the v-derivative of p . v - L vanishes at
/// L_v = p) is supplied as `gradient`, so hamiltonian_field needs no extra level of AD.

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geomint/ad/dual.hpp"
#include "geomint/ad/multilinear_jet.hpp"
#include "geomint/analysis/bseries/lagrangian_field.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/mechanics/lagrangian.hpp"

namespace geomint::analysis::bseries {

namespace detail {
/// The value part of a scalar (through every level of dual and jet).
template <class S>
S value_part(const S& x) { return x; }
template <class T, int N>
auto value_part(const dual<T, N>& x) { return value_part(x.v); }
template <class T>
auto value_part(const jet<T>& x) { return value_part(x.value()); }
}  // namespace detail

/// H(q, p) = p . v - L(q, v) at y = (q, p) for the Lagrangian system Sys.
template <lagrangian_system Sys>
struct lagrangian_hamiltonian {
  static constexpr int dof = Sys::dof;
  static constexpr int max_newton_iterations = 60;
  Sys system{};

  /// v with L_v(q, v) = p. std::domain_error where L_vv is singular or Newton does not converge.
  template <class S>
  vec<S, dof> velocity(const vec<S, dof>& q, const vec<S, dof>& p) const {
    using std::abs;
    using base = decltype(detail::value_part(S{}));
    const base tolerance = base(16) * std::numeric_limits<base>::epsilon();
    vec<S, dof> v = vec<S, dof>::Zero();
    for (int it = 0; it < max_newton_iterations; ++it) {
      const hessian_data<S, dof> h = lagrangian_derivatives<Sys, S>::hessian(system, q, v);
      vec<S, dof> dv;
      if (!detail::solve_in_scalar<S, dof>(h.Lvv, vec<S, dof>(p - h.Lv), dv))
        throw std::domain_error("geomint::analysis::bseries::lagrangian_hamiltonian: L_vv is singular at the state");
      v += dv;
      base step(0), size(0);
      for (int i = 0; i < dof; ++i) {
        step = std::max(step, base(abs(detail::value_part(dv[i]))));
        size = std::max(size, base(abs(detail::value_part(v[i]))));
      }
      if (step <= tolerance * (base(1) + size)) return v;
    }
    throw std::domain_error("geomint::analysis::bseries::lagrangian_hamiltonian: the inverse Legendre map p -> v did not converge in " +
                            std::to_string(max_newton_iterations) + " Newton steps");
  }

  template <class S>
  S operator()(const vec<S, 2 * dof>& y) const {
    const vec<S, dof> q = y.head(dof), p = y.tail(dof);
    const vec<S, dof> v = velocity<S>(q, p);
    return S(p.dot(v) - lagrangian_derivatives<Sys, S>::gradient(system, q, v).L);
  }

  /// grad H = (H_q, H_p) = (-L_q(q, v), v).
  template <class S>
  vec<S, 2 * dof> gradient(const vec<S, 2 * dof>& y) const {
    const vec<S, dof> q = y.head(dof), p = y.tail(dof);
    const vec<S, dof> v = velocity<S>(q, p);
    vec<S, 2 * dof> g;
    g << vec<S, dof>(-lagrangian_derivatives<Sys, S>::lagrangian_q(system, q, v)), v;
    return g;
  }
};

}  // namespace geomint::analysis::bseries
