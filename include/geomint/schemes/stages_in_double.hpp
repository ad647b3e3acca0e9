#pragma once
/// The stage equations of an RKN step in the fixed-point form (schemes/gauss_fixed_point.hpp)
/// in double, for a multiprecision step (newton_options::double_jacobian): their Newton matrix
/// formed and factorised in double, and the equations solved in double by simplified Newton, so
/// that the iteration in the working precision starts about 1e-16 from its fixed point and
/// gains about 16 digits per iteration.
///
/// The equations: with the stage momentum increments F_i, stage points
/// Q_i = q + base_i + tau M^{-1} sum_j mu_ij F_j and weights hb_i = tau b_i,
///   G(F)_i = F_i - hb_i f(Q_i) = 0,   dG/dF = I - [hb_i tau mu_ij f'(Q_i) M^{-1}]_ij,
/// f = -grad V and f' = -V'' (automatic differentiation in double).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "geomint/core/mantissa.hpp"
#include "geomint/linalg/lu_small.hpp"
#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/solvers/newton.hpp"

namespace geomint::schemes::detail {

/// The coefficients of the stage equations rounded to double, and the solver on them.
template <class Sys, int S>
class stages_in_double {
 public:
  static constexpr int n = Sys::dof;
  using Vd = vec<double, n>;
  using stages = std::array<Vd, S>;
  using weights = std::array<double, S>;
  using lu_type = lu_in_double<S * n>;

  stages_in_double() = default;
  /// From the coefficients in T: mu, the extrapolation of the previous step's increments
  /// (extrapolate_ij) and M^{-1}.
  template <class T>
  stages_in_double(const std::array<std::array<T, S>, S>& mu, const std::array<std::array<T, S>, S>& extrapolate,
                   const mat<T, n>& minv) {
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
      for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J) {
        mu_[I][J] = to_double(mu[I][J]);
        extrapolate_[I][J] = to_double(extrapolate[I][J]);
      }
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) minv_(r, c) = to_double(minv(r, c));
  }

  /// dG/dF at the stage points Q, formed and factorised in double (partial pivoting: the matrix
  /// is near the identity for the steps the iteration reaches); false if it is not finite or
  /// singular there.
  bool matrix(const Sys& sys, const stages& Q, double tau, const weights& hb, lu_type& lu) const {
    for (int i = 0; i < S; ++i) {
      const auto I = static_cast<std::size_t>(i);
      if (!all_finite(Q[I])) return false;
      const mat<double, n> B = lagrangian_derivatives<Sys, double>::hessian(sys, Q[I], Vd::Zero()).Lqq * minv_;
      const double h = hb[I] * tau;
      for (int j = 0; j < S; ++j) {
        const double w = h * mu_[I][static_cast<std::size_t>(j)];
        for (int r = 0; r < n; ++r)
          for (int c = 0; c < n; ++c) lu.at(i * n + r, j * n + c) = double(i == j && r == c) - w * B(r, c);
      }
    }
    return lu.factor_in_place(linalg::pivoting::partial);
  }

  /// The equations solved in double by simplified Newton from the extrapolation of the previous
  /// step's increments (`previous`, in double) or else from the explicit stage estimate: F
  /// receives that solution (about 16 digits) and `lu` the matrix factorised at it. False (F and
  /// lu unusable) if double cannot hold the step, or if the iteration does not reach its
  /// round-off floor within max_iterations.
  bool solve(const Sys& sys, const Vd& q, const stages& base, const weights& hb, double tau, const stages* previous,
             stages& F, lu_type& lu, int max_iterations) const {
    using std::abs;
    const double eps = std::numeric_limits<double>::epsilon();
    const double floor_level = epsilon_two_thirds<double>();
    stages Q;
    auto force = [&](const Vd& x) { return lagrangian_derivatives<Sys, double>::lagrangian_q(sys, x, Vd::Zero()); };
    auto stage_points = [&] {
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
        Vd z = Vd::Zero();
        for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J) z += mu_[I][J] * F[J];
        Q[I] = q + Vd(base[I] + tau * Vd(minv_ * z));
      }
    };
    if (previous) {
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
        F[I] = Vd::Zero();
        for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J) F[I] += extrapolate_[I][J] * (*previous)[J];
      }
    } else {
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) F[I] = hb[I] * force(Vd(q + base[I]));
    }
    // Simplified Newton's method: the matrix formed at the start, again where the iteration
    // contracts by less than 1/16, and once more at the end, at the solution.
    double previous_change = std::numeric_limits<double>::infinity();
    bool refresh = true, converged = false;
    for (int it = 1; it <= max_iterations && !converged; ++it) {
      stage_points();
      vec<double, S * n> r, d;
      for (int i = 0; i < S; ++i) {
        const auto I = static_cast<std::size_t>(i);
        r.template segment<n>(i * n) = hb[I] * force(Q[I]) - F[I];
      }
      if (!all_finite(r)) return false;
      if (refresh && !matrix(sys, Q, tau, hb, lu)) return false;
      if (!lu.solve(r, d)) return false;
      double change = 0, size = 0;
      for (int i = 0; i < S; ++i) {
        const auto I = static_cast<std::size_t>(i);
        F[I] += d.template segment<n>(i * n);
        for (int c = 0; c < n; ++c) {
          change = std::max(change, abs(d[i * n + c]));
          size = std::max(size, abs(F[I][c]));
        }
      }
      // At double's floor: a change of a few ulps, one that the contraction rate bounds below
      // eps, or one that stopped shrinking below eps^(2/3).
      converged = change <= 4 * eps * size || (it > 1 && rate_bounds_error(change / previous_change, change, size)) ||
                  (change >= previous_change && change <= floor_level * size);
      refresh = it > 1 && change > previous_change / 16;
      previous_change = change;
    }
    if (!converged) return false;
    stage_points();
    return matrix(sys, Q, tau, hb, lu);
  }

 private:
  std::array<std::array<double, S>, S> mu_{}, extrapolate_{};
  mat<double, n> minv_ = mat<double, n>::Zero();
};

}  // namespace geomint::schemes::detail
