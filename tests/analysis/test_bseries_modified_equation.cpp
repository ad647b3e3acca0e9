/// The modified equation of a B-/P-series method (include/geomint/analysis/bseries/
/// modified_equation.hpp), tree by tree, against published modified equations.
///
/// HLW: Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006. The h^(n-1) term
/// of the modified field is sum_{|t| = n} b(t)/sigma(t) F(t), so a printed coefficient c of
/// F(t) gives b(t) = sigma(t) c.
#include <vector>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/series.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_modified_equation_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;

Q at(const std::vector<Q>& b, int t) { return b[static_cast<std::size_t>(t)]; }

/// The tall trees tau, [tau], [[tau]], ... (index n - 1 holds the one of order n).
std::vector<int> chains(const tree_set& trees, int colour) {
  std::vector<int> out = {trees.leaf(colour)};
  while (static_cast<int>(out.size()) < trees.max_order()) out.push_back(trees.find(colour, {out.back()}));
  return out;
}

TEST_CASE("bseries modified equation: the exact flow's modified field is the field itself", "[bseries]") {
  for (int colours = 1; colours <= 2; ++colours) {
    const tree_set trees(colours == 1 ? 8 : 6, colours);
    const auto b = modified_field(trees, exact_flow_coefficients<Q>(trees));
    for (int t = 0; t < trees.size(); ++t) CHECK(at(b, t) == (trees[t].order == 1 ? q(1) : q(0)));
  }
}

TEST_CASE("bseries modified equation: explicit Euler (HLW IX.1)", "[bseries]") {
  // HLW section IX.1 (the modified equation of the explicit Euler method, its first example):
  //   y' = f - h/2 f'f + h^2/12 (f''(f,f) + 4 f'f'f) + O(h^3),
  // so b([tau]) = -1/2, b([tau,tau]) = 2 * 1/12 = 1/6 (sigma = 2), b([[tau]]) = 4/12 = 1/3.
  const tree_set trees(8, 1);
  const auto b = modified_field(trees, elementary_weights(trees, explicit_euler()));
  const int tau = trees.leaf(0), t2 = trees.find(0, {tau});
  CHECK(at(b, tau) == q(1));
  CHECK(at(b, t2) == q(-1, 2));
  CHECK(at(b, trees.find(0, {tau, tau})) == q(1, 6));
  CHECK(at(b, trees.find(0, {t2})) == q(1, 3));
  // On y' = lambda y only the tall trees contribute (F = lambda^n y, sigma = 1), and the
  // modified equation is y' = log(R(h lambda))/h y with R(z) = 1 + z: b(tall tree of order n)
  // is the z^n coefficient of log(1 + z), (-1)^(n+1)/n.
  const auto tall = chains(trees, 0);
  for (int n = 1; n <= 8; ++n) CHECK(at(b, tall[static_cast<std::size_t>(n - 1)]) == q(n % 2 == 1 ? 1 : -1, n));
}

TEST_CASE("bseries modified equation: implicit midpoint rule (HLW IX.1, IX.2)", "[bseries]") {
  // HLW section IX.1 (the implicit midpoint rule's modified equation):
  //   y' = f + h^2 (1/12 f'f'f - 1/24 f''(f,f)) + O(h^4),
  // so b([[tau]]) = 1/12, b([tau,tau]) = 2 * (-1/24) = -1/12 and b([tau]) = 0.
  const tree_set trees(8, 1);
  const auto b = modified_field(trees, elementary_weights(trees, implicit_midpoint()));
  const int tau = trees.leaf(0), t2 = trees.find(0, {tau});
  CHECK(at(b, t2) == q(0));
  CHECK(at(b, trees.find(0, {tau, tau})) == q(-1, 12));
  CHECK(at(b, trees.find(0, {t2})) == q(1, 12));
  // A symmetric method has a modified equation in even powers of h only (HLW section IX.2):
  // b(t) = 0 for every tree of even order.
  for (int t = 0; t < trees.size(); ++t)
    if (trees[t].order % 2 == 0) CHECK(at(b, t) == q(0));
  // Linear test equation: R(z) = (1 + z/2)/(1 - z/2), log R(z) = 2 artanh(z/2)
  // = sum_k z^(2k+1) / (4^k (2k+1)).
  const auto tall = chains(trees, 0);
  for (int k = 0; 2 * k + 1 <= 8; ++k) {
    int four_k = 1;
    for (int i = 0; i < k; ++i) four_k *= 4;
    CHECK(at(b, tall[static_cast<std::size_t>(2 * k)]) == q(1, four_k * (2 * k + 1)));
  }
}

TEST_CASE("bseries modified equation: a method of order p has f~ = f + O(h^p)", "[bseries]") {
  // HLW section IX.1: for a method of order p the modified field differs from f first at
  // h^p, i.e. b(t) = 0 for 2 <= |t| <= p, and b(t) = a(t) - 1/gamma(t) (the local error) at
  // |t| = p + 1.
  const tree_set trees(7, 1);
  for (const auto& method : {classical_rk4(), lobatto_iiia_3()}) {
    const auto a = elementary_weights(trees, method);
    const auto b = modified_field(trees, a);
    const auto err = local_error_coefficients(trees, a);
    for (int t = trees.first(2); t < trees.first(5); ++t) CHECK(at(b, t) == q(0));
    bool some_nonzero = false;
    for (int t = trees.first(5); t < trees.first(6); ++t) {
      CHECK(at(b, t) == at(err, t));
      some_nonzero = some_nonzero || at(b, t) != q(0);
    }
    CHECK(some_nonzero);
  }
}

TEST_CASE("bseries modified equation: Stormer-Verlet as a Lobatto IIIA-IIIB pair (HLW IX.3)", "[bseries]") {
  // Colour 0 = p with f = -U'(q), colour 1 = q with g = T'(p), H = T(p) + U(q). The modified
  // Hamiltonian of the Stormer-Verlet scheme with half steps in p (p by Lobatto IIIB, q by
  // Lobatto IIIA; HLW section I.1, the Stormer-Verlet scheme for separable H) is
  //   H~ = H + h^2 (1/12 U''(T',T') - 1/24 T''(U',U')) + O(h^4),
  // and for the variant with half steps in q the roles of T and U are exchanged:
  //   H~ = H + h^2 (-1/24 U''(T',T') + 1/12 T''(U',U')) + O(h^4)
  // (HLW section IX.3 prints the latter form; which variant it belongs to we check on the
  // harmonic oscillator T = p^2/2, U = q^2/2: the half-steps-in-p map conserves exactly
  // p^2 + (1 - h^2/4) q^2, whose ratio of q^2 to p^2 coefficients 1 - h^2/4 + O(h^4) is that of
  // the first form, (1 - h^2/12)/(1 + h^2/6); the second form gives 1 + h^2/4).
  // The modified field (p' = -dH~/dq, q' = dH~/dp) of the first form, in elementary
  // differentials (f' g = -U'' T', g' f = -T'' U', f''(g,g) = -U'''(T',T'),
  // g''(f,f) = T'''(U',U')), is
  //   p' = f + h^2 (1/12 f''(g,g) + 1/12 f'g'f),   q' = g + h^2 (-1/24 g''(f,f) - 1/6 g'f'g),
  // so b(p[q,q]) = 2/12 = 1/6, b(p[q[p]]) = 1/12, b(q[p,p]) = 2 (-1/24) = -1/12,
  // b(q[p[q]]) = -1/6 (trees written root colour [subtrees]). The second form gives the same
  // values with the colours exchanged.
  const tree_set trees(4, 2);
  const int p = trees.leaf(0), qq = trees.leaf(1);
  const int p_qq = trees.find(0, {qq, qq}), p_q_p = trees.find(0, {trees.find(1, {p})});
  const int q_pp = trees.find(1, {p, p}), q_p_q = trees.find(1, {trees.find(0, {qq})});
  struct variant { tableau pair; Q p_qq, p_q_p, q_pp, q_p_q; };
  const std::vector<variant> variants = {
      {pair_of(lobatto_iiib_2(), lobatto_iiia_2()), q(1, 6), q(1, 12), q(-1, 12), q(-1, 6)},   // half steps in p
      {pair_of(lobatto_iiia_2(), lobatto_iiib_2()), q(-1, 12), q(-1, 6), q(1, 6), q(1, 12)},   // half steps in q
  };
  for (const variant& v : variants) {
    const auto b = modified_field(trees, elementary_weights(trees, v.pair));
    CHECK(at(b, p) == q(1));
    CHECK(at(b, qq) == q(1));
    for (int t = trees.first(2); t < trees.first(3); ++t) CHECK(at(b, t) == q(0));
    CHECK(at(b, p_qq) == v.p_qq);
    CHECK(at(b, p_q_p) == v.p_q_p);
    CHECK(at(b, q_pp) == v.q_pp);
    CHECK(at(b, q_p_q) == v.q_p_q);
    // Symmetric pair: no odd powers of h (HLW section IX.2), b = 0 on trees of order 4.
    for (int t = trees.first(4); t < trees.first(5); ++t) CHECK(at(b, t) == q(0));
  }
}

TEST_CASE("bseries modified equation: one coefficient per tree is required", "[bseries]") {
  const tree_set trees(3, 1);
  CHECK_THROWS_AS(modified_field(trees, std::vector<Q>(2)), std::invalid_argument);
}

}  // namespace bseries_modified_equation_test
