#pragma once
/// Exact real roots for the stability analyses (linear_stability.hpp, rk_stability.hpp,
/// field_stability.hpp) and the stability interval (0, tau*) they bound.
///
/// Polynomials over Z with wide big_integer coefficients; the squarefree part, its Sturm
/// sequence (exact primitive remainder sequence) and exact bisection isolate a root in a
/// rational interval (low, high] holding no other root; `refine` narrows it and
/// `compare_with_root` compares it with a rational exactly. `first_sign_change` finds the first
/// positive root where a function changes sign, given its sign at rational points: the
/// polynomial itself (`smallest_odd_positive_root`), or a polynomial over Q(r) whose real roots
/// are among those of its rational norm (field_stability.hpp). Everything is constexpr.

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/core/integer_polynomial.hpp"

namespace geomint {

/// Degree bound of the stability polynomials.
inline constexpr int max_stability_degree = max_exact_stages + 2;
using stability_integer = big_integer<exact_algebra_limbs>;
using stability_polynomial = integer_polynomial<exact_algebra_limbs, 2 * max_stability_degree + 2>;

/// Which interval a method has on y'' = -y.
enum class stability_kind {
  periodic,  ///< det M = 1: interval of periodicity (|tr M| <= 2)
  absolute   ///< det M != 1: interval of absolute stability (spectral radius <= 1)
};

namespace analysis::detail {

/// Exact root isolation: wide integers for the Sturm sequences and for the signs at rational
/// points (the sequences of degree-16 polynomials and points of 130-bit numerators need some
/// 2500 bits; an overflow throws, never a wrong sign).
inline constexpr int root_limbs = 96;
using wide_integer = big_integer<root_limbs>;
using wide_polynomial = integer_polynomial<root_limbs, 2 * max_stability_degree + 2>;

template <int L>
constexpr wide_integer widen(const big_integer<L>& x) {
  wide_integer w;
  for (int k = 0; k < x.size; ++k) w.limb[k] = x.limb[k];
  w.size = x.size;
  w.negative = x.negative;
  return w;
}
constexpr wide_polynomial widen(const stability_polynomial& p) {
  wide_polynomial w;
  for (int k = 0; k <= p.degree; ++k) w[k] = widen(p[k]);
  w.trim();
  return w;
}

/// Sign of p at the rational x = n / d (d > 0): the sign of sum_k p_k n^k d^(deg - k).
constexpr int sign_at(const wide_polynomial& p, const exact_number& x) {
  if (p.is_zero()) return 0;
  const wide_integer n = widen(x.num), d = widen(x.den());
  wide_integer v, dk(1);
  for (int k = p.degree; k >= 0; --k) {
    v = v * n;
    if (!p[k].is_zero()) v += p[k] * dk;
    if (k > 0) dk = dk * d;
  }
  return v.sign();
}

constexpr wide_polynomial derivative(const wide_polynomial& p) {
  wide_polynomial r;
  for (int k = 1; k <= p.degree; ++k) r[k - 1] = wide_integer(k) * p[k];
  r.trim();
  return r;
}

/// The Sturm sequence of a squarefree p: p, p', then -(positive multiple of the remainder),
/// primitive (pseudo-division by |lead| keeps the signs; the content removed is positive).
struct sturm_sequence {
  wide_polynomial p[2 * max_stability_degree + 3];
  int length = 0;
  /// Sign changes at x (zeros skipped).
  constexpr int variations(const exact_number& x) const {
    int count = 0, last = 0;
    for (int i = 0; i < length; ++i) {
      const int sg = sign_at(p[i], x);
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++count;
      last = sg;
    }
    return count;
  }
};
constexpr sturm_sequence make_sturm_sequence(const wide_polynomial& h) {
  sturm_sequence s;
  s.p[0] = h;
  s.p[1] = derivative(h);
  s.length = 2;
  while (s.p[s.length - 1].degree > 0) {
    const wide_polynomial& v = s.p[s.length - 1];
    wide_polynomial r = s.p[s.length - 2];
    while (!r.is_zero() && r.degree >= v.degree) {
      const int shift = r.degree - v.degree;
      const wide_integer f = v.lead().negative ? -r.lead() : r.lead();
      r = abs(v.lead()) * r;
      for (int j = 0; j <= v.degree; ++j) r[shift + j] -= f * v[j];
      r.trim();
    }
    if (r.is_zero()) throw std::logic_error("geomint: Sturm sequence of a polynomial that is not squarefree");
    s.p[s.length] = wide_integer(-1) * primitive_part(r);
    ++s.length;
  }
  return s;
}

/// bits(|x|): 0 for 0.
constexpr int bit_length(const wide_integer& x) {
  if (x.size == 0) return 0;
  int bits = 32 * (x.size - 1);
  for (std::uint32_t top = x.limb[x.size - 1]; top != 0; top >>= 1) ++bits;
  return bits;
}

constexpr exact_number power_of_two(int e) {
  exact_number r(1);
  const exact_number two(2);
  for (int k = 0; k < e; ++k) r = r * two;
  for (int k = 0; k > e; --k) r = r / two;
  return r;
}

/// A positive real root of a polynomial (nonzero at 0), isolated: its only root in (low, high],
/// where it has the sign `below` on (low, root); low == high when the root is that rational.
struct isolated_root {
  bool found = false;
  wide_polynomial polynomial{};
  exact_number low{}, high{};
  int below = 0;
};

/// The first positive root of the squarefree h (h(0) != 0) where a function f, whose real roots
/// are among those of h, changes sign: the roots of h in increasing order (Sturm sequence,
/// bisection from the Cauchy bound until one root is isolated in (a, b]), and the sign of f just
/// right of each, `sign_of_f(x)` at a rational x that is not a root of h (f has no root between
/// two roots of h). `below` is f's sign on (0, first root). The result's polynomial is h and its
/// bracket (low, high] holds one root of h; found = false when f keeps its sign on z > 0.
/// `variations(x)` counts the sign changes of a Sturm sequence of h at x (the roots of h in
/// (a, b] are variations(a) - variations(b)).
template <class Variations, class SignOfF>
constexpr isolated_root first_sign_change(const wide_polynomial& h, const Variations& variations, int below, const SignOfF& sign_of_f) {
  isolated_root out;
  out.polynomial = h;
  out.below = below;
  if (h.degree < 1) return out;
  // Cauchy: every root is below 1 + max |h_k / h_n| <= 2^e.
  int top = 0;
  for (int k = 0; k < h.degree; ++k) top = std::max(top, bit_length(h[k]));
  const int e = std::max(1, top - bit_length(h.lead()) + 2);
  const exact_number upper = power_of_two(e), two(2);
  exact_number lo(0);
  while (true) {
    const int v_upper = variations(upper);
    if (variations(lo) - v_upper == 0) return out;  // no root left: no sign change
    exact_number a = lo, b = upper;
    int v_a = variations(a), v_b = v_upper;
    while (v_a - v_b > 1) {
      const exact_number mid = (a + b) / two;
      const int v_mid = variations(mid);
      if (v_a - v_mid >= 1) {
        b = mid;
        v_b = v_mid;
      } else {
        a = mid;
        v_a = v_mid;
      }
    }
    // One root r of h in (a, b]; f has the sign `below` on (lo, r).
    if (sign_at(h, b) == 0) {  // r = b: the sign just right of it
      exact_number c = b + (b - a);
      while (variations(b) - variations(c) > 0) c = (b + c) / two;
      if (sign_of_f(c) != out.below) {
        out.found = true;
        out.low = out.high = b;
        return out;
      }
    } else if (sign_of_f(b) != out.below) {
      out.found = true;
      out.low = a;
      out.high = b;
      return out;
    }
    lo = b;
  }
}
/// The same with h's Sturm sequence in wide integers (constexpr; an overflow throws).
template <class SignOfF>
constexpr isolated_root first_sign_change(const wide_polynomial& h, int below, const SignOfF& sign_of_f) {
  if (h.degree < 1) return first_sign_change(h, [](const exact_number&) { return 0; }, below, sign_of_f);
  const sturm_sequence sturm = make_sturm_sequence(h);
  return first_sign_change(h, [&](const exact_number& x) { return sturm.variations(x); }, below, sign_of_f);
}

/// The smallest positive root of odd multiplicity of F (F(0) != 0): the first sign change of F
/// among the roots of its squarefree part h = F / gcd(F, F') (an even root is passed over). The
/// result's polynomial is F, with F's sign `below` on (low, root).
constexpr isolated_root smallest_odd_positive_root(const wide_polynomial& F) {
  wide_polynomial h = F;
  if (F.degree >= 1) {
    const wide_polynomial g = polynomial_gcd(F, derivative(F));
    if (g.degree > 0) h = exact_quotient(F, g);
  }
  isolated_root out = first_sign_change(h, F[0].sign(), [&](const exact_number& x) { return sign_at(F, x); });
  out.polynomial = F;
  return out;
}

/// Halves (low, high] around the root until high - low <= 2^-bits high.
constexpr void refine(isolated_root& r, int bits) {
  const exact_number two(2), tolerance = power_of_two(-bits);
  while (r.low < r.high && tolerance * r.high < r.high - r.low) {
    const exact_number mid = (r.low + r.high) / two;
    const int s = sign_at(r.polynomial, mid);
    if (s == 0) {
      r.low = r.high = mid;
    } else if (s == r.below) {
      r.low = mid;
    } else {
      r.high = mid;
    }
  }
}

/// sign(x - root), exactly.
constexpr int compare_with_root(const isolated_root& r, const exact_number& x) {
  if (!(r.low < x)) return r.low == r.high && x == r.low ? 0 : -1;
  if (r.high < x) return 1;
  const int s = sign_at(r.polynomial, x);
  return s == 0 ? 0 : (s == r.below ? -1 : 1);
}

/// F / z^k with F(0) != 0 (F not zero).
constexpr wide_polynomial without_zero_roots(wide_polynomial F) {
  int k = 0;
  while (F[k].is_zero()) ++k;
  wide_polynomial r;
  for (int j = k; j <= F.degree; ++j) r[j - k] = F[j];
  r.trim();
  return primitive_part(r);
}

}  // namespace analysis::detail

/// The stability interval (0, tau*) of a method on y'' = -y (see the header comment): empty,
/// unbounded, or tau*^2 = z* an exact algebraic number, the isolated root of `bound`.
struct stability_interval {
  stability_kind kind = stability_kind::periodic;
  bool empty = false;
  bool unbounded = true;
  analysis::detail::isolated_root bound{};  ///< z* = tau*^2 with its polynomial and bracket
  /// sign(z - z*) for a rational z = tau^2 (-1: inside the interval; unbounded: always -1).
  constexpr int compare_squared(const exact_number& z) const {
    if (empty) return 1;
    if (unbounded) return -1;
    return analysis::detail::compare_with_root(bound, z);
  }
  /// z* bracketed by (low, high] with high - low <= 2^-bits high.
  constexpr stability_interval refined(int bits) const {
    stability_interval r = *this;
    if (!empty && !unbounded) analysis::detail::refine(r.bound, bits);
    return r;
  }
  constexpr const exact_number& low() const { return bound.low; }
  constexpr const exact_number& high() const { return bound.high; }
};

namespace analysis::detail {

/// The bound of `out` becomes the smaller of it and `root` (out unbounded: root): both brackets
/// are narrowed until they are disjoint or one's rational bracket end is the other's root.
constexpr void keep_smaller_bound(stability_interval& out, isolated_root root) {
  if (out.unbounded) {
    out.bound = root;
    out.unbounded = false;
    return;
  }
  for (int bits = 8;; bits += 8) {
    if (!(out.bound.low < root.high)) {  // root <= root.high <= out.bound.low < out.bound
      out.bound = root;
      return;
    }
    if (!(root.low < out.bound.high)) return;  // out.bound <= out.bound.high <= root.low < root
    if (root.low == root.high && compare_with_root(out.bound, root.low) >= 0) {
      out.bound = root;
      return;
    }
    if (out.bound.low == out.bound.high && compare_with_root(root, out.bound.low) >= 0) return;
    if (bits > 192) {
      // Brackets still overlapping at 2^-192: equal when the polynomials share a factor (a
      // common root); otherwise no decision (an exception, never a guess).
      if (polynomial_gcd(out.bound.polynomial, root.polynomial).degree > 0) return;
      throw std::logic_error("geomint: cannot separate two stability bounds");
    }
    refine(out.bound, bits);
    refine(root, bits);
  }
}

}  // namespace analysis::detail

}  // namespace geomint
