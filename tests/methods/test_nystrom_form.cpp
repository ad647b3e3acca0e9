/// Tableaux as data (methods/tableau.hpp, methods/nystrom_form.hpp): compile-time tableaux over
/// geomint::rational, and the exact Nystrom forms of each kind and of a composition.
#include "catch.hpp"
#include "geomint/core/rational.hpp"
#include "geomint/methods/nystrom_form.hpp"

using namespace geomint;
using R = rational;

namespace {
constexpr auto verlet_rkn = methods::make_rkn<R>({0, 1}, {{0, 0}, {R(1, 2), 0}}, {R(1, 2), 0}, {R(1, 2), R(1, 2)});
// Structural: a tableau over geomint::rational is a template argument.
template <auto Tableau>
struct method_constant {
  static constexpr int stages = Tableau.stages;
};
static_assert(method_constant<verlet_rkn>::stages == 2);
static_assert(methods::strictly_lower<R, 2>(verlet_rkn.a));
static_assert(verlet_rkn.bbar[0] == R(1, 2) && verlet_rkn.b[1] == R(1, 2));
// The 2-stage Lobatto IIIA-IIIB pair, Stormer-Verlet as a PRK method (Hairer, Lubich & Wanner
// 2006, section II.2.2): A = [[0, 0], [1/2, 1/2]], Ahat = [[1/2, 0], [1/2, 0]], b = bhat = (1/2, 1/2).
constexpr auto verlet_prk = methods::make_prk<R>({0, 1}, {{0, 0}, {R(1, 2), R(1, 2)}}, {R(1, 2), R(1, 2)},
                                                 {{R(1, 2), 0}, {R(1, 2), 0}}, {R(1, 2), R(1, 2)});
static_assert(!methods::strictly_lower<R, 2>(verlet_prk.a));
}  // namespace

TEST_CASE("nystrom form: the Lobatto IIIA-IIIB pair is the Stormer-Verlet RKN method on q'' = f(q)", "[methods]") {
  // A Ahat = [[0, 0], [1/2, 0]], b^T Ahat = (1/2, 0), bhat = (1/2, 1/2), c = row sums of A = (0, 1).
  const auto from_prk = methods::nystrom_form_of(verlet_prk);
  const auto from_rkn = methods::nystrom_form_of(verlet_rkn);
  CHECK(from_prk.a == from_rkn.a);
  CHECK(from_prk.bbar == from_rkn.bbar);
  CHECK(from_prk.b == from_rkn.b);
  CHECK(from_prk.c == from_rkn.c);
  CHECK(from_prk.d == R(1));
  CHECK(from_prk.explicit_positions);
  CHECK(from_prk.natural_only);
}

TEST_CASE("nystrom form: two half steps of Stormer-Verlet are the 4-stage method of the composition", "[methods]") {
  // Steps h/2, h/2: stages at 0, 1/2, 1/2, 1; the second half step starts from
  // q_1 = q + (h/2) v + (h/2)^2/2 F_1, v_1 = v + (h/4)(F_1 + F_2), so its stage 1 is
  // Q = q_1: a = (1/8, 0, 0, 0); its stage 2 is q_1 + (h/2) v_1 + (h/2)^2/2 F_3:
  // a = (1/8 + 1/8, 1/8, 1/8, 0) = (1/4, 1/8, 1/8, 0); bbar = a of the last row; b = (1/4, 1/4, 1/4, 1/4).
  methods::composition<decltype(verlet_rkn), 2> halves{verlet_rkn, {R(1, 2), R(1, 2)}};
  const auto f = methods::nystrom_form_of(halves);
  CHECK(f.stages == 4);
  CHECK(f.c == std::vector<R>{0, R(1, 2), R(1, 2), 1});
  CHECK(f.a[2] == std::vector<R>{R(1, 8), 0, 0, 0});
  CHECK(f.a[3] == std::vector<R>{R(1, 4), R(1, 8), R(1, 8), 0});
  CHECK(f.bbar == std::vector<R>{R(1, 4), R(1, 8), R(1, 8), 0});
  CHECK(f.b == std::vector<R>{R(1, 4), R(1, 4), R(1, 4), R(1, 4)});
  CHECK(f.d == R(1));
  CHECK(f.explicit_positions);
}
