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
#include "geomint/core/multiprecision.hpp"

#include "geomint/lpf/dual.hpp"

namespace geomint {

template <class S, int N>
using vec = Eigen::Matrix<S, N, 1>;
template <class S, int N>
using mat = Eigen::Matrix<S, N, N>;

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

template <class T>
bool is_finite(const T& x) {
  using std::isfinite;
  return static_cast<bool>(isfinite(x));
}
template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& m) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (!is_finite(m(i, j))) return false;
  return true;
}

/// LU factorisation with complete pivoting (P A Q = L U) of a small fixed-size matrix, kept for
/// reuse (e.g. across Newton iterations); singular to working precision when the largest
/// remaining pivot is <= N eps max|A|. Written out instead of Eigen::FullPivLU: same algorithm,
/// but a fraction of the compile time per matrix size, which matters for the many (m, n) sizes
/// a program instantiates.
template <class T, int N>
class lu_small {
 public:
  /// False if A is singular to working precision or not finite.
  bool factor(const mat<T, N>& A) {
    using std::abs;
    lu_ = A;
    T scale(0);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        if (abs(lu_(i, j)) > scale) scale = abs(lu_(i, j));
    if (!is_finite(scale)) return false;
    const T tiny = T(N) * std::numeric_limits<T>::epsilon() * scale;
    for (int k = 0; k < N; ++k) {
      int pr = k, pc = k;
      T best(-1);
      for (int i = k; i < N; ++i)
        for (int j = k; j < N; ++j)
          if (abs(lu_(i, j)) > best) {
            best = abs(lu_(i, j));
            pr = i;
            pc = j;
          }
      if (!(best > tiny)) return false;
      row_[static_cast<std::size_t>(k)] = pr;
      col_[static_cast<std::size_t>(k)] = pc;
      if constexpr (N > 1) {
        if (pr != k)
          for (int j = 0; j < N; ++j) std::swap(lu_(k, j), lu_(pr, j));
        if (pc != k)
          for (int i = 0; i < N; ++i) std::swap(lu_(i, k), lu_(i, pc));
      }
      const T inv = T(1) / lu_(k, k);
      for (int i = k + 1; i < N; ++i) {
        const T f = lu_(i, k) * inv;
        lu_(i, k) = f;
        if (f == T(0)) continue;
        for (int j = k + 1; j < N; ++j) lu_(i, j) -= f * lu_(k, j);
      }
    }
    return true;
  }
  /// x = A^{-1} b; false if x is not finite.
  bool solve(vec<T, N> b, vec<T, N>& x) const {
    // The multipliers were swapped with their rows, so all row swaps come first (P b).
    if constexpr (N > 1) {
      for (int k = 0; k < N; ++k) {
        const int r = row_[static_cast<std::size_t>(k)];
        if (r != k) std::swap(b[k], b[r]);
      }
    }
    for (int k = 0; k < N; ++k)
      for (int i = k + 1; i < N; ++i) b[i] -= lu_(i, k) * b[k];
    for (int k = N - 1; k >= 0; --k) {
      T sum = b[k];
      for (int j = k + 1; j < N; ++j) sum -= lu_(k, j) * b[j];
      b[k] = sum / lu_(k, k);
    }
    if constexpr (N > 1) {
      for (int k = N - 1; k >= 0; --k) {
        const int c = col_[static_cast<std::size_t>(k)];
        if (c != k) std::swap(b[k], b[c]);
      }
    }
    x = b;
    return all_finite(x);
  }

 private:
  mat<T, N> lu_ = mat<T, N>::Zero();
  std::array<int, N> row_{}, col_{};
};

/// Solves A x = b for a small fixed-size A (lu_small); false if A is singular to working
/// precision (x = 0) or not finite (x = NaN), or if x is not finite.
template <class T, int N>
bool solve_small(const mat<T, N>& A, const vec<T, N>& b, vec<T, N>& x) {
  lu_small<T, N> lu;
  if (!lu.factor(A)) {
    x.setConstant(all_finite(A) ? T(0) : std::numeric_limits<T>::quiet_NaN());
    return false;
  }
  return lu.solve(b, x);
}

/// Inverse of a small fixed-size matrix (columns solved one by one); false if singular.
template <class T, int N>
bool invert_small(const mat<T, N>& A, mat<T, N>& inv) {
  for (int j = 0; j < N; ++j) {
    vec<T, N> e = vec<T, N>::Zero(), x;
    e[j] = T(1);
    if (!solve_small<T, N>(A, e, x)) return false;
    inv.col(j) = x;
  }
  return true;
}

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
