#pragma once
/// Products, sums, dot products and conversions of Boost cpp_bin_float numbers formed on their
/// integer mantissas.
///
/// Boost's arithmetic on cpp_bin_float goes through a double-width cpp_int temporary, a generic
/// normalising shift and a generic rounding, and every copy of a number moves its limbs by
/// memmove. Here the exact product or sum of the mantissas (a sum's smaller operand aligned in
/// a frame with 64 guard bits and a sticky bit) is rounded once, to nearest with ties to even
/// (IEEE 754's rule), straight into the destination: `multiply_into`, `add_into`,
/// `subtract_into` (and the value-returning `fast_product`, `fast_sum`, `fast_difference`),
/// `to_double`, and `exact_dot_into` (a dot product accumulated in one fixed-point integer, for
/// linalg::dot, which states its bound). All but the dot product are correctly rounded
/// (tests/core/test_mantissa.cpp: against the exact results in 1200 bits), so the same as
/// Boost's operators except where those are not (docs/results/performance.md).
/// For every other type, and for zeros, infinities, NaN and results beyond the exponent range,
/// they are Boost's operators. Used in the implicit stages' inner loops and the elementary
/// functions.

#include <bit>
#include <cstddef>
#include <type_traits>

#include "geomint/core/scalar_traits.hpp"  // exact_mantissa_arithmetic

namespace geomint {

namespace core::detail {
/// Rounds the W-limb integer `sum` (nonzero, leading one at bit msb; `sticky`: nonzero bits
/// below it were cut, which the callers have only where msb leaves bits below the mantissa) to
/// p = Traits::bits bits, to nearest with ties to even, into `mantissa` (L limbs, leading one at
/// bit p - 1). Returns how far the binary point moved: the rounded value is mantissa
/// 2^(returned), so msb + 1 - p, plus one where rounding up carried out.
template <class Traits, unsigned W>
int round_to_mantissa(const unsigned long long (&sum)[W], int msb, bool sticky,
                      unsigned long long (&mantissa)[Traits::limbs]) {
  using limb = unsigned long long;
  constexpr unsigned L = Traits::limbs;
  constexpr int bits = static_cast<int>(Traits::bits);
  const int drop = msb + 1 - bits;  // below zero after cancellation: shifted left, exact
  auto limb_at = [&](long long w) -> limb { return (w >= 0 && w < static_cast<long long>(W)) ? sum[w] : 0; };
  if (drop < 0) {
    for (unsigned i = 0; i < L; ++i) {
      const long long from = static_cast<long long>(drop) + 64LL * i;
      const long long word = from >= 0 ? from / 64 : -((-from + 63) / 64);  // floor(from / 64)
      const int offset = static_cast<int>(from - 64 * word);
      limb v = limb_at(word) >> offset;
      if (offset != 0) v |= limb_at(word + 1) << (64 - offset);
      mantissa[i] = v;
    }
    return drop;
  }
  const auto word = static_cast<unsigned>(drop / 64), offset = static_cast<unsigned>(drop % 64);
  for (unsigned i = 0; i < L; ++i) {
    limb v = limb_at(word + i) >> offset;
    if (offset != 0) v |= limb_at(word + i + 1) << (64 - offset);
    mantissa[i] = v;
  }
  if (drop == 0) return drop;
  const int half = drop - 1;
  if (((sum[half / 64] >> (half % 64)) & 1) == 0) return drop;
  bool above = sticky || (sum[half / 64] & ((limb(1) << (half % 64)) - 1)) != 0;
  for (int i = 0; i < half / 64 && !above; ++i) above = sum[i] != 0;
  if (!above && (mantissa[0] & 1) == 0) return drop;  // a tie, already even
  limb carry = 1;
  for (unsigned i = 0; i < L && carry != 0; ++i) {
    mantissa[i] += carry;
    carry = mantissa[i] == 0 ? 1 : 0;
  }
  // Rounding up 2^p - 1 gives 2^p: the mantissa 2^(p-1), one exponent up.
  constexpr unsigned carry_word = bits / 64, carry_bit = bits % 64;
  bool overflow = false;
  if constexpr (carry_word < L) overflow = ((mantissa[carry_word] >> carry_bit) & 1) != 0;
  else overflow = carry != 0;
  if (!overflow) return drop;
  for (unsigned i = 0; i < L; ++i) mantissa[i] = 0;
  mantissa[(bits - 1) / 64] = limb(1) << ((bits - 1) % 64);
  return drop + 1;
}

/// Writes sign, exponent and mantissa into out's backend (no temporary: a copy of a
/// cpp_bin_float moves its limbs by memmove).
template <class T>
void store(T& out, bool negative, long long exponent,
           const unsigned long long (&mantissa)[exact_mantissa_arithmetic<T>::limbs]) {
  constexpr unsigned L = exact_mantissa_arithmetic<T>::limbs;
  auto& result = out.backend();
  result.bits().resize(L, L);
  for (unsigned i = 0; i < L; ++i) result.bits().limbs()[i] = mantissa[i];
  result.exponent() = static_cast<int>(exponent);
  result.sign() = negative;
}

/// The exact 2L-limb product of two L-limb mantissas (schoolbook).
template <unsigned L>
void multiply_mantissas(const unsigned long long* x, const unsigned long long* y,
                        unsigned long long (&product)[2 * L]) {
  __extension__ using wide = unsigned __int128;  // (a GCC and Clang extension)
  for (unsigned i = 0; i < 2 * L; ++i) product[i] = 0;
  for (unsigned i = 0; i < L; ++i) {
    unsigned long long carry = 0;
    for (unsigned j = 0; j < L; ++j) {
      const wide t = static_cast<wide>(x[i]) * y[j] + product[i + j] + carry;
      product[i + j] = static_cast<unsigned long long>(t);
      carry = static_cast<unsigned long long>(t >> 64);
    }
    product[i + L] = carry;
  }
}

/// out = a b rounded to nearest, ties to even, from the exact product of the mantissas (out may
/// alias a or b); false (out untouched) for a zero, infinite or NaN factor or a result outside
/// the exponent range, which the caller leaves to Boost.
template <class T>
bool exact_product(const T& a, const T& b, T& out) {
  using traits = exact_mantissa_arithmetic<T>;
  using backend = typename traits::backend;
  using limb = unsigned long long;
  constexpr unsigned L = traits::limbs;
  constexpr int bits = static_cast<int>(traits::bits);
  static_assert(sizeof(*a.backend().bits().limbs()) == sizeof(limb), "geomint::exact_product: 64-bit limbs expected");
  const backend& x = a.backend();
  const backend& y = b.backend();
  if (x.exponent() > backend::max_exponent || y.exponent() > backend::max_exponent ||
      x.exponent() == backend::exponent_zero || y.exponent() == backend::exponent_zero)
    return false;
  limb product[2 * L];
  multiply_mantissas<L>(x.bits().limbs(), y.bits().limbs(), product);
  // Both mantissas lie in [2^(p-1), 2^p): the product's leading one is at bit 2p - 1 or 2p - 2,
  // and its value is product 2^(e_x + e_y - 2 (p - 1)).
  constexpr int top = 2 * bits - 1;
  const int msb = ((product[top / 64] >> (top % 64)) & 1) != 0 ? top : top - 1;
  limb mantissa[L];
  const int moved = round_to_mantissa<traits>(product, msb, false, mantissa);
  const long long exponent = static_cast<long long>(x.exponent()) + y.exponent() + moved - (bits - 1);
  if (exponent > backend::max_exponent || exponent < backend::min_exponent) return false;
  store(out, x.sign() != y.sign(), exponent, mantissa);
  return true;
}

/// out = a + b (or a - b with `subtract`) rounded to nearest, ties to even: the smaller
/// operand aligned to the larger in a frame of L + 2 limbs (a carry limb above, 64 guard bits
/// below, and a sticky bit for what falls below them), added or subtracted exactly, rounded
/// once. False (out untouched) for a zero, infinite or NaN operand, an exactly zero result, or
/// one outside the exponent range, which the caller leaves to Boost. out may alias a or b.
template <class T>
bool exact_sum(const T& a, const T& b, bool subtract, T& out) {
  using traits = exact_mantissa_arithmetic<T>;
  using backend = typename traits::backend;
  using limb = unsigned long long;
  __extension__ using wide = unsigned __int128;
  constexpr unsigned L = traits::limbs;
  constexpr unsigned W = L + 2;
  const backend& x = a.backend();
  const backend& y = b.backend();
  if (x.exponent() > backend::max_exponent || y.exponent() > backend::max_exponent ||
      x.exponent() == backend::exponent_zero || y.exponent() == backend::exponent_zero)
    return false;
  const bool x_negative = x.sign(), y_negative = y.sign() != subtract;
  // The larger magnitude first.
  bool x_larger = x.exponent() != y.exponent() ? x.exponent() > y.exponent() : true;
  if (x.exponent() == y.exponent()) {
    for (unsigned i = L; i-- > 0;) {
      if (x.bits().limbs()[i] != y.bits().limbs()[i]) {
        x_larger = x.bits().limbs()[i] > y.bits().limbs()[i];
        break;
      }
    }
  }
  const backend& big = x_larger ? x : y;
  const backend& small = x_larger ? y : x;
  const bool negative = x_larger ? x_negative : y_negative;
  const bool opposite = x_negative != y_negative;
  const long long gap = static_cast<long long>(big.exponent()) - small.exponent();
  limb frame[W] = {}, aligned[W] = {};
  for (unsigned i = 0; i < L; ++i) frame[i + 1] = big.bits().limbs()[i];
  // small << 64 >> gap, and whether anything nonzero fell off the end.
  bool sticky = false;
  const limb* ms = small.bits().limbs();
  if (gap >= 64LL * (L + 1)) {
    sticky = true;  // (a nonzero mantissa, entirely below the frame)
  } else {
    const auto word = static_cast<unsigned>(gap / 64), shift = static_cast<unsigned>(gap % 64);
    // shifted[k] = bits 64 (k + word) + shift ... of (ms << 64): source limb k + word - 1 of ms.
    auto source = [&](long long k) -> limb { return (k >= 0 && k < static_cast<long long>(L)) ? ms[k] : 0; };
    for (unsigned k = 0; k < W; ++k) {
      const long long from = static_cast<long long>(k) + word - 1;
      limb v = source(from) >> shift;
      if (shift != 0) v |= source(from + 1) << (64 - shift);
      aligned[k] = v;
    }
    // Bits below the frame: source limbs below word - 1, and the low `shift` bits of limb word - 1.
    for (long long k = 0; k + 1 < static_cast<long long>(word) && !sticky; ++k) sticky = source(k) != 0;
    if (!sticky && shift != 0) sticky = (source(static_cast<long long>(word) - 1) & ((limb(1) << shift) - 1)) != 0;
  }
  limb sum[W];
  if (!opposite) {
    limb carry = 0;
    for (unsigned i = 0; i < W; ++i) {
      const wide t = static_cast<wide>(frame[i]) + aligned[i] + carry;
      sum[i] = static_cast<limb>(t);
      carry = static_cast<limb>(t >> 64);
    }
  } else {
    // big - (aligned + a fraction in (0, 1) if sticky) = (big - aligned - 1) + (1 - fraction):
    // subtract one more unit and keep the sticky bit for the fraction.
    limb borrow = sticky ? 1 : 0;
    for (unsigned i = 0; i < W; ++i) {
      const wide t = static_cast<wide>(frame[i]) - aligned[i] - borrow;
      sum[i] = static_cast<limb>(t);
      borrow = static_cast<limb>(t >> 64) != 0 ? 1 : 0;
    }
  }
  int msb = -1;
  for (unsigned i = W; i-- > 0;)
    if (sum[i] != 0) {
      msb = static_cast<int>(64 * i) + 63 - __builtin_clzll(sum[i]);
      break;
    }
  if (msb < 0) return false;  // exact cancellation: Boost's signed zero
  limb mantissa[L];
  const int moved = round_to_mantissa<traits>(sum, msb, sticky, mantissa);
  // The frame's unit is 2^(e_big - (bits - 1) - 64) and the value mantissa 2^moved units: the
  // result's exponent (of its leading bit, p - 1 places above the mantissa's unit) is then
  // e_big - 64 + moved.
  const long long exponent = static_cast<long long>(big.exponent()) - 64 + moved;
  if (exponent > backend::max_exponent || exponent < backend::min_exponent) return false;
  store(out, negative, exponent, mantissa);
  return true;
}
}  // namespace core::detail

/// out = sum_k a[k] b[k stride], k < count, for exact_mantissa_arithmetic types: the products
/// formed exactly on the mantissas, added in one fixed-point accumulator aligned to the largest
/// (2L + 1 limbs; the products' bits below it are cut) and rounded once, to nearest with ties
/// to even (linalg/dot.hpp states the accuracy). False (out untouched) for other types, a term
/// that is not finite, or exponents near the ends of the type's range: the caller's loop then.
template <class T>
bool exact_dot_into(T& out, const T* a, const T* b, std::size_t count, std::size_t stride) {
  if constexpr (!exact_mantissa_arithmetic_v<T>) {
    return false;
  } else {
    using traits = exact_mantissa_arithmetic<T>;
    using backend = typename traits::backend;
    using limb = unsigned long long;
    __extension__ using wide = unsigned __int128;  // (a GCC and Clang extension)
    constexpr unsigned L = traits::limbs;
    constexpr unsigned W = 2 * L + 1;  // the products' 2L limbs and a limb for the carries
    static_assert(sizeof(*a[0].backend().bits().limbs()) == sizeof(limb), "geomint::exact_dot_into: 64-bit limbs expected");
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
      out = T(0);
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
      limb product[2 * L];
      core::detail::multiply_mantissas<L>(x.bits().limbs(), y.bits().limbs(), product);
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
    int msb = -1;
    for (unsigned i = W; i-- > 0;)
      if (sum[i] != 0) {
        msb = static_cast<int>(64 * i) + 63 - __builtin_clzll(sum[i]);
        break;
      }
    if (msb < 0) {
      out = T(0);
      return true;
    }
    limb mantissa[L];
    const long long final_exponent = exponent + core::detail::round_to_mantissa<traits>(sum, msb, false, mantissa);
    if (final_exponent > backend::max_exponent || final_exponent < backend::min_exponent) return false;
    core::detail::store(out, negative_result, final_exponent, mantissa);
    return true;
  }
}

/// x rounded to the nearest double, ties to even, as static_cast<double>(x) rounds: for
/// exact_mantissa_arithmetic types from the mantissa's top bits where the result is a normal
/// double (Boost's conversion shifts the whole mantissa and rounds generically); for a sum of
/// doubles (core/scalar_traits.hpp), its leading term; else the cast.
template <class T>
double to_double(const T& x) {
  if constexpr (double_expansion<T>::value) {
    return double_expansion<T>::term(x, 0);
  } else if constexpr (exact_mantissa_arithmetic_v<T>) {
    using traits = exact_mantissa_arithmetic<T>;
    using backend = typename traits::backend;
    using limb = unsigned long long;
    constexpr int bits = static_cast<int>(traits::bits);
    const backend& b = x.backend();
    const int e = b.exponent();
    if (b.exponent() != backend::exponent_zero && e >= -1022 && e <= 1022) {
      const limb* m = b.bits().limbs();
      // The top 64 bits (bits - 64 .. bits - 1): 53 kept, the next one the half, the rest and
      // everything below them the sticky part.
      constexpr int from = bits - 64;
      constexpr unsigned word = from / 64, offset = from % 64;
      limb top = m[word] >> offset;
      if constexpr (offset != 0) top |= m[word + 1] << (64 - offset);
      limb kept = top >> 11;
      if ((top >> 10) & 1) {
        bool above = (top & 0x3FF) != 0;
        if constexpr (offset != 0) above = above || (m[word] & ((limb(1) << offset) - 1)) != 0;
        for (unsigned i = 0; i < word && !above; ++i) above = m[i] != 0;
        if (above || (kept & 1) != 0) ++kept;
      }
      // kept in [2^52, 2^53]: 2^53 is 2^52 one exponent up (e <= 1022 keeps that finite).
      const int exponent = kept >> 53 ? e + 1 : e;
      if (kept >> 53) kept >>= 1;
      const limb pattern = (static_cast<limb>(b.sign()) << 63) | (static_cast<limb>(exponent + 1023) << 52) |
                           (kept & ((limb(1) << 52) - 1));
      return std::bit_cast<double>(pattern);
    }
    return static_cast<double>(x);
  } else {
    return static_cast<double>(x);
  }
}

/// out = a b, rounded once as a * b rounds (out may alias a or b): for
/// exact_mantissa_arithmetic types on the mantissas (see the top of the file), else a * b.
template <class T>
void multiply_into(T& out, const T& a, const T& b) {
  if constexpr (exact_mantissa_arithmetic_v<T>) {
    if (core::detail::exact_product(a, b, out)) return;
  }
  out = a * b;
}

/// out = a + b, rounded once as a + b rounds (out may alias a or b): for
/// exact_mantissa_arithmetic types on the mantissas, else a + b.
template <class T>
void add_into(T& out, const T& a, const T& b) {
  if constexpr (exact_mantissa_arithmetic_v<T>) {
    if (core::detail::exact_sum(a, b, false, out)) return;
  }
  out = a + b;
}

/// out = a - b (add_into).
template <class T>
void subtract_into(T& out, const T& a, const T& b) {
  if constexpr (exact_mantissa_arithmetic_v<T>) {
    if (core::detail::exact_sum(a, b, true, out)) return;
  }
  out = a - b;
}

/// a + b, a - b and a b, the values of the operators (add_into, multiply_into).
template <class T>
T fast_sum(const T& a, const T& b) {
  T out;
  add_into(out, a, b);
  return out;
}
template <class T>
T fast_difference(const T& a, const T& b) {
  T out;
  subtract_into(out, a, b);
  return out;
}

template <class T>
T fast_product(const T& a, const T& b) {
  T out;
  multiply_into(out, a, b);
  return out;
}

}  // namespace geomint

// The cpp_bin_float specialisation of exact_mantissa_arithmetic, when Boost.Multiprecision is
// already in use (as linalg/types.hpp does for the Eigen traits).
#if defined(BOOST_MATH_EXTENDED_REAL_HPP) || defined(BOOST_MP_NUMBER_HPP)
#include "geomint/core/multiprecision.hpp"
#endif
