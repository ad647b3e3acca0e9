#pragma once
/// Dot products sum_k a_k b_k, the inner loop of the implicit stages' combinations.
///
/// For Boost's cpp_bin_float (fixed precision, stack storage: exact_mantissa_arithmetic) the
/// products are formed exactly on the integer mantissas, added in one fixed-point accumulator
/// aligned to the largest, and the sum is rounded once, to nearest with ties to even
/// (exact_dot_into, core/mantissa.hpp): a fraction of the time of the multiply-add loop, whose
/// every product and sum rounds and renormalises a temporary. The result is within half an ulp
/// of the exact dot product plus count 2^(2-2p) of its largest product (p = the type's bits;
/// the products' bits below the accumulator are cut), so at least as accurate as the loop's.
/// Other types, and non-finite data or exponents near the ends of the type's range: the loop,
/// in order.

#include <cstddef>
#include <type_traits>

#include "geomint/core/mantissa.hpp"

namespace geomint::linalg {

namespace detail {
/// sum_k a[k] b[k stride], in order.
template <class T>
T dot_in_order(const T* a, const T* b, std::size_t count, std::size_t stride) {
  T sum(0);
  for (std::size_t k = 0; k < count; ++k) sum += a[k] * b[k * stride];
  return sum;
}
}  // namespace detail

/// sum_k a[k] b[k stride], k < count: exactly accumulated and rounded once for Boost's
/// cpp_bin_float (see the top of the file), in order otherwise.
template <class T>
T dot(const T* a, const T* b, std::size_t count, std::size_t stride = 1) {
  T result;  // (one named result on every path: returned without a copy)
  if constexpr (exact_mantissa_arithmetic_v<T>) {
    if (exact_dot_into(result, a, b, count, stride)) return result;
  }
  result = detail::dot_in_order(a, b, count, stride);
  return result;
}

}  // namespace geomint::linalg
