#pragma once
/// Holonomic constraints f(q) = 0 (LPF paper, eq. 4) and their derivatives by forward-mode AD.
///
/// A constraint set is a type with `static constexpr int count` (c equations) and a call
/// operator templated on the scalar,
/// `Eigen::Matrix<S, count, 1> operator()(const Eigen::Matrix<S, n, 1>& q) const`,
/// so that the Jacobian G = df/dq and the Hessians d^2 f_l/dq^2 come from the same code in
/// every scalar type.

#include <array>

#include "geomint/mechanics/lagrangian.hpp"

namespace geomint {

template <class Con, int n>
concept holonomic_constraints = requires { Con::count; } && (Con::count >= 1) && (Con::count < n) &&
    requires(const Con& f, const vec<double, n>& q) {
      { f(q) } -> std::convertible_to<vec<double, Con::count>>;
    };


/// f, G = df/dq and (optionally) the Hessians H_l = d^2 f_l / dq^2 at q.
template <class Con, class T, int n>
struct constraint_derivatives {
  static constexpr int c = Con::count;
  using jacobian = Eigen::Matrix<T, c, n>;

  struct first_order {
    vec<T, c> f;
    jacobian G;
  };
  struct second_order {
    vec<T, c> f;
    jacobian G;
    std::array<mat<T, n>, c> H;
  };

  static first_order first(const Con& con, const vec<T, n>& q) {
    using D = dual<T, n>;
    vec<D, n> qd;
    for (int i = 0; i < n; ++i) qd[i] = D::variable(q[i], i);
    const vec<D, c> fd = con(qd);
    first_order out;
    for (int l = 0; l < c; ++l) {
      out.f[l] = fd[l].v;
      for (int i = 0; i < n; ++i) out.G(l, i) = fd[l].d[static_cast<std::size_t>(i)];
    }
    return out;
  }

  static second_order second(const Con& con, const vec<T, n>& q) {
    using D1 = dual<T, n>;
    using D2 = dual<D1, n>;
    vec<D2, n> qd;
    for (int i = 0; i < n; ++i) qd[i] = D2::variable(D1::variable(q[i], i), i);
    const vec<D2, c> fd = con(qd);
    second_order out;
    for (int l = 0; l < c; ++l) {
      out.f[l] = fd[l].v.v;
      for (int i = 0; i < n; ++i) {
        const D1& gi = fd[l].d[static_cast<std::size_t>(i)];
        out.G(l, i) = gi.v;
        for (int j = 0; j < n; ++j) out.H[static_cast<std::size_t>(l)](i, j) = gi.d[static_cast<std::size_t>(j)];
      }
    }
    return out;
  }
};


/// The largest |f_l(q)|: the constraint violation reported by the tools.
template <class Con, class T, int n>
T constraint_violation(const Con& con, const vec<T, n>& q) {
  return T(con(q).template lpNorm<Eigen::Infinity>());
}

}  // namespace geomint
