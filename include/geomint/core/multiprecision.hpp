#pragma once
/// Boost.Multiprecision scalars in Eigen: Boost's own NumTraits (<boost/multiprecision/eigen.hpp>),
/// plus one gap filled for Boost 1.74 with Eigen 3.4.
///
/// Boost 1.74's NumTraits has no infinity()/quiet_NaN(), which Eigen 3.4's generic
/// positive_real_hypot names (it is used by the Givens rotations of the eigen-solvers and the
/// stable norms). Where those members are missing, hypot_impl for Boost numbers is routed to
/// Boost's own hypot; where a newer Boost provides them, this specialisation drops out.
///
/// Include this header (or geomint/geomint.hpp, or any Boost.Multiprecision header before
/// geomint's own headers) to use Boost.Multiprecision scalars with geomint.
#include <type_traits>

#include <Eigen/Core>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/number.hpp>

#include "geomint/core/scalar_traits.hpp"

namespace geomint {
/// Eigen has the traits of every Boost.Multiprecision number from here on (core/scalar_traits.hpp).
template <class Backend, boost::multiprecision::expression_template_option ET>
struct eigen_scalar_ready<boost::multiprecision::number<Backend, ET>> : std::true_type {};

/// cpp_bin_float with stack storage (Allocator void), int exponents and more than 128 bits: its
/// mantissa is an array of 64-bit limbs, read by core/mantissa.hpp and linalg/dot.hpp
/// (core/scalar_traits.hpp).
template <unsigned Digits, boost::multiprecision::backends::digit_base_type Base, int MinE, int MaxE,
          boost::multiprecision::expression_template_option ET>
  requires(boost::multiprecision::backends::cpp_bin_float<Digits, Base, void, int, MinE, MaxE>::bit_count > 128 &&
           sizeof(boost::multiprecision::limb_type) == 8)
struct exact_mantissa_arithmetic<
    boost::multiprecision::number<boost::multiprecision::backends::cpp_bin_float<Digits, Base, void, int, MinE, MaxE>, ET>>
    : std::true_type {
  using backend = boost::multiprecision::backends::cpp_bin_float<Digits, Base, void, int, MinE, MaxE>;
  static constexpr unsigned bits = backend::bit_count;
  static constexpr unsigned limbs = (bits + 63) / 64;
};
}  // namespace geomint

namespace geomint::core::detail {
template <class Traits>
concept eigen_traits_have_infinity = requires { Traits::infinity(); Traits::quiet_NaN(); };
}  // namespace geomint::core::detail

namespace Eigen::internal {
template <class Backend, boost::multiprecision::expression_template_option ET>
  requires(!geomint::core::detail::eigen_traits_have_infinity<NumTraits<boost::multiprecision::number<Backend, ET>>>)
struct hypot_impl<boost::multiprecision::number<Backend, ET>> {
  using Scalar = boost::multiprecision::number<Backend, ET>;
  using RealScalar = typename NumTraits<Scalar>::Real;
  static RealScalar run(const Scalar& x, const Scalar& y) { return RealScalar(hypot(x, y)); }
};
}  // namespace Eigen::internal

#include "geomint/core/decimal.hpp"  // from_decimal, for the users of this header
