/// Compile-time checks of analysis/rk_stability.hpp and method_verdicts.hpp on rational RK
/// tableaux, against the published stability functions and properties:
/// - the Gauss, Radau IIA and Lobatto IIIA stability functions are the Pade approximants
///   R_kj = P_kj / Q_kj of exp (diagonal k = j = s for Gauss, k = s - 1, j = s for Radau IIA and
///   Radau IA, k = j = s - 1 for Lobatto IIIA), with
///     P_kj(z) = sum_{i<=k} k! (k+j-i)! / ((k+j)! i! (k-i)!) z^i,
///     Q_kj(z) = sum_{i<=j} j! (k+j-i)! / ((k+j)! i! (j-i)!) (-z)^i
///   (Hairer & Wanner, Solving ODEs II, section IV.3, Pade approximations, and section IV.5);
///   the diagonal ones are A-stable and not L-stable, the first and second subdiagonal ones
///   L-stable (ibid., section IV.4, Theorem of Ehle; Radau IIA: section IV.5);
/// - explicit RK4: R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, |R(iy)|^2 = 1 - y^6/72 + y^8/576, so
///   |R(iy)| <= 1 exactly for y^2 <= 8: the imaginary-axis interval 2 sqrt 2 (ibid., section IV.2);
///   explicit Euler |1 + iy| > 1 for y != 0: empty;
/// - symmetry (Hairer, Lubich & Wanner, Geometric Numerical Integration, Theorem V.2.3): Gauss and
///   Lobatto IIIA symmetric, Radau and the Euler methods not; implicit Euler over h/2 followed
///   by explicit Euler over h/2 is symmetric (HLW section II.3: Phi*_{h/2} o Phi_{h/2}), its two
///   stages with the equal node 1/2 exchanged by the adjoint;
/// - on y'' = -y: see the last block;
/// - stage order (largest q with B(q) and C(q); HW II sections IV.5 and IV.15): Gauss s
///   (B(2s), C(s)), Radau IIA s (B(2s-1), C(s)), Radau IA s - 1 (C(s-1)), Lobatto IIIA s
///   (B(2s-2), C(s)), explicit RK4 1 (C(2) fails: a_21 c_1 = 0 != c_2^2 / 2).
#include <array>
#include <cstddef>

#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/analysis/rk_stability.hpp"
#include "../pade.hpp"

namespace {

using geomint::exact_number;
using geomint::rational;
using geomint::methods::make_rk;
using R = rational;

/// R (unreduced, P(0) = Q(0) = 1) equals the Pade approximant R_kj of exp (tests/pade.hpp),
/// coefficient by coefficient.
template <class F>
constexpr bool is_pade(const F& f, int k, int j) {
  for (int i = 0; i < static_cast<int>(f.numerator.size()); ++i)
    if (!(f.numerator[static_cast<std::size_t>(i)] == geomint::test::pade_numerator(k, j, i)) ||
        !(f.denominator[static_cast<std::size_t>(i)] == geomint::test::pade_denominator(k, j, i)))
      return false;
  return true;
}

// Gauss s = 1 (implicit midpoint), Radau IIA s = 1 (implicit Euler), s = 2, Radau IA s = 2
// (HW II section IV.5, Tables 5.3 and 5.5), Lobatto IIIA s = 2 (trapezoidal), s = 3 (ibid., Table 5.7).
constexpr auto midpoint = make_rk<R>({R(1, 2)}, {{R(1, 2)}}, {R(1)});
constexpr auto implicit_euler = make_rk<R>({R(1)}, {{R(1)}}, {R(1)});
constexpr auto radau_iia2 = make_rk<R>({R(1, 3), R(1)}, {{R(5, 12), R(-1, 12)}, {R(3, 4), R(1, 4)}}, {R(3, 4), R(1, 4)});
constexpr auto radau_ia2 = make_rk<R>({R(0), R(2, 3)}, {{R(1, 4), R(-1, 4)}, {R(1, 4), R(5, 12)}}, {R(1, 4), R(3, 4)});
constexpr auto trapezoidal = make_rk<R>({R(0), R(1)}, {{R(0), R(0)}, {R(1, 2), R(1, 2)}}, {R(1, 2), R(1, 2)});
constexpr auto lobatto_iiia3 = make_rk<R>({R(0), R(1, 2), R(1)},
                                          {{R(0), R(0), R(0)}, {R(5, 24), R(1, 3), R(-1, 24)}, {R(1, 6), R(2, 3), R(1, 6)}},
                                          {R(1, 6), R(2, 3), R(1, 6)});
constexpr auto rk4 = make_rk<R>({R(0), R(1, 2), R(1, 2), R(1)},
                                {{R(0), R(0), R(0), R(0)}, {R(1, 2), R(0), R(0), R(0)}, {R(0), R(1, 2), R(0), R(0)}, {R(0), R(0), R(1), R(0)}},
                                {R(1, 6), R(1, 3), R(1, 3), R(1, 6)});
constexpr auto explicit_euler = make_rk<R>({R(0)}, {{R(0)}}, {R(1)});
// Implicit Euler over h/2 (k1 = f(y0 + h/2 k1)), then explicit Euler over h/2 (k2 = f(y0 + h/2 k1)).
constexpr auto split_midpoint = make_rk<R>({R(1, 2), R(1, 2)}, {{R(1, 2), R(0)}, {R(1, 2), R(0)}}, {R(1, 2), R(1, 2)});

static_assert(is_pade(geomint::stability_function(midpoint), 1, 1));
static_assert(is_pade(geomint::stability_function(implicit_euler), 0, 1));
static_assert(is_pade(geomint::stability_function(radau_iia2), 1, 2));
static_assert(is_pade(geomint::stability_function(radau_ia2), 1, 2));
static_assert(is_pade(geomint::stability_function(trapezoidal), 1, 1));
static_assert(is_pade(geomint::stability_function(lobatto_iiia3), 2, 2));
static_assert(is_pade(geomint::stability_function(rk4), 4, 0));  // the Taylor polynomial

constexpr geomint::rk_stability_result midpoint_v = geomint::rk_stability(midpoint);
static_assert(midpoint_v.a_stable && !midpoint_v.l_stable && midpoint_v.imaginary_axis.unbounded);
static_assert(midpoint_v.imaginary_axis.kind == geomint::stability_kind::periodic);  // |R(iy)| = 1
constexpr auto trapezoidal_v = geomint::rk_stability(trapezoidal);
static_assert(trapezoidal_v.a_stable && !trapezoidal_v.l_stable);
static_assert(trapezoidal_v.numerator.degree == 1 && trapezoidal_v.denominator.degree == 1);  // reduced: (2 + z) / (2 - z)
static_assert(geomint::rk_stability(lobatto_iiia3).a_stable && !geomint::rk_stability(lobatto_iiia3).l_stable);
static_assert(geomint::rk_stability(implicit_euler).l_stable);
static_assert(geomint::rk_stability(radau_iia2).l_stable);
static_assert(geomint::rk_stability(radau_ia2).l_stable);

constexpr auto rk4_v = geomint::rk_stability(rk4);
static_assert(!rk4_v.a_stable && !rk4_v.l_stable && !rk4_v.bounded_on_imaginary_axis && rk4_v.poles_in_right_half_plane);
static_assert(!rk4_v.imaginary_axis.empty && !rk4_v.imaginary_axis.unbounded);
static_assert(rk4_v.imaginary_axis.compare_squared(exact_number(8)) == 0);  // Y = 2 sqrt 2
static_assert(rk4_v.imaginary_axis.compare_squared(exact_number(rational(799, 100))) < 0);
static_assert(rk4_v.imaginary_axis.compare_squared(exact_number(rational(801, 100))) > 0);
constexpr auto euler_v = geomint::rk_stability(explicit_euler);
static_assert(euler_v.imaginary_axis.empty && !euler_v.a_stable);

static_assert(geomint::is_symmetric(midpoint) && geomint::is_symmetric(trapezoidal) && geomint::is_symmetric(lobatto_iiia3));
static_assert(!geomint::is_symmetric(implicit_euler) && !geomint::is_symmetric(radau_iia2) && !geomint::is_symmetric(radau_ia2));
static_assert(!geomint::is_symmetric(rk4) && !geomint::is_symmetric(explicit_euler));
constexpr geomint::stage_permutation split = geomint::symmetry_permutation(split_midpoint);
static_assert(split.found && split.sigma[0] == 1 && split.sigma[1] == 0);

static_assert(geomint::stage_order(midpoint) == 1 && geomint::stage_order(implicit_euler) == 1);
static_assert(geomint::stage_order(radau_iia2) == 2 && geomint::stage_order(radau_ia2) == 1);
static_assert(geomint::stage_order(trapezoidal) == 2 && geomint::stage_order(lobatto_iiia3) == 3);
static_assert(geomint::stage_order(rk4) == 1);

// On y'' = -y (constexpr linear_stability of a fixed-size tableau): RK4's interval is its
// imaginary-axis interval 2 sqrt 2; the Lobatto IIIA-IIIB pair s = 2 is Stormer-Verlet (HLW
// section II.2): det M = 1, tr M = 2 - tau^2, periodic for tau <= 2.
static_assert(geomint::linear_stability_interval(geomint::linear_stability(rk4)).compare_squared(exact_number(8)) == 0);
constexpr auto lobatto_pair2 = geomint::methods::make_prk<R>({R(0), R(1)}, {{R(0), R(0)}, {R(1, 2), R(1, 2)}}, {R(1, 2), R(1, 2)},
                                                             {{R(1, 2), R(0)}, {R(1, 2), R(0)}}, {R(1, 2), R(1, 2)});
constexpr geomint::linear_stability_result pair2_v = geomint::linear_stability(lobatto_pair2);
static_assert(pair2_v.determinant_is_one && geomint::linear_stability_interval(pair2_v).compare_squared(exact_number(4)) == 0);
static_assert(geomint::is_symmetric(lobatto_pair2) && geomint::stage_order(lobatto_pair2) == 0);

}  // namespace
