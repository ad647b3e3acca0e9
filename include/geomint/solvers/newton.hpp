#pragma once
/// Newton's method on unknowns of compile-time size (full, and simplified with a reusable
/// factorisation). The Newton matrix is a square_matrix (linalg/types.hpp): fixed-size for small
/// systems, on the heap for large ones, where the simplified solver keeps it in its
/// jacobian_cache (allocated once with it) instead of allocating it in every solve.
///
/// Convergence is declared when the Newton correction falls below a multiple of the scalar's
/// epsilon (relative to the iterate), or when, already below eps^(2/3), it stops contracting
/// (the round-off floor of an ill-conditioned system). Anything else is reported: a singular
/// Jacobian, a non-finite residual or iterate, or no convergence within the iteration budget.

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "geomint/linalg/lu_small.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/solvers/step_status.hpp"

namespace geomint {

/// Newton settings. The tolerance is `tolerance_ulps` units of epsilon relative to the iterate.
///
/// Both must be >= 1 (max_iterations at most 100000, tolerance_ulps at most 2^20): validate()
/// throws std::invalid_argument otherwise, and every solve calls it, so that 0 or -5 iterations
/// is an error with a reason, never a step that "fails to converge" without trying.
template <class T>
struct newton_options {
  int max_iterations = 50;
  int tolerance_ulps = 64;
  /// Simplified Newton: stop as soon as the contraction rate rho (<= 1/8) says the error left,
  /// rho / (1 - rho) times the last correction, is below eps, instead of making one more,
  /// eps-sized correction to confirm it. In multiprecision that saves the last residual of most
  /// steps, the dearest part of a step, and eps is far below any accuracy asked. In a built-in
  /// type the confirming correction is cheap and makes the converged iterate the solution to
  /// round-off, which the long-run round-off studies rely on: off by default there.
  bool stop_on_rate = !std::is_floating_point_v<T>;
  /// Simplified Newton in a multiprecision T: factorise the Newton matrix rounded to double and
  /// solve for each correction in double from the residual in T (mixed-precision iterative
  /// refinement; Kelley 2022, docs/references.md). The residual, and so the solution, keep T's
  /// precision; each iteration contracts the error by about kappa(J) 1e-16 (plus the matrix's
  /// staleness) instead of quadratically, while the LU and its solves cost double's arithmetic
  /// instead of T's. The solver falls back to T where double cannot hold the matrix or the correction, or
  /// where the double matrix stops the contraction. The fixed-point form (lpf_fixed_point) also
  /// solves its stage equations in double first and iterates in T from there. No effect in
  /// built-in types.
  bool double_jacobian = !std::is_floating_point_v<T>;
  /// In double, for a natural system that declares `stage_parallel_forces` (core/simd.hpp): the
  /// fixed-point sweeps (lpf_fixed_point, lpf on Gauss-interior nodes) evaluate their S stage
  /// forces simd_width at a time on SIMD packs instead of one by one. The values differ only by
  /// the elementary functions' last bit (SLEEF's 1-ulp sin against the C library's). No effect
  /// elsewhere.
  bool simd_forces = true;

  void validate() const {
    if (max_iterations < 1 || max_iterations > 100000)
      throw std::invalid_argument("newton_options: max_iterations must be in 1..100000, got " +
                                  std::to_string(max_iterations));
    if (tolerance_ulps < 1 || tolerance_ulps > (1 << 20))
      throw std::invalid_argument("newton_options: tolerance_ulps must be in 1..1048576, got " +
                                  std::to_string(tolerance_ulps));
  }
};


/// eps^(2/3) of T, the round-off floor of the convergence tests. Built-in floating types use
/// std::cbrt. Other types use Newton's iteration for the cube root of eps^2 from the power of two
/// nearest to it (frexp, ldexp): within an ulp or two of cbrt, and unlike Boost.Multiprecision's
/// generic cbrt (which instantiates Boost.Math's, about 1.5 s of GCC 12 -O2 time in every
/// cpp_bin_float_50 file, docs/results/compile_time.md) it needs only + * /.
template <class T>
T epsilon_two_thirds() {
  const T eps = std::numeric_limits<T>::epsilon();
  const T a = eps * eps;
  if constexpr (std::is_floating_point_v<T>) {
    return std::cbrt(a);
  } else {
    // Computed once per type (a function-local static, thread-safe): the iteration costs as much
    // as a small step's arithmetic.
    static const T value = [&a] {
      using std::frexp;
      using std::ldexp;
      int e = 0;
      frexp(a, &e);  // a = f 2^e with f in [1/2, 1)
      T x = ldexp(T(1), e / 3);
      x = (T(2) * x + a / (x * x)) / T(3);  // now x >= cbrt(a) (AM-GM), and the iteration decreases
      for (int it = 0; it < 200; ++it) {
        const T next = (T(2) * x + a / (x * x)) / T(3);
        if (!(next < x)) break;
        x = next;
      }
      return x;
    }();
    return value;
  }
}

/// Whether an iteration contracting at rate rho (<= 1/8) has, after a change of `size`, at
/// most eps `scale` left to go: rho / (1 - rho) size <= eps scale (the stop of
/// newton_options::stop_on_rate, shared by simplified Newton and the fixed-point sweeps).
template <class T>
bool rate_bounds_error(const T& rho, const T& size, const T& scale) {
  return rho <= T(1) / T(8) && rho * size <= (T(1) - rho) * std::numeric_limits<T>::epsilon() * scale;
}

/// Solves F(z) = 0 from z. `residual(z, F, J)` fills F and J = dF/dz (a square_matrix<T, N>).
template <int N, class T, class Fn>
step_status newton_solve(Fn&& residual, vec<T, N>& z, const newton_options<T>& opt) {
  opt.validate();
  using std::abs;
  const T eps = std::numeric_limits<T>::epsilon();
  const T tol = T(opt.tolerance_ulps) * eps;
  const T floor_level = epsilon_two_thirds<T>();
  step_status st;
  vec<T, N> F;
  square_matrix<T, N> J = make_square_matrix<T, N>();
  T previous = std::numeric_limits<T>::infinity();
  for (int it = 1; it <= opt.max_iterations; ++it) {
    st.iterations = it;
    residual(z, F, J);
    if (!all_finite(F) || !all_finite(J)) {
      st.reason = step_failure::non_finite_iterate;
      return st;
    }
    vec<T, N> dz;
    if (!solve_small<T, N>(J, vec<T, N>(-F), dz)) {
      st.reason = all_finite(dz) ? step_failure::singular_jacobian : step_failure::non_finite_iterate;
      return st;
    }
    z += dz;
    const T size = dz.template lpNorm<Eigen::Infinity>();
    const T scale = T(1) + z.template lpNorm<Eigen::Infinity>();
    if (size <= tol * scale) return st;
    if (size <= floor_level * scale && size * T(2) > previous) return st;  // round-off floor
    previous = size;
  }
  st.reason = step_failure::no_convergence;
  return st;
}

/// A factorised Newton matrix kept between solves (e.g. from one step to the next), with the
/// largest contraction rate observed while it was used.
template <class T, int N>
struct jacobian_cache {
  lu_small<T, N> lu;
  /// The factorisation of the matrix rounded to double (newton_options::double_jacobian), used
  /// instead of `lu` when `in_double`.
  lu_in_double<N> lu_double;
  bool in_double = false;
  bool valid = false;
  T rate = T(0);

 private:
  struct none {};

 public:
  /// Where newton_solve_simplified forms the Newton matrix when it is on the heap (allocated
  /// here once; small sizes form it in a local of the solve instead).
  [[no_unique_address]] std::conditional_t<heap_matrix<T, N>, square_matrix<T, N>, none> matrix = [] {
    if constexpr (heap_matrix<T, N>)
      return make_square_matrix<T, N>();
    else
      return none{};
  }();

  /// Factorises J, in double if `try_double` and J rounds to a finite double matrix that is not
  /// singular there, else in T. False if J is singular in T.
  bool factor(const square_matrix<T, N>& J, [[maybe_unused]] bool try_double) {
    in_double = false;
    if constexpr (!std::is_floating_point_v<T>) {
      if (try_double && lu_double.factor(J)) {
        in_double = true;
        return true;
      }
    }
    return lu.factor(J);
  }
  /// dz = -J^{-1} F with the kept factorisation; false if dz is not finite.
  bool correction(const vec<T, N>& F, vec<T, N>& dz) const {
    if constexpr (!std::is_floating_point_v<T>) {
      if (in_double) return lu_double.solve(vec<T, N>(-F), dz);
    }
    return lu.solve(vec<T, N>(-F), dz);
  }
};

/// Simplified Newton for F(z) = 0 from z: the Jacobian is evaluated and factorised at the first
/// iterate (or taken from `cache` if that holds a valid factorisation) and reused while the
/// iteration contracts; the other iterations evaluate the residual alone, which for the
/// variational integrators needs one level of AD less. `residual(z, F, J)` fills F and, if the
/// pointer J (to a square_matrix<T, N>) is not null, J = dF/dz.
///
/// Convergence: the correction is at the eps level relative to `scale` + |z|, or below
/// `tolerance_ulps` eps with a contraction rate rho <= 1/8 (so the error left, about rho times
/// the correction, is at the eps level), or (opt.stop_on_rate) the error left that the rate
/// predicts, rho / (1 - rho) times the correction, is below eps; or, below eps^(2/3), the
/// correction has stopped contracting (round-off floor). The Jacobian is refreshed at the current iterate when the
/// iteration contracts by less than a factor 2 or too slowly to reach eps in four more steps.
template <int N, class T, class Fn>
step_status newton_solve_simplified(Fn&& residual, vec<T, N>& z, const newton_options<T>& opt, const T& scale,
                                    jacobian_cache<T, N>* cache = nullptr) {
  opt.validate();
  const T eps = std::numeric_limits<T>::epsilon();
  const T tol = T(opt.tolerance_ulps) * eps;
  const T floor_level = epsilon_two_thirds<T>();
  step_status st;
  if (!cache) {
    jacobian_cache<T, N> local;
    return newton_solve_simplified<N, T>(residual, z, opt, scale, &local);
  }
  jacobian_cache<T, N>& jc = *cache;
  vec<T, N> F;
  square_matrix<T, N> local;  // the matrix of a small system; empty (not allocated) for a large one
  square_matrix<T, N>& J = [&]() -> square_matrix<T, N>& {
    if constexpr (heap_matrix<T, N>)
      return jc.matrix;
    else
      return local;
  }();
  bool refresh = !jc.valid;
  jc.valid = false;
  jc.rate = T(0);
  T previous(0);
  // Whether the next factorisation may be in double (newton_options::double_jacobian); cleared
  // for the rest of the solve when double fails it (below).
  bool try_double = opt.double_jacobian;
  for (int it = 1; it <= opt.max_iterations; ++it) {
    st.iterations = it;
    const bool fresh = refresh;
    residual(z, F, fresh ? &J : static_cast<square_matrix<T, N>*>(nullptr));
    if (!all_finite(F) || (fresh && !all_finite(J))) {
      st.reason = step_failure::non_finite_iterate;
      return st;
    }
    if (fresh) {
      if (!jc.factor(J, try_double)) {
        st.reason = step_failure::singular_jacobian;  // J is finite (checked above)
        return st;
      }
      refresh = false;
    }
    vec<T, N> dz;
    if (!jc.correction(F, dz)) {
      if (jc.in_double) {  // F or the correction beyond double's range: again in T, from here
        try_double = false;
        refresh = true;
        continue;
      }
      st.reason = step_failure::non_finite_iterate;
      return st;
    }
    z += dz;
    const T size = dz.template lpNorm<Eigen::Infinity>();
    const T s = scale + z.template lpNorm<Eigen::Infinity>();
    // A fresh Jacobian makes this a full Newton step (quadratic convergence); a reused one
    // converges linearly with rate rho, measured from the previous correction.
    T rho(1);
    if (!fresh && it > 1) {
      rho = size / previous;
      if (rho > jc.rate) jc.rate = rho;
    }
    const bool converged = size <= eps * s || (size <= tol * s && (fresh || rho <= T(1) / T(8))) ||
                           (opt.stop_on_rate && !fresh && it > 1 && rate_bounds_error(rho, size, s)) ||
                           (it > 1 && size <= floor_level * s && size * T(2) > previous);  // round-off floor
    if (converged) {
      jc.valid = true;
      return st;
    }
    // Refresh the matrix when the iteration contracts by less than 2, or when at its rate more
    // than four further corrections would be needed to reach eps (rho^4 > eps s / size): then
    // a Newton step (quadratic) is cheaper. In double a reused matrix typically stays; in 50
    // digits the linear rate rarely pays.
    if (!fresh && it > 1) {
      const T rho2 = rho * rho;
      if (rho > T(1) / T(2) || rho2 * rho2 * size > eps * s) refresh = true;
      if (rho > T(1) / T(2) && jc.in_double) try_double = false;  // double's matrix stalls it
    }
    previous = size;
  }
  st.reason = step_failure::no_convergence;
  return st;
}

}  // namespace geomint
