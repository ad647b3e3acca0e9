#pragma once
/// Tableaux of the B-series tests, exact over cpp_rational (as printed in Hairer, Norsett, Wanner,
/// Solving ODEs I, section II.1; Hairer, Wanner, Solving ODEs II, section IV.5; Hairer, Lubich,
/// Wanner, Geometric Numerical Integration, 2nd ed. 2006, section II.2). Lobatto IIIB with
/// s = 2 does not satisfy c_i = sum_j a_ij; c is unused by the series.
#include <boost/multiprecision/cpp_int.hpp>

#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/series.hpp"

namespace bseries_test_methods {

using Q = boost::multiprecision::cpp_rational;
using tableau = geomint::methods::tableau_data<Q>;
using geomint::analysis::bseries::pair_of;

inline Q q(int p, int r = 1) { return Q(p) / Q(r); }

/// A Runge-Kutta tableau (c, A, b) as the library's run-time tableau.
inline tableau rk(std::vector<Q> c, std::vector<std::vector<Q>> a, std::vector<Q> b) {
  tableau t;
  t.kind = geomint::methods::method_kind::rk;
  t.stages = static_cast<int>(b.size());
  t.c = std::move(c);
  t.a = std::move(a);
  t.b = std::move(b);
  return t;
}

inline tableau explicit_euler() { return rk({q(0)}, {{q(0)}}, {q(1)}); }
inline tableau implicit_midpoint() { return rk({q(1, 2)}, {{q(1, 2)}}, {q(1)}); }
inline tableau classical_rk4() {
  return rk({q(0), q(1, 2), q(1, 2), q(1)},
          {{q(0), q(0), q(0), q(0)}, {q(1, 2), q(0), q(0), q(0)}, {q(0), q(1, 2), q(0), q(0)}, {q(0), q(0), q(1), q(0)}},
          {q(1, 6), q(1, 3), q(1, 3), q(1, 6)});
}
inline tableau radau_iia_2() { return rk({q(1, 3), q(1)}, {{q(5, 12), q(-1, 12)}, {q(3, 4), q(1, 4)}}, {q(3, 4), q(1, 4)}); }
inline tableau lobatto_iiia_3() {
  return rk({q(0), q(1, 2), q(1)},
          {{q(0), q(0), q(0)}, {q(5, 24), q(1, 3), q(-1, 24)}, {q(1, 6), q(2, 3), q(1, 6)}},
          {q(1, 6), q(2, 3), q(1, 6)});
}
inline tableau lobatto_iiib_3() {
  return rk({q(0), q(1, 2), q(1)},
          {{q(1, 6), q(-1, 6), q(0)}, {q(1, 6), q(1, 3), q(0)}, {q(1, 6), q(5, 6), q(0)}},
          {q(1, 6), q(2, 3), q(1, 6)});
}
inline tableau lobatto_iiia_2() { return rk({q(0), q(1)}, {{q(0), q(0)}, {q(1, 2), q(1, 2)}}, {q(1, 2), q(1, 2)}); }
inline tableau lobatto_iiib_2() { return rk({q(0), q(1)}, {{q(1, 2), q(0)}, {q(1, 2), q(0)}}, {q(1, 2), q(1, 2)}); }
/// Two implicit midpoint steps of sizes h/3 and 2h/3: symplectic (b_i a_ij + b_j a_ji = b_i b_j,
/// HLW section VI.4), order 2, not symmetric.
inline tableau composed_midpoint() {
  return rk({q(1, 6), q(2, 3)}, {{q(1, 6), q(0)}, {q(1, 3), q(1, 3)}}, {q(1, 3), q(2, 3)});
}

/// The Runge-Kutta method "first, then second" (each on a full step h; HNW section II.12).
inline tableau then(const tableau& first, const tableau& second) {
  const std::size_t s = first.b.size(), r = second.b.size();
  tableau t = rk(std::vector<Q>(s + r, Q(0)), std::vector<std::vector<Q>>(s + r, std::vector<Q>(s + r, Q(0))), {});
  for (std::size_t i = 0; i < s; ++i) {
    for (std::size_t j = 0; j < s; ++j) t.a[i][j] = first.a[i][j];
    t.b.push_back(first.b[i]);
  }
  for (std::size_t i = 0; i < r; ++i) {
    for (std::size_t j = 0; j < s; ++j) t.a[s + i][j] = first.b[j];
    for (std::size_t j = 0; j < r; ++j) t.a[s + i][s + j] = second.a[i][j];
    t.b.push_back(second.b[i]);
  }
  t.stages = static_cast<int>(s + r);
  return t;
}

/// chi^{-1} o phi o chi with chi the explicit Euler step of size theta h (its inverse: implicit
/// Euler with step -theta h).
inline tableau conjugated(const tableau& phi, const Q& theta) {
  return then(then(rk({q(0)}, {{q(0)}}, {theta}), phi), rk({-theta}, {{-theta}}, {-theta}));
}

/// The modified field b of a tableau (rk or prk) on `trees`.
inline std::vector<Q> modified_field_of(const geomint::analysis::bseries::tree_set& trees, const tableau& method) {
  return geomint::analysis::bseries::modified_field(trees, geomint::analysis::bseries::elementary_weights(trees, method));
}

/// Stormer-Verlet as an RKN tableau (HLW section I.1.4): c = (0, 1), A = [[0, 0], [1/2, 0]],
/// bbar = (1/2, 0), b = (1/2, 1/2).
inline tableau verlet_rkn() {
  tableau v;
  v.kind = geomint::methods::method_kind::rkn;
  v.stages = 2;
  v.c = {q(0), q(1)};
  v.a = {{q(0), q(0)}, {q(1, 2), q(0)}};
  v.bbar = {q(1, 2), q(0)};
  v.b = {q(1, 2), q(1, 2)};
  return v;
}

}  // namespace bseries_test_methods
