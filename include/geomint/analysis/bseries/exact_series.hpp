#pragma once
/// The series of a run-time tableau over Q(r) (methods::field_element: tableau files, the
/// catalogue), exactly, on the fastest exact type that holds it.
///
/// Most published tableaux have rational entries, and their series to order 10 (half a million
/// two-colour trees) are rationals whose numerators and denominators fit 64 bits. Over
/// geomint::rational (core/rational.hpp: 64-bit, every operation checked in 128 bits, an overflow
/// throws std::overflow_error, never a wrapped value) the weights and the modified field take a
/// tenth of the time they take over cpp_rational. So: when every entry is such a rational, the
/// series is computed over geomint::rational, and if any operation overflows, the whole series is
/// computed again over field_element. Either way the values are the same exact numbers.

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/series.hpp"
#include "geomint/core/rational.hpp"
#include "geomint/methods/number_field.hpp"

namespace geomint::analysis::bseries {

/// The coefficients a(t) of one step and b(t) of the modified field, one per tree.
struct exact_series {
  std::vector<methods::field_element> a, b;
};

namespace detail {
/// x as a 64-bit rational, or false if it is irrational or does not fit.
inline bool to_small_rational(const methods::field_element& x, rational& out) {
  if (!x.is_rational()) return false;
  const methods::exact_rational q = x.rational_value();
  const boost::multiprecision::cpp_int n = boost::multiprecision::numerator(q), d = boost::multiprecision::denominator(q);
  const boost::multiprecision::cpp_int limit = std::numeric_limits<std::int64_t>::max();
  if (n > limit || n < -limit || d > limit) return false;
  out = rational(static_cast<std::int64_t>(n), static_cast<std::int64_t>(d));
  return true;
}

/// The tableau over geomint::rational, or false if an entry is irrational or too large.
inline bool to_small_rationals(const tableau_data<methods::field_element>& t, tableau_data<rational>& out) {
  const auto vector = [](const std::vector<methods::field_element>& x, std::vector<rational>& y) {
    y.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!to_small_rational(x[i], y[i])) return false;
    return true;
  };
  const auto matrix = [&](const std::vector<std::vector<methods::field_element>>& x, std::vector<std::vector<rational>>& y) {
    y.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!vector(x[i], y[i])) return false;
    return true;
  };
  out.kind = t.kind;
  out.stages = t.stages;
  return vector(t.c, out.c) && vector(t.b, out.b) && vector(t.bbar, out.bbar) && vector(t.bhat, out.bhat) &&
         matrix(t.a, out.a) && matrix(t.ap, out.ap) && matrix(t.ahat, out.ahat);
}

inline std::vector<methods::field_element> to_field(const std::vector<rational>& x) {
  std::vector<methods::field_element> out;
  out.reserve(x.size());
  for (const rational& v : x) out.emplace_back(methods::exact_rational(v.num, v.den));
  return out;
}
}  // namespace detail

/// b = modified_field(trees, a), exactly: over geomint::rational where that holds it.
inline std::vector<methods::field_element> exact_modified_field(const tree_set& trees, const std::vector<methods::field_element>& a) {
  std::vector<rational> small(a.size());
  bool fits = true;
  for (std::size_t i = 0; fits && i < a.size(); ++i) fits = detail::to_small_rational(a[i], small[i]);
  if (fits) {
    try {
      return detail::to_field(modified_field(trees, small));
    } catch (const std::overflow_error&) {
      // a value beyond 64 bits: the same field over field_element below
    }
  }
  return modified_field(trees, a);
}

/// a = elementary_weights(trees, method, wanted) (series.hpp: an rk or prk tableau) and
/// b = modified_field(trees, a), exactly: over geomint::rational where that holds them.
inline exact_series exact_series_of(const tree_set& trees, const tableau_data<methods::field_element>& method,
                                    const std::vector<bool>* wanted = nullptr) {
  tableau_data<rational> small;
  if (detail::to_small_rationals(method, small)) {
    try {
      const std::vector<rational> a = elementary_weights(trees, small, wanted);
      const std::vector<rational> b = modified_field(trees, a);
      return {detail::to_field(a), detail::to_field(b)};
    } catch (const std::overflow_error&) {
      // a value beyond 64 bits: the same series over field_element below
    }
  }
  exact_series s;
  s.a = elementary_weights(trees, method, wanted);
  s.b = exact_modified_field(trees, s.a);
  return s;
}

}  // namespace geomint::analysis::bseries
