/// Free trees and the modified Hamiltonian of a symplectic B-series method
/// (include/geomint/analysis/bseries/modified_hamiltonian.hpp).
///
/// Independent sources: the number of free trees per order (OEIS A000055: 1, 1, 1, 2, 3, 6, 11,
/// 23, 47, 106 for n = 1..10); the superfluous ones u o u exist only for even n and are one per
/// rooted tree u of order n/2 (the edge joining the halves is the tree's central edge, which is
/// unique, so u and the free tree determine each other): A000081(n/2) of them; automorphism
/// counts of paths (2) and stars ((n-1)!). The modified Hamiltonian of the implicit midpoint
/// rule to h^2, derived by hand from its printed modified equation (Hairer, Lubich, Wanner,
/// Geometric Numerical Integration, 2nd ed. 2006 (HLW), section IX.1)
///   f~ = f + h^2 (1/12 f'f'f - 1/24 f''(f,f)) + O(h^4),   f = J^{-1} grad H:
/// grad (H''(f,f)) = H'''(f,f) + 2 f'^T H'' f and f'^T = -H'' J^{-1}, so
/// J^{-1} grad (H''(f,f)) = f''(f,f) - 2 f'f'f, and f~ = J^{-1} grad H~ with
///   H~ = H - h^2/24 H''(f,f) + O(h^4)   (H''(f,f) = H([tau,tau]) = -H([[tau]])).
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "bseries_methods.hpp"
#include "catch.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/modified_hamiltonian.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/symplectic_conditions.hpp"
#include "geomint/methods/composition.hpp"
#include "geomint/methods/number_field.hpp"
#include "geomint/analysis/bseries/series.hpp"

// Own namespace: the suites of tests/analysis are compiled as one unity unit.
namespace bseries_modified_hamiltonian_test {

using namespace bseries_test_methods;
using namespace geomint::analysis::bseries;
using geomint::methods::field_element;

TEST_CASE("bseries modified Hamiltonian: free trees per order (OEIS A000055), superfluous ones, automorphisms", "[bseries]") {
  const tree_set trees(10, 1);
  const auto classes = free_trees(trees);
  const std::vector<int> free_count = {1, 1, 1, 2, 3, 6, 11, 23, 47, 106};
  const std::vector<int> rooted_count = {1, 1, 2, 4, 9};  // A000081, n = 1..5
  std::vector<int> found(11, 0), superfluous(11, 0), rooted_members(11, 0);
  for (const free_tree& theta : classes) {
    ++found[static_cast<std::size_t>(theta.order)];
    superfluous[static_cast<std::size_t>(theta.order)] += theta.superfluous;
    rooted_members[static_cast<std::size_t>(theta.order)] += static_cast<int>(theta.rooted.size());
    // n = sum over rooted trees of sigma(theta)/sigma(t), exactly.
    std::int64_t vertices_times_lcm = 0, lcm = 1;
    for (int t : theta.rooted) lcm = std::lcm(lcm, trees[t].sigma);
    for (int t : theta.rooted) vertices_times_lcm += theta.sigma * (lcm / trees[t].sigma);
    CHECK(vertices_times_lcm == theta.order * lcm);
  }
  for (int n = 1; n <= 10; ++n) {
    CHECK(found[static_cast<std::size_t>(n)] == free_count[static_cast<std::size_t>(n - 1)]);
    CHECK(superfluous[static_cast<std::size_t>(n)] == (n % 2 == 0 ? rooted_count[static_cast<std::size_t>(n / 2 - 1)] : 0));
    CHECK(rooted_members[static_cast<std::size_t>(n)] == trees.count(n));  // every rooted tree in one class
  }
  // Paths and stars.
  int path = trees.leaf(0), star_subtrees = 0;
  std::vector<int> leaves;
  std::int64_t factorial = 1;
  for (int n = 2; n <= 10; ++n) {
    path = trees.find(0, {path});
    leaves.push_back(trees.leaf(0));
    factorial *= ++star_subtrees;
    const int star = trees.find(0, leaves);
    for (const free_tree& theta : classes) {
      if (std::find(theta.rooted.begin(), theta.rooted.end(), path) != theta.rooted.end()) CHECK(theta.sigma == 2);
      if (n > 2 && std::find(theta.rooted.begin(), theta.rooted.end(), star) != theta.rooted.end()) CHECK(theta.sigma == factorial);
    }
  }
}

TEST_CASE("bseries modified Hamiltonian: implicit midpoint rule to h^2 (HLW IX.1)", "[bseries]") {
  const tree_set trees(7, 1);
  const auto terms = modified_hamiltonian(trees, modified_field(trees, elementary_weights(trees, implicit_midpoint())));
  const int tau = trees.leaf(0), cherry = trees.find(0, {tau, tau}), tall = trees.find(0, {trees.find(0, {tau})});
  REQUIRE(terms.size() >= 2);
  CHECK(terms[0].order == 1);
  CHECK(terms[0].tree == tau);
  CHECK(terms[0].coefficient == q(1));
  CHECK(terms[1].order == 3);
  // -1/24 H([tau,tau]) = +1/24 H([[tau]]).
  REQUIRE((terms[1].tree == cherry || terms[1].tree == tall));
  CHECK(terms[1].coefficient == (terms[1].tree == cherry ? q(-1, 24) : q(1, 24)));
  // Symmetric method: only even powers of h (HLW section IX.2), so only odd orders.
  for (const auto& term : terms) CHECK(term.order % 2 == 1);
  for (std::size_t i = 2; i < terms.size(); ++i) CHECK(terms[i].order >= 5);
}

TEST_CASE("bseries modified Hamiltonian: exists for a symplectic method, refused for explicit Euler", "[bseries]") {
  const tree_set trees(7, 1);
  // Two midpoint steps of sizes h/3 and 2h/3 (symplectic, HLW section VI.4; see
  // test_bseries_symplectic_conditions.cpp): an h^3 term (order 4) appears.
  const tableau composed = composed_midpoint();
  const auto b = modified_field(trees, elementary_weights(trees, composed));
  const auto terms = modified_hamiltonian(trees, b);
  // The h^3 term by hand: the order-4 free trees are the path (superfluous, [tau] o [tau]) and
  // the star, rooted as [tau,tau,tau] (sigma 6) or [[tau,tau]] (sigma 2). For H~ = ... +
  // h^3 c H'''(f,f,f): grad (H'''(f,f,f)) = H''''(f,f,f) + 3 f'^T H'''(f,f), f'^T = -H'' J^{-1},
  // so J^{-1} grad = f'''(f,f,f) - 3 f'f''(f,f): the field's coefficients are
  // b([tau,tau,tau])/6 = c and b([[tau,tau]])/2 = -3c.
  const int tau = trees.leaf(0);
  const int star_at_centre = trees.find(0, {tau, tau, tau}), star_at_leaf = trees.find(0, {trees.find(0, {tau, tau})});
  const Q c = b[static_cast<std::size_t>(star_at_centre)] / 6;
  CHECK(c != q(0));
  CHECK(b[static_cast<std::size_t>(star_at_leaf)] / 2 == -3 * c);
  int order_four = 0;
  for (const auto& term : terms) {
    if (term.order != 4) continue;
    ++order_four;
    REQUIRE((term.tree == star_at_centre || term.tree == star_at_leaf));
    // H([[tau,tau]]) = H'(f''(f,f)) = -H'''(f,f,f) (f = J^{-1} grad H, J^{-1} skew).
    CHECK(term.coefficient == (term.tree == star_at_centre ? c : -c));
  }
  CHECK(order_four == 1);
  CHECK_THROWS_AS(modified_hamiltonian(trees, modified_field(trees, elementary_weights(trees, explicit_euler()))), std::domain_error);
  CHECK_THROWS_AS(modified_hamiltonian(trees, std::vector<Q>(3)), std::invalid_argument);
  const tree_set two(3, 2);
  CHECK_THROWS_AS(hamiltonian_trees(trees, hamiltonian_class::separable, 0), std::invalid_argument);
  CHECK_THROWS_AS(hamiltonian_trees(two, hamiltonian_class::separable, 2), std::invalid_argument);
}


// ---- Two colours: P-series of partitioned methods, RKN methods through their partitioned form.

/// A polynomial in (p, q) with exact coefficients: exponents (of p, of q) -> coefficient. The
/// independent evaluation of elementary differentials and Hamiltonians for one degree of
/// freedom, by differentiating a polynomial H.
using poly = std::map<std::pair<int, int>, Q>;

poly plus(poly a, const poly& b, const Q& scale = Q(1)) {
  for (const auto& [e, c] : b) {
    a[e] += scale * c;
    if (a[e] == 0) a.erase(e);
  }
  return a;
}
poly times(const poly& a, const poly& b) {
  poly out;
  for (const auto& [ea, ca] : a)
    for (const auto& [eb, cb] : b) out[{ea.first + eb.first, ea.second + eb.second}] += ca * cb;
  for (auto it = out.begin(); it != out.end();) it = it->second == 0 ? out.erase(it) : std::next(it);
  return out;
}
/// d/dp (in_p) or d/dq.
poly derivative(const poly& a, bool in_p) {
  poly out;
  for (const auto& [e, c] : a) {
    const int k = in_p ? e.first : e.second;
    if (k > 0) out[{e.first - (in_p ? 1 : 0), e.second - (in_p ? 0 : 1)}] += c * k;
  }
  return out;
}
poly monomial(int i, int j, const Q& c) { return poly{{{i, j}, c}}; }

/// F(t) and H(t) of every tree for p' = -H_q (colour p_colour), q' = H_p: a vertex is its
/// function (-H_q, H_p, or H at the root of H(t)) differentiated in p for each child of the
/// p-colour and in q for each other child, times the children's F (one degree of freedom:
/// the multilinear forms are products).
struct elementary {
  std::vector<poly> F, H;
  elementary(const tree_set& trees, const poly& hamiltonian, int p_colour) {
    const poly f_p = plus(poly{}, derivative(hamiltonian, false), Q(-1)), g_q = derivative(hamiltonian, true);
    for (int t = 0; t < trees.size(); ++t) {
      poly at_root = trees[t].colour == p_colour ? f_p : g_q, h = hamiltonian, product = monomial(0, 0, 1);
      for (int u : trees[t].subtrees) {
        at_root = derivative(at_root, trees[u].colour == p_colour);
        h = derivative(h, trees[u].colour == p_colour);
        product = times(product, F[static_cast<std::size_t>(u)]);
      }
      F.push_back(times(at_root, product));
      H.push_back(times(h, product));
    }
  }
};

/// The h^(n-1) part of H~ from the terms.
poly modified_hamiltonian_part(const std::vector<hamiltonian_term<Q>>& terms, const elementary& e, int n) {
  poly out;
  for (const auto& term : terms)
    if (term.order == n) out = plus(out, e.H[static_cast<std::size_t>(term.tree)], term.coefficient);
  return out;
}

/// Checks, order by order, that the Hamiltonian vector field of H~ (p' = -dH~/dq, q' = dH~/dp)
/// is the modified field sum b(t)/sigma(t) F(t) over the marked trees, and that F(t) vanishes
/// on the unmarked ones. Returns the number of non-zero orders compared.
int check_hamiltonian_field(const tree_set& trees, const std::vector<Q>& b, const std::vector<bool>* marked,
                            const poly& hamiltonian, int p_colour) {
  const elementary e(trees, hamiltonian, p_colour);
  const auto terms = modified_hamiltonian(trees, b, marked);
  int compared = 0;
  for (int n = 1; n <= trees.max_order(); ++n) {
    const poly h = modified_hamiltonian_part(terms, e, n);
    poly field[2];
    for (int t = trees.first(n); t < trees.first(n + 1); ++t) {
      const auto k = static_cast<std::size_t>(t);
      if (marked && !(*marked)[k]) {
        CHECK(e.F[k].empty());
        continue;
      }
      field[trees[t].colour] = plus(field[trees[t].colour], e.F[k], b[k] / Q(trees[t].sigma));
    }
    INFO("order " << n);
    CHECK(field[p_colour] == plus(poly{}, derivative(h, false), Q(-1)));
    CHECK(field[1 - p_colour] == derivative(h, true));
    compared += !h.empty();
  }
  return compared;
}

/// T = p^2/2 + p^3/3 + p^6/6, V = q^2/2 + q^3/3 + q^6/6: every derivative up to the fifth is a
/// non-zero polynomial, so (one degree of freedom: H(t) is a product of derivatives) every
/// elementary Hamiltonian of a tree of order <= 6 that is not identically zero on separable H
/// is non-zero here.
poly separable_hamiltonian() {
  poly h;
  for (int k : {2, 3, 6}) h = plus(plus(h, monomial(k, 0, q(1, k))), monomial(0, k, q(1, k)));
  return h;
}

tableau implicit_euler() { return rk({q(1)}, {{q(1)}}, {q(1)}); }
/// Stormer-Verlet, kick-drift-kick (p in half steps): Lobatto IIIB on p, IIIA on q (HLW
/// section II.2.2). With p on colour 0 (the convention of symplectic_conditions.hpp).
tableau velocity_verlet() { return pair_of(lobatto_iiib_2(), lobatto_iiia_2()); }
/// Drift-kick-drift (q in half steps): Lobatto IIIA on p, IIIB on q.
tableau position_verlet() { return pair_of(lobatto_iiia_2(), lobatto_iiib_2()); }
TEST_CASE("bseries modified Hamiltonian: free trees counted against labelled trees (Cayley), two colours against oriented trees (OEIS A000238)", "[bseries]") {
  // Labelled counts: sum over free trees of n!/sigma(theta) is the number of labelled trees,
  // n^(n-2) (Cayley), and for two colours (each edge oriented p-end/q-end) 2^(n-1) n^(n-2).
  // Unlabelled oriented trees per n (OEIS A000238): 1, 1, 3, 8, 27, 91, 350.
  for (int colours = 1; colours <= 2; ++colours) {
    const tree_set trees(7, colours);
    const auto classes = free_trees(trees);
    std::vector<Q> labelled(8, Q(0));
    std::vector<int> count(8, 0), superfluous(8, 0);
    for (const free_tree& theta : classes) {
      Q factorial(1);
      for (int k = 2; k <= theta.order; ++k) factorial *= k;
      labelled[static_cast<std::size_t>(theta.order)] += factorial / Q(theta.sigma);
      ++count[static_cast<std::size_t>(theta.order)];
      superfluous[static_cast<std::size_t>(theta.order)] += theta.superfluous;
      REQUIRE(theta.sign.size() == theta.rooted.size());
    }
    const std::vector<int> oriented = {1, 1, 3, 8, 27, 91, 350};
    for (int n = 2; n <= 7; ++n) {
      INFO("colours " << colours << ", order " << n);
      Q cayley(1);
      for (int k = 0; k < n - 2; ++k) cayley *= n;
      for (int k = 0; k < n - 1 && colours == 2; ++k) cayley *= 2;
      CHECK(labelled[static_cast<std::size_t>(n)] == cayley);
      if (colours == 2) {
        CHECK(count[static_cast<std::size_t>(n)] == oriented[static_cast<std::size_t>(n - 1)]);
        CHECK(superfluous[static_cast<std::size_t>(n)] == 0);
      }
    }
  }
}

TEST_CASE("bseries modified Hamiltonian: its Hamiltonian field is the modified field of symplectic pairs (one degree of freedom, non-separable H)", "[bseries]") {
  // H = (p^2 + q^2)/2 + p q^2 + p^3 q/3 + q^4/4: every mixed derivative up to the fourth.
  const poly hamiltonian = plus(plus(plus(plus(monomial(2, 0, q(1, 2)), monomial(0, 2, q(1, 2))), monomial(1, 2, q(1))),
                                     monomial(3, 1, q(1, 3))),
                                monomial(0, 4, q(1, 4)));
  const tree_set trees(6, 2);
  const std::vector<tableau> symplectic = {velocity_verlet(), position_verlet(), pair_of(lobatto_iiib_3(), lobatto_iiia_3()),
                                           pair_of(implicit_euler(), explicit_euler()), pair_of(composed_midpoint(), composed_midpoint())};
  for (const tableau& method : symplectic) {
    const auto b = modified_field_of(trees, method);
    // The existence condition agrees with the pairwise symplecticity conditions.
    CHECK(check_modified_hamiltonian_exists(trees, free_trees(trees), b).holds);
    CHECK(check_symplecticity_conditions(trees, b).holds);
    CHECK(check_hamiltonian_field(trees, b, nullptr, hamiltonian, 0) >= 2);
  }
  for (const tableau& method : {pair_of(explicit_euler(), explicit_euler()), pair_of(lobatto_iiia_3(), lobatto_iiia_3())}) {
    const auto b = modified_field_of(trees, method);
    CHECK_FALSE(check_modified_hamiltonian_exists(trees, free_trees(trees), b).holds);
    CHECK_FALSE(check_symplecticity_conditions(trees, b).holds);
    CHECK_THROWS_AS(modified_hamiltonian(trees, b), std::domain_error);
  }
}

TEST_CASE("bseries modified Hamiltonian: separable and natural H need fewer trees; RKN methods through their partitioned form", "[bseries]") {
  const tree_set trees(6, 2);
  // Separable (p colour 0, q colour 1).
  const poly separable = separable_hamiltonian();
  const auto alternating = hamiltonian_trees(trees, hamiltonian_class::separable, 1);
  CHECK(check_hamiltonian_field(trees, modified_field_of(trees, velocity_verlet()), &alternating, separable, 0) >= 2);
  // Natural, in the colours of an RKN's partitioned form (q colour 0, v = p colour 1): H =
  // p^2/2 + q^2/2 + q^4/4 + q^5/5. The marked trees are the Nystrom trees.
  const poly natural = plus(plus(plus(monomial(2, 0, q(1, 2)), monomial(0, 2, q(1, 2))), monomial(0, 4, q(1, 4))), monomial(0, 5, q(1, 5)));
  const auto nystrom = hamiltonian_trees(trees, hamiltonian_class::natural, 0);
  for (int t = 0; t < trees.size(); ++t) CHECK(nystrom[static_cast<std::size_t>(t)] == is_nystrom_tree(trees, t, true));
  const auto verlet = geomint::methods::nystrom_form_of(verlet_rkn());
  // Stormer-Verlet, and two Verlet steps of sizes h/3 and 2h/3 (symplectic, not symmetric).
  for (const auto& form : {verlet, geomint::methods::compose(verlet, {q(1, 3), q(2, 3)})}) {
    const auto b = modified_field_of(trees, partitioned_form_of(form));
    // On all trees the conversion's coefficients are not Hamiltonian; on the Nystrom trees they are.
    CHECK_FALSE(check_modified_hamiltonian_exists(trees, free_trees(trees), b).holds);
    CHECK(check_hamiltonian_field(trees, b, &nystrom, natural, 1) >= 3);
  }
  // A non-symplectic RKN (bbar_i != b_i (1 - c_i), HLW Theorem VI.4.10): explicit Euler on v,
  // q1 = q + h v + h^2/2 F(q): c = 0, A = 0, bbar = 1/2, b = 1: the h term of its modified
  // field is not Hamiltonian on natural H.
  tableau euler_rkn = verlet_rkn();
  euler_rkn.stages = 1;
  euler_rkn.c = {q(0)};
  euler_rkn.a = {{q(0)}};
  euler_rkn.bbar = {q(1, 2)};
  euler_rkn.b = {q(1)};
  const auto b_euler = modified_field_of(trees, partitioned_form_of(euler_rkn));
  const hamiltonian_existence refused = check_modified_hamiltonian_exists(trees, free_trees(trees), b_euler, &nystrom);
  CHECK_FALSE(refused.holds);
  CHECK(refused.failing_order == 2);
  CHECK_THROWS_AS(modified_hamiltonian(trees, b_euler, &nystrom), std::domain_error);
  // The free trees whose elementary Hamiltonians vanish for the class are those with no marked
  // rooted tree; the others have a non-zero one for these H.
  const elementary e_separable(trees, separable, 0), e_natural(trees, natural, 1);
  const auto separable_marks = hamiltonian_trees(trees, hamiltonian_class::separable, 0);
  const auto classes = free_trees(trees);
  const auto kept_separable = nonvanishing_free_trees(classes, separable_marks), kept_natural = nonvanishing_free_trees(classes, nystrom);
  for (std::size_t k = 0; k < classes.size(); ++k) {
    CHECK(e_separable.H[static_cast<std::size_t>(classes[k].representative)].empty() == !kept_separable[k]);
    CHECK(e_natural.H[static_cast<std::size_t>(classes[k].representative)].empty() == !kept_natural[k]);
  }
  // 131 oriented trees up to order 6 (A000238); fewer for separable H, fewer again for natural H.
  CHECK(std::count(kept_natural.begin(), kept_natural.end(), true) < std::count(kept_separable.begin(), kept_separable.end(), true));
  CHECK(std::count(kept_separable.begin(), kept_separable.end(), true) < static_cast<std::ptrdiff_t>(classes.size()));
  // The same function H~ of (p, q) from Stormer-Verlet as an RKN tableau (its Nystrom trees, p
  // on colour 1) and as the kick-drift-kick pair (every tree, p on colour 0), to h^4.
  const auto as_rkn = modified_hamiltonian_of(verlet_rkn(), 6);
  CHECK(as_rkn.p_colour == 1);
  const tree_set all(6, 2);
  const auto as_pair = modified_hamiltonian(all, modified_field_of(all, velocity_verlet()));
  const elementary e_pair(all, natural, 0);
  for (int n = 1; n <= 6; ++n) CHECK(modified_hamiltonian_part(as_rkn.terms, e_natural, n) == modified_hamiltonian_part(as_pair, e_pair, n));
}

TEST_CASE("bseries modified Hamiltonian: Stormer-Verlet and symplectic Euler to h^2", "[bseries]") {
  // Symmetric BCH formula (HLW section III.4.2): log(exp(A/2) exp(B) exp(A/2)) = A + B
  // - 1/24 [A,[A,B]] + 1/12 [B,[B,A]] + ..., with the Poisson brackets of the split flows
  // ({V,{V,T}} = T_pp(V_q,V_q), {T,{T,V}} = V_qq(T_p,T_p) for either sign convention of the
  // bracket, one degree of freedom). Kick-drift-kick (A = V in half steps):
  //   H~ = H + h^2 (-1/24 H_pp(H_q,H_q) + 1/12 H_qq(H_p,H_p)) + O(h^4);
  // drift-kick-drift: the two coefficients exchanged. (Check on the harmonic oscillator:
  // kick-drift-kick conserves p^2 + (1 - h^2/4) q^2 exactly, and the ratio of the q^2 to the
  // p^2 coefficient of H~, (1 - h^2/12)/(1 + h^2/6), is 1 - h^2/4 + O(h^4).)
  const poly separable = separable_hamiltonian();
  const tree_set trees(4, 2);
  const elementary e(trees, separable, 0);
  const poly h_p = derivative(separable, true), h_q = derivative(separable, false);
  const poly pp_qq = times(derivative(derivative(separable, true), true), times(h_q, h_q));
  const poly qq_pp = times(derivative(derivative(separable, false), false), times(h_p, h_p));
  const auto alternating = hamiltonian_trees(trees, hamiltonian_class::separable, 1);
  for (const bool kick_first : {true, false}) {
    const auto terms = modified_hamiltonian(trees, modified_field_of(trees, kick_first ? velocity_verlet() : position_verlet()), &alternating);
    CHECK(modified_hamiltonian_part(terms, e, 1) == separable);
    CHECK(modified_hamiltonian_part(terms, e, 2).empty());
    CHECK(modified_hamiltonian_part(terms, e, 3) == plus(plus(poly{}, pp_qq, kick_first ? q(-1, 24) : q(1, 12)), qq_pp, kick_first ? q(1, 12) : q(-1, 24)));
    CHECK(modified_hamiltonian_part(terms, e, 4).empty());
  }
  // Symplectic Euler p_{n+1} = p_n - h H_q(p_{n+1}, q_n), q_{n+1} = q_n + h H_p(p_{n+1}, q_n)
  // (implicit Euler on p, explicit on q), non-separable H: HLW section IX.3.1 (example of the
  // symplectic Euler method) prints
  //   H~ = H - h/2 H_p H_q + h^2/12 (H_pp H_q^2 + H_qq H_p^2 + 4 H_pq H_p H_q) + O(h^3).
  const poly general = plus(plus(plus(plus(monomial(2, 0, q(1, 2)), monomial(0, 2, q(1, 2))), monomial(1, 2, q(1))),
                                 monomial(3, 1, q(1, 3))),
                            monomial(0, 4, q(1, 4)));
  const tree_set all(3, 2);
  const elementary g(all, general, 0);
  const auto terms = modified_hamiltonian(all, modified_field_of(all, pair_of(implicit_euler(), explicit_euler())));
  const poly gp = derivative(general, true), gq = derivative(general, false);
  CHECK(modified_hamiltonian_part(terms, g, 2) == plus(poly{}, times(gp, gq), q(-1, 2)));
  const poly h2 = plus(plus(times(derivative(gp, true), times(gq, gq)), times(derivative(gq, false), times(gp, gp))),
                       times(derivative(gp, false), times(gp, gq)), Q(4));
  CHECK(modified_hamiltonian_part(terms, g, 3) == plus(poly{}, h2, q(1, 12)));
}

/// Truncated power series in h with exact coefficients (the first N).
using series = std::vector<Q>;
series mul(const series& a, const series& b) {
  series c(a.size(), Q(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; i + j < a.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}
/// sum_k w_k x^k for a series x without constant term.
series compose_with(const std::vector<Q>& w, const series& x) {
  series out(x.size(), Q(0)), power(x.size(), Q(0));
  power[0] = 1;
  for (const Q& wk : w) {
    for (std::size_t i = 0; i < x.size(); ++i) out[i] += wk * power[i];
    power = mul(power, x);
  }
  return out;
}

TEST_CASE("bseries modified Hamiltonian: harmonic oscillator against the closed form from the step matrix", "[bseries]") {
  // H = (p^2 + q^2)/2. A linear symplectic step y -> M y with |tr M| < 2 is exp(h J^{-1} S):
  // M = cos(theta) I + sin(theta) K, K^2 = -I, cos(theta) = tr M / 2, h J^{-1} S = theta K,
  // and H~ = y^T S y / 2 exactly.
  // Gauss s = 2 (an RK method): M is the rotation by theta = arg R(ih)/..., R(z) = P(z)/P(-z),
  // P(z) = 1 + z/2 + z^2/12 (HLW section VI.4 / Hairer-Wanner II section IV.3), so
  // theta = 2 atan((h/2)/(1 - h^2/12)) and H~ = (theta/h) H.
  // Kick-drift-kick Verlet on (q, p): M = [[1 - h^2/2, h], [-h + h^3/4, 1 - h^2/2]],
  // theta = 2 asin(h/2), K = [[0, 1/s], [-s, 0]] with s = sqrt(1 - h^2/4), so
  // H~ = theta/(h s) p^2/2 + theta s/h q^2/2.
  constexpr int N = 8;  // h^0 .. h^7: orders 1..8
  series x(N, Q(0)), h_squared(N, Q(0));
  h_squared[2] = 1;
  {  // (h/2)/(1 - h^2/12) = h/2 sum (h^2/12)^k
    Q c = q(1, 2);
    for (int k = 1; k < N; k += 2, c /= 12) x[static_cast<std::size_t>(k)] = c;
  }
  std::vector<Q> atan_w(N, Q(0)), asin_w(N, Q(0)), sqrt_w(N, Q(0));
  Q central(1);  // binomial(2k, k) / 4^k
  for (int k = 0; 2 * k + 1 < N; ++k) {
    atan_w[static_cast<std::size_t>(2 * k + 1)] = Q(k % 2 == 0 ? 1 : -1) / (2 * k + 1);
    asin_w[static_cast<std::size_t>(2 * k + 1)] = central / (2 * k + 1);
    central *= Q((2 * k + 1) * (2 * k + 2)) / Q(4 * (k + 1) * (k + 1));
  }
  Q binomial(1);  // binomial(1/2, k) (-1)^k: sqrt(1 - u) = sum sqrt_w[k] u^k
  for (int k = 0; k < N; ++k) {
    sqrt_w[static_cast<std::size_t>(k)] = binomial;
    binomial *= (q(1, 2) - k) * Q(-1) / Q(k + 1);
  }
  series half_h(N, Q(0));
  half_h[1] = q(1, 2);
  const series gauss_theta = compose_with(atan_w, x);          // theta/2
  const series verlet_theta = compose_with(asin_w, half_h);    // theta/2
  series quarter_h2 = h_squared;
  for (auto& c : quarter_h2) c /= 4;
  const series s = compose_with(sqrt_w, quarter_h2);
  series s_inverse(N, Q(0));  // 1/s = sum over k of binomial(-1/2, k) (-u)^k
  {
    Q c(1);
    series power(N, Q(0));
    power[0] = 1;
    for (int k = 0; k < N; ++k, c *= (q(-1, 2) - (k - 1)) * Q(-1) / Q(k)) {
      if (k == 0) c = 1;
      for (int i = 0; i < N; ++i) s_inverse[static_cast<std::size_t>(i)] += c * power[static_cast<std::size_t>(i)];
      power = mul(power, quarter_h2);
    }
  }
  REQUIRE(mul(s, s_inverse)[0] == 1);
  for (int i = 1; i < N; ++i) REQUIRE(mul(s, s_inverse)[static_cast<std::size_t>(i)] == 0);
  // theta/h: drop the h of 2 (theta/2).
  const auto over_h = [&](const series& half_theta) {
    series out(N, Q(0));
    for (int i = 1; i < N; ++i) out[static_cast<std::size_t>(i - 1)] = 2 * half_theta[static_cast<std::size_t>(i)];
    return out;
  };
  const series alpha = mul(over_h(verlet_theta), s_inverse), beta = mul(over_h(verlet_theta), s), gauss = over_h(gauss_theta);

  const tree_set trees(N - 1, 2);
  const poly oscillator = plus(monomial(2, 0, q(1, 2)), monomial(0, 2, q(1, 2)));
  const elementary e(trees, oscillator, 0);
  field_element::field_ptr sqrt3 = geomint::methods::algebraic_field::make({-3, 0, 1});
  const field_element r = field_element::generator(sqrt3), one(1), two(2), four(4), six(6);
  geomint::methods::tableau_data<field_element> gauss2;
  gauss2.kind = geomint::methods::method_kind::rk;
  gauss2.stages = 2;
  gauss2.c = {one / two - r / six, one / two + r / six};
  gauss2.a = {{one / four, one / four - r / six}, {one / four + r / six, one / four}};
  gauss2.b = {one / two, one / two};
  const auto b_field = modified_field(trees, elementary_weights(trees, pair_of(gauss2, gauss2)));
  std::vector<Q> b_gauss;
  for (const field_element& x_t : b_field) {
    REQUIRE(x_t.is_rational());  // Gauss's series is invariant under sqrt 3 -> -sqrt 3
    b_gauss.push_back(x_t.rational_value());
  }
  const auto gauss_terms = modified_hamiltonian(trees, b_gauss);
  const auto verlet_terms = modified_hamiltonian(trees, modified_field_of(trees, velocity_verlet()));
  for (int n = 1; n < N; ++n) {
    INFO("order " << n);
    const auto k = static_cast<std::size_t>(n - 1);
    CHECK(modified_hamiltonian_part(gauss_terms, e, n) == plus(poly{}, oscillator, gauss[k]));
    CHECK(modified_hamiltonian_part(verlet_terms, e, n) ==
          plus(plus(poly{}, monomial(2, 0, q(1, 2)), alpha[k]), monomial(0, 2, q(1, 2)), beta[k]));
  }
  // The published leading terms: Gauss s = 2 is of order 4, so its first correction is at h^4.
  CHECK(gauss[1] == 0);
  CHECK(gauss[2] == 0);
  CHECK(gauss[4] != 0);
}


/// The pendulum H = p^2/2 - cos q (one degree of freedom): the partial derivatives of H in
/// closed form (mixed ones vanish; p: p, 1, 0, ...; q: sin, cos, -sin, -cos, ...), and from them
/// F(t) and H(t) as in `elementary` (p on colour 0).
template <class R>
struct pendulum {
  R p, q;
  R partial(int in_p, int in_q) const {
    if (in_p > 0 && in_q > 0) return R(0);
    if (in_p > 0) return in_p == 1 ? p : (in_p == 2 ? R(1) : R(0));
    if (in_q == 0) return p * p / 2 - cos(q);
    switch (in_q % 4) {
      case 1: return sin(q);
      case 2: return cos(q);
      case 3: return -sin(q);
      default: return -cos(q);
    }
  }
  /// H(t) (at_root: the Hamiltonian itself) or F(t) (f = -H_q on colour 0, g = H_p on colour 1).
  R value(const tree_set& trees, int t, bool at_root) const {
    int in_p = 0, in_q = 0;
    R product(1);
    for (int u : trees[t].subtrees) {
      (trees[u].colour == 0 ? in_p : in_q) += 1;
      product *= value(trees, u, false);
    }
    if (at_root) return partial(in_p, in_q) * product;
    return trees[t].colour == 0 ? -partial(in_p, in_q + 1) * product : partial(in_p + 1, in_q) * product;
  }
};

TEST_CASE("bseries modified Hamiltonian: Stormer-Verlet on the pendulum conserves H~ to O(h^4) and O(h^6) (50 digits, measured slopes)", "[bseries]") {
  // Kick-drift-kick Verlet integrated in 50 digits over t in [0, 1] from (p, q) = (1/2, 1);
  // max_n |H~(y_n) - H~(y_0)| with H~ truncated after its h^(2k) terms is O(h^(2k+2)): the
  // truncation leaves O(h^(2k+3)) per step (HLW section IX.8), the terms of H~ being the ones
  // computed here.
  using R = boost::multiprecision::cpp_bin_float_50;
  const tree_set trees(5, 2);
  const auto alternating = hamiltonian_trees(trees, hamiltonian_class::separable, 1);
  const auto terms = modified_hamiltonian(trees, modified_field_of(trees, velocity_verlet()), &alternating);
  const auto modified = [&](const R& p, const R& q, const R& h, int max_order) {
    const pendulum<R> at{p, q};
    R sum(0);
    for (const auto& term : terms)
      if (term.order <= max_order) sum += pow(h, term.order - 1) * R(term.coefficient) * at.value(trees, term.tree, true);
    return sum;
  };
  std::vector<R> drift[3];  // H, H~ to h^2, H~ to h^4
  for (int steps : {20, 40, 80, 160}) {
    const R h = R(1) / steps;
    R p = R(1) / 2, q = R(1), worst[3] = {R(0), R(0), R(0)}, start[3];
    for (int k = 0; k < 3; ++k) start[k] = modified(p, q, h, 1 + 2 * k);
    for (int n = 0; n < steps; ++n) {
      p -= h / 2 * sin(q);
      q += h * p;
      p -= h / 2 * sin(q);
      for (int k = 0; k < 3; ++k) worst[k] = std::max(worst[k], R(abs(modified(p, q, h, 1 + 2 * k) - start[k])));
    }
    for (int k = 0; k < 3; ++k) drift[k].push_back(worst[k]);
  }
  for (int k = 0; k < 3; ++k)
    for (std::size_t i = 1; i < drift[k].size(); ++i) {
      const double slope = static_cast<double>(log2(drift[k][i - 1] / drift[k][i]));
      INFO("truncated after h^" << 2 * k << ", halving " << i << ": slope " << slope);
      CHECK(std::abs(slope - (2 * k + 2)) < 0.1);
    }
}

}  // namespace bseries_modified_hamiltonian_test
