/// The exactly symplectic rounding of RKN tableaux (methods/symplectic_rounding.hpp) on methods of
/// the catalogue other than Gauss: Yoshida's triple jump (explicit, coefficients in Q(2^(1/3)))
/// and the Lobatto IIIA-IIIB pairs s = 3, 4 (implicit; s = 4 in Q(sqrt 5)), all symplectic and
/// symmetric by their sources (Yoshida 1990; Jay 1996; Hairer, Lubich & Wanner 2006, section
/// VI.4; docs/references.md). Suris's conditions b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji) and
/// bbar_i = b_i (1 - c_i) (Hairer, Lubich & Wanner 2006, Theorem VI.4.3) are evaluated on the
/// stored doubles converted to exact rationals (cpp_rational holds every double exactly), with
/// a_ij = mu_ij b_j and bbar_i = e_i b_i taken exactly: the residual must be zero, not small.
#include <boost/multiprecision/cpp_int.hpp>
#include <stdexcept>
#include <string>

#include "catch.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/methods/symplectic_rounding.hpp"
#include "scalar_types.hpp"

namespace symplectic_rounding_test {

using namespace geomint;
using methods::rkn;
using rational_number = boost::multiprecision::cpp_rational;
using T50 = geomint::test::cpp_bin_float_50;

/// The RKN part (c, a, bbar, b) of a catalogue entry's Nystrom form in T, at T's precision.
template <class T, int S>
rkn<T, S> catalogue_rkn(const std::string& name) {
  const methods::catalogue_entry* e = methods::find_in_catalogue(name);
  REQUIRE(e != nullptr);
  return methods::rkn_of<S>(methods::to_scalar<T>(methods::nystrom_form_of(e->tableau())));
}

rational_number exact(double x) { return rational_number(x); }

/// The largest |residual| of Suris's conditions on (c, a, bbar, b), every value an exact rational.
template <std::size_t S>
rational_number suris_residual(const std::array<rational_number, S>& c, const std::array<std::array<rational_number, S>, S>& a,
                               const std::array<rational_number, S>& bbar, const std::array<rational_number, S>& b) {
  rational_number worst(0);
  auto keep = [&](const rational_number& r) {
    const rational_number m = r < 0 ? rational_number(-r) : r;
    if (m > worst) worst = m;
  };
  for (std::size_t i = 0; i < S; ++i) {
    keep(bbar[i] - b[i] * (rational_number(1) - c[i]));
    for (std::size_t j = 0; j < S; ++j) keep(b[i] * (bbar[j] - a[i][j]) - b[j] * (bbar[i] - a[j][i]));
  }
  return worst;
}

/// The residual of the stored method: a_ij = mu_ij b_j, bbar_i = e_i b_i, exactly.
template <std::size_t S>
rational_number stored_residual(const methods::symplectic_rkn<double, static_cast<int>(S)>& k) {
  std::array<rational_number, S> c, bbar, b;
  std::array<std::array<rational_number, S>, S> a;
  for (std::size_t i = 0; i < S; ++i) {
    c[i] = exact(k.c[i]);
    b[i] = exact(k.b[i]);
    bbar[i] = exact(k.e[i]) * b[i];
    CHECK(exact(k.e[i]) == rational_number(1) - c[i]);
  }
  for (std::size_t i = 0; i < S; ++i)
    for (std::size_t j = 0; j < S; ++j) a[i][j] = exact(k.mu[i][j]) * b[j];
  return suris_residual<S>(c, a, bbar, b);
}

/// The residual of the tableau rounded entry by entry.
template <std::size_t S>
rational_number rounded_residual(const rkn<double, static_cast<int>(S)>& t) {
  std::array<rational_number, S> c, bbar, b;
  std::array<std::array<rational_number, S>, S> a;
  for (std::size_t i = 0; i < S; ++i) {
    c[i] = exact(t.c[i]);
    b[i] = exact(t.b[i]);
    bbar[i] = exact(t.bbar[i]);
    for (std::size_t j = 0; j < S; ++j) a[i][j] = exact(t.a[i][j]);
  }
  return suris_residual<S>(c, a, bbar, b);
}

/// symplecticize on the catalogue entry `name` (S stages) in double: Suris's conditions exact,
/// the symmetry exact, each coefficient within a few grid units of the 50-digit one.
template <std::size_t S>
void check_method(const std::string& name) {
  INFO(name);
  constexpr int stages = static_cast<int>(S);
  const rkn<double, stages> t = catalogue_rkn<double, stages>(name);
  const methods::symplectic_rkn<double, stages> k = methods::symplecticize(t);
  CHECK(stored_residual<S>(k) == rational_number(0));
  // Symmetric methods (by their sources) keep the symmetry exactly: c_i' = 1 - c_i and
  // mu_i'j' = mu_ij + c_j - c_i (i' = S-1-i).
  REQUIRE(k.mirrored);
  for (std::size_t i = 0; i < S; ++i) {
    const std::size_t im = S - 1 - i;
    CHECK(exact(k.c[im]) == rational_number(1) - exact(k.c[i]));
    for (std::size_t j = 0; j < S; ++j)
      CHECK(exact(k.mu[im][S - 1 - j]) == exact(k.mu[i][j]) + exact(k.c[j]) - exact(k.c[i]));
  }
  // Second computation: the exact coefficients in 50 digits. The stored ones are them rounded to
  // the grid (c, mu), or to double (b).
  const rkn<T50, stages> w = catalogue_rkn<T50, stages>(name);
  using std::abs;
  for (std::size_t i = 0; i < S; ++i) {
    CHECK(abs(T50(T50(k.c[i]) - w.c[i])) <= T50(k.grid));
    CHECK(abs(T50(T50(k.b[i]) - w.b[i])) <= T50(2) * T50(std::numeric_limits<double>::epsilon()) * abs(w.b[i]));
    for (std::size_t j = 0; j < S; ++j) CHECK(abs(T50(T50(k.mu[i][j]) - w.a[i][j] / w.b[j])) <= T50(4) * T50(k.grid));
  }
}

TEST_CASE("symplectic rounding: Suris's conditions hold exactly for Yoshida's triple jump and Lobatto IIIA-IIIB",
          "[methods][symplectic_rounding]") {
  check_method<6>("yoshida-triple-jump");
  check_method<3>("lobatto-iiia-iiib-3");
  check_method<4>("lobatto-iiia-iiib-4");
}

TEST_CASE("symplectic rounding: the entries rounded one by one miss Suris's conditions", "[methods][symplectic_rounding]") {
  // The check above can fail: the same tableaux converted entry by entry to double (what a
  // tableau in double is without the transform) leave a residual of the order of an ulp.
  const rational_number ulp = exact(std::numeric_limits<double>::epsilon());
  const rational_number yoshida = rounded_residual<6>(catalogue_rkn<double, 6>("yoshida-triple-jump"));
  const rational_number lobatto = rounded_residual<4>(catalogue_rkn<double, 4>("lobatto-iiia-iiib-4"));
  CHECK(yoshida > rational_number(0));
  CHECK(lobatto > rational_number(0));
  CHECK(yoshida < rational_number(16) * ulp);
  CHECK(lobatto < rational_number(16) * ulp);
}

TEST_CASE("symplectic rounding: an explicit method stays explicit", "[methods][symplectic_rounding]") {
  const methods::symplectic_rkn<double, 6> k = methods::symplecticize(catalogue_rkn<double, 6>("yoshida-triple-jump"));
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = i; j < 6; ++j) CHECK(k.mu[i][j] == 0.0);
}

TEST_CASE("symplectic rounding: a tableau that is not symplectic, or has a zero weight, is refused",
          "[methods][symplectic_rounding][errors]") {
  // Radau IIA with s = 2 is not symplectic (Hairer, Lubich & Wanner 2006, section VI.4; its
  // weights are nonzero): as an RKN method Suris's conditions fail by O(1).
  CHECK_THROWS_AS(methods::symplecticize(catalogue_rkn<double, 2>("radau-iia-2")), std::domain_error);
  // Stormer-Verlet (velocity form) with its second weight set to zero: the relations divide by b.
  rkn<double, 2> verlet = catalogue_rkn<double, 2>("stormer-verlet");
  verlet.b[1] = 0.0;
  CHECK_THROWS_AS(methods::symplecticize(verlet), std::domain_error);
  // The fixed-size form of a run-time tableau with another number of stages.
  CHECK_THROWS_AS((catalogue_rkn<double, 3>("stormer-verlet")), std::invalid_argument);
}

}  // namespace symplectic_rounding_test
