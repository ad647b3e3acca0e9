#pragma once
/// Lagrangian systems, the checked system contract, and derivatives by forward-mode AD.
///
/// A *general* system is a type with `static constexpr int dof` and a call operator templated
/// on the scalar,
/// `template <class S> S operator()(const geomint::vec<S, dof>& q, const geomint::vec<S, dof>& qdot) const`,
/// returning L(q, qdot). The integrators differentiate it with nested dual numbers, so math
/// functions must be called unqualified (`using std::cos; cos(q[0])`).
///
/// A *natural* system, L = 1/2 qdot^T M qdot - V(q) with constant SPD M, is declared as such by
/// deriving from `geomint::natural<Self, dof>` and providing
/// `template <class S> static S potential(const geomint::vec<S, dof>& q)` and
/// `template <class S> static geomint::mat<S, dof> mass_matrix()`.
/// The base derives operator() from them, so the fast path (no third derivatives) and the
/// Lagrangian cannot disagree; a natural system may not define its own operator(). A system
/// with any other term (e.g. a magnetic A(q) . qdot) is a general system.
///
/// `geomint::checked_system<Sys, T>` checks the contract for the scalar T and the dual types the
/// integrators use, with one readable static_assert per mistake; the integrators assert it.

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <utility>
#include <string_view>
#include <type_traits>

#include <Eigen/Core>
#include "geomint/ad/dual.hpp"
#include "geomint/core/simd.hpp"
#include "geomint/linalg/lu_small.hpp"
#include "geomint/linalg/types.hpp"

namespace geomint {

/// The tag of the natural-system base (see natural below).
struct natural_tag {};

/// Base of a natural system Self: L = 1/2 qdot^T M qdot - V(q) from Self::potential and
/// Self::mass_matrix, so the integrators' fast path and the Lagrangian are the same function.
template <class Self, int n>
struct natural : natural_tag {
  static_assert(n >= 1, "geomint::natural<Self, n>: n is the number of degrees of freedom and must be >= 1");
  static constexpr int dof = n;
  template <class S>
  S operator()(const vec<S, n>& q, const vec<S, n>& qdot) const {
    const mat<S, n> M = Self::template mass_matrix<S>();
    S kinetic(0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) kinetic += qdot[i] * M(i, j) * qdot[j];
    return S(kinetic / S(2) - Self::template potential<S>(q));
  }
};

namespace mechanics::detail {
/// The dual types the integrators call a Lagrangian with (mechanics/lagrangian.hpp below):
/// gradient, Hessian and Euler-Lagrange Jacobian levels of the general path.
template <class T, int n>
using gradient_dual = dual<T, 2 * n>;
template <class T, int n>
using hessian_dual = dual<dual<T, 2 * n>, 2 * n>;
template <class T, int n>
using euler_lagrange_dual = dual<dual<dual<T, 3 * n>, 1>, 2 * n>;

template <class Sys>
concept has_dof = requires { typename std::integral_constant<int, Sys::dof>; };

template <class Sys, class S>
concept callable_over = requires(const Sys& s, const vec<S, Sys::dof>& q) { s(q, q); };

template <class Sys, class S>
concept returns_scalar = requires(const Sys& s, const vec<S, Sys::dof>& q) {
  { s(q, q) } -> std::same_as<S>;
};

template <class Sys, class S>
concept static_potential = requires(const vec<S, Sys::dof>& q) {
  { Sys::template potential<S>(q) } -> std::same_as<S>;
  { Sys::template mass_matrix<S>() } -> std::convertible_to<mat<S, Sys::dof>>;
};
/// A natural system that supplies grad V itself (optional): `template <class S> static
/// geomint::vec<S, dof> potential_gradient(const geomint::vec<S, dof>& q)`. The integrators then
/// evaluate forces with it instead of differentiating the potential (AD), which also forms V.
template <class Sys, class S>
concept supplies_potential_gradient = requires(const vec<S, Sys::dof>& q) {
  { Sys::template potential_gradient<S>(q) } -> std::convertible_to<vec<S, Sys::dof>>;
};
template <class Sys, class S>
concept member_potential = requires(const Sys& s, const vec<S, Sys::dof>& q) { s.template potential<S>(q); };

/// Whether operator() of a natural system is the one natural<Sys, dof> derives (not redefined).
template <class Sys>
concept uses_natural_operator = requires { &Sys::template operator()<double>; } &&
    std::is_same_v<decltype(&Sys::template operator()<double>),
                   double (natural<Sys, Sys::dof>::*)(const vec<double, Sys::dof>&, const vec<double, Sys::dof>&) const>;

/// One readable static_assert per contract violation, checked in order.
template <class Sys, class T>
constexpr bool check_system() {
  if constexpr (!has_dof<Sys>) {
    static_assert(has_dof<Sys>,
                  "geomint: a system needs `static constexpr int dof = n;` (its number of degrees of freedom, n >= 1)");
    return false;
  } else if constexpr (!(Sys::dof >= 1)) {
    static_assert(Sys::dof >= 1, "geomint: a system's dof (number of degrees of freedom) must be >= 1");
    return false;
  } else if constexpr (std::is_base_of_v<natural_tag, Sys> && !std::is_base_of_v<natural<Sys, Sys::dof>, Sys>) {
    static_assert(std::is_base_of_v<natural<Sys, Sys::dof>, Sys>,
                  "geomint: a natural system derives from geomint::natural<Self, dof> with Self its own type and "
                  "dof its number of degrees of freedom");
    return false;
  } else if constexpr (std::is_base_of_v<natural_tag, Sys> && member_potential<Sys, T> && !static_potential<Sys, T>) {
    static_assert(static_potential<Sys, T>,
                  "geomint: a natural system's potential and mass_matrix must be static member templates: "
                  "`template <class S> static S potential(const geomint::vec<S, dof>& q)` and "
                  "`template <class S> static geomint::mat<S, dof> mass_matrix()`");
    return false;
  } else if constexpr (std::is_base_of_v<natural_tag, Sys> && !static_potential<Sys, T>) {
    static_assert(static_potential<Sys, T>,
                  "geomint: a natural system (derived from geomint::natural) needs "
                  "`template <class S> static S potential(const geomint::vec<S, dof>& q)` and "
                  "`template <class S> static geomint::mat<S, dof> mass_matrix()`, templated on the scalar S");
    return false;
  } else if constexpr (std::is_base_of_v<natural_tag, Sys> && !uses_natural_operator<Sys>) {
    static_assert(uses_natural_operator<Sys>,
                  "geomint: a natural system must not define operator(): its Lagrangian is 1/2 qdot^T M qdot - V(q), "
                  "derived from potential() and mass_matrix(). For any other term (e.g. a magnetic A(q) . qdot) "
                  "write a general system: operator() alone, without the geomint::natural base");
    return false;
  } else if constexpr (!callable_over<Sys, T>) {
    static_assert(callable_over<Sys, T>,
                  "geomint: the system cannot be called as L(q, qdot) with q, qdot of type geomint::vec<S, dof>: "
                  "check that `dof` equals the size your operator() takes, and declare it as "
                  "`template <class S> S operator()(const geomint::vec<S, dof>& q, const geomint::vec<S, dof>& qdot) const`");
    return false;
  } else if constexpr (!(returns_scalar<Sys, T> && returns_scalar<Sys, gradient_dual<T, Sys::dof>> &&
                         returns_scalar<Sys, hessian_dual<T, Sys::dof>> &&
                         returns_scalar<Sys, euler_lagrange_dual<T, Sys::dof>>)) {
    static_assert(returns_scalar<Sys, T> && returns_scalar<Sys, euler_lagrange_dual<T, Sys::dof>>,
                  "geomint: the Lagrangian must be a template on its scalar type S and return S: "
                  "`template <class S> S operator()(const geomint::vec<S, dof>& q, const geomint::vec<S, dof>& qdot) const`. "
                  "The integrators call it with nested dual numbers to differentiate it, so a Lagrangian written "
                  "for double (or for one scalar type) cannot be used");
    return false;
  } else {
    return true;
  }
}
}  // namespace mechanics::detail

/// True if Sys satisfies the system contract for the scalar T (double by default); if not,
/// compilation stops at a static_assert that names the mistake.
template <class Sys, class T = double>
inline constexpr bool checked_system = mechanics::detail::check_system<Sys, T>();

/// Sys::dof, or 1 where the contract check has already failed (fewer follow-on errors).
template <class Sys>
constexpr int contract_dof() {
  if constexpr (mechanics::detail::has_dof<Sys>) return Sys::dof >= 1 ? Sys::dof : 1;
  else return 1;
}

/// A Lagrangian in n = Sys::dof degrees of freedom, callable over double and the dual types.
template <class Sys>
concept lagrangian_system = mechanics::detail::has_dof<Sys> && (Sys::dof >= 1) && mechanics::detail::returns_scalar<Sys, double> &&
                            mechanics::detail::returns_scalar<Sys, mechanics::detail::euler_lagrange_dual<double, Sys::dof>>;

/// A system declared natural (derived from geomint::natural): the fast path.
template <class Sys>
concept natural_system = lagrangian_system<Sys> && std::is_base_of_v<natural_tag, Sys> &&
                         mechanics::detail::static_potential<Sys, double> && mechanics::detail::uses_natural_operator<Sys>;

/// A natural system whose potential_gradient may be instantiated on SIMD packs (core/simd.hpp):
/// it declares `static constexpr bool stage_parallel_forces = true;`.
template <class Sys>
concept stage_parallel_system = natural_system<Sys> && requires {
  requires Sys::stage_parallel_forces;
} && mechanics::detail::supplies_potential_gradient<Sys, double_pack<simd_width>>;

/// Hides the natural-system structure of Sys: derivatives then come from AD on L itself.
template <lagrangian_system Sys>
struct general {
  static constexpr int dof = Sys::dof;
  Sys system{};
  template <class S>
  S operator()(const vec<S, dof>& q, const vec<S, dof>& qdot) const { return system(q, qdot); }
};


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
struct lagrangian_derivatives {
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

  /// L_q alone. Natural systems: -grad V(x), from the system's potential_gradient if it supplies
  /// one, else one level of AD on V (its gradient without forming L). Others: one level of AD
  /// on L.
  static V lagrangian_q(const Sys& sys, const V& x, const V& v) {
    if constexpr (natural_system<Sys> && mechanics::detail::supplies_potential_gradient<Sys, T>) {
      return V(-V(Sys::template potential_gradient<T>(x)));
    } else if constexpr (natural_system<Sys>) {
      return ad_potential_force(x);
    } else {
      return gradient(sys, x, v).Lq;
    }
  }

  /// -grad V(x) of a natural system by one level of AD on V, whether or not the system supplies
  /// its gradient (the independent value potential_gradient_defect compares against).
  static V ad_potential_force(const V& x) {
    using D = dual<T, n>;
    vec<D, n> qd;
    for (int i = 0; i < n; ++i) qd[i] = D::variable(x[i], i);
    const D pot = Sys::template potential<D>(qd);
    V f;
    for (int i = 0; i < n; ++i) f[i] = -pot.d[static_cast<std::size_t>(i)];
    return f;
  }

  /// Bytes of the fully nested Hessian duals of a natural system's position vector; above 64 KiB
  /// (half of Eigen's fixed-size stack limit) the Hessian is built column by column instead.
  static constexpr std::size_t full_hessian_bytes = sizeof(dual<dual<T, n>, n>) * static_cast<std::size_t>(n);

  /// The velocity terms of a natural system's derivatives: L_v = M v, L_vv = M, no mixed terms.
  static void natural_velocity_terms(hessian_data<T, n>& h, const V& v) {
    const Mt M = Sys::template mass_matrix<T>();
    h.Lv = M * v;
    h.Lqv.setZero();
    h.Lvq.setZero();
    h.Lvv = M;
  }

  /// Whether the Hessian of a natural system comes from one level of AD on its own gradient
  /// (n + 1 components per operation) instead of two nested levels on V ((n + 1)^2): from 4
  /// degrees of freedom on, where the nested duals cost more than the gradient's extra
  /// operations (the outer solar system: 18).
  static constexpr bool hessian_from_gradient =
      natural_system<Sys> && n >= 4 && mechanics::detail::supplies_potential_gradient<Sys, dual<T, n>>;

  /// First and second derivatives: two nested levels of AD (natural systems: see
  /// hessian_from_gradient).
  static hessian_data<T, n> hessian(const Sys& sys, const V& x, const V& v) {
    hessian_data<T, n> h;
    if constexpr (hessian_from_gradient) {
      using D1 = dual<T, n>;
      vec<D1, n> qd;
      for (int i = 0; i < n; ++i) qd[i] = D1::variable(x[i], i);
      const vec<D1, n> g = Sys::template potential_gradient<D1>(qd);
      for (int i = 0; i < n; ++i) {
        h.Lq[i] = -g[i].v;
        for (int j = 0; j < n; ++j) h.Lqq(i, j) = -g[i].d[static_cast<std::size_t>(j)];
      }
      natural_velocity_terms(h, v);
    } else if constexpr (natural_system<Sys> && full_hessian_bytes > 64 * 1024) {
      // Many degrees of freedom in a wide scalar (e.g. the outer solar system in 50 digits):
      // one directional second derivative per column, outer dual<., 1> along e_j over the
      // gradient duals: n evaluations of V with 2(n + 1) components each, instead of one with
      // (n + 1)^2, which would not fit Eigen's fixed-size stack limit.
      using D1 = dual<T, n>;
      using D2 = dual<D1, 1>;
      for (int j = 0; j < n; ++j) {
        vec<D2, n> qd;
        for (int i = 0; i < n; ++i) {
          qd[i] = D2(D1::variable(x[i], i));
          if (i == j) qd[i].d[0] = D1(T(1));
        }
        const D2 pot = Sys::template potential<D2>(qd);
        for (int i = 0; i < n; ++i) {
          if (j == 0) h.Lq[i] = -pot.v.d[static_cast<std::size_t>(i)];
          h.Lqq(i, j) = -pot.d[0].d[static_cast<std::size_t>(i)];
        }
      }
      natural_velocity_terms(h, v);
    } else if constexpr (natural_system<Sys>) {
      using D1 = dual<T, n>;
      using D2 = dual<D1, n>;
      vec<D2, n> qd;
      for (int i = 0; i < n; ++i) qd[i] = D2::variable(D1::variable(x[i], i), i);
      const D2 pot = Sys::template potential<D2>(qd);
      for (int i = 0; i < n; ++i) {
        const D1& gi = pot.d[static_cast<std::size_t>(i)];
        h.Lq[i] = -gi.v;
        for (int j = 0; j < n; ++j) h.Lqq(i, j) = -gi.d[static_cast<std::size_t>(j)];
      }
      natural_velocity_terms(h, v);
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
      return V(lagrangian_q(sys, x, v) - M * a);
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


/// dL/dqdot at (q, qdot): the momentum p.
template <lagrangian_system Sys, class T>
vec<T, Sys::dof> momentum(const Sys& sys, const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& qdot) {
  return lagrangian_derivatives<Sys, T>::gradient(sys, q, qdot).Lv;
}

/// The energy (Hamiltonian) qdot . dL/dqdot - L at (q, qdot).
template <lagrangian_system Sys, class T>
T energy_qv(const Sys& sys, const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& qdot) {
  const auto g = lagrangian_derivatives<Sys, T>::gradient(sys, q, qdot);
  return T(qdot.dot(g.Lv) - g.L);
}

/// The energy at (q, p): qdot from p by the inverse Legendre transform, then energy_qv; NaN where
/// the transform cannot be inverted.
template <lagrangian_system Sys, class T>
T energy_qp(const Sys& sys, const vec<T, Sys::dof>& q, const vec<T, Sys::dof>& p) {
  vec<T, Sys::dof> v;
  if (!lagrangian_derivatives<Sys, T>::velocity(sys, q, p, v)) return std::numeric_limits<T>::quiet_NaN();
  return energy_qv<Sys, T>(sys, q, v);
}

/// How far a natural system's own potential_gradient is from the gradient of its potential at q
/// (AD on V): max_i |supplied_i - (grad V)_i| in units of eps max(1, |grad V|). A correct hook
/// gives a few units (the two roundings); a wrong one gives a large number. Test your hook with it.
template <natural_system Sys, class T>
T potential_gradient_defect(const vec<T, Sys::dof>& q) {
  static_assert(mechanics::detail::supplies_potential_gradient<Sys, T>,
                "geomint::potential_gradient_defect: the system supplies no "
                "`template <class S> static geomint::vec<S, dof> potential_gradient(const geomint::vec<S, dof>& q)`");
  using std::abs;
  constexpr int n = Sys::dof;
  const vec<T, n> ad = -lagrangian_derivatives<Sys, T>::ad_potential_force(q);
  const vec<T, n> supplied = Sys::template potential_gradient<T>(q);
  T largest(0), size(1);
  for (int i = 0; i < n; ++i) {
    const T d = abs(T(supplied[i] - ad[i]));
    if (d > largest) largest = d;
    if (abs(ad[i]) > size) size = abs(ad[i]);
  }
  return T(largest / (std::numeric_limits<T>::epsilon() * size));
}

}  // namespace geomint
