#pragma once
/// A multilinear jet: a scalar of the truncated algebra T[e_1, ..., e_K] / (e_1^2, ..., e_K^2),
/// K chosen at run time, for mixed directional derivatives of any order in one evaluation; and
/// its generalisation to repeated directions, T[e_1, ..., e_K] / (e_1^(m_1+1), ..., e_K^(m_K+1)).
///
/// A multilinear jet holds 2^K coefficients x_S, one per subset S of {1..K} (a bitmask; S = 0 is
/// the value), x = sum_S x_S prod_{k in S} e_k. The product is the subset convolution
/// (xy)_S = sum_{A subset S} x_A y_{S minus A} (3^K multiplications). Evaluating a function f at
/// y + e_1 u_1 + ... + e_K u_K gives f^(k)(y)[u_{i_1}, ..., u_{i_k}] as the coefficient of
/// e_{i_1} ... e_{i_k}: exactly, with no truncation error (only the rounding of T). Where nested
/// dual levels (ad/dual.hpp) need one type per order, a jet is one type for every order.
///
/// Repeated directions (a vertex of a tree whose children repeat): with degrees m_k the jet holds
/// prod (m_k + 1) coefficients x_a, a multi-index with 0 <= a_k <= m_k stored in mixed radix
/// (digit k of radix m_k + 1; with every m_k = 1 the index is the bitmask above), and the product
/// is the truncated convolution (xy)_c = sum_{a <= c} x_a y_{c - a} (prod (m_k+1)(m_k+2)/2
/// multiplications). f(y + s_1 u_1 + ... + s_K u_K) has the coefficient
/// f^(|a|)(y)[u_1^(a_1), ..., u_K^(a_K)] / (a_1! ... a_K!) at s^a (Taylor's formula), so
/// f^(m)(y)[u_1, u_1, u_2] costs 6 coefficients where three multilinear directions cost 8, and a
/// bushy tree's f^(k)(y)[u, ..., u] costs k + 1 instead of 2^k.
///
/// Elementary functions: x = x_0 + n with n nilpotent (n^(d+1) = 0 for d = sum m_k, the total
/// degree: every monomial of higher degree exceeds some m_k), so f(x) = sum_{k=0}^{d} f^(k)(x_0)
/// / k! n^k exactly, summed by Horner's scheme; the Taylor coefficients are the textbook ones
/// (Abramowitz & Stegun, ch. 4), or, for the inverse trigonometric functions, those of their
/// derivatives' power series (Griewank & Walther, Evaluating Derivatives, 2nd ed., SIAM 2008,
/// section 13.2). Values come from the scalar's functions by unqualified calls (std:: for
/// built-in types, ADL for Boost.Multiprecision), sin, cos and 1/sqrt through
/// core/elementary.hpp (fast in multiprecision). Comparisons look at the value only.
///
/// Jets of different K mix: one of fewer directions is one of more that does not depend on the
/// others (its coefficients are those of its own directions; its degrees must be the leading
/// degrees of the other, std::invalid_argument otherwise); a constant (T or an arithmetic value)
/// is a jet of K = 0. Storage: the coefficients of small jets inline (no allocation: most jets
/// of a field evaluation are short-lived temporaries), more on the heap.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "geomint/core/decimal.hpp"
#include "geomint/core/elementary.hpp"

namespace geomint {

namespace ad::detail {
/// n values of T: inline up to N, on the heap beyond. Grows only.
template <class T, std::size_t N>
class small_buffer {
 public:
  small_buffer(std::size_t n, const T& value) { assign(n, value); }
  /// Copies and moves touch the used values only.
  small_buffer(const small_buffer& o) : size_(o.size_), large_(o.large_) { copy_small(o); }
  small_buffer(small_buffer&& o) noexcept : size_(o.size_), large_(std::move(o.large_)) { copy_small(o); }
  small_buffer& operator=(const small_buffer& o) {
    if (this != &o) {
      size_ = o.size_;
      large_ = o.large_;
      copy_small(o);
    }
    return *this;
  }
  small_buffer& operator=(small_buffer&& o) noexcept {
    if (this != &o) {
      size_ = o.size_;
      large_ = std::move(o.large_);
      copy_small(o);
    }
    return *this;
  }
  ~small_buffer() = default;
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return size_ <= N ? small_[i] : large_[i]; }
  const T& operator[](std::size_t i) const { return size_ <= N ? small_[i] : large_[i]; }
  void assign(std::size_t n, const T& value) {
    if (n <= N) {
      for (std::size_t i = 0; i < n; ++i) small_[i] = value;
      large_.clear();
    } else {
      large_.assign(n, value);
    }
    size_ = n;
  }
  /// Grows to n values, the new ones zero.
  void widen(std::size_t n) {
    if (n <= size_) return;
    if (n <= N) {
      for (std::size_t i = size_; i < n; ++i) small_[i] = T(0);
    } else {
      if (size_ <= N) large_.assign(small_.begin(), small_.begin() + static_cast<std::ptrdiff_t>(size_));
      large_.resize(n, T(0));
    }
    size_ = n;
  }

 private:
  void copy_small(const small_buffer& o) {
    if (size_ <= N)
      for (std::size_t i = 0; i < size_; ++i) small_[i] = o.small_[i];
  }
  std::size_t size_ = 0;
  std::array<T, N> small_{};  // (values beyond size_ are never read; zeroed for GCC 12's -O3 -Wmaybe-uninitialized)
  std::vector<T> large_;
};
}  // namespace ad::detail

template <class T>
class jet {
 public:
  /// The largest number of directions (2^K coefficients; 2^20 is already 8 MB in double).
  static constexpr int max_directions = 20;
  /// The largest number of coefficients of a jet with repeated directions (prod (m_k + 1)).
  static constexpr std::size_t max_coefficients = std::size_t{1} << max_directions;

  /// The coefficients stored inline: K <= 4 for built-in types, K <= 2 for wider ones (whose
  /// coefficients are large and whose arithmetic costs more than an allocation).
  static constexpr std::size_t inline_coefficients = sizeof(T) <= sizeof(long double) ? 16 : 4;

  jet() : c_(1, T(0)) {}
  /// A constant. Implicit, so constants mix freely with jets.
  jet(const T& value) : c_(1, value) {}  // NOLINT
  template <class S>
    requires(std::is_arithmetic_v<S> && !std::is_same_v<S, T>)
  jet(S value) : c_(1, T(value)) {}  // NOLINT
  /// A decimal constant read in the precision of T (core/decimal.hpp: from_decimal<jet<T>>).
  explicit jet(const char* decimal) : c_(1, from_decimal<T>(decimal)) {}

  /// value + sum_k directions[k] e_{k+1}: the point y_i + e_1 u_1[i] + ... + e_K u_K[i].
  static jet variable(const T& value, const std::vector<T>& directions) {
    return variable(value, directions, std::vector<int>(directions.size(), 1));
  }
  /// value + sum_k directions[k] s_{k+1} with s_{k+1}^(degrees[k] + 1) = 0: a direction repeated
  /// degrees[k] times (see the top of the file).
  static jet variable(const T& value, const std::vector<T>& directions, const std::vector<int>& degrees) {
    jet x = zero(degrees);
    if (directions.size() != degrees.size())
      throw std::invalid_argument("geomint::jet::variable: one degree per direction is needed");
    x.c_[0] = value;
    for (std::size_t k = 0; k < directions.size(); ++k) x.c_[x.stride(static_cast<int>(k))] = directions[k];
    return x;
  }
  /// The zero jet of `directions` directions (all 2^K coefficients stored).
  static jet zero(int directions) {
    if (directions < 0 || directions > max_directions)
      throw std::invalid_argument("geomint::jet: " + std::to_string(directions) + " directions, at most " +
                                  std::to_string(max_directions));
    return zero(std::vector<int>(static_cast<std::size_t>(directions), 1));
  }
  /// The zero jet of directions of the given degrees (prod (m_k + 1) coefficients stored).
  static jet zero(const std::vector<int>& degrees) {
    if (degrees.size() > static_cast<std::size_t>(max_directions))
      throw std::invalid_argument("geomint::jet: " + std::to_string(degrees.size()) + " directions, at most " +
                                  std::to_string(max_directions));
    jet x;
    std::size_t n = 1;
    for (std::size_t k = 0; k < degrees.size(); ++k) {
      if (degrees[k] < 1 || degrees[k] > 255 || n * static_cast<std::size_t>(degrees[k] + 1) > max_coefficients)
        throw std::invalid_argument("geomint::jet: direction degrees must be in 1..255 with at most " +
                                    std::to_string(max_coefficients) + " coefficients in all");
      n *= static_cast<std::size_t>(degrees[k] + 1);
      x.degrees_[k] = static_cast<std::uint8_t>(degrees[k]);
    }
    x.directions_ = static_cast<std::uint8_t>(degrees.size());
    x.c_.assign(n, T(0));
    return x;
  }

  /// K, the number of directions stored.
  int directions() const { return directions_; }
  /// The degree m_k of direction k (1 for a multilinear jet).
  int degree(int k) const { return degrees_[static_cast<std::size_t>(k)]; }
  /// d = sum m_k: n^(d+1) = 0 for the part n without the value (K for a multilinear jet).
  int total_degree() const {
    int d = 0;
    for (int k = 0; k < directions_; ++k) d += degrees_[static_cast<std::size_t>(k)];
    return d;
  }
  /// The index step of direction k: prod_{j < k} (m_j + 1) (2^k for a multilinear jet).
  std::size_t stride(int k) const {
    std::size_t n = 1;
    for (int j = 0; j < k; ++j) n *= static_cast<std::size_t>(degrees_[static_cast<std::size_t>(j)]) + 1;
    return n;
  }
  std::size_t size() const { return c_.size(); }
  const T& value() const { return c_[0]; }
  /// The coefficient of prod_{k in S} e_{k+1} (bit k of `subset` set for e_{k+1}); with repeated
  /// directions, of the multi-index stored at `subset`; zero beyond the stored coefficients.
  T coefficient(std::size_t subset) const { return subset < c_.size() ? c_[subset] : T(0); }
  T& operator[](std::size_t subset) { return c_[subset]; }
  const T& operator[](std::size_t subset) const { return c_[subset]; }

  jet& operator+=(const jet& o) {
    widen_to(o);  // (a jet of fewer directions embeds in one of more)
    for (std::size_t s = 0; s < o.c_.size(); ++s) c_[s] += o.c_[s];
    return *this;
  }
  jet& operator-=(const jet& o) {
    widen_to(o);  // (a jet of fewer directions embeds in one of more)
    for (std::size_t s = 0; s < o.c_.size(); ++s) c_[s] -= o.c_[s];
    return *this;
  }
  jet& operator*=(const jet& o) {
    if (o.c_.size() == 1) return scale(o.c_[0]);
    if (c_.size() == 1) {
      const T a = c_[0];
      *this = o;
      return scale(a);
    }
    const jet& wide = c_.size() >= o.c_.size() ? *this : o;
    const jet& narrow = c_.size() >= o.c_.size() ? o : *this;
    check_prefix(narrow, wide);
    const std::size_t n = wide.c_.size();
    coefficients out(n, T(0));
    const std::size_t na = c_.size(), nb = o.c_.size();
    if (wide.multilinear()) {
      for (std::size_t s = 0; s < n; ++s) {
        T& sum = out[s];
        for (std::size_t a = s;; a = (a - 1) & s) {  // every subset a of s
          const std::size_t b = s ^ a;
          if (a < na && b < nb) sum += c_[a] * o.c_[b];
          if (a == 0) break;
        }
      }
    } else {
      // Every multi-index a <= s digitwise, by an odometer over the digits of s; the index of
      // s - a is s - a (no borrows).
      const int K = wide.directions_;
      std::array<std::size_t, max_directions> digit{}, limit{}, step{};
      for (std::size_t s = 0; s < n; ++s) {
        std::size_t rest = s;
        for (int k = 0; k < K; ++k) {
          const std::size_t radix = static_cast<std::size_t>(wide.degrees_[static_cast<std::size_t>(k)]) + 1;
          limit[static_cast<std::size_t>(k)] = rest % radix;
          rest /= radix;
          digit[static_cast<std::size_t>(k)] = 0;
          step[static_cast<std::size_t>(k)] = k == 0 ? 1 : step[static_cast<std::size_t>(k) - 1] *
                                                               (static_cast<std::size_t>(wide.degrees_[static_cast<std::size_t>(k) - 1]) + 1);
        }
        T& sum = out[s];
        std::size_t a = 0;
        while (true) {
          const std::size_t b = s - a;
          if (a < na && b < nb) sum += c_[a] * o.c_[b];
          int k = 0;
          while (k < K && digit[static_cast<std::size_t>(k)] == limit[static_cast<std::size_t>(k)]) {
            a -= digit[static_cast<std::size_t>(k)] * step[static_cast<std::size_t>(k)];
            digit[static_cast<std::size_t>(k)] = 0;
            ++k;
          }
          if (k == K) break;
          ++digit[static_cast<std::size_t>(k)];
          a += step[static_cast<std::size_t>(k)];
        }
      }
    }
    const jet shape = wide.shape_only();
    c_ = std::move(out);
    degrees_ = shape.degrees_;
    directions_ = shape.directions_;
    return *this;
  }
  jet& operator/=(const jet& o) {
    if (o.c_.size() == 1) return scale(T(T(1) / o.c_[0]));
    return *this *= reciprocal(o);
  }
  jet& scale(const T& a) {
    for (std::size_t s = 0; s < c_.size(); ++s) c_[s] *= a;
    return *this;
  }

  /// 1 / x: the Taylor coefficients (-1)^k / x_0^(k+1).
  friend jet reciprocal(const jet& x) {
    const T inv = T(1) / x.value();
    std::vector<T> c(static_cast<std::size_t>(x.total_degree()) + 1);
    c[0] = inv;
    for (std::size_t k = 1; k < c.size(); ++k) c[k] = T(-c[k - 1] * inv);
    return taylor(x, c);
  }

  /// sum_k c[k] n^k with n = x - x_0 (n^(d+1) = 0, d the total degree: terms beyond d are
  /// dropped), by Horner.
  friend jet taylor(const jet& x, const std::vector<T>& c) {
    const std::size_t terms = std::min(c.size(), static_cast<std::size_t>(x.total_degree()) + 1);
    if (terms == 0) return jet(T(0));
    jet n = x;
    n.c_[0] = T(0);
    jet r(c[terms - 1]);
    for (std::size_t k = terms - 1; k-- > 0;) {
      r *= n;
      r.c_[0] += c[k];
    }
    return r;
  }

 private:
  using coefficients = ad::detail::small_buffer<T, inline_coefficients>;

  bool multilinear() const {
    for (int k = 0; k < directions_; ++k)
      if (degrees_[static_cast<std::size_t>(k)] != 1) return false;
    return true;
  }
  /// The degrees without the coefficients.
  jet shape_only() const {
    jet x;
    x.degrees_ = degrees_;
    x.directions_ = directions_;
    return x;
  }
  /// narrow's directions are the leading directions of wide, with the same degrees.
  static void check_prefix(const jet& narrow, const jet& wide) {
    bool ok = narrow.directions_ <= wide.directions_;
    for (int k = 0; ok && k < narrow.directions_; ++k)
      ok = narrow.degrees_[static_cast<std::size_t>(k)] == wide.degrees_[static_cast<std::size_t>(k)];
    if (!ok) throw std::invalid_argument("geomint::jet: jets of different direction degrees do not combine");
  }
  /// Grows to o's directions if o has more (this one's being its leading ones).
  void widen_to(const jet& o) {
    if (o.c_.size() <= c_.size()) {
      if (o.c_.size() > 1) check_prefix(o, *this);
      return;
    }
    if (c_.size() > 1) check_prefix(*this, o);
    c_.widen(o.c_.size());
    degrees_ = o.degrees_;
    directions_ = o.directions_;
  }

  coefficients c_;
  std::array<std::uint8_t, max_directions> degrees_{};  ///< m_k of the directions stored
  std::uint8_t directions_ = 0;                          ///< K
};

/// The scalars that mix with jet<T>: arithmetic types and T.
template <class S, class T>
concept jet_operand = std::is_arithmetic_v<std::remove_cvref_t<S>> || std::is_same_v<std::remove_cvref_t<S>, T>;

template <class T> jet<T> operator+(jet<T> a, const jet<T>& b) { a += b; return a; }
template <class T> jet<T> operator-(jet<T> a, const jet<T>& b) { a -= b; return a; }
template <class T> jet<T> operator*(jet<T> a, const jet<T>& b) { a *= b; return a; }
template <class T> jet<T> operator/(jet<T> a, const jet<T>& b) { a /= b; return a; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator+(jet<T> a, const S& b) { a[0] += T(b); return a; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator+(const S& a, jet<T> b) { b[0] += T(a); return b; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator-(jet<T> a, const S& b) { a[0] -= T(b); return a; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator-(const S& a, jet<T> b) { b.scale(T(-1)); b[0] += T(a); return b; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator*(jet<T> a, const S& b) { a.scale(T(b)); return a; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator*(const S& a, jet<T> b) { b.scale(T(a)); return b; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator/(jet<T> a, const S& b) { a.scale(T(T(1) / T(b))); return a; }
template <class T, class S> requires jet_operand<S, T>
jet<T> operator/(const S& a, const jet<T>& b) { return reciprocal(b).scale(T(a)); }
template <class T> jet<T> operator-(jet<T> a) { a.scale(T(-1)); return a; }
template <class T> jet<T> operator+(const jet<T>& a) { return a; }

/// Comparisons look at values only (branches inside a potential).
template <class T> bool operator<(const jet<T>& a, const jet<T>& b) { return a.value() < b.value(); }
template <class T> bool operator>(const jet<T>& a, const jet<T>& b) { return a.value() > b.value(); }
template <class T> bool operator<=(const jet<T>& a, const jet<T>& b) { return a.value() <= b.value(); }
template <class T> bool operator>=(const jet<T>& a, const jet<T>& b) { return a.value() >= b.value(); }
template <class T> bool operator==(const jet<T>& a, const jet<T>& b) { return a.value() == b.value(); }
template <class T> bool operator!=(const jet<T>& a, const jet<T>& b) { return !(a.value() == b.value()); }
template <class T, class S> requires jet_operand<S, T>
bool operator<(const jet<T>& a, const S& b) { return a.value() < T(b); }
template <class T, class S> requires jet_operand<S, T>
bool operator<(const S& a, const jet<T>& b) { return T(a) < b.value(); }
template <class T, class S> requires jet_operand<S, T>
bool operator>(const jet<T>& a, const S& b) { return a.value() > T(b); }
template <class T, class S> requires jet_operand<S, T>
bool operator>(const S& a, const jet<T>& b) { return T(a) > b.value(); }
template <class T, class S> requires jet_operand<S, T>
bool operator<=(const jet<T>& a, const S& b) { return a.value() <= T(b); }
template <class T, class S> requires jet_operand<S, T>
bool operator<=(const S& a, const jet<T>& b) { return T(a) <= b.value(); }
template <class T, class S> requires jet_operand<S, T>
bool operator>=(const jet<T>& a, const S& b) { return a.value() >= T(b); }
template <class T, class S> requires jet_operand<S, T>
bool operator>=(const S& a, const jet<T>& b) { return T(a) >= b.value(); }
template <class T, class S> requires jet_operand<S, T>
bool operator==(const jet<T>& a, const S& b) { return a.value() == T(b); }
template <class T, class S> requires jet_operand<S, T>
bool operator!=(const jet<T>& a, const S& b) { return !(a.value() == T(b)); }
template <class T, class S> requires jet_operand<S, T>
bool operator==(const S& a, const jet<T>& b) { return T(a) == b.value(); }
template <class T, class S> requires jet_operand<S, T>
bool operator!=(const S& a, const jet<T>& b) { return !(T(a) == b.value()); }

namespace ad::detail {
/// The Taylor coefficients of x^a at x_0 != 0 from its value v = x_0^a:
/// c_k = v binom(a, k) / x_0^k, k = 0..K.
template <class T>
std::vector<T> power_coefficients(const T& x0, const T& a, const T& v, int K) {
  std::vector<T> c(static_cast<std::size_t>(K) + 1);
  c[0] = v;
  for (int k = 1; k <= K; ++k) c[static_cast<std::size_t>(k)] = T(c[static_cast<std::size_t>(k - 1)] * (a - T(k - 1)) / (T(k) * x0));
  return c;
}
/// The Taylor coefficients of F at x_0 from F(x_0) and those of F' (length >= K):
/// c_0 = F(x_0), c_k = F'_{k-1} / k.
template <class T>
std::vector<T> integrated(const T& value, const std::vector<T>& derivative, int K) {
  std::vector<T> c(static_cast<std::size_t>(K) + 1);
  c[0] = value;
  for (int k = 1; k <= K; ++k) c[static_cast<std::size_t>(k)] = T(derivative[static_cast<std::size_t>(k - 1)] / T(k));
  return c;
}
/// The first `terms` power-series coefficients of w = v^a with v = v_0 + v_1 s + v_2 s^2, by
/// the recurrence from v w' = a v' w: k v_0 w_k = sum_{j=1,2} (a j - (k - j)) v_j w_{k-j}.
template <class T>
std::vector<T> quadratic_power(const T& v0, const T& v1, const T& v2, const T& a, const T& w0, int terms) {
  std::vector<T> w(static_cast<std::size_t>(terms > 0 ? terms : 1), T(0));
  w[0] = w0;
  for (int k = 1; k < terms; ++k) {
    T sum = T((a - T(k - 1)) * v1 * w[static_cast<std::size_t>(k - 1)]);
    if (k >= 2) sum += T((T(2) * a - T(k - 2)) * v2 * w[static_cast<std::size_t>(k - 2)]);
    w[static_cast<std::size_t>(k)] = T(sum / (T(k) * v0));
  }
  return w;
}
/// (1/k!) times the cycle value, sign(k) * (k even ? even : odd), of sin, cos, sinh, cosh.
template <class T>
std::vector<T> cyclic_coefficients(const T& even, const T& odd, bool alternating, int K) {
  std::vector<T> c(static_cast<std::size_t>(K) + 1);
  T inverse_factorial(1);
  for (int k = 0; k <= K; ++k) {
    if (k > 0) inverse_factorial /= T(k);
    const bool negative = alternating && (k % 4 == 2 || k % 4 == 3);
    const T& base = k % 2 == 0 ? even : odd;
    c[static_cast<std::size_t>(k)] = negative ? T(-base * inverse_factorial) : T(base * inverse_factorial);
  }
  return c;
}
}  // namespace ad::detail

/// (sin x, cos x): sin^(k) cycles through sin, cos, -sin, -cos; cos^(k) through cos, -sin, -cos, sin.
template <class T>
std::pair<jet<T>, jet<T>> sin_cos(const jet<T>& x) {
  const std::pair<T, T> sc = sin_cos(x.value());
  const int K = x.total_degree();
  return {taylor(x, ad::detail::cyclic_coefficients(sc.first, sc.second, true, K)),
          taylor(x, ad::detail::cyclic_coefficients(sc.second, T(-sc.first), true, K))};
}
template <class T> jet<T> sin(const jet<T>& x) {
  const std::pair<T, T> sc = sin_cos(x.value());
  return taylor(x, ad::detail::cyclic_coefficients(sc.first, sc.second, true, x.total_degree()));
}
template <class T> jet<T> cos(const jet<T>& x) {
  const std::pair<T, T> sc = sin_cos(x.value());
  return taylor(x, ad::detail::cyclic_coefficients(sc.second, T(-sc.first), true, x.total_degree()));
}
/// sine and cosine of core/elementary.hpp (the systems' fast forms) on a jet: sin and cos.
template <class T> jet<T> sine(const jet<T>& x) { return sin(x); }
template <class T> jet<T> cosine(const jet<T>& x) { return cos(x); }
template <class T> jet<T> tan(const jet<T>& x) {
  const auto sc = sin_cos(x);
  return sc.first / sc.second;
}
template <class T> jet<T> exp(const jet<T>& x) {
  using std::exp;
  const T e = exp(x.value());
  return taylor(x, ad::detail::cyclic_coefficients(e, e, false, x.total_degree()));
}
/// expm1: the value by the scalar's expm1, the derivatives exp(x_0).
template <class T> jet<T> expm1(const jet<T>& x) {
  using std::exp;
  using std::expm1;
  const T e = exp(x.value());
  std::vector<T> c = ad::detail::cyclic_coefficients(e, e, false, x.total_degree());
  c[0] = expm1(x.value());
  return taylor(x, c);
}
/// sinh^(k) alternates sinh, cosh.
template <class T> jet<T> sinh(const jet<T>& x) {
  using std::cosh;
  using std::sinh;
  return taylor(x, ad::detail::cyclic_coefficients(T(sinh(x.value())), T(cosh(x.value())), false, x.total_degree()));
}
template <class T> jet<T> cosh(const jet<T>& x) {
  using std::cosh;
  using std::sinh;
  return taylor(x, ad::detail::cyclic_coefficients(T(cosh(x.value())), T(sinh(x.value())), false, x.total_degree()));
}
template <class T> jet<T> tanh(const jet<T>& x) { return sinh(x) / cosh(x); }
/// log: c_k = (-1)^(k+1) / (k x_0^k) (x_0 > 0).
template <class T> jet<T> log(const jet<T>& x) {
  using std::log;
  const int K = x.total_degree();
  std::vector<T> c(static_cast<std::size_t>(K) + 1);
  c[0] = log(x.value());
  T power(1);
  for (int k = 1; k <= K; ++k) {
    power = T(-power / x.value());
    c[static_cast<std::size_t>(k)] = T(-power / T(k));
  }
  return taylor(x, c);
}
/// log1p(x) = log(1 + x), the value by the scalar's log1p.
template <class T> jet<T> log1p(const jet<T>& x) {
  using std::log1p;
  jet<T> r = log(jet<T>(x + 1));
  r[0] = log1p(x.value());
  return r;
}
template <class T> jet<T> sqrt(const jet<T>& x) {
  using std::sqrt;
  return taylor(x, ad::detail::power_coefficients(x.value(), T(T(1) / T(2)), T(sqrt(x.value())), x.total_degree()));
}
/// 1 / sqrt(x), the value by core/elementary.hpp's inverse_sqrt (fast in multiprecision).
template <class T> jet<T> inverse_sqrt(const jet<T>& x) {
  return taylor(x, ad::detail::power_coefficients(x.value(), T(T(-1) / T(2)), inverse_sqrt(x.value()), x.total_degree()));
}
/// cbrt (x_0 != 0; also for x_0 < 0, where cbrt' = cbrt / (3 x) holds too).
template <class T> jet<T> cbrt(const jet<T>& x) {
  using std::cbrt;
  return taylor(x, ad::detail::power_coefficients(x.value(), T(T(1) / T(3)), T(cbrt(x.value())), x.total_degree()));
}
/// x^k for an integer exponent, by repeated multiplication (exact).
template <class T> jet<T> pow(const jet<T>& x, int k) {
  jet<T> r(1), base = x;
  unsigned e = k < 0 ? 0u - static_cast<unsigned>(k) : static_cast<unsigned>(k);  // |k|, also for INT_MIN
  while (e) {
    if (e & 1u) r *= base;
    e >>= 1u;
    if (e) base *= base;
  }
  return k < 0 ? reciprocal(r) : r;
}
/// x^a for a constant exponent a (x_0 > 0).
template <class T, class S> requires(jet_operand<S, T> && !std::is_integral_v<S>)
jet<T> pow(const jet<T>& x, const S& a) {
  using std::pow;
  const T ta(a);
  return taylor(x, ad::detail::power_coefficients(x.value(), ta, T(pow(x.value(), ta)), x.total_degree()));
}
/// a^y = exp(y log a) for a constant base a > 0.
template <class T, class S> requires jet_operand<S, T>
jet<T> pow(const S& a, const jet<T>& y) {
  using std::log;
  return exp(jet<T>(y * T(log(T(a)))));
}
/// x^y = exp(y log x) (x_0 > 0).
template <class T> jet<T> pow(const jet<T>& x, const jet<T>& y) { return exp(jet<T>(y * log(x))); }
/// atan: atan' = 1 / (1 + x^2) = (v_0 + v_1 s + s^2)^(-1) at x = x_0 + s.
template <class T> jet<T> atan(const jet<T>& x) {
  using std::atan;
  const int K = x.total_degree();
  const T& x0 = x.value();
  const T v0 = T(1) + x0 * x0;
  const auto w = ad::detail::quadratic_power(v0, T(T(2) * x0), T(1), T(-1), T(T(1) / v0), K);
  return taylor(x, ad::detail::integrated(T(atan(x0)), w, K));
}
/// asin' = (1 - x^2)^(-1/2) (|x_0| < 1).
template <class T> jet<T> asin(const jet<T>& x) {
  using std::asin;
  using std::sqrt;
  const int K = x.total_degree();
  const T& x0 = x.value();
  const T v0 = T(1) - x0 * x0;
  const auto w = ad::detail::quadratic_power(v0, T(T(-2) * x0), T(-1), T(T(-1) / T(2)), T(T(1) / sqrt(v0)), K);
  return taylor(x, ad::detail::integrated(T(asin(x0)), w, K));
}
/// acos = pi/2 - asin, the value by the scalar's acos.
template <class T> jet<T> acos(const jet<T>& x) {
  using std::acos;
  jet<T> r = -asin(x);
  r[0] = acos(x.value());
  return r;
}
/// atan2(y, x) = atan2(y_0, x_0) + atan(z), z = (x_0 y - y_0 x) / (x_0 x + y_0 y): the angle
/// from (x_0, y_0) to (x, y); z has value zero (not both x_0, y_0 zero).
template <class T> jet<T> atan2(const jet<T>& y, const jet<T>& x) {
  using std::atan2;
  const T& x0 = x.value();
  const T& y0 = y.value();
  jet<T> z = (x0 * y - y0 * x) / (x0 * x + y0 * y);
  z[0] = T(0);
  jet<T> r = atan(z);
  r[0] = atan2(y0, x0);
  return r;
}
template <class T, class S> requires jet_operand<S, T>
jet<T> atan2(const jet<T>& y, const S& x) { return atan2(y, jet<T>(T(x))); }
template <class T, class S> requires jet_operand<S, T>
jet<T> atan2(const S& y, const jet<T>& x) { return atan2(jet<T>(T(y)), x); }
/// hypot(x, y) = sqrt(x^2 + y^2), the value by the scalar's hypot (not both zero).
template <class T> jet<T> hypot(const jet<T>& x, const jet<T>& y) {
  using std::hypot;
  const jet<T> r2 = x * x + y * y;
  return taylor(r2, ad::detail::power_coefficients(r2.value(), T(T(1) / T(2)), T(hypot(x.value(), y.value())), r2.total_degree()));
}
template <class T, class S> requires jet_operand<S, T>
jet<T> hypot(const jet<T>& x, const S& y) { return hypot(x, jet<T>(T(y))); }
template <class T, class S> requires jet_operand<S, T>
jet<T> hypot(const S& x, const jet<T>& y) { return hypot(jet<T>(T(x)), y); }
/// |x| (the derivatives of x kept at x_0 = 0).
template <class T> jet<T> abs(const jet<T>& x) { return x.value() < T(0) ? -x : x; }
template <class T> jet<T> fabs(const jet<T>& x) { return abs(x); }

}  // namespace geomint

/// Eigen needs NumTraits to store jets in fixed-size matrices.
namespace Eigen {
template <class T>
struct NumTraits<geomint::jet<T>> : NumTraits<T> {
  using Real = geomint::jet<T>;
  using NonInteger = Real;
  using Nested = Real;
  using Literal = Real;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1,
         ReadCost = HugeCost, AddCost = HugeCost, MulCost = HugeCost };
};
}  // namespace Eigen
