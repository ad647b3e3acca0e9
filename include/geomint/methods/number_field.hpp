#pragma once
/// Exact coefficients at run time: rationals of any size (`exact_rational`, Boost's cpp_rational)
/// and the real algebraic number field Q(r), r a real root of a rational polynomial P, for
/// method coefficients such as sqrt 15 or 2^(1/3).
///
/// An element of Q(r) is a polynomial in r with rational coefficients reduced mod P; +, -, *
/// are polynomial arithmetic mod P, and 1/a is the inverse of a mod P by the extended Euclidean
/// algorithm over Q. P need not be irreducible: it is made square-free, and where a shares a
/// factor g with P, a(r) = 0 exactly when r is a root of g (a division by zero, reported), else
/// a is inverted mod P / g. The chosen root is isolated exactly (Sturm sequence and bisection
/// over Q) and computed in any scalar T at T's full precision by bisection in T from that
/// rational bracket (`root_in<T>`), never through a double literal.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "geomint/core/scalar_traits.hpp"
#include "geomint/methods/algebraic_number.hpp"

namespace geomint::methods {

/// A rational of any size.
using exact_rational = boost::multiprecision::cpp_rational;

/// The nearest T to an exact rational: correctly rounded conversion for built-in types; for a
/// sum of doubles (core/scalar_traits.hpp), each term the correctly rounded remainder of the
/// terms before it (within half a unit of the sum's last bit); the multiprecision type's own
/// rational conversion otherwise.
template <class T>
T rational_to(const exact_rational& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return x.template convert_to<T>();
  } else if constexpr (double_expansion<T>::value) {
    return narrow<T>(x);
  } else {
    return T(x);
  }
}

namespace detail {
/// Polynomials over Q as coefficient vectors, constant term first, without trailing zeros
/// (the zero polynomial is empty).
using poly = std::vector<exact_rational>;

inline void trim(poly& p) {
  while (!p.empty() && p.back().is_zero()) p.pop_back();
}
inline int degree(const poly& p) { return static_cast<int>(p.size()) - 1; }

/// a += b (sign 1) or a -= b (sign -1), in place.
inline void accumulate(poly& a, const poly& b, int sign) {
  if (a.size() < b.size()) a.resize(b.size(), exact_rational(0));
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (sign < 0) a[i] -= b[i];
    else a[i] += b[i];
  }
  trim(a);
}
inline poly add(poly a, const poly& b) {
  accumulate(a, b, 1);
  return a;
}
inline poly subtract(poly a, const poly& b) {
  accumulate(a, b, -1);
  return a;
}
/// a + s b.
inline poly add_scaled(poly a, const poly& b, const exact_rational& s) {
  if (a.size() < b.size()) a.resize(b.size(), exact_rational(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += s * b[i];
  trim(a);
  return a;
}
inline poly multiply(const poly& a, const poly& b) {
  if (a.empty() || b.empty()) return {};
  if (a.size() == 1 && b.size() == 1) return {a[0] * b[0]};  // rationals: the common case in series
  poly out(a.size() + b.size() - 1, exact_rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  trim(out);
  return out;
}
/// a = q b + rem with deg rem < deg b (b not zero).
inline void divide(const poly& a, const poly& b, poly& q, poly& rem) {
  rem = a;
  q.assign(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, exact_rational(0));
  while (!rem.empty() && rem.size() >= b.size()) {
    const std::size_t shift = rem.size() - b.size();
    const exact_rational f = b.back() == 1 ? rem.back() : exact_rational(rem.back() / b.back());  // field polynomials are monic
    q[shift] = f;
    for (std::size_t i = 0; i + 1 < b.size(); ++i)
      if (!b[i].is_zero()) rem[shift + i] -= f * b[i];
    rem.pop_back();  // the leading term cancels exactly
    trim(rem);
  }
  trim(q);
}
inline poly remainder(const poly& a, const poly& b) {
  poly q, r;
  divide(a, b, q, r);
  return r;
}
inline poly monic(poly p) {
  if (p.empty()) return p;
  const exact_rational lead = p.back();
  for (auto& x : p) x /= lead;
  return p;
}
inline poly gcd(poly a, poly b) {
  while (!b.empty()) {
    poly r = remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  return monic(a);
}
inline poly derivative(const poly& p) {
  poly out;
  for (std::size_t i = 1; i < p.size(); ++i) out.push_back(p[i] * exact_rational(static_cast<long>(i)));
  trim(out);
  return out;
}
inline exact_rational evaluate(const poly& p, const exact_rational& x) {
  exact_rational s = 0;
  for (std::size_t i = p.size(); i-- > 0;) s = s * x + p[i];
  return s;
}
inline int sign(const exact_rational& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

/// The Sturm sequence of a square-free p: p, p', -rem(p_{k-1}, p_k), ...
inline std::vector<poly> sturm_sequence(const poly& p) {
  std::vector<poly> s{p, derivative(p)};
  while (!s.back().empty() && degree(s.back()) > 0) {
    poly r = remainder(s[s.size() - 2], s.back());
    for (auto& x : r) x = -x;
    if (r.empty()) break;
    s.push_back(r);
  }
  return s;
}
inline int sign_changes(const std::vector<poly>& s, const exact_rational& x) {
  int changes = 0, last = 0;
  for (const poly& p : s) {
    const int v = sign(evaluate(p, x));
    if (v == 0) continue;
    if (last != 0 && v != last) ++changes;
    last = v;
  }
  return changes;
}
}  // namespace detail

/// Q(r): the square-free part of P and an exact isolating interval [lo, hi] of the chosen real
/// root (lo = hi when the root is rational).
class algebraic_field {
 public:
  /// r is the real root of `poly` (constant term first) nearest to `near` (default: the
  /// largest). std::invalid_argument if P is constant, has no real root, or two roots are
  /// equally near.
  static std::shared_ptr<const algebraic_field> make(std::vector<exact_rational> poly,
                                                     const std::optional<exact_rational>& near = std::nullopt) {
    detail::trim(poly);
    if (detail::degree(poly) < 1) throw std::invalid_argument("the field polynomial must have degree >= 1");
    // The square-free part P / gcd(P, P') has the same roots, each simple.
    detail::poly q, rem;
    detail::divide(poly, detail::gcd(poly, detail::derivative(poly)), q, rem);
    auto f = std::shared_ptr<algebraic_field>(new algebraic_field());
    f->p_ = detail::monic(q);
    f->isolate(near);
    return f;
  }

  /// The defining polynomial (square-free, monic, constant term first).
  const std::vector<exact_rational>& polynomial() const { return p_; }
  int degree() const { return detail::degree(p_); }
  const exact_rational& lower() const { return lo_; }
  const exact_rational& upper() const { return hi_; }

  /// Whether r is a root of the divisor g of P: g has a root in [lo, hi] (which holds only r).
  bool vanishes_at_root(const std::vector<exact_rational>& g) const {
    if (lo_ == hi_) return detail::evaluate(g, lo_) == 0;
    const int a = detail::sign(detail::evaluate(g, lo_)), b = detail::sign(detail::evaluate(g, hi_));
    return a == 0 || b == 0 || a != b;
  }

  /// r in T to T's full precision: bisection in T on the sign of P from the rational bracket.
  template <class T>
  T root_in() const {
    if (lo_ == hi_) return rational_to<T>(lo_);
    // P with integer coefficients (exact in T where they fit its mantissa).
    boost::multiprecision::cpp_int lcm = 1;
    for (const auto& c : p_) lcm = boost::multiprecision::lcm(lcm, boost::multiprecision::denominator(c));
    std::vector<T> pt;
    for (const auto& c : p_) pt.push_back(rational_to<T>(exact_rational(c * lcm)));
    auto value = [&](const T& x) {
      T s(0);
      for (std::size_t i = pt.size(); i-- > 0;) s = s * x + pt[i];
      return s;
    };
    auto sgn = [](const T& x) { return x > T(0) ? 1 : (x < T(0) ? -1 : 0); };
    T a = rational_to<T>(lo_), b = rational_to<T>(hi_);
    const int sa = sgn(value(a));
    if (sa == 0) return a;
    if (sgn(value(b)) == 0) return b;
    if (sgn(value(b)) == sa) return (a + b) / T(2);  // bracket narrower than T's resolution
    for (int it = 0; it < 100000; ++it) {
      const T mid = (a + b) / T(2);
      if (!(mid > a && mid < b)) break;
      const int sm = sgn(value(mid));
      if (sm == 0) return mid;
      (sm == sa ? a : b) = mid;
    }
    using std::abs;
    return abs(value(a)) <= abs(value(b)) ? a : b;
  }

  /// The real roots of the square-free P, ascending, each in an exact bracket [a, b] that holds
  /// no other root (a = b for a rational root), narrower than 2^-64 of the Cauchy bound
  /// (`width`, if given, receives that width).
  static std::vector<std::pair<exact_rational, exact_rational>> real_root_brackets(const std::vector<exact_rational>& p,
                                                                                   exact_rational* width_out = nullptr) {
    using detail::sign_changes;
    const auto s = detail::sturm_sequence(p);
    exact_rational bound = 0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
      const exact_rational a = boost::multiprecision::abs(p[i] / p.back());
      if (a > bound) bound = a;
    }
    bound += 1;
    std::vector<std::pair<exact_rational, exact_rational>> roots, work{{-bound, bound}};
    // roots in (a, b] = V(a) - V(b); +-bound are not roots.
    while (!work.empty()) {
      auto [a, b] = work.back();
      work.pop_back();
      const int count = sign_changes(s, a) - sign_changes(s, b);
      if (count == 0) continue;
      if (count == 1) {
        roots.emplace_back(a, b);
        continue;
      }
      const exact_rational mid = (a + b) / 2;
      work.emplace_back(a, mid);
      work.emplace_back(mid, b);
    }
    const exact_rational width = bound / exact_rational(boost::multiprecision::cpp_int(1) << 64);
    if (width_out) *width_out = width;
    for (auto& [a, b] : roots) {
      // One root in (a, b]: narrow by the sign of P (simple root, so a sign change).
      if (detail::evaluate(p, b) == 0) {
        a = b;
        continue;
      }
      while (b - a > width) {
        const exact_rational mid = (a + b) / 2;
        const int sm = detail::sign(detail::evaluate(p, mid));
        if (sm == 0) {
          a = b = mid;
          break;
        }
        if (sm == detail::sign(detail::evaluate(p, b)))
          b = mid;
        else
          a = mid;
      }
    }
    std::sort(roots.begin(), roots.end());
    return roots;
  }

 private:
  algebraic_field() = default;

  /// Isolates every real root (Sturm counts, bisection from the Cauchy bound), narrows each to a
  /// width below 2^-64 of the bound, and keeps the one nearest `near` (or the largest).
  void isolate(const std::optional<exact_rational>& near) {
    exact_rational width;
    const auto roots = real_root_brackets(p_, &width);
    if (roots.empty()) throw std::invalid_argument("the field polynomial has no real root");
    std::size_t best = 0;
    bool tie = false;
    for (std::size_t i = 1; i < roots.size(); ++i) {
      if (!near) {
        if (roots[i].first > roots[best].first) best = i;
        continue;
      }
      const exact_rational di = boost::multiprecision::abs((roots[i].first + roots[i].second) / 2 - *near);
      const exact_rational db = boost::multiprecision::abs((roots[best].first + roots[best].second) / 2 - *near);
      if (di < db) {
        best = i;
        tie = false;
      } else if (di - db <= 2 * width && db - di <= 2 * width) {
        tie = true;
      }
    }
    if (tie) throw std::invalid_argument("two real roots of the field polynomial are equally near the given point");
    lo_ = roots[best].first;
    hi_ = roots[best].second;
  }

  std::vector<exact_rational> p_;
  exact_rational lo_, hi_;
};

/// An element of Q(r): a polynomial in r reduced mod P. Elements without a field (from a
/// rational) are constants and combine with elements of any field; two different fields do
/// not combine (std::invalid_argument).
class field_element {
 public:
  using field_ptr = std::shared_ptr<const algebraic_field>;
  field_element() = default;
  field_element(const exact_rational& x) : c_{x} { detail::trim(c_); }  // NOLINT(google-explicit-constructor)
  field_element(long x) : field_element(exact_rational(x)) {}             // NOLINT(google-explicit-constructor)
  /// The generator r of `field`.
  static field_element generator(field_ptr field) {
    field_element g;
    g.field_ = std::move(field);
    g.c_ = {exact_rational(0), exact_rational(1)};
    g.reduce();
    return g;
  }

  const field_ptr& field() const { return field_; }
  /// The coefficients of the reduced polynomial in r (constant first; empty for zero).
  const std::vector<exact_rational>& coefficients() const { return c_; }
  /// Whether the element is rational (a constant polynomial).
  bool is_rational() const { return c_.size() <= 1; }
  exact_rational rational_value() const { return c_.empty() ? exact_rational(0) : c_[0]; }

  /// Whether the value is 0 (exactly; also for a polynomial that is not zero but vanishes at r).
  bool is_zero() const {
    if (c_.empty()) return true;
    if (!field_) return false;
    const detail::poly g = detail::gcd(field_->polynomial(), c_);
    return detail::degree(g) >= 1 && field_->vanishes_at_root(g);
  }

  friend field_element operator+(const field_element& a, const field_element& b) {
    field_element out;
    out.field_ = common(a, b);
    out.c_ = detail::add(a.c_, b.c_);
    return out;
  }
  friend field_element operator-(const field_element& a, const field_element& b) {
    field_element out;
    out.field_ = common(a, b);
    out.c_ = detail::subtract(a.c_, b.c_);
    return out;
  }
  friend field_element operator-(const field_element& a) { return field_element() - a; }
  friend field_element operator*(const field_element& a, const field_element& b) {
    field_element out;
    out.field_ = common(a, b);
    out.c_ = detail::multiply(a.c_, b.c_);
    out.reduce();
    return out;
  }
  /// std::domain_error for a divisor whose value is 0.
  friend field_element operator/(const field_element& a, const field_element& b) { return a * b.inverse(); }
  field_element& operator+=(const field_element& b) {
    field_ = common(*this, b);
    detail::accumulate(c_, b.c_, 1);
    return *this;
  }
  field_element& operator-=(const field_element& b) {
    field_ = common(*this, b);
    detail::accumulate(c_, b.c_, -1);
    return *this;
  }
  field_element& operator*=(const field_element& b) { return *this = *this * b; }
  /// Exact equality of values.
  friend bool operator==(const field_element& a, const field_element& b) { return (a - b).is_zero(); }

  /// 1/a mod P (extended Euclid over Q); std::domain_error if a(r) = 0.
  field_element inverse() const {
    if (is_zero()) throw std::domain_error("division by zero");
    field_element out;
    out.field_ = field_;
    if (!field_) {
      out.c_ = {exact_rational(1) / c_[0]};
      return out;
    }
    // Where a shares a factor g with P (then g(r) != 0, checked above), invert mod P / g.
    detail::poly modulus = field_->polynomial();
    const detail::poly g = detail::gcd(modulus, c_);
    if (detail::degree(g) >= 1) {
      detail::poly q, rem;
      detail::divide(modulus, g, q, rem);
      modulus = q;
    }
    // Extended Euclid: s a + t m = gcd = const.
    detail::poly r0 = modulus, r1 = detail::remainder(c_, modulus), s0{}, s1{exact_rational(1)};
    while (detail::degree(r1) > 0) {
      detail::poly q, rem;
      detail::divide(r0, r1, q, rem);
      detail::poly s2 = detail::subtract(s0, detail::multiply(q, s1));
      r0 = std::move(r1);
      r1 = std::move(rem);
      s0 = std::move(s1);
      s1 = std::move(s2);
    }
    // r1 is a nonzero constant (gcd(a, modulus) = 1).
    out.c_ = s1;
    for (auto& x : out.c_) x /= r1[0];
    out.reduce();
    return out;
  }

  /// The value in T: Horner's rule at r computed in T (root_in).
  template <class T>
  T to(const T& root) const {
    T s(0);
    for (std::size_t i = c_.size(); i-- > 0;) s = s * root + rational_to<T>(c_[i]);
    return s;
  }
  template <class T>
  T to() const {
    return to<T>(field_ ? field_->root_in<T>() : T(0));
  }

 private:
  static field_ptr common(const field_element& a, const field_element& b) {
    if (a.field_ && b.field_ && a.field_ != b.field_)
      throw std::invalid_argument("geomint::methods::field_element: elements of two different fields");
    return a.field_ ? a.field_ : b.field_;
  }
  void reduce() {
    if (field_ && detail::degree(c_) >= field_->degree()) c_ = detail::remainder(c_, field_->polynomial());
  }

  field_ptr field_;
  std::vector<exact_rational> c_;
};

/// The sign of x's value, exactly: 0 iff x.is_zero(); otherwise x's polynomial is evaluated in
/// exact interval arithmetic over the root's rational bracket, which is halved (by the sign of
/// the field polynomial at its midpoint) until the interval of values excludes 0. It does: the
/// value is nonzero and the interval shrinks to it.
inline int exact_sign(const field_element& x) {
  if (x.is_zero()) return 0;
  const std::vector<exact_rational>& c = x.coefficients();
  if (!x.field() || x.is_rational()) return detail::sign(x.rational_value());
  const algebraic_field& f = *x.field();
  exact_rational lo = f.lower(), hi = f.upper();
  if (lo == hi) return detail::sign(detail::evaluate(c, lo));
  const int sign_high = detail::sign(detail::evaluate(f.polynomial(), hi));  // nonzero: the root is inside
  while (true) {
    exact_rational low = 0, high = 0;  // Horner in intervals: [low, high] * [lo, hi] + c_i
    for (std::size_t i = c.size(); i-- > 0;) {
      const exact_rational p[4] = {low * lo, low * hi, high * lo, high * hi};
      low = std::min({p[0], p[1], p[2], p[3]}) + c[i];
      high = std::max({p[0], p[1], p[2], p[3]}) + c[i];
    }
    if (low > 0) return 1;
    if (high < 0) return -1;
    const exact_rational mid = (lo + hi) / 2;
    const int s = detail::sign(detail::evaluate(f.polynomial(), mid));
    if (s == 0) return detail::sign(detail::evaluate(c, mid));  // r = mid, rational after all
    (s == sign_high ? hi : lo) = mid;
  }
}

/// The run-time element of the same value: Q(r) from P with r the root nearest the middle of
/// P's bracket (the only root in the bracket, so no other root is as near).
template <auto P>
field_element to_field_element(const algebraic_number<P>& x) {
  using C = typename algebraic_number<P>::coefficient_type;
  auto to_exact_rational = [](const C& v) {
    return exact_rational(boost::multiprecision::cpp_int(v.num.str()), boost::multiprecision::cpp_int(v.den().str()));
  };
  static const std::shared_ptr<const algebraic_field> field = [] {
    std::vector<exact_rational> poly;
    for (const rational& c : P.c) poly.push_back(exact_rational(c.num, c.den));
    return algebraic_field::make(poly, (exact_rational(P.lo.num, P.lo.den) + exact_rational(P.hi.num, P.hi.den)) / 2);
  }();
  const field_element r = field_element::generator(field);
  field_element out(exact_rational(0));
  for (int k = decltype(P)::degree - 1; k >= 0; --k) out = out * r + field_element(to_exact_rational(x.coefficient(k)));
  return out;
}

}  // namespace geomint::methods
