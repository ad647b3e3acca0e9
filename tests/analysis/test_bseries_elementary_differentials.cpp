/// Elementary differentials by automatic differentiation (analysis/bseries/
/// elementary_differentials.hpp) against closed-form derivatives, for every one- and two-colour
/// tree up to order 5; the P-series of the schemes' exact RKN tableaux (rkn_series.hpp) against
/// the partitioned form of the same methods read from tableau files.
///
/// Closed forms (exact mathematics): the pendulum f(q, p) = (p, -sin q) has
/// d^m/dq^m (-sin q) = -sin(q + m pi/2) and no other nonzero derivative but d/dp of p; the
/// harmonic oscillator f = (p, -q) is linear. So for a one-colour tree [t_1..t_m]:
///   q-part: F(t_1)_p if m = 1, else 0;  p-part: -sin(q + m pi/2) prod F(t_i)_q,
/// and for two colours (q colour 0, p colour 1) the same blocks, a colour-1 child of a p-vertex
/// or any child but one colour-1 child of a q-vertex giving 0.
///
/// The periodic Toda lattice of three particles (zoo::toda3, 3 dof), V = sum_j a_j with
/// a_j = exp(q_j - q_{j+1}) (indices mod 3): d a_j [u] = a_j (u_j - u_{j+1}), so
/// (grad V)_j = a_j - a_{j-1} and its m-th derivative along u_1..u_m is
///   a_j prod_i (u_i,j - u_i,j+1) - a_{j-1} prod_i (u_i,j-1 - u_i,j),
/// and f = (p, -grad V(q)) gives F(t) by the same block rules as the pendulum.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/bseries/elementary_differentials.hpp"
#include "geomint/analysis/bseries/rkn_series.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "geomint/methods/tableau_file.hpp"

namespace bseries_elementary_differentials_test {

using namespace geomint::analysis::bseries;
using geomint::vec;

/// d^m/dq^m sin(q) = sin(q + m pi/2).
template <class T>
T sin_derivative(int m, const T& q) {
  using std::cos;
  using std::sin;
  switch (m % 4) {
    case 0: return sin(q);
    case 1: return cos(q);
    case 2: return -sin(q);
    default: return -cos(q);
  }
}

/// The closed-form F(t) of the pendulum (linear = false) or the harmonic oscillator (true).
template <class T>
std::vector<vec<T, 2>> closed_form(const tree_set& trees, const vec<T, 2>& y, bool linear) {
  std::vector<vec<T, 2>> F(static_cast<std::size_t>(trees.size()));
  for (int t = 0; t < trees.size(); ++t) {
    const rooted_tree& tree = trees[t];
    const auto m = static_cast<int>(tree.subtrees.size());
    T q_part(0), p_part(0);
    if (m == 0) q_part = y[1];
    if (m == 1) q_part = F[static_cast<std::size_t>(tree.subtrees[0])][1];
    if (linear) {
      if (m == 0) p_part = -y[0];
      if (m == 1) p_part = -F[static_cast<std::size_t>(tree.subtrees[0])][0];
    } else {
      p_part = -sin_derivative(m, y[0]);
      for (int u : tree.subtrees) p_part *= F[static_cast<std::size_t>(u)][0];
    }
    if (trees.colours() == 2) {
      // A child's F lives in its own colour's block: a q-vertex sees only a single p-child, a
      // p-vertex only q-children (blocks of the wrong colour are zero).
      for (int u : tree.subtrees) {
        if (tree.colour == 1 && trees[u].colour == 1) p_part = T(0);
        if (tree.colour == 0 && trees[u].colour == 0) q_part = T(0);
      }
      if (tree.colour == 0) p_part = T(0);
      else q_part = T(0);
    }
    F[static_cast<std::size_t>(t)] = vec<T, 2>(q_part, p_part);
  }
  return F;
}

/// H = p^2/2 + 1 - cos q, as a functor for hamiltonian_field.
struct pendulum_hamiltonian {
  template <class S>
  S operator()(const vec<S, 2>& y) const {
    using std::cos;
    return y[1] * y[1] / S(2) + S(1) - cos(y[0]);
  }
};

template <class T, class Field>
void check_against_closed_form(const Field& field, bool linear, int colours) {
  const tree_set trees(5, colours);
  const vec<T, 2> y(T(7) / T(10), T(-13) / T(10));
  const auto ad = elementary_differentials(trees, field, y);
  const auto exact = closed_form<T>(trees, y, linear);
  const T tolerance = T(64) * std::numeric_limits<T>::epsilon();
  for (int t = 0; t < trees.size(); ++t) {
    INFO("tree " << t << " of order " << trees[t].order << ", colour " << trees[t].colour);
    using std::abs;
    const auto i = static_cast<std::size_t>(t);
    const T scale = T(1) + T(exact[i].template lpNorm<Eigen::Infinity>());
    CHECK(T((ad[i] - exact[i]).template lpNorm<Eigen::Infinity>()) <= tolerance * scale);
  }
}

/// The closed-form F(t) of the Toda lattice of three particles, y = (q, p).
template <class T>
std::vector<vec<T, 6>> toda_closed_form(const tree_set& trees, const vec<T, 6>& y) {
  using std::exp;
  const auto next = [](int j) { return (j + 1) % 3; };
  const auto previous = [](int j) { return (j + 2) % 3; };
  std::vector<vec<T, 6>> F(static_cast<std::size_t>(trees.size()));
  for (int t = 0; t < trees.size(); ++t) {
    const rooted_tree& tree = trees[t];
    const auto m = tree.subtrees.size();
    vec<T, 6> value = vec<T, 6>::Zero();
    for (int j = 0; j < 3; ++j) {
      if (m == 0) value[j] = y[3 + j];
      if (m == 1) value[j] = F[static_cast<std::size_t>(tree.subtrees[0])][3 + j];
      T ahead = exp(T(y[j] - y[next(j)])), behind = exp(T(y[previous(j)] - y[j]));
      for (int u : tree.subtrees) {
        const vec<T, 6>& Fu = F[static_cast<std::size_t>(u)];
        ahead *= Fu[j] - Fu[next(j)];
        behind *= Fu[previous(j)] - Fu[j];
      }
      value[3 + j] = behind - ahead;
    }
    if (trees.colours() == 2) {  // as closed_form: a q-vertex sees one p-child, a p-vertex q-children
      for (int u : tree.subtrees) {
        if (tree.colour == 1 && trees[u].colour == 1) value.tail(3).setZero();
        if (tree.colour == 0 && trees[u].colour == 0) value.head(3).setZero();
      }
      if (tree.colour == 0) value.tail(3).setZero();
      else value.head(3).setZero();
    }
    F[static_cast<std::size_t>(t)] = value;
  }
  return F;
}

TEMPLATE_TEST_CASE("elementary differentials of a 3-dof natural system (Toda) equal the closed form up to order 5",
                   "[bseries]", double, boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  vec<T, 6> y;
  y << T(3) / T(10), T(-1) / T(5), T(1) / T(2), T(7) / T(10), T(-13) / T(10), T(2) / T(5);
  for (int colours = 1; colours <= 2; ++colours) {
    INFO("colours " << colours);
    const tree_set trees(5, colours);
    const auto ad = elementary_differentials(trees, natural_field<geomint::zoo::toda3, T>{}, y);
    const auto exact = toda_closed_form<T>(trees, y);
    const T tolerance = T(256) * std::numeric_limits<T>::epsilon();
    for (int t = 0; t < trees.size(); ++t) {
      INFO("tree " << t << " of order " << trees[t].order << ", colour " << trees[t].colour);
      const auto i = static_cast<std::size_t>(t);
      const T scale = T(1) + T(exact[i].template lpNorm<Eigen::Infinity>());
      CHECK(T((ad[i] - exact[i]).template lpNorm<Eigen::Infinity>()) <= tolerance * scale);
    }
  }
}

TEMPLATE_TEST_CASE("elementary differentials by AD equal the closed forms up to order 5", "[bseries]", double,
                   boost::multiprecision::cpp_bin_float_50) {
  using T = TestType;
  for (int colours = 1; colours <= 2; ++colours) {
    INFO("colours " << colours);
    check_against_closed_form<T>(natural_field<geomint::systems::pendulum, T>{}, false, colours);
    check_against_closed_form<T>(natural_field<geomint::systems::harmonic, T>{}, true, colours);
    check_against_closed_form<T>(hamiltonian_field<pendulum_hamiltonian, 1>{}, false, colours);
  }
}

TEST_CASE("elementary differentials: the tree counts and the vanishing trees of a natural system", "[bseries]") {
  // On q' = p, p' = -V'(q) every two-colour tree outside the Nystrom trees has F = 0 (the
  // claim of partitioned_form.hpp's is_nystrom_tree), and the Nystrom trees do not (pendulum at
  // a generic point).
  const tree_set trees(5, 2);
  const vec<double, 2> y(0.7, -1.3);
  const auto F = elementary_differentials(trees, natural_field<geomint::systems::pendulum, double>{}, y);
  for (int t = 0; t < trees.size(); ++t) {
    INFO("tree " << t);
    CHECK(F[static_cast<std::size_t>(t)].isZero(0) == !is_nystrom_tree(trees, t, true));
  }
}

TEST_CASE("elementary differentials: derivative order beyond the limit is refused", "[bseries]") {
  const natural_field<geomint::systems::pendulum, double> f{};
  const vec<double, 2> y(0.5, 0.5);
  std::vector<const vec<double, 2>*> u(static_cast<std::size_t>(max_derivative_order) + 1, &y);
  CHECK_THROWS_AS(directional_derivative(f, y, u), std::invalid_argument);
}

geomint::methods::tableau_data<geomint::methods::field_element> example(const std::string& file) {
  return geomint::methods::read_tableau_file(std::string(GEOMINT_SOURCE_DIR) + "/examples/tableaux/" + file);
}

TEST_CASE("rkn series: the schemes' exact tableaux against the partitioned form of tableau files", "[bseries]") {
  // Two routes to the same P-series: the stage algebra of rkn_tableau.hpp (trapezoidal =
  // Stormer-Verlet; lpf m = 3 on Gauss-interior nodes = the 2-stage Gauss collocation RKN
  // method, the map of gauss2.tableau) and series.hpp on the partitioned form of
  // the tableau files of the same methods (examples/tableaux, exact over Q(sqrt 3)).
  using geomint::methods::field_element;
  const tree_set trees(7, 2);
  const std::vector<bool> wanted = nystrom_trees(trees);
  struct pair {
    geomint::exact_rkn_tableau scheme;
    const char* file;
  };
  for (const pair& p : {pair{geomint::trapezoidal_tableau(), "stormer_verlet.tableau"},
                        pair{geomint::lpf_tableau<3, geomint::gauss_interior>(), "gauss2.tableau"}}) {
    INFO(p.file);
    const auto a = elementary_weights(trees, p.scheme);
    const auto b = elementary_weights(trees, partitioned_form_of(example(p.file)), &wanted);
    int compared = 0;
    for (int t = 0; t < trees.size(); ++t) {
      if (!wanted[static_cast<std::size_t>(t)]) continue;
      INFO("tree " << t);
      CHECK(field_element(a[static_cast<std::size_t>(t)]) == b[static_cast<std::size_t>(t)]);
      ++compared;
    }
    CHECK(compared > 50);
  }
}

}  // namespace bseries_elementary_differentials_test
