#pragma once
/// Explicit rational RKN tableaux (analysis/stage_algebra.hpp, values basis) from braced lists
/// checked at compile time, the `_q` literal for their large entries, and the two classical
/// VIs: the midpoint VI (s = 1, c = 1/2, a = 1/4, bbar = 1/2, b = 1) and the trapezoidal VI
/// (Stormer-Verlet: s = 2, c = (0, 1), a = [[0, 0], [1/2, 0]], bbar = (1/2, 0), b = (1/2, 1/2)).

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "geomint/analysis/stage_algebra.hpp"
#include "geomint/core/rational.hpp"

namespace geomint {

/// An explicit rational RKN tableau with s stages (values basis): c (s nodes), a (s rows of s
/// entries), bbar and b (s weights each), all exact geomint::rational. Sizes and entry types are
/// deduced, so that a malformed tableau is a readable compile error.
template <class NodeEntry, std::size_t S, class MatrixEntry, std::size_t Columns, std::size_t Rows, class BbarEntry,
          std::size_t BbarSize, class BEntry, std::size_t BSize>
constexpr exact_rkn_tableau rational_rkn_tableau(const std::array<NodeEntry, S>& c,
                                                 const std::array<std::array<MatrixEntry, Columns>, Rows>& a,
                                                 const std::array<BbarEntry, BbarSize>& bbar,
                                                 const std::array<BEntry, BSize>& b) {
  static_assert(std::is_same_v<NodeEntry, rational> && std::is_same_v<MatrixEntry, rational> &&
                    std::is_same_v<BbarEntry, rational> && std::is_same_v<BEntry, rational>,
                "geomint::rational_rkn_tableau: every entry must be an exact geomint::rational (floating-point "
                "entries are not exact; write rational(1, 3), not 1.0 / 3)");
  static_assert(S >= 1 && S <= max_exact_stages, "geomint::rational_rkn_tableau: the number of stages must be in 1..8");
  static_assert(Rows == S, "geomint::rational_rkn_tableau: a must have one row per stage (as many rows as nodes c)");
  static_assert(Columns == S, "geomint::rational_rkn_tableau: every row of a must have one entry per stage");
  static_assert(BbarSize == S && BSize == S, "geomint::rational_rkn_tableau: bbar and b must have one weight per stage");
  exact_rkn_tableau t;
  t.stages = static_cast<int>(S);
  t.basis = stage_basis::values;
  for (std::size_t i = 0; i < S; ++i) {
    t.c[static_cast<int>(i)] = exact_number(c[i]);
    t.one[static_cast<int>(i)] = exact_number(1);
    t.b[i] = exact_number(b[i]);
    t.bbar[i] = exact_number(bbar[i]);
    for (std::size_t j = 0; j < S; ++j) t.a[i][j] = exact_number(a[i][j]);
  }
  return t;
}
namespace analysis::detail {
template <class>
inline constexpr bool dependent_false = false;
}  // namespace analysis::detail

/// One entry of a braced tableau list (`rational_rkn_tableau<S>({...}, ...)`): an exact rational
/// or an integer. A std::array (a row of a) filled from a shorter braced list value-initialises
/// the missing entries; here that default constructor is a static_assert, so that a left-out
/// entry is a compile error and never a silent 0.
struct tableau_entry {
  rational value;
  constexpr tableau_entry(const rational& v) : value(v) {}  // NOLINT(google-explicit-constructor)
  template <std::integral Int>
    requires(!std::is_same_v<Int, bool>)
  constexpr tableau_entry(Int n) : value(n) {}  // NOLINT(google-explicit-constructor)
  template <std::floating_point F>
  constexpr tableau_entry(F) : value() {  // NOLINT(google-explicit-constructor)
    static_assert(analysis::detail::dependent_false<F>,
                  "geomint::rational_rkn_tableau: every entry must be an exact geomint::rational (floating-point entries are "
                  "not exact; write rational(1, 3), not 1.0 / 3)");
  }
  template <class Missing = void>
  constexpr tableau_entry() : value() {
    static_assert(analysis::detail::dependent_false<Missing>,
                  "geomint::rational_rkn_tableau<S>: a braced list is shorter than the number of stages S (every row of a "
                  "needs S entries and a needs S rows; a left-out entry would be a silent 0)");
  }
};

/// The same with the number of stages given, for braced lists: `rational_rkn_tableau<2>({...}, ...)`.
/// Every list must have exactly S entries: the lengths of c, bbar and b are deduced and checked by
/// static_asserts; a short row of a is caught by tableau_entry, a long one by std::array.
template <int S, std::size_t NodeCount, std::size_t BbarCount, std::size_t BCount>
constexpr exact_rkn_tableau rational_rkn_tableau(const tableau_entry (&c)[NodeCount],
                                                 const std::array<std::array<tableau_entry, S>, S>& a,
                                                 const tableau_entry (&bbar)[BbarCount], const tableau_entry (&b)[BCount]) {
  static_assert(NodeCount == S, "geomint::rational_rkn_tableau<S>: the braced list c must have S entries (one node per stage)");
  static_assert(BbarCount == S, "geomint::rational_rkn_tableau<S>: the braced list bbar must have S entries (one weight per stage)");
  static_assert(BCount == S, "geomint::rational_rkn_tableau<S>: the braced list b must have S entries (one weight per stage)");
  std::array<rational, S> c_values{}, bbar_values{}, b_values{};
  std::array<std::array<rational, S>, S> a_values{};
  for (std::size_t i = 0; i < S && i < NodeCount && i < BbarCount && i < BCount; ++i) {
    c_values[i] = c[i].value;
    bbar_values[i] = bbar[i].value;
    b_values[i] = b[i].value;
    for (std::size_t j = 0; j < S; ++j) a_values[i][j] = a[i][j].value;
  }
  return rational_rkn_tableau<rational, S, rational, S, S, rational, S, rational, S>(c_values, a_values, bbar_values, b_values);
}

/// Integer literals of any length for tableau entries: `123456789012345678_q` is a
/// geomint::rational, and a literal that does not fit (|n| > 2^63 - 1) is a compile error. A plain
/// integer literal above 2^64 - 1 is truncated by GCC with only a warning ("integer constant is
/// too large for its type"; Clang rejects it) before any library code sees it: write large
/// numerators and denominators with _q, e.g. `9007199254740993_q / 3`.
namespace literals {
namespace detail {
__extension__ using unsigned_wide = unsigned __int128;
struct parsed_literal {
  bool decimal = true;
  bool fits = true;
  std::int64_t value = 0;
};
template <char... Digits>
consteval parsed_literal parse_literal() {
  parsed_literal out;
  constexpr char digits[] = {Digits...};
  if (sizeof...(Digits) > 1 && digits[0] == '0') out.decimal = false;  // 0x.., 0b.., octal
  unsigned_wide v = 0;
  for (char ch : digits) {
    if (ch == '\'') continue;
    if (ch < '0' || ch > '9') {
      out.decimal = false;
      break;
    }
    v = v * 10 + static_cast<unsigned>(ch - '0');
    if (v > static_cast<unsigned_wide>(std::numeric_limits<std::int64_t>::max())) {
      out.fits = false;
      break;
    }
  }
  if (out.decimal && out.fits) out.value = static_cast<std::int64_t>(v);
  return out;
}
}  // namespace detail

template <char... Digits>
consteval rational operator""_q() {
  constexpr detail::parsed_literal parsed = detail::parse_literal<Digits...>();
  static_assert(parsed.decimal, "geomint::literals::operator\"\"_q: write a decimal integer (no prefix, no leading 0)");
  static_assert(parsed.fits,
                "geomint::literals::operator\"\"_q: the integer literal does not fit geomint::rational (|n| <= 2^63 - 1 = "
                "9223372036854775807)");
  return rational(parsed.value);
}
}  // namespace literals

/// The midpoint VI (scheme 17) and the trapezoidal VI (Stormer-Verlet).
constexpr exact_rkn_tableau midpoint_tableau() {
  return rational_rkn_tableau<1>({rational(1, 2)}, {{{rational(1, 4)}}}, {rational(1, 2)}, {rational(1)});
}
constexpr exact_rkn_tableau trapezoidal_tableau() {
  return rational_rkn_tableau<2>({rational(0), rational(1)}, {{{rational(0), rational(0)}, {rational(1, 2), rational(0)}}},
                                 {rational(1, 2), rational(0)}, {rational(1, 2), rational(1, 2)});
}

}  // namespace geomint
