#pragma once
/// Lagrangian systems and their derivatives by forward-mode AD.
///
/// A system is a type with `static constexpr int dof` and a call operator templated on the
/// scalar, `S operator()(const Eigen::Matrix<S, dof, 1>& q, const Eigen::Matrix<S, dof, 1>& qdot)`,
/// returning L(q, qdot). A *natural* system additionally provides
/// `template <class S> static S potential(const Eigen::Matrix<S, dof, 1>& q)` and
/// `template <class T> static Eigen::Matrix<T, dof, dof> mass_matrix()` (constant, SPD), with
/// L = 1/2 qdot^T M qdot - V(q); the integrators then take a fast path (no third derivatives).
/// Wrap a natural system in `geomint::general<Sys>` to force the general (AD on L) path.

#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <string_view>
#include <type_traits>

#include <Eigen/Dense>
#include "geomint/ad/dual.hpp"
#include "geomint/linalg/lu_small.hpp"
#include "geomint/linalg/types.hpp"

namespace geomint {

/// A Lagrangian in n = Sys::dof degrees of freedom, callable over any scalar (double is checked).
template <class Sys>
concept lagrangian_system = requires { Sys::dof; } && (Sys::dof >= 1) &&
    requires(const Sys& s, const vec<double, Sys::dof>& q) {
      { s(q, q) } -> std::convertible_to<double>;
    };

/// L = 1/2 qdot^T M qdot - V(q) with constant M: the fast path.
template <class Sys>
concept natural_system = lagrangian_system<Sys> && requires(const vec<double, Sys::dof>& q) {
  { Sys::template potential<double>(q) } -> std::convertible_to<double>;
  { Sys::template mass_matrix<double>() } -> std::convertible_to<mat<double, Sys::dof>>;
};

/// Hides the natural-system structure of Sys: derivatives then come from AD on L itself.
template <lagrangian_system Sys>
struct general {
  static constexpr int dof = Sys::dof;
  Sys system{};
  template <class S>
  S operator()(const vec<S, dof>& q, const vec<S, dof>& qdot) const { return system(q, qdot); }
};

namespace detail {

/// L and its first derivatives.
template <class T, int n>
struct gradient_data {
  T L;
  vec<T, n> Lq, Lv;
};
/// ... and its second derivatives (Lqv(i, j) = d^2 L / dq_i dqdot_j).
template <class T, int n>
struct hessian_data {
  vec<T, n> Lq, Lv;
  mat<T, n> Lqq, Lqv, Lvq, Lvv;
};
/// The Euler-Lagrange expression E(x, v, a) = L_q - L_vq v - L_vv a (eq. 12, i.e. dL/dq -
/// d/dt dL/dqdot along a path with x, xdot = v, xddot = a) and its Jacobians.
template <class T, int n>
struct el_data {
  vec<T, n> E;
  mat<T, n> Ex, Ev, Ea;
};

/// Derivatives of a system's Lagrangian over the scalar T.
template <class Sys, class T>
struct derivatives {
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;
  using Mt = mat<T, n>;

  /// L, L_q, L_v: one level of AD over (q, qdot).
  static gradient_data<T, n> gradient(const Sys& sys, const V& x, const V& v) {
    if constexpr (natural_system<Sys>) {
      using D = dual<T, n>;
      vec<D, n> qd;
      for (int i = 0; i < n; ++i) qd[i] = D::variable(x[i], i);
      const D pot = Sys::template potential<D>(qd);
      const Mt M = Sys::template mass_matrix<T>();
      gradient_data<T, n> g;
      g.Lv = M * v;
      g.L = T(v.dot(g.Lv) / T(2) - pot.v);
      for (int i = 0; i < n; ++i) g.Lq[i] = -pot.d[static_cast<std::size_t>(i)];
      return g;
    } else {
      using D = dual<T, 2 * n>;
      vec<D, n> qd, vd;
      for (int i = 0; i < n; ++i) {
        qd[i] = D::variable(x[i], i);
        vd[i] = D::variable(v[i], n + i);
      }
      const D L = sys(qd, vd);
      gradient_data<T, n> g;
      g.L = L.v;
      for (int i = 0; i < n; ++i) {
        g.Lq[i] = L.d[static_cast<std::size_t>(i)];
        g.Lv[i] = L.d[static_cast<std::size_t>(n + i)];
      }
      return g;
    }
  }

  /// First and second derivatives: two nested levels of AD.
  static hessian_data<T, n> hessian(const Sys& sys, const V& x, const V& v) {
    hessian_data<T, n> h;
    if constexpr (natural_system<Sys>) {
      using D1 = dual<T, n>;
      using D2 = dual<D1, n>;
      vec<D2, n> qd;
      for (int i = 0; i < n; ++i) qd[i] = D2::variable(D1::variable(x[i], i), i);
      const D2 pot = Sys::template potential<D2>(qd);
      const Mt M = Sys::template mass_matrix<T>();
      h.Lv = M * v;
      for (int i = 0; i < n; ++i) {
        const D1& gi = pot.d[static_cast<std::size_t>(i)];
        h.Lq[i] = -gi.v;
        for (int j = 0; j < n; ++j) h.Lqq(i, j) = -gi.d[static_cast<std::size_t>(j)];
      }
      h.Lqv.setZero();
      h.Lvq.setZero();
      h.Lvv = M;
    } else {
      using D1 = dual<T, 2 * n>;
      using D2 = dual<D1, 2 * n>;
      vec<D2, n> qd, vd;
      for (int i = 0; i < n; ++i) {
        qd[i] = D2::variable(D1::variable(x[i], i), i);
        vd[i] = D2::variable(D1::variable(v[i], n + i), n + i);
      }
      const D2 L = sys(qd, vd);
      for (int i = 0; i < n; ++i) {
        const D1& gq = L.d[static_cast<std::size_t>(i)];
        const D1& gv = L.d[static_cast<std::size_t>(n + i)];
        h.Lq[i] = gq.v;
        h.Lv[i] = gv.v;
        for (int j = 0; j < n; ++j) {
          h.Lqq(i, j) = gq.d[static_cast<std::size_t>(j)];
          h.Lqv(i, j) = gq.d[static_cast<std::size_t>(n + j)];
          h.Lvq(i, j) = gv.d[static_cast<std::size_t>(j)];
          h.Lvv(i, j) = gv.d[static_cast<std::size_t>(n + j)];
        }
      }
    }
    return h;
  }

  /// E(x, v, a) = L_q - d/dt L_v and its Jacobians (eq. 12). General path: three levels of AD,
  /// innermost over (x, v, a) for the Jacobian, middle along time (q = x + eps v,
  /// qdot = v + eps a gives d/dt), outer over (q, qdot) for the gradient of L.
  static el_data<T, n> euler_lagrange(const Sys& sys, const V& x, const V& v, const V& a) {
    el_data<T, n> e;
    if constexpr (natural_system<Sys>) {
      const hessian_data<T, n> h = hessian(sys, x, v);
      const Mt M = Sys::template mass_matrix<T>();
      e.E = h.Lq - M * a;
      e.Ex = h.Lqq;
      e.Ev.setZero();
      e.Ea = -M;
    } else {
      using I = dual<T, 3 * n>;
      using Md = dual<I, 1>;
      using O = dual<Md, 2 * n>;
      vec<O, n> qd, vd;
      for (int i = 0; i < n; ++i) {
        const I xi = I::variable(x[i], i), vi = I::variable(v[i], n + i), ai = I::variable(a[i], 2 * n + i);
        Md qm(xi), vm(vi);
        qm.d[0] = vi;
        vm.d[0] = ai;
        qd[i] = O::variable(qm, i);
        vd[i] = O::variable(vm, n + i);
      }
      const O L = sys(qd, vd);
      for (int i = 0; i < n; ++i) {
        const I Ei = L.d[static_cast<std::size_t>(i)].v - L.d[static_cast<std::size_t>(n + i)].d[0];
        e.E[i] = Ei.v;
        for (int j = 0; j < n; ++j) {
          e.Ex(i, j) = Ei.d[static_cast<std::size_t>(j)];
          e.Ev(i, j) = Ei.d[static_cast<std::size_t>(n + j)];
          e.Ea(i, j) = Ei.d[static_cast<std::size_t>(2 * n + j)];
        }
      }
    }
    return e;
  }

  /// E(x, v, a) alone (no Jacobian): one level of AD on V for natural systems, two on L
  /// otherwise (E = L_q - L_vq v - L_vv a needs only second derivatives of L).
  static V el_residual(const Sys& sys, const V& x, const V& v, const V& a) {
    if constexpr (natural_system<Sys>) {
      const Mt M = Sys::template mass_matrix<T>();
      return V(gradient(sys, x, v).Lq - M * a);
    } else {
      const hessian_data<T, n> h = hessian(sys, x, v);
      return V(h.Lq - h.Lvq * v - h.Lvv * a);
    }
  }

  /// dL/dqdot alone: M v for natural systems (no AD), one level of AD otherwise.
  static V momentum_of(const Sys& sys, const V& x, const V& v) {
    if constexpr (natural_system<Sys>) {
      return V(Sys::template mass_matrix<T>() * v);
    } else {
      return gradient(sys, x, v).Lv;
    }
  }

  /// qddot from the Euler-Lagrange equations: L_vv a = L_q - L_vq v.
  static V acceleration(const Sys& sys, const V& x, const V& v) {
    const hessian_data<T, n> h = hessian(sys, x, v);
    V a;
    if (!solve_small<T, n>(h.Lvv, V(h.Lq - h.Lvq * v), a)) a.setZero();
    return a;
  }

  /// Inverse Legendre transform: qdot with dL/dqdot(q, qdot) = p (Newton from qdot = 0).
  /// Returns false if it does not converge (degenerate Lagrangian).
  static bool velocity(const Sys& sys, const V& q, const V& p, V& v) {
    if constexpr (natural_system<Sys>) {
      return solve_small<T, n>(Sys::template mass_matrix<T>(), p, v);
    } else {
      const T eps = std::numeric_limits<T>::epsilon();
      v.setZero();
      for (int it = 0; it < 60; ++it) {
        const hessian_data<T, n> h = hessian(sys, q, v);
        V dv;
        if (!solve_small<T, n>(h.Lvv, V(p - h.Lv), dv)) return false;
        v += dv;
        if (!all_finite(v)) return false;
        if (dv.template lpNorm<Eigen::Infinity>() <= T(16) * eps * (T(1) + v.template lpNorm<Eigen::Infinity>()))
          return true;
      }
      return false;
    }
  }
};

}  // namespace detail

/// dL/dqdot at (q, qdot): the momentum p.
template <lagrangian_system Sys, class T>
vec<T, Sys::dof> momentum(const Sys& sys, const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& qdot) {
  return detail::derivatives<Sys, T>::gradient(sys, q, qdot).Lv;
}

/// The energy (Hamiltonian) qdot . dL/dqdot - L at (q, qdot).
template <lagrangian_system Sys, class T>
T energy_qv(const Sys& sys, const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& qdot) {
  const auto g = detail::derivatives<Sys, T>::gradient(sys, q, qdot);
  return T(qdot.dot(g.Lv) - g.L);
}

}  // namespace geomint
