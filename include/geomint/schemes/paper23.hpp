#pragma once
/// The LPF paper's scheme (23) for the particle on the unit circle, exactly as printed.

#include <cmath>

#include "geomint/ad/dual.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/solvers/newton.hpp"

namespace geomint {

/// The LPF paper's scheme (23), exactly as printed (m = 2, equispaced, unit circle): the
/// residual of its two equations at (x^{k-1}, x^k, x^{k+1}),
///   x^{k-1} + 6 x^k + x^{k+1} - 4 (x^k + x^{k+1}) / |x^k + x^{k+1}|
///                             - 4 (x^{k-1} + x^k) / |x^{k-1} + x^k| = 0.
/// It does not depend on tau: the multiplier of the interior node is eliminated.
template <class S>
vec<S, 2> paper23_residual(const vec<S, 2>& x_prev, const vec<S, 2>& x_curr, const vec<S, 2>& x_next) {
  using std::sqrt;
  const vec<S, 2> ahead = x_curr + x_next, behind = x_prev + x_curr;
  const S ahead_norm = sqrt(S(ahead[0] * ahead[0] + ahead[1] * ahead[1]));
  const S behind_norm = sqrt(S(behind[0] * behind[0] + behind[1] * behind[1]));
  return vec<S, 2>(x_prev + S(6) * x_curr + x_next - (S(4) / ahead_norm) * ahead - (S(4) / behind_norm) * behind);
}

/// One step of scheme (23): solves its residual for x^{k+1} by Newton (Jacobian by AD), from
/// the predictor 2 x^k - x^{k-1}. Throws integration_error with the step index on failure.
template <class T>
vec<T, 2> paper23_step(const vec<T, 2>& x_prev, const vec<T, 2>& x_curr, long k = 1,
                       const newton_options<T>& opt = {}) {
  using Dl = dual<T, 2>;
  vec<T, 2> z = T(2) * x_curr - x_prev;
  const vec<Dl, 2> prev_d = x_prev.template cast<Dl>(), curr_d = x_curr.template cast<Dl>();
  auto residual = [&](const vec<T, 2>& zz, vec<T, 2>& F, mat<T, 2>& J) {
    vec<Dl, 2> next_d;
    for (int i = 0; i < 2; ++i) next_d[i] = Dl::variable(zz[i], i);
    const vec<Dl, 2> r = paper23_residual<Dl>(prev_d, curr_d, next_d);
    for (int i = 0; i < 2; ++i) {
      F[i] = r[i].v;
      for (int j = 0; j < 2; ++j) J(i, j) = r[i].d[static_cast<std::size_t>(j)];
    }
  };
  step_status st;
  if (!all_finite(x_prev) || !all_finite(x_curr))
    st.reason = step_failure::non_finite_input;
  else
    st = newton_solve<2, T>(residual, z, opt);
  st.step = k;
  if (!st) throw integration_error(st);
  return z;
}

}  // namespace geomint
