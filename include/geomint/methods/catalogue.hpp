#pragma once
/// Methods from the literature with exact coefficients, each a scheme of the one integrator
/// (integrator<tableau_method<M>, Sys, T>, methods/tableau_method.hpp) and, by name, an entry of
/// `catalogue()` (geomint-scheme --analyse --scheme NAME). Full references: docs/references.md.
///
/// - Explicit methods over geomint::rational (constexpr, structural): Stormer-Verlet, Ruth's
///   order-3 method, the Dormand-El-Mikkawy-Prince RKN pairs 4(3) and 6(4) (each formula of a
///   pair an entry), Nystrom's classical order-4 method (nystrom kind).
/// - Compositions over Q(2^(1/3)) (methods/composition.hpp): Forest-Ruth, Yoshida's triple
///   jump, Suzuki's fractal order-4 method.
/// - Splittings over a quadratic field: McLachlan's symmetric order-4 RKN methods SB3A with 4 and
///   5 force evaluations.
/// - The collocation-type families (methods/collocation_families.hpp): Gauss, Radau IIA, Radau
///   IA, Lobatto IIIA, IIIB, IIIC and the IIIA-IIIB pair; Radau with s = 5 over its stage
///   algebra (methods/collocation_algebra.hpp: `algebra` instead of `tableau`).
///
/// The explicit methods, compositions and splittings are constexpr tableaux, their number fields
/// algebraic_number (methods/algebraic_number.hpp), so tests/methods/static_catalogue.cpp checks
/// them in static_assert.
///
/// Each entry carries its published order, symplecticity and symmetry with the source that states
/// them; tests/methods/test_catalogue.cpp checks them against the exact analysis.

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/core/rational.hpp"
#include "geomint/methods/algebraic_number.hpp"
#include "geomint/methods/collocation_algebra.hpp"
#include "geomint/methods/collocation_families.hpp"
#include "geomint/methods/composition.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/methods/number_field.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

namespace detail {
/// The explicit RKN method of a splitting (drift d_0,) kick b_1, drift d_1, ..., kick b_s,
/// drift d_s (sum d = 1, as H = T(p) + V(q) with T quadratic; d_0 = `first_drift`, 0 unless
/// the method starts with a drift): the i-th force is evaluated at c_i = d_0 + ... + d_{i-1},
/// and the velocity of kick j drifts for (c_i - c_j) h before it, so a_ij = b_j (c_i - c_j)
/// (j < i) and bbar_j = b_j (1 - c_j) (Hairer, Lubich & Wanner 2006, section V.3.2).
template <class K, std::size_t S>
constexpr rkn<K, static_cast<int>(S)> kick_drift_rkn(const K (&kick)[S], const K (&drift)[S], const K& first_drift = K(0)) {
  rkn<K, static_cast<int>(S)> t{};
  K position = first_drift;
  for (std::size_t i = 0; i < S; ++i) {
    t.c[i] = position;
    position = position + drift[i];
  }
  for (std::size_t i = 0; i < S; ++i) {
    t.b[i] = kick[i];
    t.bbar[i] = kick[i] * (K(1) - t.c[i]);
    for (std::size_t j = 0; j < S; ++j) t.a[i][j] = j < i ? kick[j] * (t.c[i] - t.c[j]) : K(0);
  }
  return t;
}

/// The formula with the same c and a and other weights (the other formula of an embedded pair).
template <int S>
constexpr rkn<rational, S> with_weights(rkn<rational, S> t, const rational (&bbar)[S], const rational (&b)[S]) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(S); ++i) {
    t.bbar[i] = bbar[i];
    t.b[i] = b[i];
  }
  return t;
}

/// Q(2^(1/3)), the compositions' field (r^3 = 2 has one real root, in (1, 2]).
inline constexpr field_polynomial<3> cube_root_of_two_field{{-2, 0, 0, 1}, 1, 2};
using cube_root_number = algebraic_number<cube_root_of_two_field>;
constexpr cube_root_number cube_root_of_two() { return cube_root_number::generator(); }

/// Velocity Stormer-Verlet (kick-drift-kick) and position Stormer-Verlet (drift-kick-drift) as
/// RKN tableaux over K, the bases of the compositions.
template <class K>
constexpr rkn<K, 2> velocity_verlet() {
  return make_rkn<K>({K(0), K(1)}, {{K(0), K(0)}, {K(rational(1, 2)), K(0)}}, {K(rational(1, 2)), K(0)},
                     {K(rational(1, 2)), K(rational(1, 2))});
}
template <class K>
constexpr rkn<K, 1> position_verlet() {
  return make_rkn<K>({K(rational(1, 2))}, {{K(0)}}, {K(rational(1, 2))}, {K(1)});
}
}  // namespace detail

/// Stormer-Verlet (velocity form): q1 = q + h v + h^2/2 f(q), v1 = v + h/2 (f(q) + f(q1));
/// order 2, symplectic, symmetric (Hairer, Lubich & Wanner 2006, sections I.1.4, VI.3 and V.1).
/// On y'' = -y its step matrix has trace 2 - h^2 and determinant 1: periodic for 0 < h < 2.
struct stormer_verlet {
  static constexpr std::string_view name() { return "stormer-verlet"; }
  static constexpr auto tableau() {
    return make_rkn<rational>({0, 1}, {{0, 0}, {rational(1, 2), 0}}, {rational(1, 2), 0}, {rational(1, 2), rational(1, 2)});
  }
};

/// Ruth's order-3 method: kicks (7/24, 3/4, -1/24) and drifts (2/3, -2/3, 1), the kick first
/// (Ruth 1983, IEEE Trans. Nucl. Sci. 30, 2669-2671; as quoted by Forest & Ruth 1990). Order 3,
/// symplectic, not symmetric.
struct ruth3 {
  static constexpr std::string_view name() { return "ruth-3"; }
  static constexpr auto tableau() {
    return detail::kick_drift_rkn({rational(7, 24), rational(3, 4), rational(-1, 24)}, {rational(2, 3), rational(-2, 3), rational(1)});
  }
};

/// Dormand, El-Mikkawy & Prince (1987), RKN4(3)4FM: the explicit FSAL pair of orders 4 and 3
/// with c = (0, 1/4, 7/10, 1) (IMA J. Numer. Anal. 7, 235-250). `embedded`: the
/// order-3 formula of the pair (same c and a).
struct demp_rkn43 {
  static constexpr std::string_view name() { return "demp-rkn43"; }
  static constexpr auto tableau() {
    using R = rational;
    return make_rkn<R>({0, R(1, 4), R(7, 10), 1},
                       {{0, 0, 0, 0}, {R(1, 32), 0, 0, 0}, {R(7, 1000), R(119, 500), 0, 0}, {R(1, 14), R(8, 27), R(25, 189), 0}},
                       {R(1, 14), R(8, 27), R(25, 189), 0}, {R(1, 14), R(32, 81), R(250, 567), R(5, 54)});
  }
};
struct demp_rkn43_embedded {
  static constexpr std::string_view name() { return "demp-rkn43-embedded"; }
  static constexpr auto tableau() {
    using R = rational;
    return detail::with_weights<4>(demp_rkn43::tableau(), {R(-7, 150), R(67, 150), R(3, 20), R(-1, 20)},
                                   {R(13, 21), R(-20, 27), R(275, 189), R(-1, 3)});
  }
};

/// Dormand, El-Mikkawy & Prince (1987), RKN6(4)6FM: the explicit FSAL pair of orders 6 and 4
/// with c = (0, 1/10, 3/10, 7/10, 17/25, 1) (IMA J. Numer. Anal. 7, 235-250).
struct demp_rkn64 {
  static constexpr std::string_view name() { return "demp-rkn64"; }
  static constexpr auto tableau() {
    using R = rational;
    return make_rkn<R>({0, R(1, 10), R(3, 10), R(7, 10), R(17, 25), 1},
                       {{0, 0, 0, 0, 0, 0},
                        {R(1, 200), 0, 0, 0, 0, 0},
                        {R(-1, 2200), R(1, 22), 0, 0, 0, 0},
                        {R(637, 6600), R(-7, 110), R(7, 33), 0, 0, 0},
                        {R(225437, 1968750), R(-30073, 281250), R(65569, 281250), R(-9367, 984375), 0, 0},
                        {R(151, 2142), R(5, 116), R(385, 1368), R(55, 168), R(-6250, 28101), 0}},
                       {R(151, 2142), R(5, 116), R(385, 1368), R(55, 168), R(-6250, 28101), 0},
                       {R(151, 2142), R(25, 522), R(275, 684), R(275, 252), R(-78125, 112404), R(1, 12)});
  }
};
struct demp_rkn64_embedded {
  static constexpr std::string_view name() { return "demp-rkn64-embedded"; }
  static constexpr auto tableau() {
    using R = rational;
    return detail::with_weights<6>(demp_rkn64::tableau(),
                                   {R(1349, 157500), R(7873, 50000), R(192199, 900000), R(521683, 2100000), R(-16, 125), 0},
                                   {R(1349, 157500), R(7873, 45000), R(27457, 90000), R(521683, 630000), R(-2, 5), R(1, 12)});
  }
};

/// Nystrom's classical method of order 4 for q'' = F(q, q') (Nystrom 1925; Hairer, Norsett &
/// Wanner I, section II.14): ap is the classical RK4 matrix, a = (1/8; 1/8, 0;
/// 0, 0, 1/2), bbar = (1, 1, 1, 0)/6, b = (1, 2, 2, 1)/6.
struct nystrom4 {
  static constexpr std::string_view name() { return "nystrom-4"; }
  static constexpr auto tableau() {
    using R = rational;
    return make_nystrom<R>({0, R(1, 2), R(1, 2), 1}, {{0, 0, 0, 0}, {R(1, 8), 0, 0, 0}, {R(1, 8), 0, 0, 0}, {0, 0, R(1, 2), 0}},
                           {{0, 0, 0, 0}, {R(1, 2), 0, 0, 0}, {0, R(1, 2), 0, 0}, {0, 0, 1, 0}}, {R(1, 6), R(1, 6), R(1, 6), 0},
                           {R(1, 6), R(1, 3), R(1, 3), R(1, 6)});
  }
};

/// Forest & Ruth (1990): position Stormer-Verlet with the steps theta h,
/// (1 - 2 theta) h, theta h, theta = 1/(2 - 2^(1/3)) (drift theta h/2, kick theta h, drift
/// (1 - theta) h/2, ...). Order 4, symplectic, symmetric.
struct forest_ruth {
  static constexpr std::string_view name() { return "forest-ruth"; }
  static constexpr auto tableau() {
    using K = detail::cube_root_number;
    const K r = detail::cube_root_of_two(), theta = K(1) / (K(2) - r);
    return composition<rkn<K, 1>, 3>{detail::position_verlet<K>(), {theta, K(1) - theta - theta, theta}};
  }
};

/// Yoshida's triple jump (Yoshida 1990, section 4): velocity Stormer-Verlet with the
/// steps w1 h, w0 h, w1 h, w1 = 1/(2 - 2^(1/3)), w0 = -2^(1/3)/(2 - 2^(1/3)). Order 4,
/// symplectic, symmetric.
struct yoshida_triple_jump {
  static constexpr std::string_view name() { return "yoshida-triple-jump"; }
  static constexpr auto tableau() {
    using K = detail::cube_root_number;
    const K r = detail::cube_root_of_two(), w1 = K(1) / (K(2) - r);
    return composition<rkn<K, 2>, 3>{detail::velocity_verlet<K>(), {w1, -r * w1, w1}};
  }
};

/// Suzuki's fractal order-4 method (Suzuki 1990): velocity
/// Stormer-Verlet with the steps p h, p h, (1 - 4p) h, p h, p h, p = 1/(4 - 4^(1/3)),
/// 4^(1/3) = (2^(1/3))^2. Order 4, symplectic, symmetric.
struct suzuki4 {
  static constexpr std::string_view name() { return "suzuki-4"; }
  static constexpr auto tableau() {
    using K = detail::cube_root_number;
    const K r = detail::cube_root_of_two(), p = K(1) / (K(4) - r * r);
    const K middle = K(1) - K(4) * p;
    return composition<rkn<K, 2>, 5>{detail::velocity_verlet<K>(), {p, p, middle, p, p}};
  }
};

/// McLachlan's symmetric order-4 RKN methods "SB3A" with m = 4 and m = 5 force evaluations
/// (McLachlan 1995, SIAM J. Sci. Comput. 16, 151-168): splittings that start and end with a
/// drift, drifts (a_1, a_2, ..., a_2, a_1) around kicks (b_1, ..., b_1). Symplectic, symmetric,
/// order 4 on q'' = f(q). The coefficients as transcribed to 20 digits in Principia
/// (mockingbirdnest/Principia, integrators/methods.hpp, McLachlan1995SB3A4 and
/// McLachlan1995SB3A5); the exact values here agree with every printed digit and are the
/// solutions of the order conditions (docs/references.md):
/// - m = 4: kicks (1, -1/2, -1/2, 1), drifts a_1 = 1/2 - sqrt 14/12 = 0.188195217768838...,
///   a_2 = sqrt 14/12 - 1/3, a_3 = 2/3 (a_1, a_2 the roots of 72 x^2 - 72 x + 11 and
///   72 x^2 + 48 x + 1 nearest the printed values);
/// - m = 5: kicks (-3/73, 17/59, 2179/4307, 17/59, -3/73) (the printed 20 digits are these
///   fractions'), drifts (a_1, a_2, a_3, a_3, a_2, a_1) with a_3 = 1/2 - a_1 - a_2, in
///   Q(sqrt 722025967665): the root of the two order-3 conditions nearest the printed
///   a_1 = 0.4051886183952522772, a_2 = -0.2871440408165240890 (the other root of that
///   quadratic system is a_1 = -0.670...).
struct mclachlan_sb3a4 {
  static constexpr std::string_view name() { return "mclachlan-sb3a-4"; }
  static constexpr field_polynomial<2> field{{-14, 0, 1}, 3, 4};  // sqrt 14
  static constexpr auto tableau() {
    using K = algebraic_number<field>;
    const K r = K::generator(), a1 = K(rational(1, 2)) - r / K(12), a2 = r / K(12) - K(rational(1, 3));
    return detail::kick_drift_rkn<K, 4>({K(1), K(rational(-1, 2)), K(rational(-1, 2)), K(1)}, {a2, K(rational(2, 3)), a2, a1}, a1);
  }
};
struct mclachlan_sb3a5 {
  static constexpr std::string_view name() { return "mclachlan-sb3a-5"; }
  static constexpr field_polynomial<2> field{{-722025967665LL, 0, 1}, 849721, 849722};  // its square root
  static constexpr auto tableau() {
    using K = algebraic_number<field>;
    const K r = K::generator();
    const K a1 = K(rational(-229483763, 1729961856)) + K(rational(365, 576653952)) * r;
    const K a2 = K(rational(18550249, 123568704)) - K(rational(1081, 2100667968)) * r;
    const K a3 = K(rational(1, 2)) - a1 - a2;
    const K b1 = K(rational(-3, 73)), b2 = K(rational(17, 59));
    return detail::kick_drift_rkn<K, 5>({b1, b2, K(rational(2179, 4307)), b2, b1}, {a2, a3, a3, a2, a1}, a1);
  }
};

/// One method of the catalogue by name, with the properties its source publishes.
struct catalogue_entry {
  std::string name;     ///< the name geomint-scheme --scheme takes
  std::string title;    ///< e.g. "Gauss, s = 3"
  std::string source;   ///< where the coefficients and the published properties are printed
  method_kind kind = method_kind::rkn;
  int stages = 0;
  int order = 0;        ///< published order
  bool symplectic = false;
  bool symmetric = false;
  /// Exact, compositions as their rkn tableau; empty where the entries need too large a field
  /// (Radau with s = 5), which `algebra` gives instead.
  std::function<tableau_data<field_element>()> tableau;
  /// The rk method over its stage algebra, or empty: the analysis's model where present (Gauss
  /// s = 4, 5 and Radau s = 4, whose fields have degree 8 and 6, and Radau s = 5).
  std::function<rk_stage_algebra()> algebra;
};

namespace detail {
inline field_element to_field(const rational& x) { return field_element(exact_rational(x.num, x.den)); }
inline const field_element& to_field(const field_element& x) { return x; }
template <auto P>
field_element to_field(const algebraic_number<P>& x) {
  return to_field_element(x);
}

/// A typed tableau (or composition, by its Nystrom form) as run-time data over field_element.
template <class Tableau>
tableau_data<field_element> field_data_of(const Tableau& t) {
  const nystrom_form<typename Tableau::coefficient> f = nystrom_form_of(t);
  tableau_data<field_element> d;
  d.kind = f.has_velocity_stages ? method_kind::nystrom : method_kind::rkn;
  d.stages = f.stages;
  auto vec = [](const auto& x) {
    std::vector<field_element> out;
    for (const auto& v : x) out.push_back(to_field(v));
    return out;
  };
  d.c = vec(f.c);
  d.bbar = vec(f.bbar);
  d.b = vec(f.b);
  for (const auto& row : f.a) d.a.push_back(vec(row));
  if (f.has_velocity_stages)
    for (const auto& row : f.ap) d.ap.push_back(vec(row));
  return d;
}

template <class Method>
catalogue_entry explicit_entry(std::string title, std::string source, int order, bool symplectic, bool symmetric) {
  catalogue_entry e;
  e.name = std::string(Method::name());
  e.title = std::move(title);
  e.source = std::move(source);
  e.order = order;
  e.symplectic = symplectic;
  e.symmetric = symmetric;
  e.tableau = [] {
    tableau_data<field_element> d = field_data_of(Method::tableau());
    d.name = std::string(Method::name());
    return d;
  };
  const tableau_data<field_element> d = e.tableau();
  e.kind = d.kind;
  e.stages = d.stages;
  return e;
}

/// The stages of the entries over their stage algebra alone (Radau with s = 5; numeric_form).
inline constexpr int catalogue_algebra_stages = 5;

inline std::vector<catalogue_entry> make_catalogue() {
  std::vector<catalogue_entry> out;
  struct family {
    collocation_family id;
    const char* name;
    const char* title;
    int first, last;
    int order_offset;  // order = 2s + offset
    bool symplectic, symmetric;
    const char* source;
  };
  const family families[] = {
      {collocation_family::gauss, "gauss", "Gauss", 2, 5, 0, true, true,
       "Butcher 1964; Hairer & Wanner II, section IV.5; Hairer, Lubich & Wanner, sections V.2 and VI.4"},
      {collocation_family::radau_iia, "radau-iia", "Radau IIA", 2, 5, -1, false, false, "Ehle 1969; Hairer & Wanner II, section IV.5"},
      {collocation_family::radau_ia, "radau-ia", "Radau IA", 2, 5, -1, false, false, "Ehle 1969; Hairer & Wanner II, section IV.5"},
      {collocation_family::lobatto_iiia, "lobatto-iiia", "Lobatto IIIA", 2, 5, -2, false, true,
       "Ehle 1969; Hairer & Wanner II, section IV.5; Hairer, Lubich & Wanner, sections II.1.4 and V.2"},
      {collocation_family::lobatto_iiib, "lobatto-iiib", "Lobatto IIIB", 2, 5, -2, false, true,
       "Ehle 1969; Hairer & Wanner II, section IV.5; Hairer, Lubich & Wanner, sections II.1.4 and V.2"},
      {collocation_family::lobatto_iiic, "lobatto-iiic", "Lobatto IIIC", 2, 5, -2, false, false,
       "Chipman 1971; Hairer & Wanner II, section IV.5"},
      {collocation_family::lobatto_iiia_iiib, "lobatto-iiia-iiib", "Lobatto IIIA-IIIB pair", 2, 5, -2, true, true,
       "Jay 1996; Hairer, Lubich & Wanner, sections II.2.2, V.2 and VI.4"},
  };
  for (const family& f : families)
    for (int s = f.first; s <= f.last; ++s) {
      catalogue_entry e;
      e.name = std::string(f.name) + "-" + std::to_string(s);
      e.title = std::string(f.title) + ", s = " + std::to_string(s);
      e.source = f.source;
      e.kind = f.id == collocation_family::lobatto_iiia_iiib ? method_kind::prk : method_kind::rk;
      e.stages = s;
      e.order = 2 * s + f.order_offset;
      e.symplectic = f.symplectic;
      e.symmetric = f.symmetric;
      if (f.id == collocation_family::lobatto_iiib && s == 2) {
        // Its tableau violates b_i a_ij + b_j a_ji = b_i b_j, but the method is reducible: both
        // stages solve K = f(y + h K / 2), so y1 = y + h K is the implicit midpoint rule, which is
        // symplectic (Hairer, Lubich & Wanner, section VI.3); the B-series analysis says so.
        e.symplectic = true;
        e.source += "; reducible to the implicit midpoint rule (symplectic)";
      }
      const std::string name = e.name;
      // Over their stage algebra too, where the field of the entries has degree > 2 (Gauss s = 4,
      // 5; Radau s = 4) or 24 (Radau s = 5: no tableau): the analysis's series there are rational.
      const bool radau = f.id == collocation_family::radau_iia || f.id == collocation_family::radau_ia;
      if (f.id == collocation_family::gauss && s >= 4)
        e.algebra = [s, name] { return collocation_algebra(detail::monic(detail::shifted_legendre(s)), name); };
      if (radau && s >= 4) {
        const bool right = f.id == collocation_family::radau_iia;
        e.algebra = [right, s] { return right ? radau_iia_algebra(s) : radau_ia_algebra(s); };
      }
      if (radau && s == catalogue_algebra_stages) {
        out.push_back(std::move(e));
        continue;
      }
      e.tableau = [id = f.id, s, name] {
        tableau_data<field_element> d = collocation_family_tableau(id, s);
        d.name = name;
        return d;
      };
      out.push_back(std::move(e));
    }
  out.push_back(explicit_entry<stormer_verlet>("Stormer-Verlet", "Hairer, Lubich & Wanner, sections I.1.4, V.1 and VI.3", 2, true, true));
  out.push_back(explicit_entry<ruth3>("Ruth's order-3 method", "Ruth 1983; Forest & Ruth 1990", 3, true, false));
  out.push_back(explicit_entry<forest_ruth>("Forest-Ruth", "Forest & Ruth 1990", 4, true, true));
  out.push_back(explicit_entry<yoshida_triple_jump>("Yoshida's triple jump", "Yoshida 1990", 4, true, true));
  out.push_back(explicit_entry<suzuki4>("Suzuki's fractal order 4", "Suzuki 1990", 4, true, true));
  out.push_back(explicit_entry<mclachlan_sb3a4>("McLachlan's SB3A, m = 4 (order 4)", "McLachlan 1995 (coefficients as transcribed in Principia)",
                                                4, true, true));
  out.push_back(explicit_entry<mclachlan_sb3a5>("McLachlan's SB3A, m = 5 (order 4)", "McLachlan 1995 (coefficients as transcribed in Principia)",
                                                4, true, true));
  out.push_back(explicit_entry<demp_rkn43>("DEMP RKN4(3)4FM, order-4 formula", "Dormand, El-Mikkawy & Prince 1987", 4, false, false));
  out.push_back(
      explicit_entry<demp_rkn43_embedded>("DEMP RKN4(3)4FM, order-3 formula", "Dormand, El-Mikkawy & Prince 1987", 3, false, false));
  out.push_back(explicit_entry<demp_rkn64>("DEMP RKN6(4)6FM, order-6 formula", "Dormand, El-Mikkawy & Prince 1987", 6, false, false));
  out.push_back(
      explicit_entry<demp_rkn64_embedded>("DEMP RKN6(4)6FM, order-4 formula", "Dormand, El-Mikkawy & Prince 1987", 4, false, false));
  out.push_back(explicit_entry<nystrom4>("Nystrom's classical order 4", "Nystrom 1925; Hairer, Norsett & Wanner I, section II.14",
                                         4, false, false));
  return out;
}
}  // namespace detail

/// Every method of the catalogue (built once).
inline const std::vector<catalogue_entry>& catalogue() {
  static const std::vector<catalogue_entry> entries = detail::make_catalogue();
  return entries;
}

/// The Nystrom form of an entry in T, every coefficient at T's full precision: its exact tableau
/// converted, or the numeric tableau of its stage algebra (methods/collocation_algebra.hpp).
/// (The entries without a tableau, Radau with s = catalogue_algebra_stages, are the only ones
/// over their stage algebra alone: one numeric_tableau instantiated per scalar, not eight.)
template <class T>
nystrom_form<T> numeric_form(const catalogue_entry& e) {
  return e.tableau ? to_scalar<T>(nystrom_form_of(e.tableau()))
                   : nystrom_form_of(numeric_tableau<T, detail::catalogue_algebra_stages>(e.algebra()));
}

/// The entry called `name`, or nullptr.
inline const catalogue_entry* find_in_catalogue(std::string_view name) {
  for (const catalogue_entry& e : catalogue())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace geomint::methods
