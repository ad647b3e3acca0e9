#pragma once
/// The coefficients of the Pade approximants R_kj = P_kj / Q_kj of exp (Hairer & Wanner, Solving
/// ODEs II, section IV.3), the published stability functions of the collocation families:
///   P_kj(z) = sum_(i<=k) k! (k+j-i)! / ((k+j)! i! (k-i)!) z^i,   Q_kj(z) = P_jk(-z),
/// normalised by P(0) = Q(0) = 1. Exact in geomint::rational (64-bit products: k + j <= 12).
#include <cstdint>

#include "geomint/core/rational.hpp"

namespace geomint::test {

constexpr std::int64_t pade_factorial(int n) { return n <= 1 ? 1 : n * pade_factorial(n - 1); }

/// The coefficient of z^i in P_kj (0 for i > k).
constexpr rational pade_numerator(int k, int j, int i) {
  if (i > k) return rational(0);
  return rational(pade_factorial(k) * pade_factorial(k + j - i), pade_factorial(k + j) * pade_factorial(i) * pade_factorial(k - i));
}
/// The coefficient of z^i in Q_kj (0 for i > j).
constexpr rational pade_denominator(int k, int j, int i) {
  const rational p = pade_numerator(j, k, i);
  return i % 2 ? -p : p;
}

}  // namespace geomint::test
