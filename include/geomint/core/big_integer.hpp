#pragma once
/// Exact signed integers of fixed capacity for constant expressions.
///
/// `geomint::big_integer<L>` holds sign and magnitude in L little-endian 32-bit limbs (32 L
/// bits), with 64-bit intermediates, so it works in constant expressions (C arrays, no
/// allocation) and at run time alike. It is a structural type, always normalised (limbs at and
/// above `size` are zero, zero is never negative), so member-wise equality is value equality.
/// Every operation whose result does not fit throws std::overflow_error: a compile error in a
/// constant expression, an exception at run time, never a wrong value. Division truncates
/// towards zero like the built-in integers (Knuth, TAOCP vol. 2, section 4.3.1, algorithm D).
///
///   constexpr geomint::big_integer<4> a = geomint::big_integer<4>(1) * (std::int64_t(1) << 62) * 8;
///   static_assert(a % 7 == 1 && gcd(a, geomint::big_integer<4>(12)) == 4);

#include <bit>
#include <compare>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>

namespace geomint {

template <int L>
struct big_integer {
  static_assert(L >= 2, "geomint::big_integer needs at least two limbs");
  std::uint32_t limb[L];  ///< magnitude (C arrays: far cheaper than std::array in constant evaluation)
  int size;               ///< limbs in use; limb[size - 1] != 0 unless the value is 0
  bool negative;          ///< never true for zero

  /// Zero. The members have no default member initialisers: every constructor sets all of them
  /// in its initialiser list. (With `limb[L]{}` as a default member initialiser, GCC 12 lost the
  /// initialiser list's limbs of big_integer(std::int64_t) inside larger constant-initialised
  /// objects, leaving denominators of big_rational equal to a non-normalised zero.)
  constexpr big_integer() : limb{}, size(0), negative(false) {}
  /// Any 64-bit integer; implicit, so that mixed arithmetic reads naturally. Every member is set
  /// in the initialiser list (no assignment in the body, which Clang 14 rejects in constant
  /// evaluation of array elements).
  constexpr big_integer(std::int64_t v)  // NOLINT(google-explicit-constructor)
      : limb{low_limb(v), high_limb(v)}, size(high_limb(v) != 0 ? 2 : (low_limb(v) != 0 ? 1 : 0)), negative(v < 0) {}
  static constexpr std::uint64_t magnitude_of(std::int64_t v) {
    return v < 0 ? std::uint64_t(0) - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  }
  static constexpr std::uint32_t low_limb(std::int64_t v) { return static_cast<std::uint32_t>(magnitude_of(v)); }
  static constexpr std::uint32_t high_limb(std::int64_t v) { return static_cast<std::uint32_t>(magnitude_of(v) >> 32); }

  constexpr bool is_zero() const { return size == 0; }
  constexpr int sign() const { return size == 0 ? 0 : (negative ? -1 : 1); }

  /// True when the value is an int64 (INT64_MIN excluded, like geomint::rational).
  constexpr bool fits_int64() const {
    if (size > 2) return false;
    const std::uint64_t mag = magnitude64();
    return mag <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  }
  /// Checked narrowing to int64; throws std::overflow_error when it does not fit.
  constexpr std::int64_t to_int64() const {
    if (!fits_int64()) throw std::overflow_error("geomint::big_integer: value does not fit in int64");
    const auto mag = static_cast<std::int64_t>(magnitude64());
    return negative ? -mag : mag;
  }

  /// Decimal representation (run time).
  std::string str() const {
    if (size == 0) return "0";
    std::string digits;
    big_integer rest = *this;
    rest.negative = false;
    while (!rest.is_zero()) {
      std::uint32_t chunk = 0;
      rest = rest.divide_small(1000000000U, chunk);
      for (int d = 0; d < 9; ++d) {
        digits.insert(digits.begin(), static_cast<char>('0' + chunk % 10));
        chunk /= 10;
        if (rest.is_zero() && chunk == 0) break;
      }
    }
    return negative ? "-" + digits : digits;
  }
  friend std::ostream& operator<<(std::ostream& os, const big_integer& x) { return os << x.str(); }

  // --- magnitude helpers ---------------------------------------------------------------------
  constexpr std::uint64_t magnitude64() const {
    return (size > 1 ? static_cast<std::uint64_t>(limb[1]) << 32 : 0) | (size > 0 ? limb[0] : 0);
  }
  constexpr void normalise() {
    while (size > 0 && limb[size - 1] == 0) --size;
    if (size == 0) negative = false;
  }

  static constexpr int compare_magnitude(const big_integer& a, const big_integer& b) {
    if (a.size != b.size) return a.size < b.size ? -1 : 1;
    for (int i = a.size - 1; i >= 0; --i) {
      const int k = i;
      if (a.limb[k] != b.limb[k]) return a.limb[k] < b.limb[k] ? -1 : 1;
    }
    return 0;
  }
  /// |a| + |b| (non-negative).
  static constexpr big_integer add_magnitude(const big_integer& a, const big_integer& b) {
    big_integer r;
    const int n = a.size > b.size ? a.size : b.size;
    std::uint64_t carry = 0;
    for (int i = 0; i < n; ++i) {
      const int k = i;
      carry += static_cast<std::uint64_t>(a.limb[k]) + b.limb[k];
      r.limb[k] = static_cast<std::uint32_t>(carry);
      carry >>= 32;
    }
    r.size = n;
    if (carry != 0) {
      if (n == L) throw std::overflow_error("geomint::big_integer overflow");
      r.limb[n] = static_cast<std::uint32_t>(carry);
      r.size = n + 1;
    }
    return r;
  }
  /// |a| - |b| for |a| >= |b| (non-negative).
  static constexpr big_integer subtract_magnitude(const big_integer& a, const big_integer& b) {
    big_integer r;
    std::int64_t borrow = 0;
    for (int i = 0; i < a.size; ++i) {
      const int k = i;
      std::int64_t t = static_cast<std::int64_t>(a.limb[k]) - b.limb[k] - borrow;
      borrow = t < 0 ? 1 : 0;
      if (t < 0) t += std::int64_t(1) << 32;
      r.limb[k] = static_cast<std::uint32_t>(t);
    }
    r.size = a.size;
    r.normalise();
    return r;
  }
  /// |this| / d for a one-limb d; the remainder goes to `remainder`.
  constexpr big_integer divide_small(std::uint32_t d, std::uint32_t& remainder) const {
    big_integer q;
    std::uint64_t rest = 0;
    for (int i = size - 1; i >= 0; --i) {
      const int k = i;
      rest = (rest << 32) | limb[k];
      q.limb[k] = static_cast<std::uint32_t>(rest / d);
      rest %= d;
    }
    q.size = size;
    q.normalise();
    remainder = static_cast<std::uint32_t>(rest);
    return q;
  }

  // --- arithmetic ----------------------------------------------------------------------------
  constexpr big_integer operator-() const {
    big_integer r = *this;
    if (r.size != 0) r.negative = !r.negative;
    return r;
  }
  friend constexpr big_integer operator+(const big_integer& a, const big_integer& b) {
    if (a.negative == b.negative) {
      big_integer r = add_magnitude(a, b);
      r.negative = a.negative && r.size != 0;
      return r;
    }
    const int c = compare_magnitude(a, b);
    if (c == 0) return big_integer();
    big_integer r = c > 0 ? subtract_magnitude(a, b) : subtract_magnitude(b, a);
    r.negative = c > 0 ? a.negative : b.negative;
    return r;
  }
  friend constexpr big_integer operator-(const big_integer& a, const big_integer& b) { return a + (-b); }
  friend constexpr big_integer operator*(const big_integer& a, const big_integer& b) {
    if (a.size == 0 || b.size == 0) return big_integer();
    if (a.size + b.size - 1 > L) throw std::overflow_error("geomint::big_integer overflow");
    // Product digits go straight into the result unless they may need the (L+1)-th limb.
    big_integer r;
    std::uint32_t spill[L + 1]{};
    std::uint32_t* w = a.size + b.size <= L ? r.limb : spill;
    for (int i = 0; i < a.size; ++i) {
      std::uint64_t carry = 0;
      const std::uint64_t ai = a.limb[i];
      for (int j = 0; j < b.size; ++j) {
        const int k = i + j;
        carry += w[k] + ai * b.limb[j];  // < 2^64: (2^32-1)^2 + 2 (2^32-1)
        w[k] = static_cast<std::uint32_t>(carry);
        carry >>= 32;
      }
      w[i + b.size] = static_cast<std::uint32_t>(carry);
    }
    int n = a.size + b.size;
    while (n > 0 && w[n - 1] == 0) --n;
    if (n > L) throw std::overflow_error("geomint::big_integer overflow");
    if (w == spill)
      for (int i = 0; i < n; ++i) r.limb[i] = spill[i];
    r.size = n;
    r.negative = a.negative != b.negative;
    return r;
  }

  struct division;
  /// Truncated division (like built-in integers): a = q b + r, |r| < |b|, sign(r) = sign(a).
  /// Knuth's algorithm D (TAOCP 4.3.1) on 32-bit digits, as in Hacker's Delight `divmnu`.
  static constexpr division divmod(const big_integer& a, const big_integer& b);

  friend constexpr big_integer operator/(const big_integer& a, const big_integer& b) { return divmod(a, b).quotient; }
  friend constexpr big_integer operator%(const big_integer& a, const big_integer& b) { return divmod(a, b).remainder; }
  constexpr big_integer& operator+=(const big_integer& b) { return *this = *this + b; }
  constexpr big_integer& operator-=(const big_integer& b) { return *this = *this - b; }
  constexpr big_integer& operator*=(const big_integer& b) { return *this = *this * b; }

  friend constexpr bool operator==(const big_integer&, const big_integer&) = default;
  friend constexpr std::strong_ordering operator<=>(const big_integer& a, const big_integer& b) {
    if (a.negative != b.negative) return a.negative ? std::strong_ordering::less : std::strong_ordering::greater;
    const int c = compare_magnitude(a, b);
    const int signed_c = a.negative ? -c : c;
    return signed_c < 0 ? std::strong_ordering::less
                        : (signed_c > 0 ? std::strong_ordering::greater : std::strong_ordering::equal);
  }

  // Hidden friends (found by argument-dependent lookup only, so that they never shadow other
  // abs/gcd overloads in namespace geomint).
  friend constexpr big_integer abs(big_integer x) {
    x.negative = false;
    return x;
  }
  /// gcd(|a|, |b|) >= 0 (Euclid); gcd(0, 0) = 0.
  friend constexpr big_integer gcd(big_integer a, big_integer b) {
    a.negative = false;
    b.negative = false;
    while (!b.is_zero()) {
      big_integer r = divmod(a, b).remainder;
      a = b;
      b = r;
    }
    return a;
  }
};

template <int L>
struct big_integer<L>::division {
  big_integer quotient;
  big_integer remainder;
};

template <int L>
constexpr typename big_integer<L>::division big_integer<L>::divmod(const big_integer& a, const big_integer& b) {
  if (b.is_zero()) throw std::domain_error("geomint::big_integer: division by zero");
  division out;
  if (compare_magnitude(a, b) < 0) {
    out.remainder = a;
    return out;
  }
  if (b.size == 1) {
    std::uint32_t rest = 0;
    out.quotient = a.divide_small(b.limb[0], rest);
    out.remainder = big_integer(static_cast<std::int64_t>(rest));
  } else {
    constexpr std::uint64_t base = std::uint64_t(1) << 32;
    const int m = a.size;
    const int n = b.size;
    const int s = std::countl_zero(b.limb[n - 1]);  // normalise: top bit of v set
    std::uint32_t vn[L]{};
    std::uint32_t un[L + 1]{};
    for (int i = n - 1; i > 0; --i)
      vn[i] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(b.limb[i]) << s) |
                                         (static_cast<std::uint64_t>(b.limb[i - 1]) >> (32 - s)));
    vn[0] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(b.limb[0]) << s);
    un[m] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(a.limb[m - 1]) >> (32 - s));
    for (int i = m - 1; i > 0; --i)
      un[i] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(a.limb[i]) << s) |
                                         (static_cast<std::uint64_t>(a.limb[i - 1]) >> (32 - s)));
    un[0] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(a.limb[0]) << s);
    for (int j = m - n; j >= 0; --j) {
      const std::uint64_t top = (static_cast<std::uint64_t>(un[j + n]) << 32) | un[j + n - 1];
      std::uint64_t qhat = top / vn[n - 1];
      std::uint64_t rhat = top % vn[n - 1];
      while (qhat >= base || qhat * vn[n - 2] > ((rhat << 32) | un[j + n - 2])) {
        --qhat;
        rhat += vn[n - 1];
        if (rhat >= base) break;
      }
      std::int64_t borrow = 0;
      std::int64_t t = 0;
      for (int i = 0; i < n; ++i) {
        const std::uint64_t p = qhat * vn[i];
        t = static_cast<std::int64_t>(un[i + j]) - borrow - static_cast<std::int64_t>(p & 0xFFFFFFFFU);
        un[i + j] = static_cast<std::uint32_t>(t);
        borrow = static_cast<std::int64_t>(p >> 32) - (t >> 32);
      }
      t = static_cast<std::int64_t>(un[j + n]) - borrow;
      un[j + n] = static_cast<std::uint32_t>(t);
      if (t < 0) {  // qhat was one too large: add v back
        --qhat;
        std::uint64_t carry = 0;
        for (int i = 0; i < n; ++i) {
          carry += static_cast<std::uint64_t>(un[i + j]) + vn[i];
          un[i + j] = static_cast<std::uint32_t>(carry);
          carry >>= 32;
        }
        un[j + n] = static_cast<std::uint32_t>(un[j + n] + carry);
      }
      out.quotient.limb[j] = static_cast<std::uint32_t>(qhat);
    }
    out.quotient.size = m - n + 1;
    out.quotient.normalise();
    for (int i = 0; i < n; ++i)
      out.remainder.limb[i] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(un[i]) >> s) |
                                                         ((static_cast<std::uint64_t>(un[i + 1]) << (32 - s)) & 0xFFFFFFFFU));
    out.remainder.size = n;
    out.remainder.normalise();
  }
  out.quotient.negative = (a.negative != b.negative) && !out.quotient.is_zero();
  out.remainder.negative = a.negative && !out.remainder.is_zero();
  return out;
}

/// a / b when b divides a; otherwise throws std::domain_error.
template <int L>
constexpr big_integer<L> exact_quotient(const big_integer<L>& a, const big_integer<L>& b) {
  const auto d = big_integer<L>::divmod(a, b);
  if (!d.remainder.is_zero()) throw std::domain_error("geomint::big_integer: inexact division");
  return d.quotient;
}

}  // namespace geomint
