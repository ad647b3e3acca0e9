/// The Nystrom weights of fixed-size rkn and nystrom tableaux and of their compositions
/// (bseries/nystrom_weights.hpp, the constexpr route) against series.hpp on the exact
/// partitioned pair of the same method read as run-time data (nystrom_form_of, then
/// partitioned_form_of). The two routes share no weight code: one multiplies the Nystrom stage
/// vectors, the other the (2s + 2)-stage pair of partitioned_form.hpp. (The coefficients of a
/// composition are composed by the same code on both routes, compose_coefficients of
/// methods/composition.hpp; tests/methods/test_nystrom_form.cpp checks them by hand and
/// test_bseries_static.cpp the orders and errors of compositions against published values.)
/// Compared on every Nystrom tree to order 7 (q'' = f(q); 6 for the 10 stages of Suzuki's
/// method) or 6 (q'' = F(q, q')), on the full two-colour set (0 off the Nystrom trees) and on
/// the class sets, over the catalogue's methods (methods/catalogue.hpp).
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/bseries/nystrom_weights.hpp"
#include "geomint/analysis/bseries/partitioned_form.hpp"
#include "geomint/analysis/bseries/rkn_series.hpp"
#include "geomint/methods/catalogue.hpp"

namespace bseries_nystrom_weights_test {

using namespace geomint::analysis::bseries;
namespace methods = geomint::methods;
using methods::exact_rational;
using methods::field_element;

field_element to_field(const geomint::rational& x) { return field_element(exact_rational(x.num, x.den)); }
const field_element& to_field(const field_element& x) { return x; }
template <auto P>
field_element to_field(const methods::algebraic_number<P>& x) {
  return methods::to_field_element(x);
}

/// A typed tableau with its coefficients as field_element (the run-time data's type).
template <class K, int S>
methods::rkn<field_element, S> over_field(const methods::rkn<K, S>& t) {
  methods::rkn<field_element, S> out;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    out.c[i] = to_field(t.c[i]);
    out.bbar[i] = to_field(t.bbar[i]);
    out.b[i] = to_field(t.b[i]);
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) out.a[i][j] = to_field(t.a[i][j]);
  }
  return out;
}
template <class K, int S>
methods::nystrom<field_element, S> over_field(const methods::nystrom<K, S>& t) {
  methods::nystrom<field_element, S> out;
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    out.c[i] = to_field(t.c[i]);
    out.bbar[i] = to_field(t.bbar[i]);
    out.b[i] = to_field(t.b[i]);
    for (std::size_t j = 0; j < static_cast<std::size_t>(S); ++j) {
      out.a[i][j] = to_field(t.a[i][j]);
      out.ap[i][j] = to_field(t.ap[i][j]);
    }
  }
  return out;
}
template <class Base, int M>
auto over_field(const methods::composition<Base, M>& t) {
  methods::composition<decltype(over_field(t.base)), M> out{over_field(t.base), {}};
  for (std::size_t l = 0; l < static_cast<std::size_t>(M); ++l) out.gamma[l] = to_field(t.gamma[l]);
  return out;
}

/// Whether the method has velocity stages (weights on the trees of q'' = F(q, q')).
template <class K, int S>
bool velocity_stages(const methods::rkn<K, S>&) {
  return false;
}
template <class K, int S>
bool velocity_stages(const methods::nystrom<K, S>&) {
  return true;
}
template <class Base, int M>
bool velocity_stages(const methods::composition<Base, M>& t) {
  return velocity_stages(t.base);
}

/// The first tree (index into the full two-colour set) where the typed route and series.hpp on
/// the partitioned pair of the method's run-time form differ, -1 if none: on the full set (the
/// pair on the Nystrom trees of the method's class, 0 elsewhere), and on the class set of
/// q'' = f(q) (velocity_free) or q'' = F(q, q').
template <class Typed>
int first_difference(const Typed& typed, bool velocity_free, int order) {
  const tree_set all(order, 2), part(order, velocity_free ? tree_class::rkn : tree_class::nystrom);
  const std::vector<bool> wanted = nystrom_trees(all, !velocity_stages(typed));
  const std::vector<field_element> reference =
      elementary_weights(all, partitioned_form_of(methods::nystrom_form_of(typed)), &wanted);
  const std::vector<field_element> on_all = elementary_weights(all, typed), on_class = elementary_weights(part, typed);
  for (int t = 0; t < all.size(); ++t) {
    const auto i = static_cast<std::size_t>(t);
    if (!(on_all[i] == (wanted[i] ? reference[i] : field_element(0)))) return t;
  }
  const std::vector<int> same = indices_in(part, all);
  for (int t = 0; t < part.size(); ++t) {
    const auto u = static_cast<std::size_t>(same[static_cast<std::size_t>(t)]);
    if (!wanted[u] || !(on_class[static_cast<std::size_t>(t)] == reference[u])) return static_cast<int>(u);
  }
  return -1;
}

/// A catalogue method's typed tableau (over field_element: the compositions' and McLachlan's
/// coefficients are in Q(r), the others rational).
template <class Method>
void check_catalogue_method(bool velocity_free, int order) {
  INFO(Method::name());
  CHECK(first_difference(over_field(Method::tableau()), velocity_free, order) == -1);
}

TEST_CASE("nystrom weights: rkn tableaux and compositions agree with the partitioned form on q'' = f(q) to order 7",
          "[bseries]") {
  check_catalogue_method<methods::stormer_verlet>(true, 7);
  check_catalogue_method<methods::ruth3>(true, 7);
  check_catalogue_method<methods::demp_rkn43>(true, 7);
  check_catalogue_method<methods::demp_rkn43_embedded>(true, 7);
  check_catalogue_method<methods::demp_rkn64>(true, 7);
  check_catalogue_method<methods::mclachlan_sb3a4>(true, 7);
  check_catalogue_method<methods::forest_ruth>(true, 7);
  check_catalogue_method<methods::yoshida_triple_jump>(true, 7);
  check_catalogue_method<methods::suzuki4>(true, 6);  // 10 stages: its pair has 22
  // The nystrom tableau on q'' = f(q), where its velocity stages do not enter.
  check_catalogue_method<methods::nystrom4>(true, 7);
  // Two steps that do not add up to one: d = 1/2 + 1/4, the weight of the leaf q.
  const auto verlet = over_field(methods::stormer_verlet::tableau());
  const methods::composition<methods::rkn<field_element, 2>, 2> short_verlet{verlet, {exact_rational(1, 2), exact_rational(1, 4)}};
  CHECK(first_difference(short_verlet, true, 7) == -1);
}

TEST_CASE("nystrom weights: nystrom tableaux and compositions agree with the partitioned form on q'' = F(q, q') to order 6",
          "[bseries]") {
  check_catalogue_method<methods::nystrom4>(false, 6);
  // Compositions of a nystrom tableau (their velocity stages composed too): two steps that do
  // not add up to one (d = 1/2 + 1/4), and three steps, one backwards (12 stages: to order 5).
  const auto nystrom4 = over_field(methods::nystrom4::tableau());
  const methods::composition<methods::nystrom<field_element, 4>, 2> short_steps{nystrom4, {exact_rational(1, 2), exact_rational(1, 4)}};
  CHECK(first_difference(short_steps, false, 6) == -1);
  const methods::composition<methods::nystrom<field_element, 4>, 3> three{
      nystrom4, {exact_rational(1, 3), exact_rational(-1, 2), exact_rational(7, 6)}};
  CHECK(first_difference(three, false, 5) == -1);
}

TEST_CASE("nystrom weights: one-colour trees, and an rkn tableau on the trees of F(q, q'), are refused", "[bseries]") {
  const auto verlet = methods::stormer_verlet::tableau();
  CHECK_THROWS_AS(elementary_weights(tree_set(3, 1), verlet), std::invalid_argument);
  CHECK_THROWS_AS(elementary_weights(tree_set(3, 1), methods::nystrom4::tableau()), std::invalid_argument);
  CHECK_THROWS_AS(elementary_weights(tree_set(3, tree_class::nystrom), verlet), std::invalid_argument);
  CHECK_NOTHROW(elementary_weights(tree_set(3, tree_class::rkn), methods::nystrom4::tableau()));
}

}  // namespace bseries_nystrom_weights_test
