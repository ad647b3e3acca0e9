#pragma once
/// The scalar types every runtime test is instantiated for: with MPFR and libqd (Debian
/// libmpfr-dev, libqd-dev) also mpfr_float_100, dd_real and qd_real.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <geomint/core/multiprecision.hpp>
#include <cmath>
#include <limits>
#include <tuple>
#ifdef GEOMINT_HAVE_MPFR
#include <boost/multiprecision/mpfr.hpp>
#endif
#ifdef GEOMINT_HAVE_QD
#include <geomint/core/qd.hpp>
#endif

namespace geomint::test {
using boost::multiprecision::cpp_bin_float_50;
using boost::multiprecision::cpp_bin_float_100;
#ifdef GEOMINT_HAVE_MPFR
using boost::multiprecision::mpfr_float_100;
#endif
#if defined(GEOMINT_REDUCED_SCALAR_TYPES)
/// The clang build (with the sanitizers): one built-in and one multiprecision type keep its
/// build short. The gcc preset runs all types.
using scalar_types = std::tuple<double, cpp_bin_float_50>;
#elif defined(GEOMINT_HAVE_MPFR) && defined(GEOMINT_HAVE_QD)
using scalar_types = std::tuple<double, long double, cpp_bin_float_50, cpp_bin_float_100, mpfr_float_100, dd_real, qd_real>;
#elif defined(GEOMINT_HAVE_MPFR)
using scalar_types = std::tuple<double, long double, cpp_bin_float_50, cpp_bin_float_100, mpfr_float_100>;
#elif defined(GEOMINT_HAVE_QD)
using scalar_types = std::tuple<double, long double, cpp_bin_float_50, cpp_bin_float_100, dd_real, qd_real>;
#else
using scalar_types = std::tuple<double, long double, cpp_bin_float_50, cpp_bin_float_100>;
#endif
/// The types that the integrator tests use (the slow ones are left to the core suites).
using integrator_scalar_types = std::tuple<double, cpp_bin_float_50>;

/// A tolerance of `ulps` units of the scalar's epsilon; never passes through a double literal.
template <class T>
T eps_tol(int ulps) { return T(ulps) * std::numeric_limits<T>::epsilon(); }

/// |a - b| in T (std::abs for built-in types, Boost's abs found by ADL otherwise).
template <class T>
T abs_diff(const T& a, const T& b) {
  using std::abs;
  return T(abs(T(a - b)));
}
}  // namespace geomint::test
