#pragma once
/// Dot products sum_k a_k b_k, the inner loop of the implicit stages' combinations.
///
/// For Boost's cpp_bin_float (fixed precision, stack storage; exact_mantissa_arithmetic) the products are formed exactly
/// on the integer mantissas, added in one fixed-point accumulator aligned to the largest, and
/// the sum is rounded once, to nearest with ties to even: a fraction of the time of the
/// multiply-add loop, whose every product and sum rounds and renormalises a temporary. The
/// result is within half an ulp of the exact dot product plus count 2^(2-2p) of its largest
/// product (p = the type's bits; the products' bits below the accumulator are cut), so at
/// least as accurate as the loop's. Other types, and non-finite data or exponents near the
/// ends of the type's range: the loop, in order.

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

/// The exact dot product of cpp_bin_float numbers (see the top of the file); false (result
/// untouched) if a term is not finite or the exponents leave the type's range.
template <class T>
bool exact_dot(const T* a, const T* b, std::size_t count, std::size_t stride, T& result) {
  using traits = exact_mantissa_arithmetic<T>;
  using backend = typename traits::backend;
  using limb = unsigned long long;
  __extension__ using wide = unsigned __int128;  // (a GCC and Clang extension)
  constexpr unsigned L = traits::limbs;
  constexpr unsigned W = 2 * L + 1;  // the products' 2L limbs and a limb for the carries
  static_assert(sizeof(*a[0].backend().bits().limbs()) == sizeof(limb), "geomint::linalg::exact_dot: 64-bit limbs expected");
  // The exponent of each product (the sum of the factors' exponents), and the largest.
  long long top = 0;
  bool any = false;
  for (std::size_t k = 0; k < count; ++k) {
    const backend& x = a[k].backend();
    const backend& y = b[k * stride].backend();
    if (x.exponent() == backend::exponent_zero || y.exponent() == backend::exponent_zero) continue;
    if (x.exponent() > backend::max_exponent || y.exponent() > backend::max_exponent) return false;  // inf, NaN
    const long long e = static_cast<long long>(x.exponent()) + y.exponent();
    if (!any || e > top) top = e;
    any = true;
  }
  if (!any) {
    result = T(0);
    return true;
  }
  // The result's exponent before rounding, which the rounding moves by at most the
  // accumulator's 64 W bits: kept far inside int (and far outside any exponent a step meets).
  const long long exponent = top - static_cast<long long>(traits::bits) + 1;
  if (exponent > static_cast<long long>(backend::max_exponent) - 64LL * W ||
      exponent < static_cast<long long>(backend::min_exponent) + 64LL * W)
    return false;
  // Positive and negative parts, each sum_k m_x m_y 2^-(top - e_k) in units of 2^(top - 2 bits + 2).
  limb positive[W] = {}, negative[W] = {};
  for (std::size_t k = 0; k < count; ++k) {
    const backend& x = a[k].backend();
    const backend& y = b[k * stride].backend();
    if (x.exponent() == backend::exponent_zero || y.exponent() == backend::exponent_zero) continue;
    const long long shift = top - (static_cast<long long>(x.exponent()) + y.exponent());
    if (shift >= 64LL * 2 * L) continue;  // below the accumulator's last bit
    const limb* mx = x.bits().limbs();
    const limb* my = y.bits().limbs();
    limb product[2 * L] = {};
    for (unsigned i = 0; i < L; ++i) {
      limb carry = 0;
      for (unsigned j = 0; j < L; ++j) {
        const wide t = static_cast<wide>(mx[i]) * my[j] + product[i + j] + carry;
        product[i + j] = static_cast<limb>(t);
        carry = static_cast<limb>(t >> 64);
      }
      product[i + L] = carry;
    }
    // product >> shift, added to its part.
    const auto limb_shift = static_cast<unsigned>(shift / 64);
    const auto bit_shift = static_cast<unsigned>(shift % 64);
    limb* part = (x.sign() != y.sign()) ? negative : positive;
    limb carry = 0;
    for (unsigned i = 0; i + limb_shift < 2 * L; ++i) {
      limb v = product[i + limb_shift] >> bit_shift;
      if (bit_shift != 0 && i + limb_shift + 1 < 2 * L) v |= product[i + limb_shift + 1] << (64 - bit_shift);
      const wide t = static_cast<wide>(part[i]) + v + carry;
      part[i] = static_cast<limb>(t);
      carry = static_cast<limb>(t >> 64);
    }
    for (unsigned i = 2 * L - limb_shift; i < W && carry != 0; ++i) {
      const wide t = static_cast<wide>(part[i]) + carry;
      part[i] = static_cast<limb>(t);
      carry = static_cast<limb>(t >> 64);
    }
  }
  // |positive - negative| and its sign.
  bool negative_result = false;
  for (unsigned i = W; i-- > 0;) {
    if (positive[i] != negative[i]) {
      negative_result = negative[i] > positive[i];
      break;
    }
  }
  const limb* big = negative_result ? negative : positive;
  const limb* small = negative_result ? positive : negative;
  limb sum[W];
  limb borrow = 0;
  for (unsigned i = 0; i < W; ++i) {
    const wide t = static_cast<wide>(big[i]) - small[i] - borrow;
    sum[i] = static_cast<limb>(t);
    borrow = static_cast<limb>(t >> 64) != 0 ? 1 : 0;
  }
  // Round to `bits` bits, to nearest with ties to even: the mantissa is sum >> drop (or, after
  // cancellation, sum << -drop, exact), the exponent moves by drop.
  int msb = -1;
  for (unsigned i = W; i-- > 0;)
    if (sum[i] != 0) {
      msb = static_cast<int>(64 * i) + 63 - __builtin_clzll(sum[i]);
      break;
    }
  if (msb < 0) {
    result = T(0);
    return true;
  }
  const int drop = msb + 1 - static_cast<int>(traits::bits);
  auto bit = [&](int i) { return i >= 0 && ((sum[i / 64] >> (i % 64)) & 1) != 0; };
  bool round_up = false;
  if (drop > 0) {
    const bool half = bit(drop - 1);
    bool sticky = false;
    for (int i = 0; i < (drop - 1) / 64 && !sticky; ++i) sticky = sum[i] != 0;
    if (!sticky && (drop - 1) % 64 != 0) sticky = (sum[(drop - 1) / 64] & ((limb(1) << ((drop - 1) % 64)) - 1)) != 0;
    round_up = half && (sticky || bit(drop));
  }
  // The mantissa's L limbs: bits drop .. drop + bits - 1 of sum (negative drop: shifted in zeros).
  limb mantissa[L + 1] = {};
  for (unsigned i = 0; i < L; ++i) {
    const long long from = static_cast<long long>(drop) + 64LL * i;  // bit of sum at mantissa bit 64 i
    const long long word = from >= 0 ? from / 64 : -((-from + 63) / 64);  // floor(from / 64)
    const int offset = static_cast<int>(from - 64 * word);
    auto limb_at = [&](long long w) -> limb { return (w >= 0 && w < static_cast<long long>(W)) ? sum[w] : 0; };
    limb v = limb_at(word) >> offset;
    if (offset != 0) v |= limb_at(word + 1) << (64 - offset);
    mantissa[i] = v;
  }
  long long final_exponent = exponent + drop;
  if (round_up) {
    limb carry = 1;
    for (unsigned i = 0; i < L && carry != 0; ++i) {
      mantissa[i] += carry;
      carry = mantissa[i] == 0 ? 1 : 0;
    }
    // A carry into bit `bits`: the mantissa is 2^bits, i.e. 2^(bits-1) one exponent up.
    const unsigned top_limb = (traits::bits - 1) / 64, top_bit = (traits::bits - 1) % 64;
    const bool overflow = top_bit == 63 ? carry != 0 : ((mantissa[top_limb] >> (top_bit + 1)) & 1) != 0;
    if (overflow) {
      for (unsigned i = 0; i < L; ++i) mantissa[i] = 0;
      mantissa[top_limb] = limb(1) << top_bit;
      ++final_exponent;
    }
  }
  if (final_exponent > backend::max_exponent || final_exponent < backend::min_exponent) return false;
  backend& out = result.backend();  // (written in place: a copy of T moves its limbs by memmove)
  out.bits().resize(L, L);
  for (unsigned i = 0; i < L; ++i) out.bits().limbs()[i] = mantissa[i];
  out.bits().normalize();
  out.exponent() = static_cast<int>(final_exponent);
  out.sign() = negative_result;
  return true;
}
}  // namespace detail

/// sum_k a[k] b[k stride], k < count: exactly accumulated and rounded once for Boost's
/// cpp_bin_float (see the top of the file), in order otherwise.
template <class T>
T dot(const T* a, const T* b, std::size_t count, std::size_t stride = 1) {
  T result;  // (one named result on every path: returned without a copy)
  if constexpr (exact_mantissa_arithmetic_v<T>) {
    if (detail::exact_dot(a, b, count, stride, result)) return result;
  }
  result = detail::dot_in_order(a, b, count, stride);
  return result;
}

}  // namespace geomint::linalg
