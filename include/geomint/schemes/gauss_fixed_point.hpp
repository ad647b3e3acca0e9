#pragma once
/// The fixed-point form of LPF on Gauss-interior nodes for natural systems: the engine of
/// `lpf<m, gauss_interior>` on a natural system (its default solver, schemes/lpf.hpp) and of
/// `lpf<m, gauss_interior, lagrange, fixed_point_solver>`.
///
/// For a natural system (L = qdot^T M qdot / 2 - V(q), M constant) the LPF path of degree m
/// with the Euler-Lagrange equations at the m-1 interior Gauss nodes (lpf.hpp, eq. 12) is the
/// s = m-1 stage Nystrom collocation method at the Gauss points (Hairer, Lubich & Wanner 2006,
/// sections II.1.4 and VI.4; docs/references.md): with v = M^{-1} p and the momentum increments
/// F_i = tau b_i f(Q_i), f = -grad V,
///
///   Q_i     = q + tau (c_i v + M^{-1} sum_j mu_ij F_j)        (mu_ij = abar_ij / b_j)
///   p_{k+1} = p + sum_i F_i
///   q_{k+1} = q + tau (v + M^{-1} sum_i e_i F_i)              (e_i = 1 - c_i)
///
/// the same map as LPF's Newton form (tests/schemes/test_lpf_fixed_point.cpp). The coefficients
/// are that collocation tableau (methods/collocation_rkn.hpp) rounded so that the
/// symplecticity relations e_i = 1 - c_i, mu_ji - mu_ij = e_i - e_j and the symmetry hold
/// exactly in T (methods/symplectic_rounding.hpp, as in IRKGL16: Antonana, Makazaga & Murua
/// 2017): rounded one by one they miss them by an ulp, and the map then drifts off the
/// symplectic manifold by that much every step. The stage equations are solved by fixed-point
/// iteration (no Jacobian, s force evaluations per iteration), iterated until the increments
/// stop changing (schemes/fixed_point_stopping.hpp), so that no iteration error is left that
/// depends smoothly on the state. In multiprecision (newton_options::double_jacobian, the
/// default there) they are solved instead by simplified Newton with the stage matrix in double
/// (schemes/stages_in_double.hpp): the same equations in the working precision, about 15 digits
/// per iteration where a sweep gains a few, each iteration the same s force evaluations.
///
/// With compensated summation in a built-in floating type the step also keeps the two roundings
/// that otherwise grow like t instead of Brouwer's t^(1/2) out of the result: each stage offset
/// is added to the exact product tau (c_i v + ...) (fma), and the increments of q and p are
/// formed to twice the working precision before the compensated sum (stage_point, exact_update).

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "geomint/core/basis.hpp"
#include "geomint/core/mantissa.hpp"
#include "geomint/linalg/dot.hpp"
#include "geomint/linalg/lu_small.hpp"
#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/methods/collocation_rkn.hpp"
#include "geomint/methods/symplectic_rounding.hpp"
#include "geomint/schemes/fixed_point_stopping.hpp"
#include "geomint/schemes/stages_in_double.hpp"
#include "geomint/schemes/step_skeleton.hpp"

namespace geomint {
namespace schemes::detail {


/// The coefficients c, e = 1 - c, b and mu = a / b of the Nystrom collocation method at the s
/// Gauss points (methods/collocation_rkn.hpp), rounded so that the symplecticity conditions and the symmetry
/// mu_i'j' = mu_ij + c_j - c_i (i' = s-1-i) hold exactly in T (methods/symplectic_rounding.hpp);
/// with them the weights of the engine's predictor.
template <class T, int S>
struct gauss_nystrom_coefficients : methods::symplectic_rkn<T, S> {
  /// The predictor of a continuing step: extrapolate_ij = b_i l_j(1 + c_i) / b_j (l_j the
  /// Lagrange basis on the nodes c), which carries the increments F_j = tau b_j f_j of the
  /// previous step's force polynomial (degree S-1 through its S stages) to this step's stages.
  methods::stage_matrix<T, S> extrapolate{};

  /// Computed once per (T, S) and copied: in 50 digits the Gauss rule and the rounding cost more
  /// than the steps of a short run (docs/results/performance.md). A function-local static is
  /// initialised once, thread-safely, and again on the next call if its computation threw. A
  /// variable-precision T (numeric_limits digits INT_MAX, e.g. Boost's mpfr_float) depends on
  /// the precision set at run time, so it is computed every time.
  static gauss_nystrom_coefficients make() {
    if constexpr (std::numeric_limits<T>::digits < std::numeric_limits<int>::max()) {
      static const gauss_nystrom_coefficients once = compute();
      return once;
    } else {
      return compute();
    }
  }

 private:
  static gauss_nystrom_coefficients compute() {
    gauss_nystrom_coefficients k;
    static_cast<methods::symplectic_rkn<T, S>&>(k) = methods::symplecticize(methods::gauss_collocation_rkn<T, S>());
    if (!k.mirrored) throw std::logic_error("geomint: the Gauss coefficients lost their symmetry in rounding");
    for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
      const auto l = lagrange_values_at(k.c, T(T(1) + k.c[i]));
      for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) k.extrapolate[i][j] = k.b[i] * l[j] / k.b[j];
    }
    return k;
  }
};


/// The engine's cache (step_continuation, step_skeleton.hpp): the stage increments of the last
/// step, to predict the next step's by extrapolation.
template <class T, int n, int S>
struct fixed_point_cache : step_continuation<T, n> {
  /// Zero until a step records its own (a copied cache reads every member).
  std::array<vec<T, n>, S> F = [] {
    std::array<vec<T, n>, S> zero;
    zero.fill(vec<T, n>::Zero());
    return zero;
  }();
};

/// The engine: one step (q, p) -> (q1, p1) of the Nystrom form above.
template <class Sys, class T, int M>
class gauss_fixed_point_engine {
 public:
  static constexpr int S = M - 1;
  /// The stage pairs (i, S-1-i); with S odd, stage H is its own mirror.
  static constexpr int H = S / 2;
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;
  /// The unknowns: the stage momentum increments F_1..F_S.
  using unknowns = vec<T, S * n>;
  /// What a caller keeps between steps (fixed_point_cache above).
  using cache_type = fixed_point_cache<T, n, S>;

  explicit gauss_fixed_point_engine(const Sys& sys)
      : sys_(sys), k_(gauss_nystrom_coefficients<T, S>::make()), minv_(inverse_of<T, n>(Sys::template mass_matrix<T>())) {
    if constexpr (!std::is_floating_point_v<T>) {
      for (std::size_t I = 0; I < static_cast<std::size_t>(H); ++I)
        for (std::size_t J = 0; J < static_cast<std::size_t>(H); ++J) {
          const std::size_t Jm = static_cast<std::size_t>(S) - 1 - J;
          mirror_sum_[I][J] = (k_.mu[I][J] + k_.mu[I][Jm]) / T(2);  // exact: grid values
          mirror_difference_[I][J] = (k_.mu[I][J] - k_.mu[I][Jm]) / T(2);
        }
      in_double_ = stages_in_double<Sys, S>(k_.mu, k_.extrapolate, minv_);
    }
  }

  const gauss_nystrom_coefficients<T, S>& coefficients() const { return k_; }

  /// The increments x(c_i) - q of the step's collocation path at the stages c_1..c_S and at the
  /// end (the last entry), from the stage increments F of a step from (q, p) (with a carry, from
  /// (q + carry.q, p + carry.p), as the step): the node values of LPF's path in the Lagrange
  /// basis (lpf.hpp), for its dense output.
  std::array<V, S + 1> path_increments(const V& p, const T& tau, const unknowns& z, const phase_carry<T, n>* carry) const {
    std::array<V, S> F;
    for (int i = 0; i < S; ++i) F[static_cast<std::size_t>(i)] = z.template segment<n>(i * n);
    const V v = inverse_mass(carry ? V(p + carry->p) : p);
    std::array<V, S + 1> Y;
    V se = V::Zero();
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
      Y[I] = tau * V(k_.c[I] * v + inverse_mass(mu_row(I, F)));
      se += k_.e[I] * F[I];
    }
    Y[static_cast<std::size_t>(S)] = tau * V(v + inverse_mass(se));
    return Y;
  }

  /// (q_k, p_k) -> (q_{k+1}, p_{k+1}); `mem` (if not null) is the caller's cache: the stage
  /// increments of its last step are extrapolated when this step continues it, and it then
  /// holds this step; `solution` (if not null) receives the stage increments; `carry` selects
  /// compensated summation of the update (as step_skeleton::one_step). On failure q1, p1 and
  /// carry are untouched. opt.max_iterations bounds the fixed-point sweeps per 16 digits of T
  /// (sweep_budget).
  step_status one_step(const V& q, const V& p, const T& tau, V& q1, V& p1, const newton_options<T>& opt,
                       cache_type* mem = nullptr, unknowns* solution = nullptr,
                       phase_carry<T, n>* carry = nullptr) const {
    opt.validate();
    const V v = inverse_mass(p);
    // Compensated summation: the state is (q + carry.q, p + carry.p). The stages and the update
    // see the carried parts (as in IRKGL16), so that the increments are those of the state the
    // carry stands for, not of its rounding: stage i is q + (offset_i + tau (c_i v + M^{-1} z_i))
    // with offset_i = carry.q + tau c_i M^{-1} carry.p (zero without compensation), the offset
    // added to the exact product in built-in floating types (stage_point).
    const V dv = carry ? inverse_mass(carry->p) : V::Zero();
    stage_terms terms;
    terms.exact_offsets = std::is_floating_point_v<T> && carry;
    for (int i = 0; i < S; ++i) {
      const auto I = static_cast<std::size_t>(i);
      terms.hb[I] = tau * k_.b[I];
      terms.cv[I] = scaled(k_.c[I], v);
      terms.offset[I] = carry ? V(carry->q + scaled(tau, scaled(k_.c[I], dv))) : V::Zero();
      if constexpr (!std::is_floating_point_v<T>) terms.base[I] = terms.offset[I] + scaled(tau, terms.cv[I]);
    }
    std::array<V, S> F;
    const bool continues = mem && mem->continues(q, p, tau);
    // Multiprecision (opt.double_jacobian): the stage equations solved first in double
    // (presolve_in_double), which also leaves the Newton matrix factorised at that solution.
    lu_in_double<S * n> lu;
    bool presolved = false;
    if constexpr (!std::is_floating_point_v<T>) {
      if (opt.double_jacobian) presolved = presolve_in_double(q, tau, terms, continues ? &mem->F : nullptr, F, lu, opt.max_iterations);
    }
    if (!presolved && continues) {
      for (int i = 0; i < S; ++i) {
        V x = V::Zero();
        for (int j = 0; j < S; ++j) x += k_.extrapolate[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * mem->F[static_cast<std::size_t>(j)];
        F[static_cast<std::size_t>(i)] = x;
      }
    } else if (!presolved) {
      for (int i = 0; i < S; ++i)
        F[static_cast<std::size_t>(i)] = scaled(terms.hb[static_cast<std::size_t>(i)], force(V(q + scaled(T(tau * k_.c[static_cast<std::size_t>(i)]), v))));
    }
    step_status st = iterate(q, tau, terms, F, opt, lu, presolved);
    if (!st) {
      if (mem) mem->valid = false;
      return st;
    }
    V se;
    for (int r = 0; r < n; ++r) se[r] = linalg::dot(k_.e.data(), &F[0][r], S, n);
    const V rest = dv + inverse_mass(se);
    phase_carry<T, n> carry_next;
    if (carry) carry_next = *carry;
    bool updated = false;
    if constexpr (std::is_floating_point_v<T>) {
      if (terms.exact_offsets) {
        exact_update(q, p, v, rest, tau, F, q1, p1, carry_next);
        updated = true;
      }
    }
    if (!updated) {
      V dp = V::Zero();
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) dp += F[I];
      const V dq = scaled(tau, V(v + rest));
      q1 = apply_end_update<T, n>(q, dq, true, carry ? &carry_next.q : nullptr);
      p1 = apply_end_update<T, n>(p, dp, true, carry ? &carry_next.p : nullptr);
    }
    if (carry) *carry = carry_next;
    if (solution)
      for (int i = 0; i < S; ++i) solution->template segment<n>(i * n) = F[static_cast<std::size_t>(i)];
    if (mem) {
      mem->record(tau, q1, p1);
      mem->F = F;
    }
    return st;
  }

 private:
  /// What every sweep of one step reuses: tau b_i, c_i v and the stage offsets of the carry;
  /// exact_offsets: a compensated step in a built-in floating type (below).
  struct stage_terms {
    std::array<T, S> hb;
    std::array<V, S> cv, offset;
    /// offset_i + tau c_i v (multiprecision): stage i is q + (base_i + tau M^{-1} z_i).
    std::array<V, S> base;
    bool exact_offsets = false;
  };

  /// The stage point q + (offset_i + tau s): with exact_offsets the offset is added to the exact
  /// product tau s (one rounding, fma) instead of to its rounding. Measured (geomint-brouwer,
  /// docs/results/long_runs.md): that second rounding, in every stage of every sweep, is what
  /// made the compensated energy error grow faster than Brouwer's t^(1/2).
  static V stage_point(const V& q, const V& offset, const T& tau, const V& s, bool exact_offsets) {
    if constexpr (std::is_floating_point_v<T>) {
      if (exact_offsets) {
        V Q;
        for (int r = 0; r < n; ++r) Q[r] = q[r] + std::fma(tau, s[r], offset[r]);
        return Q;
      }
    }
    return q + V(offset + tau * s);
  }

  /// The compensated update with increments to twice the working precision (built-in floating
  /// types): dp = sum_i F_i accumulated with two_sum, dq = tau (v + rest) with v + rest by
  /// two_sum and the product's rounding error by fma (TwoProduct, Ogita, Rump & Oishi 2005,
  /// docs/references.md), both added to (q, p) and their carries by the
  /// double-length add_compensated (solvers/phase_state.hpp). Rounding each increment to one
  /// scalar before the compensated sum left a drift above Brouwer's law (long_runs.md).
  static void exact_update(const V& q, const V& p, const V& v, const V& rest, const T& tau, const std::array<V, S>& F,
                           V& q1, V& p1, phase_carry<T, n>& carry) {
    V dp = V::Zero(), dp_lo = V::Zero(), dq, dq_lo;
    for (int r = 0; r < n; ++r) {
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
        T sum, err;
        two_sum(dp[r], F[I][r], sum, err);
        dp[r] = sum;
        dp_lo[r] += err;
      }
      T w, w_lo;
      two_sum(v[r], rest[r], w, w_lo);
      dq[r] = tau * w;
      dq_lo[r] = std::fma(tau, w, -dq[r]) + tau * w_lo;
    }
    q1 = q;
    p1 = p;
    add_compensated(q1, carry.q, dq, dq_lo);
    add_compensated(p1, carry.p, dp, dp_lo);
  }

  /// f(x) = -grad V(x): the system's potential_gradient if it supplies one, else AD on V.
  V force(const V& x) const { return lagrangian_derivatives<Sys, T>::lagrangian_q(sys_, x, V::Zero()); }

  /// next[I n + r] = tau b_I f_r(Q_I) at the stage points of the combinations z: on SIMD packs
  /// where the system opts in (double, newton_options::simd_forces), else one by one.
  void sweep_forces(const V& q, const T& tau, const stage_terms& terms, const T* z, T* next, bool simd) const {
    auto point = [&](std::size_t I) {
      return stage_point(q, terms.offset[I], tau, V(terms.cv[I] + inverse_mass(V::Map(&z[I * n]))), terms.exact_offsets);
    };
    if constexpr (std::is_same_v<T, double> && stage_parallel_system<Sys>) {
      if (simd) {
        std::array<V, S> Q;
        for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) Q[I] = point(I);
        forces_in_packs(Q, terms.hb, next);
        return;
      }
    }
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) {
      const V g = force(point(I));
      for (int r = 0; r < n; ++r) next[I * n + r] = terms.hb[I] * g[r];
    }
  }

  /// next[I n + r] = hb_I f_r(Q_I) for every stage, simd_width stages per call of the system's
  /// potential_gradient on packs (core/simd.hpp): the S evaluations of a Jacobi sweep are
  /// independent. The stage points are laid out component by component (lanes past the last
  /// stage repeat it, a point the force is defined at), so that each pack is one load and each
  /// result one store. f = -grad V, as force().
  static void forces_in_packs(const std::array<V, S>& Q, const std::array<T, S>& hb, T* next) {
    constexpr int W = simd_width;
    constexpr int L = (S + W - 1) / W * W;
    using P = double_pack<W>;
    std::array<double, static_cast<std::size_t>(n * L)> points, forces;
    for (int I = 0; I < L; ++I)
      for (int r = 0; r < n; ++r) points[static_cast<std::size_t>(r * L + I)] = Q[static_cast<std::size_t>(I < S ? I : S - 1)][r];
    for (int I0 = 0; I0 < L; I0 += W) {
      vec<P, n> x;
      for (int r = 0; r < n; ++r) x[r] = P::load(&points[static_cast<std::size_t>(r * L + I0)]);
      const vec<P, n> g = Sys::template potential_gradient<P>(x);
      for (int r = 0; r < n; ++r) g[r].store(&forces[static_cast<std::size_t>(r * L + I0)]);
    }
    for (int I = 0; I < S; ++I)
      for (int r = 0; r < n; ++r) next[I * n + r] = hb[static_cast<std::size_t>(I)] * -forces[static_cast<std::size_t>(r * L + I)];
  }

  /// Built-in floating types: Jacobi sweeps F <- tau b_i f(Q_i(F)), whose S force evaluations
  /// are independent and overlap in the processor's pipeline (Gauss-Seidel's chain of dependent
  /// evaluations was slower per step in double despite the fewer sweeps). Each sweep forms all
  /// stage sums at once (jacobi_combination), evaluates the forces, then measures the change,
  /// the size and the finiteness of the S n new increments in one pass over them.
  step_status sweep_in_builtin(const V& q, const T& tau, const stage_terms& terms, std::array<V, S>& F,
                               const newton_options<T>& opt) const {
    static_assert(sizeof(std::array<V, S>) == sizeof(T) * S * n, "stage vectors are stored contiguously");
    using std::abs;
    sweep_stopping_rule<T> rule{opt, T(std::numeric_limits<T>::epsilon() * q.template lpNorm<Eigen::Infinity>())};
    step_status st;
    T* f = F[0].data();
    for (int it = 1; it <= rule.budget; ++it) {
      st.iterations = it;
      std::array<T, S * n> z, next;
      jacobi_combination(f, z.data());
      sweep_forces(q, tau, terms, z.data(), next.data(), opt.simd_forces);
      T change(0), size(0);
      bool finite = true;
      for (std::size_t k = 0; k < static_cast<std::size_t>(S * n); ++k) {
        const T a = abs(next[k]), d = abs(T(next[k] - f[k]));
        finite = finite && a <= std::numeric_limits<T>::max();
        size = a > size ? a : size;
        change = d > change ? d : change;
        f[k] = next[k];
      }
      if (!finite) {
        st.reason = step_failure::non_finite_iterate;
        return st;
      }
      if (rule.stops(change, size, it, st)) return st;
    }
    st.reason = step_failure::no_convergence;
    return st;
  }

  /// Multiprecision: Gauss-Seidel sweeps (each stage sees the stages already updated in this
  /// sweep: fewer sweeps), or F <- F + (dG/dF)^{-1} (tau b f(Q(F)) - F) with dG/dF in double
  /// (in `lu`, already factorised by presolve_in_double if `factorised`, else formed here by
  /// stage_matrix), until stopping_rule stops it. A non-finite iterate is a failure. Built-in
  /// types: sweep_in_builtin.
  step_status iterate(const V& q, const T& tau, const stage_terms& terms, std::array<V, S>& F,
                      const newton_options<T>& opt, lu_in_double<S * n>& lu, bool factorised) const {
    if constexpr (std::is_floating_point_v<T>) {
      (void)lu;
      (void)factorised;
      return sweep_in_builtin(q, tau, terms, F, opt);
    } else {
      using std::abs;
      sweep_stopping_rule<T> rule{opt, T(std::numeric_limits<T>::epsilon() * q.template lpNorm<Eigen::Infinity>())};
      step_status st;
      // Simplified Newton on the stage equations with their matrix in double (stage_matrix,
      // opt.double_jacobian); otherwise, or where double cannot hold the matrix, sweeps.
      bool newton = factorised;
      if (!newton && opt.double_jacobian) {
        std::array<vec<double, n>, S> Q;
        for (int i = 0; i < S; ++i) {
          const auto I = static_cast<std::size_t>(i);
          const V Qt = stage_point(q, terms.offset[I], tau, V(terms.cv[I] + inverse_mass(mu_row(I, F))), terms.exact_offsets);
          for (int r = 0; r < n; ++r) Q[I][r] = to_double(Qt[r]);
        }
        newton = in_double_.matrix(sys_, Q, to_double(tau), weights_in_double(terms), lu);
      }
      for (int it = 1; it <= rule.budget; ++it) {
        st.iterations = it;
        std::array<V, S> next, z;
        // Newton's pass sees one F throughout: its combinations at once (mu_combination); the
        // Gauss-Seidel sweeps update F stage by stage.
        if (newton) z = mu_combination(F);
        T change(0), size(0);
        for (int i = 0; i < S; ++i) {
          const auto I = static_cast<std::size_t>(i);
          const V Q = newton ? plus(q, plus(terms.base[I], scaled(tau, inverse_mass(z[I]))))
                             : stage_point(q, terms.offset[I], tau, V(terms.cv[I] + inverse_mass(mu_row(I, F))), terms.exact_offsets);
          next[I] = scaled(terms.hb[I], force(Q));
          if (!all_finite(next[I])) {
            st.reason = step_failure::non_finite_iterate;
            return st;
          }
          if (!newton) {  // (Newton measures its corrections below)
            for (int r = 0; r < n; ++r) {
              const T d = abs(next[I][r] - F[I][r]);
              if (d > change) change = d;
              const T a = abs(next[I][r]);
              if (a > size) size = a;
            }
            F[I] = next[I];
          }
        }
        // The Newton correction d = (dG/dF)^{-1} (h(F) - F), solved in double from the residual
        // in T: the fixed point stays T's, each correction gains about 15 digits.
        if (newton) {
          vec<T, S * n> r, d;
          for (int i = 0; i < S; ++i)
            r.template segment<n>(i * n) = minus(next[static_cast<std::size_t>(i)], F[static_cast<std::size_t>(i)]);
          if (!lu.solve(r, d)) {
            // Beyond double's range: this pass becomes a Jacobi sweep (F <- h(F), its change
            // measured), Gauss-Seidel sweeps from here.
            newton = false;
            for (int i = 0; i < S; ++i)
              for (int c = 0; c < n; ++c) {
                if (abs(T(r[i * n + c])) > change) change = abs(T(r[i * n + c]));
                if (abs(next[static_cast<std::size_t>(i)][c]) > size) size = abs(next[static_cast<std::size_t>(i)][c]);
              }
          } else {
            change = T(0);
            size = T(0);
            for (int i = 0; i < S; ++i) {
              const auto I = static_cast<std::size_t>(i);
              next[I] = plus(F[I], d.template segment<n>(i * n));
              for (int c = 0; c < n; ++c) {
                const T dc = abs(T(d[i * n + c]));
                if (dc > change) change = dc;
                if (abs(next[I][c]) > size) size = abs(next[I][c]);
              }
            }
          }
        }
        F = next;
        if (rule.stops(change, size, it, st)) return st;
      }
      st.reason = step_failure::no_convergence;
      return st;
    }
  }

  /// a x, a + b and a - b, one rounding per component (multiply_into, add_into: for
  /// cpp_bin_float on the mantissas, without Boost's temporaries).
  static V scaled(const T& a, const V& x) {
    V out;
    for (int r = 0; r < n; ++r) multiply_into(out[r], a, x[r]);
    return out;
  }
  static V plus(const V& a, const V& b) {
    V out;
    for (int r = 0; r < n; ++r) add_into(out[r], a[r], b[r]);
    return out;
  }
  static V minus(const V& a, const V& b) {
    V out;
    for (int r = 0; r < n; ++r) subtract_into(out[r], a[r], b[r]);
    return out;
  }

  /// M^{-1} x: skipped for a unit mass matrix, one product per entry for a diagonal one (the
  /// same roundings as the full product, whose other terms are exact zeros).
  V inverse_mass(const V& x) const {
    if (unit_mass_) return x;
    if (diagonal_mass_) return V(minv_diagonal_.cwiseProduct(x));
    return V(minv_ * x);
  }

  /// z_i = sum_j mu_ij F_j for every stage (built-in types; f and z hold S stage vectors of n
  /// values each), by columns: each F_j added to all stages at once (contiguous, vectorised),
  /// each z_i summed over j in order.
  void jacobi_combination(const T* f, T* z) const {
    for (std::size_t k = 0; k < static_cast<std::size_t>(S * n); ++k) z[k] = T(0);
    for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J)
      for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
        for (std::size_t r = 0; r < static_cast<std::size_t>(n); ++r) z[I * n + r] += mu_by_column_[J][I] * f[J * n + r];
  }

  /// sum_j mu_ij F_j (multiprecision: the Gauss-Seidel sweeps and the odd middle stage).
  V mu_row(std::size_t I, const std::array<V, S>& F) const {
    V z;
    for (int r = 0; r < n; ++r) z[r] = linalg::dot(k_.mu[I].data(), &F[0][r], S, n);
    return z;
  }

  /// z_i = sum_j mu_ij F_j for every stage, by the mirror symmetry mu_i'j' = mu_ij + c_j - c_i
  /// (i' = S-1-i): with u_j = F_j + F_j', w_j = F_j - F_j' over the first H stages,
  ///   z_i  = X_i + Y_i,  z_i' = X_i - Y_i + sum_j e_j F_j - c_i sum_j F_j,
  ///   X_i = sum_j (mu_ij + mu_ij')/2 u_j (+ mu_iH F_H for odd S),  Y_i = sum_j (mu_ij - mu_ij')/2 w_j,
  /// the middle row of odd S directly: about S^2/2 + 3S products where the rows take S^2.
  /// (The sums of products by linalg::dot: exact products, one rounding, for cpp_bin_float.)
  std::array<V, S> mu_combination(const std::array<V, S>& F) const {
    static_assert(sizeof(std::array<V, S>) == sizeof(T) * S * n, "stage vectors are stored contiguously");
    std::array<V, H> u, w;
    V total = V::Zero(), weighted;
    for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J) total = plus(total, F[J]);
    for (int r = 0; r < n; ++r) weighted[r] = linalg::dot(k_.e.data(), &F[0][r], S, n);
    for (std::size_t J = 0; J < static_cast<std::size_t>(H); ++J) {
      const std::size_t Jm = static_cast<std::size_t>(S) - 1 - J;
      u[J] = plus(F[J], F[Jm]);
      w[J] = minus(F[J], F[Jm]);
    }
    std::array<V, S> z;
    for (std::size_t I = 0; I < static_cast<std::size_t>(H); ++I) {
      V x, y;
      for (int r = 0; r < n; ++r) {
        x[r] = linalg::dot(mirror_sum_[I].data(), &u[0][r], H, n);
        y[r] = linalg::dot(mirror_difference_[I].data(), &w[0][r], H, n);
      }
      if constexpr (S % 2 == 1) x = plus(x, scaled(k_.mu[I][static_cast<std::size_t>(H)], F[static_cast<std::size_t>(H)]));
      z[I] = plus(x, y);
      z[static_cast<std::size_t>(S) - 1 - I] = plus(minus(x, y), minus(weighted, scaled(k_.c[I], total)));
    }
    if constexpr (S % 2 == 1) z[static_cast<std::size_t>(H)] = mu_row(static_cast<std::size_t>(H), F);
    return z;
  }

  /// tau b_i in double.
  static typename stages_in_double<Sys, S>::weights weights_in_double(const stage_terms& terms) {
    typename stages_in_double<Sys, S>::weights hb;
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I) hb[I] = to_double(terms.hb[I]);
    return hb;
  }

  /// The stage equations solved first in double (stages_in_double::solve), from the
  /// extrapolation of the previous step's increments (`previous`) or else from the explicit
  /// stage estimate: F receives that solution and `lu` the matrix factorised at it, so that the
  /// iteration in T (iterate) starts where double ends. False (F and lu unusable) if double
  /// cannot hold the step or its iteration does not converge within max_iterations.
  bool presolve_in_double(const V& q, const T& tau, const stage_terms& terms, const std::array<V, S>* previous,
                          std::array<V, S>& F, lu_in_double<S * n>& lu, int max_iterations) const {
    using stages = typename stages_in_double<Sys, S>::stages;
    vec<double, n> qd;
    for (int r = 0; r < n; ++r) qd[r] = to_double(q[r]);
    stages base, last, Fd;
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
      for (int r = 0; r < n; ++r) {
        base[I][r] = to_double(terms.base[I][r]);
        if (previous) last[I][r] = to_double((*previous)[I][r]);
      }
    if (!in_double_.solve(sys_, qd, base, weights_in_double(terms), to_double(tau), previous ? &last : nullptr, Fd, lu,
                          max_iterations))
      return false;
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
      for (int r = 0; r < n; ++r) F[I][r] = from_double<T>(Fd[I][r]);
    return true;
  }

  Sys sys_;
  gauss_nystrom_coefficients<T, S> k_;
  mat<T, n> minv_;
  /// Entry by entry (Eigen's comparison with Identity() trips GCC 12's -Wmaybe-uninitialized at
  /// -O3 for multiprecision scalars).
  static bool zero_off_diagonal(const mat<T, n>& m, bool unit_diagonal) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j ? m(i, j) != T(0) : (unit_diagonal && m(i, j) != T(1))) return false;
    return true;
  }
  bool unit_mass_ = zero_off_diagonal(minv_, true);
  bool diagonal_mass_ = zero_off_diagonal(minv_, false);
  V minv_diagonal_ = minv_.diagonal();
  /// mu transposed: mu_by_column_[j][i] = mu_ij (jacobi_combination).
  std::array<std::array<T, S>, S> mu_by_column_ = [this] {
    std::array<std::array<T, S>, S> t{};
    for (std::size_t I = 0; I < static_cast<std::size_t>(S); ++I)
      for (std::size_t J = 0; J < static_cast<std::size_t>(S); ++J) t[J][I] = k_.mu[I][J];
    return t;
  }();
  /// (mu_ij + mu_ij')/2 and (mu_ij - mu_ij')/2 for i, j < H (multiprecision; mu_combination).
  std::array<std::array<T, H>, H> mirror_sum_{}, mirror_difference_{};
  /// mu, the extrapolation and M^{-1} in double, for the multiprecision steps (presolve_in_double).
  stages_in_double<Sys, S> in_double_;
};

}  // namespace schemes::detail
}  // namespace geomint
