/// geomint-workprecision: the method lists of both problems in the digits GEOMINT_WP_DIGITS; one
/// translation unit per digits, and one for libqd's dd_real at 50 digits' regime
/// (GEOMINT_WP_DOUBLE_DOUBLE; CMakeLists.txt).
#include <boost/multiprecision/cpp_bin_float.hpp>
#if GEOMINT_WP_DOUBLE_DOUBLE
#include "geomint/core/qd.hpp"
#endif

// Boost 1.74's explicit_error_generic_rk copy constructor reads members that its default
// constructor leaves empty (resized before use); GCC 12 flags the copy inside
// controlled_runge_kutta's constructor. The warning is in Boost's header, not here.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "measurement.hpp"
#include "regimes.hpp"

/// Odeint's norm_inf descends value_type chains; a Boost.Multiprecision number is its own end.
template <>
struct boost::numeric::odeint::detail::extract_value_type<boost::multiprecision::cpp_bin_float_50, void> {
  using type = boost::multiprecision::cpp_bin_float_50;
};
#if GEOMINT_WP_DOUBLE_DOUBLE
template <>
struct boost::numeric::odeint::detail::extract_value_type<dd_real, void> {
  using type = dd_real;
};
#endif

namespace geomint::workprecision {
namespace {

/// The peers of every problem. First knobs: the first error near 1e-4 in double over T = 1000
/// and near 1e-12 in 50 digits over T = 100 on the pendulum and Kepler; `steps_scale` scales the
/// first step counts of another problem (the tolerances start where they do).
template <class P, class T, bool multiprecision>
void add_peers(std::vector<method<T, P::n>>& all, double steps_scale = 1) {
  using namespace geomint;
  using rkn = odeint::symplectic_rkn_sb3a_mclachlan<arr<T, P::n>, arr<T, P::n>, T>;
  using rkn_m4 = odeint::symplectic_rkn_sb3a_m4_mclachlan<arr<T, P::n>, arr<T, P::n>, T>;
  using C = analysis::symmetric_composition<T>;
  auto steps = [steps_scale](long base) { return std::max(1L, std::lround(double(base) * steps_scale)); };
  if constexpr (!multiprecision) {
    all.push_back(odeint_rkn<P, rkn, T>("odeint-symplectic_rkn_sb3a_mclachlan", steps(4000)));
    all.push_back(odeint_rkn<P, rkn_m4, T>("odeint-symplectic_rkn_sb3a_m4_mclachlan", steps(4000)));
    all.push_back(odeint_verlet<P, T>("odeint-velocity_verlet", steps(20000)));
    all.push_back(odeint_rkf78<P, T>("odeint-runge_kutta_fehlberg78", 16));
    all.push_back(odeint_bulirsch_stoer<P, T>("odeint-bulirsch_stoer", 16));
    all.push_back(composition_method<P, T>("sv-yoshida6-s7", C::yoshida6(), steps(5000)));
    all.push_back(composition_method<P, T>("sv-kahan-li8-s17", C::kahan_li8(), steps(2000)));
    all.push_back(composition_method<P, T>("sv-sofroniou-spaletta10-s35", C::sofroniou_spaletta10(), steps(1000)));
  } else {
    all.push_back(odeint_rkn<P, rkn_m4, T>("odeint-symplectic_rkn_sb3a_m4_mclachlan", steps(10000)));
    all.push_back(odeint_rkf78<P, T>("odeint-runge_kutta_fehlberg78", 48));
    all.push_back(odeint_bulirsch_stoer<P, T>("odeint-bulirsch_stoer", 48));
    all.push_back(composition_method<P, T>("sv-yoshida6-s7", C::yoshida6(), steps(4000)));
    all.push_back(composition_method<P, T>("sv-kahan-li8-s17", C::kahan_li8(), steps(1000)));
    all.push_back(composition_method<P, T>("sv-sofroniou-spaletta10-s35", C::sofroniou_spaletta10(), steps(400)));
  }
  all.push_back(taylor_method<P, T>("taylor-series"));
}

/// The outer solar system (18 dof): LPF's fixed-point form up to m = 16, and the schemes with a
/// Newton form only while their (18 m)^2 Newton matrix stays within Eigen's fixed-size stack
/// limit (double: lpf m = 4, 6, whose default solver takes the fixed-point form's steps with
/// Newton for a step beyond its reach, and galerkin m = 4; none in 50 digits, where the first
/// one would be m = 2).
template <class P, class T, bool multiprecision>
std::vector<method<T, P::n>> methods_large(bool compensated) {
  using namespace geomint;
  std::vector<method<T, P::n>> all;
  if constexpr (!multiprecision) {
    all.push_back(geomint_method<P, galerkin_vi<4>, T>("galerkin-m4", 300, compensated));
    all.push_back(geomint_method<P, lpf<4, gauss_interior>, T>("lpf-m4-gauss-interior", 500, compensated));
    all.push_back(geomint_method<P, lpf<6, gauss_interior>, T>("lpf-m6-gauss-interior", 150, compensated));
    all.push_back(geomint_method<P, lpf_fixed_point<6>, T>("lpf-fixed-point-m6", 120, compensated));
    all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8", 80, compensated));
    all.push_back(geomint_method<P, lpf_fixed_point<10>, T>("lpf-fixed-point-m10", 60, compensated));
    all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12", 50, compensated));
    all.push_back(geomint_method<P, lpf_fixed_point<16>, T>("lpf-fixed-point-m16", 40, compensated));
    // The stage forces one by one (newton_options::simd_forces off), to measure the packs.
    all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8-scalar-forces", 80, compensated, false, false));
    all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12-scalar-forces", 50, compensated, false, false));
  } else {
    all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8", 20, compensated));
    all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12", 10, compensated));
    all.push_back(geomint_method<P, lpf_fixed_point<16>, T>("lpf-fixed-point-m16", 8, compensated));
  }
  add_peers<P, T, multiprecision>(all, multiprecision ? 0.05 : 0.1);
  return all;
}

template <class P, class T>
std::vector<method<T, P::n>> methods_16(bool compensated) {
  using namespace geomint;
  std::vector<method<T, P::n>> all;
  all.push_back(geomint_method<P, trapezoidal_vi, T>("trapezoidal", 20000, compensated));
  all.push_back(geomint_method<P, midpoint_vi, T>("midpoint", 20000, compensated));
  all.push_back(geomint_method<P, galerkin_vi<4>, T>("galerkin-m4", 500, compensated));
  all.push_back(geomint_method<P, galerkin_vi<8>, T>("galerkin-m8", 300, compensated));
  all.push_back(geomint_method<P, galerkin_vi<16>, T>("galerkin-m16", 250, compensated));
  all.push_back(geomint_method<P, lpf<4, gauss_interior>, T>("lpf-m4-gauss-interior", 2000, compensated));
  all.push_back(geomint_method<P, lpf<6, gauss_interior>, T>("lpf-m6-gauss-interior", 500, compensated));
  all.push_back(geomint_method<P, lpf<8, gauss_interior>, T>("lpf-m8-gauss-interior", 500, compensated));
  all.push_back(geomint_method<P, lpf<10, gauss_interior>, T>("lpf-m10-gauss-interior", 300, compensated));
  all.push_back(geomint_method<P, lpf<12, gauss_interior>, T>("lpf-m12-gauss-interior", 300, compensated));
  all.push_back(geomint_method<P, lpf<16, gauss_interior>, T>("lpf-m16-gauss-interior", 250, compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<6>, T>("lpf-fixed-point-m6", 500, compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8", 500, compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<10>, T>("lpf-fixed-point-m10", 300, compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12", 300, compensated));
  // The same with newton_options::stop_on_rate (the sweep that only confirms convergence saved).
  all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8-stop-on-rate", 500, compensated, true));
  all.push_back(geomint_method<P, lpf_fixed_point<10>, T>("lpf-fixed-point-m10-stop-on-rate", 300, compensated, true));
  all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12-stop-on-rate", 300, compensated, true));
  // The stage forces one by one (newton_options::simd_forces off), to measure the packs.
  all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8-scalar-forces", 500, compensated, false, false));
  all.push_back(geomint_method<P, lpf_fixed_point<10>, T>("lpf-fixed-point-m10-scalar-forces", 300, compensated, false, false));
  all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12-scalar-forces", 300, compensated, false, false));
  add_peers<P, T, false>(all);
  return all;
}

template <class P, class T>
std::vector<method<T, P::n>> methods_50(bool compensated) {
  using namespace geomint;
  std::vector<method<T, P::n>> all;
  all.push_back(geomint_method<P, galerkin_vi<8>, T>("galerkin-m8", 200, compensated));
  all.push_back(geomint_method<P, galerkin_vi<12>, T>("galerkin-m12", 100, compensated));
  all.push_back(geomint_method<P, galerkin_vi<16>, T>("galerkin-m16", 100, compensated));
  all.push_back(geomint_method<P, lpf<6, gauss_interior>, T>("lpf-m6-gauss-interior", 400, compensated));
  all.push_back(geomint_method<P, lpf<8, gauss_interior>, T>("lpf-m8-gauss-interior", 200, compensated));
  all.push_back(geomint_method<P, lpf<10, gauss_interior>, T>("lpf-m10-gauss-interior", 100, compensated));
  all.push_back(geomint_method<P, lpf<12, gauss_interior>, T>("lpf-m12-gauss-interior", 100, compensated));
  all.push_back(geomint_method<P, lpf<16, gauss_interior>, T>("lpf-m16-gauss-interior", 100, compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8", 200, compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12", 100, compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<16>, T>("lpf-fixed-point-m16", 100, compensated));
  add_peers<P, T, true>(all);
  return all;
}

/// libqd's dd_real at 50 digits' regime (1e-30 at T = 100): LPF's fixed-point form and the
/// peers: Odeint's explicit steppers, the compositions and the Taylor-series flow. Odeint's
/// bulirsch_stoer is left out: it constructs its scalar from a size_t, which dd_real cannot (its
/// constructors from int and double are both candidates).
template <class P, class T>
std::vector<method<T, P::n>> methods_double_double(bool compensated) {
  using namespace geomint;
  using rkn_m4 = odeint::symplectic_rkn_sb3a_m4_mclachlan<arr<T, P::n>, arr<T, P::n>, T>;
  using C = analysis::symmetric_composition<T>;
  const double scale = P::n > 8 ? 0.05 : 1;
  auto steps = [scale](long base) { return std::max(1L, std::lround(double(base) * scale)); };
  std::vector<method<T, P::n>> all;
  all.push_back(geomint_method<P, lpf_fixed_point<8>, T>("lpf-fixed-point-m8", steps(200), compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<12>, T>("lpf-fixed-point-m12", steps(100), compensated));
  all.push_back(geomint_method<P, lpf_fixed_point<16>, T>("lpf-fixed-point-m16", steps(100), compensated));
  all.push_back(odeint_rkn<P, rkn_m4, T>("odeint-symplectic_rkn_sb3a_m4_mclachlan", steps(10000)));
  all.push_back(odeint_rkf78<P, T>("odeint-runge_kutta_fehlberg78", 48));
  all.push_back(composition_method<P, T>("sv-yoshida6-s7", C::yoshida6(), steps(4000)));
  all.push_back(composition_method<P, T>("sv-kahan-li8-s17", C::kahan_li8(), steps(1000)));
  all.push_back(composition_method<P, T>("sv-sofroniou-spaletta10-s35", C::sofroniou_spaletta10(), steps(400)));
  all.push_back(taylor_method<P, T>("taylor-series"));
  return all;
}

/// The sweeps of one problem in the scalar T, against the reference in R.
template <class P, class T, class R, bool multiprecision>
int run_in(const settings& o) {
  std::vector<method<T, P::n>> all;
  if constexpr (P::n > 8) all = methods_large<P, T, multiprecision>(o.compensated);
  else if constexpr (multiprecision) all = methods_50<P, T>(o.compensated);
  else all = methods_16<P, T>(o.compensated);
  return run_sweeps<P, T, R>(o, multiprecision ? regime_50() : regime_16(), std::move(all));
}

}  // namespace

#if GEOMINT_WP_DOUBLE_DOUBLE
template <class P>
int run_regime_double_double(const settings& o) {
  using R = boost::multiprecision::cpp_bin_float_100;
  return run_sweeps<P, dd_real, R>(o, regime_50(), methods_double_double<P, dd_real>(o.compensated));
}
template int run_regime_double_double<pendulum_problem>(const settings&);
template int run_regime_double_double<kepler_problem>(const settings&);
template int run_regime_double_double<outer_solar_problem>(const settings&);
#else
template <class P, int Digits>
int run_regime(const settings& o) {
#if GEOMINT_WP_STUB
  (void)o;
  std::cerr << "geomint-workprecision: --digits " << Digits
            << " is not compiled into this build (configured with GEOMINT_RUN_MULTIPRECISION=OFF)\n";
  return 2;
#else
  constexpr bool multiprecision = Digits != 16;
  using T = std::conditional_t<multiprecision, boost::multiprecision::cpp_bin_float_50, double>;
  using R = std::conditional_t<multiprecision, boost::multiprecision::cpp_bin_float_100, boost::multiprecision::cpp_bin_float_50>;
  return run_in<P, T, R, multiprecision>(o);
#endif
}

template int run_regime<pendulum_problem, GEOMINT_WP_DIGITS>(const settings&);
template int run_regime<kepler_problem, GEOMINT_WP_DIGITS>(const settings&);
template int run_regime<outer_solar_problem, GEOMINT_WP_DIGITS>(const settings&);
#endif

}  // namespace geomint::workprecision
