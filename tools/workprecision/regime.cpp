/// geomint-workprecision: the method lists of both problems in the digits GEOMINT_WP_DIGITS; one
/// translation unit per digits (CMakeLists.txt).
#include <boost/multiprecision/cpp_bin_float.hpp>

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

namespace geomint::workprecision {
namespace {

/// The methods and first knobs (chosen so that the first error is near 1e-4 in double over
/// T = 1000 and near 1e-12 in 50 digits over T = 100).
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
  all.push_back(odeint_rkn<P, odeint::symplectic_rkn_sb3a_mclachlan<arr<T, P::n>, arr<T, P::n>, T>, T>(
      "odeint-symplectic_rkn_sb3a_mclachlan", 4000));
  all.push_back(odeint_rkn<P, odeint::symplectic_rkn_sb3a_m4_mclachlan<arr<T, P::n>, arr<T, P::n>, T>, T>(
      "odeint-symplectic_rkn_sb3a_m4_mclachlan", 4000));
  all.push_back(odeint_verlet<P, T>("odeint-velocity_verlet", 20000));
  all.push_back(odeint_rkf78<P, T>("odeint-runge_kutta_fehlberg78", 16));
  all.push_back(odeint_bulirsch_stoer<P, T>("odeint-bulirsch_stoer", 16));
  all.push_back(composition_method<P, T>("sv-yoshida6-s7", analysis::symmetric_composition<T>::yoshida6(), 5000));
  all.push_back(composition_method<P, T>("sv-kahan-li8-s17", analysis::symmetric_composition<T>::kahan_li8(), 2000));
  all.push_back(composition_method<P, T>("sv-sofroniou-spaletta10-s35",
                                         analysis::symmetric_composition<T>::sofroniou_spaletta10(), 1000));
  all.push_back(taylor_method<P, T>("taylor-series"));
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
  all.push_back(odeint_rkn<P, odeint::symplectic_rkn_sb3a_m4_mclachlan<arr<T, P::n>, arr<T, P::n>, T>, T>(
      "odeint-symplectic_rkn_sb3a_m4_mclachlan", 10000));
  all.push_back(odeint_rkf78<P, T>("odeint-runge_kutta_fehlberg78", 48));
  all.push_back(odeint_bulirsch_stoer<P, T>("odeint-bulirsch_stoer", 48));
  all.push_back(composition_method<P, T>("sv-yoshida6-s7", analysis::symmetric_composition<T>::yoshida6(), 4000));
  all.push_back(composition_method<P, T>("sv-kahan-li8-s17", analysis::symmetric_composition<T>::kahan_li8(), 1000));
  all.push_back(composition_method<P, T>("sv-sofroniou-spaletta10-s35",
                                         analysis::symmetric_composition<T>::sofroniou_spaletta10(), 400));
  all.push_back(taylor_method<P, T>("taylor-series"));
  return all;
}

}  // namespace

template <class P, int Digits>
int run_regime(const settings& o) {
#if GEOMINT_WP_STUB
  (void)o;
  std::cerr << "geomint-workprecision: --digits " << Digits
            << " is not compiled into this build (configured with GEOMINT_RUN_MULTIPRECISION=OFF)\n";
  return 2;
#else
  if constexpr (Digits == 16) {
    return run_sweeps<P, double, boost::multiprecision::cpp_bin_float_50>(o, regime_16(), methods_16<P, double>(o.compensated));
  } else {
    using mp = boost::multiprecision::cpp_bin_float_50;
    return run_sweeps<P, mp, boost::multiprecision::cpp_bin_float_100>(o, regime_50(), methods_50<P, mp>(o.compensated));
  }
#endif
}

template int run_regime<pendulum_problem, GEOMINT_WP_DIGITS>(const settings&);
template int run_regime<kepler_problem, GEOMINT_WP_DIGITS>(const settings&);

}  // namespace geomint::workprecision
