/// Compile-time suite of include/geomint/analysis/exact_scheme.hpp: the exact two-step schemes
/// of the harmonic oscillator and the big-integer arithmetic under them. It only has to compile.
///
/// Independent sources of the expected values:
/// - eqs. (16), (17), (18), (19): the printed formulas of Kong & Yang (2020), section 3
///   (docs/references.md);
/// - the leading error coefficients of (16) and (17): Taylor expansion by hand, e.g.
///   (16 - 6s)/(8 + s) = 2 - s + s^2/8 - ..., 2 cos(tau) = 2 - s + s^2/12 - ..., difference
///   s^2/24 = tau^4/24; (8 - 2s)/(4 + s) = 2 - s + s^2/4 - ..., difference s^2/6;
/// - the orders and leading coefficients of (18), (19) and of m = 5..8: power series of P/Q
///   minus 2 cos in Python `fractions` (outside this code);
/// - the coefficients for m = 5..8: a Python `fractions` check that evaluates R(s) at
///   s = 1/100, 1/7, 1, 3/2 by solving the LPF equations directly (Lagrange basis from
///   monomial coefficients, Gaussian elimination at each point) and compares with P(s)/Q(s);
///   at run time tests/analysis/test_exact_scheme.cpp compares them with the floating
///   integrator in 50 digits.
#include "geomint/analysis/exact_scheme.hpp"

#include <numeric>
#include <array>
#include <cstdint>
#include <initializer_list>

namespace {

using geomint::exact_rational;
using geomint::exact_two_step_scheme;
using geomint::rational;
using big = geomint::big_integer<geomint::analysis::detail::exact_limbs>;

/// R = P/Q has exactly these ascending coefficients (in s = tau^2).
constexpr bool has_coefficients(const exact_two_step_scheme& r, std::initializer_list<std::int64_t> p,
                                std::initializer_list<std::int64_t> q) {
  if (r.numerator_degree + 1 != static_cast<int>(p.size())) return false;
  if (r.denominator_degree + 1 != static_cast<int>(q.size())) return false;
  int k = 0;
  for (std::int64_t v : p)
    if (r.numerator[static_cast<std::size_t>(k++)] != v) return false;
  k = 0;
  for (std::int64_t v : q)
    if (r.denominator[static_cast<std::size_t>(k++)] != v) return false;
  return true;
}

/// Lowest terms: the integer content of (P, Q) is 1, Q(0) > 0 and gcd(P, Q) = 1 in Z[s]. The
/// last is certified modulo primes other than the header's (a prime not dividing the leading
/// coefficients cannot lower the degree of the gcd); the exact remainder sequence of two
/// degree-7 polynomials with 62-bit coefficients would need some 900-bit intermediates.
constexpr bool is_reduced(const exact_two_step_scheme& r) {
  std::int64_t g = 0;
  for (int k = 0; k <= r.numerator_degree; ++k) g = std::gcd(g, r.numerator[static_cast<std::size_t>(k)]);
  for (int k = 0; k <= r.denominator_degree; ++k) g = std::gcd(g, r.denominator[static_cast<std::size_t>(k)]);
  if (g != 1 || r.denominator[0] <= 0) return false;
  using poly = geomint::integer_polynomial<geomint::analysis::detail::exact_limbs, 2 * geomint::max_exact_m>;
  poly P, Q;
  for (int k = 0; k <= r.numerator_degree; ++k) P[k] = big(r.numerator[static_cast<std::size_t>(k)]);
  for (int k = 0; k <= r.denominator_degree; ++k) Q[k] = big(r.denominator[static_cast<std::size_t>(k)]);
  P.trim();
  Q.trim();
  for (std::uint32_t p : {1000000007U, 998244353U}) {
    if (geomint::residue(P.lead(), p) == 0 || geomint::residue(Q.lead(), p) == 0) continue;
    return geomint::gcd_degree_mod(P, Q, p) == 0;
  }
  return false;
}

// ---------------------------------------------------------------------------------------------
// The paper's schemes, exactly.
// ---------------------------------------------------------------------------------------------

constexpr auto s16 = geomint::exact_two_step_v<2>;
constexpr auto s17 = geomint::exact_midpoint_two_step_v;
constexpr auto s18 = geomint::exact_two_step_v<3>;
constexpr auto s19 = geomint::exact_two_step_v<4>;

// Eq. (16): R = (16 - 6 tau^2)/(8 + tau^2).
static_assert(has_coefficients(s16, {16, -6}, {8, 1}), "m = 2 must be the paper's eq. (16)");
// Eq. (17): the midpoint VI, R = (8 - 2 tau^2)/(4 + tau^2).
static_assert(has_coefficients(s17, {8, -2}, {4, 1}), "the midpoint VI must be the paper's eq. (17)");
// Eq. (18): R = (972 - 468 tau^2 + 22 tau^4)/(486 + 9 tau^2 + 2 tau^4).
static_assert(has_coefficients(s18, {972, -468, 22}, {486, 9, 2}), "m = 3 must be the paper's eq. (18)");
// Eq. (19): R = (294912 - 142848 tau^2 + 9616 tau^4 - 150 tau^6)/(147456 + 2304 tau^2 - 184 tau^4 + 9 tau^6).
static_assert(has_coefficients(s19, {294912, -142848, 9616, -150}, {147456, 2304, -184, 9}),
              "m = 4 must be the paper's eq. (19)");

// Orders and leading local error terms R - 2 cos(tau) = c tau^(p+2) + ...
static_assert(s16.order == 2 && s16.leading_power() == 4 && s16.leading_coefficient == rational(1, 24),
              "(16): R - 2 cos = tau^4/24 + ..., order 2");
static_assert(s17.order == 2 && s17.leading_coefficient == rational(1, 6), "(17): R - 2 cos = tau^4/6 + ..., order 2");
static_assert(s18.order == 2 && s18.leading_coefficient == rational(-1, 36), "(18): R - 2 cos = -tau^4/36 + ..., order 2");
static_assert(s19.order == 4 && s19.leading_power() == 6 && s19.leading_coefficient == rational(-7, 7680),
              "(19): R - 2 cos = -7 tau^6/7680 + ..., order 4");
// The paper's remark after table 1: (16) has the smaller local error of the two second-order
// schemes (16), (17).
static_assert(s16.leading_coefficient < s17.leading_coefficient && s16.leading_coefficient > rational(0));
static_assert(s16.m == 2 && s18.m == 3 && s19.m == 4 && s17.m == 0);

// m = 5..8 (checked in Python `fractions` by direct solves at points; see the header comment).
constexpr auto s5 = geomint::exact_two_step_v<5>;
constexpr auto s6 = geomint::exact_two_step_v<6>;
constexpr auto s7 = geomint::exact_two_step_v<7>;
constexpr auto s8 = geomint::exact_two_step_v<8>;
static_assert(has_coefficients(s5, {562500000, -273750000, 19736250, -455250, 3288},
                               {281250000, 3750000, 24375, -10750, 144}));
static_assert(s5.order == 4 && s5.leading_coefficient == rational(19, 90000));
static_assert(has_coefficients(s6, {36279705600, -17719948800, 1304112960, -33843420, 368288, -1470},
                               {18139852800, 209952000, 1205280, 127170, -8231, 50}));
static_assert(s6.order == 6 && s6.leading_coefficient == rational(41, 7838208));
static_assert(has_coefficients(s7,
                               {2092802624791200, -1025046183571200, 76631499693000, -2070984758920, 26140498538,
                                -159066936, 392040},
                               {1046401312395600, 10677564412200, 54477369450, 182944195, 155918539, -3196074,
                                10800}));
static_assert(s7.order == 6 && s7.leading_coefficient == rational(-751, 1016487360));
static_assert(has_coefficients(s8,
                               {2327446213676236800, -1142509404369715200, 86467145965240320, -2396900661657600,
                                32117757149184, -231312517632, 875721264, -1438290},
                               {1163723106838118400, 10606851234201600, 48535814799360, 147534643200,
                                -20122124288, 1639574272, -15661416, 33075}));
static_assert(s8.order == 8 && s8.leading_coefficient == rational(-989, 67947724800));

// Every scheme: lowest terms, positive denominator, consistent (R(0) = 2, i.e. P(0) = 2 Q(0)),
// and degree m - 1 in s (m + 1 nodes, m - 1 interior unknowns).
template <int M>
constexpr bool well_formed() {
  constexpr auto r = geomint::exact_two_step_v<M>;
  return is_reduced(r) && r.numerator[0] == 2 * r.denominator[0] && r.numerator_degree == M - 1 &&
         r.denominator_degree == M - 1 && r.m == M;
}
static_assert(well_formed<2>() && well_formed<3>() && well_formed<4>() && well_formed<5>());
static_assert(well_formed<6>() && well_formed<7>() && well_formed<8>());
static_assert(is_reduced(s17) && s17.numerator[0] == 2 * s17.denominator[0]);
// Orders grow by 2 every two nodes: p = 2 floor(m/2) on equispaced nodes.
static_assert(s16.order == 2 && s18.order == 2 && s19.order == 4 && s5.order == 4 && s6.order == 6 &&
              s7.order == 6 && s8.order == 8);
// The results are structural: usable as template arguments.
template <exact_two_step_scheme S>
struct scheme_tag {
  static constexpr int order = S.order;
};
static_assert(scheme_tag<geomint::exact_two_step_v<4>>::order == 4);

// ---------------------------------------------------------------------------------------------
// Big-integer and big-rational arithmetic identities.
// ---------------------------------------------------------------------------------------------

/// 2^k as a big integer.
constexpr big power_of_two(int k) {
  big r(1);
  for (int i = 0; i < k; ++i) r = r + r;
  return r;
}
constexpr big power(big b, int e) {
  big r(1);
  for (int i = 0; i < e; ++i) r *= b;
  return r;
}

// Limb boundaries: (2^32 - 1) + 1 = 2^32, 2^64 - 1 + 1 = 2^64, borrows across limbs.
static_assert(big(4294967295LL) + big(1) == power_of_two(32));
static_assert(power_of_two(64) - big(1) + big(1) == power_of_two(64));
static_assert(power_of_two(64) - big(1) == big(std::int64_t(0x7FFFFFFFFFFFFFFFLL)) * big(2) + big(1));
static_assert((power_of_two(96) - big(1)).size == 3 && power_of_two(96).size == 4);
static_assert(power_of_two(100) * power_of_two(100) == power_of_two(200));
// (a + b)^2 = a^2 + 2ab + b^2 and (a - b)(a + b) = a^2 - b^2 with signs and carries.
constexpr big qa = power(big(1000000007), 6) + big(123456789);
constexpr big qb = -power(big(998244353), 5) - big(987654321);
static_assert((qa + qb) * (qa + qb) == qa * qa + big(2) * qa * qb + qb * qb);
static_assert((qa - qb) * (qa + qb) == qa * qa - qb * qb);
static_assert(qa * qb == qb * qa && qa * qb < big(0) && -qa < qb);
// Truncated division: a = q b + r, |r| < |b|, sign(r) = sign(a), for all sign combinations,
// multi-limb and one-limb divisors, and the add-back branch of algorithm D.
constexpr bool division_identity(const big& a, const big& b) {
  const auto d = big::divmod(a, b);
  const big r = d.remainder;
  return d.quotient * b + r == a && abs(r) < abs(b) && (r.is_zero() || r.negative == a.negative);
}
static_assert(division_identity(qa * qa, qb) && division_identity(-(qa * qa), qb) && division_identity(qa, -qb));
static_assert(division_identity(-qa, -qb) && division_identity(qa, big(7)) && division_identity(-qa, big(4294967291LL)));
static_assert(division_identity(power_of_two(128) - big(1), power_of_two(64) + big(1)));
static_assert(division_identity(power_of_two(192), power_of_two(96) - big(1)));  // qhat corrections
static_assert(division_identity(power_of_two(127) * big(3) + big(5), power_of_two(63) * big(3) + big(1)));
/// Most significant 32-bit limb first.
constexpr big from_limbs(std::initializer_list<std::uint32_t> limbs) {
  big r(0);
  for (std::uint32_t l : limbs) r = r * power_of_two(32) + big(std::int64_t(l));
  return r;
}
// The add-back branch of algorithm D (qhat one too large after the two-digit test), an operand
// pair found by a run-time search over limbs 0, 1, 2^31 - 1, 2^31, 2^31 + 1, 2^32 - 2, 2^32 - 1.
static_assert(division_identity(from_limbs({0xFFFFFFFEU, 0xFFFFFFFEU, 0x80000001U, 1U}),
                                from_limbs({0xFFFFFFFEU, 0U, 0x80000001U})));
static_assert(from_limbs({0xFFFFFFFEU, 0U, 0x80000001U}).size == 3);
static_assert(big(-7) / big(2) == big(-3) && big(-7) % big(2) == big(-1) && big(7) % big(-2) == big(1));
static_assert(geomint::exact_quotient(qa * qb, qb) == qa);
static_assert(big(5) / big(9) == big(0) && big(5) % big(9) == big(5));
// gcd: gcd(a c, b c) = c gcd(a, b) with coprime a, b.
static_assert(gcd(qa * big(3) * big(1000003), big(3) * big(1000003) * big(10007)) ==
              big(3) * big(1000003) * gcd(qa, big(10007)));
static_assert(gcd(power(big(6), 40), power(big(10), 30)) == power(big(2), 30));
static_assert(gcd(big(0), qb) == -qb && gcd(big(0), big(0)).is_zero());
// Narrowing: INT64_MAX fits, 2^63 does not (nor INT64_MIN, like geomint::rational).
static_assert(big(std::int64_t(0x7FFFFFFFFFFFFFFFLL)).fits_int64() && !power_of_two(63).fits_int64());
static_assert((-power_of_two(62)).to_int64() == -(std::int64_t(1) << 62));
// Ordering.
static_assert(power_of_two(70) > power_of_two(69) && -power_of_two(70) < -power_of_two(69) && big(-1) < big(0));

// Big rationals: reduced, comparable with geomint::rational and with each other.
constexpr exact_rational third(big(1), big(3));
static_assert(exact_rational(big(2), big(-6)) == -third && exact_rational(big(2), big(-6)) == rational(-1, 3));
static_assert(third + third + third == 1 && third * exact_rational(3) == 1 && third / third == 1);
static_assert(third - rational(1, 2) == rational(-1, 6) && third < rational(1, 2) && third > rational(1, 4));
static_assert(exact_rational(power_of_two(100), power_of_two(98) * big(3)) == rational(4, 3));
static_assert(!exact_rational(power_of_two(80), big(3)).fits_rational() && third.to_rational() == rational(1, 3));
static_assert(exact_rational(power_of_two(80), big(3)) > rational(9223372036854775807LL));

// Polynomials over Z: exact division and the gcd route with a real common factor.
using small_poly = geomint::integer_polynomial<geomint::analysis::detail::exact_limbs, 6>;
constexpr small_poly make_poly(std::initializer_list<std::int64_t> c) {
  small_poly p;
  int k = 0;
  for (std::int64_t v : c) p[k++] = big(v);
  p.trim();
  return p;
}
// (s - 2)(3s + 1) and (s - 2)(s + 5): gcd s - 2 (the primitive remainder sequence route).
constexpr small_poly f1 = make_poly({-2, -5, 3});
constexpr small_poly f2 = make_poly({-10, 3, 1});
static_assert(geomint::polynomial_gcd(f1, f2) == make_poly({-2, 1}));
static_assert(geomint::exact_quotient(f1, make_poly({-2, 1})) == make_poly({1, 3}));
static_assert(geomint::polynomial_gcd(make_poly({1, 3}), make_poly({5, 1})) == make_poly({1}));
// A common factor survives modulo every prime: the gcd is found by the exact route.
static_assert(geomint::polynomial_gcd(make_poly({6, 4}), make_poly({9, 6})) == make_poly({3, 2}));

}  // namespace
