/// Analysis on any system (analysis/any_system.hpp) and the explicit fast path: a system with a
/// potential, a mass matrix and a magnetic term is integrated correctly (general path), its
/// order is observed against the generic Galerkin reference flow, and the symplecticity defect
/// separates symplectic from non-symplectic schemes.
#include <cmath>

#include "catch.hpp"
#include "geomint/analysis/any_system.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "scalar_types.hpp"

using namespace geomint;

namespace {
/// The case of the user report: potential() and mass_matrix() present, but operator() has a
/// magnetic term A(q) . qdot with A = (-y, x)/2 (uniform field B = 1). Not derived from
/// geomint::natural, so it is a general system and the term cannot be dropped.
struct magnetic {
  static constexpr int dof = 2;
  template <class S>
  static S potential(const vec<S, 2>& q) { return (q[0] * q[0] + q[1] * q[1]) / S(2) + q[0] * q[0] * q[1]; }
  template <class S>
  static mat<S, 2> mass_matrix() { return mat<S, 2>::Identity(); }
  template <class S>
  S operator()(const vec<S, 2>& q, const vec<S, 2>& v) const {
    return (v[0] * v[0] + v[1] * v[1]) / S(2) + (q[0] * v[1] - q[1] * v[0]) / S(2) - potential<S>(q);
  }
};
/// The same without the magnetic term, declared natural.
struct without_field : natural<without_field, 2> {
  template <class S>
  static S potential(const vec<S, 2>& q) { return magnetic::potential<S>(q); }
  template <class S>
  static mat<S, 2> mass_matrix() { return mat<S, 2>::Identity(); }
};
}  // namespace

static_assert(!natural_system<magnetic>, "a system is natural only when declared so");
static_assert(natural_system<without_field>);
static_assert(checked_system<magnetic, double> && checked_system<zoo::spring_pendulum, double>);

TEST_CASE("a magnetic term beside potential() and mass_matrix() is integrated, not dropped", "[analysis][contract]") {
  using T = double;
  using std::abs;
  using std::max;
  integrator<lpf<4, gauss_interior>, magnetic, T> I(magnetic{}, T(1) / T(20));
  const vec<T, 2> q0(T(1) / T(5), T(0)), v0(T(0), T(3) / T(10));
  auto s = I.initial_state(q0, v0);
  // The reference: the generic Galerkin flow (degree 8, 50 digits) of the same Lagrangian.
  const auto reference = analysis::galerkin_reference<magnetic, T>(magnetic{}, s.q, s.p);
  I.advance(s, 40);
  analysis::dynamic_vector<T> qe, pe;
  reference(T(2), qe, pe);
  const T error = max(abs(s.q[0] - qe[0]), abs(s.q[1] - qe[1]));
  // Without the field the path is elsewhere: the comparison can tell the two apart.
  integrator<lpf<4, gauss_interior>, without_field, T> J(without_field{}, T(1) / T(20));
  auto w = J.initial_state(q0, v0);
  J.advance(w, 40);
  const T field_effect = max(abs(w.q[0] - qe[0]), abs(w.q[1] - qe[1]));
  INFO("error " << error << ", distance of the field-free path " << field_effect);
  // LPF m = 4 on Gauss nodes has order 6 (docs/results/analysis.md): error ~ C tau^6 = 1.6e-8 C.
  CHECK(error < T(1) / T(1000000));
  CHECK(field_effect > T(1) / T(100));
}

TEST_CASE("study_order measures the order of a user's system in a few lines", "[analysis][order]") {
  using T = double;
  integrator<galerkin_vi<2>, zoo::spring_pendulum, T> I(zoo::spring_pendulum{});
  const auto r = analysis::study_order(I, vec<T, 2>(T(11) / T(10), T(1) / T(2)), vec<T, 2>(T(0), T(0)), T(1), {4, 8, 16, 32});
  INFO(r.failure);
  REQUIRE(r.ok);
  // Galerkin VI of degree m has order 2m (Hairer, Lubich, Wanner, GNI, VI.6.3).
  CHECK(r.global_order > T(7) / T(2));
  CHECK(r.global_order < T(9) / T(2));
}

TEST_CASE("symplecticity_defect: Galerkin VI symplectic, LPF Gauss not for a non-constant mass matrix", "[analysis][symplectic]") {
  using T = boost::multiprecision::cpp_bin_float_50;
  const vec<T, 2> q0(T(11) / T(10), T(1) / T(2)), v0(T(0), T(0));
  integrator<galerkin_vi<3>, zoo::spring_pendulum, T> G(zoo::spring_pendulum{});
  integrator<lpf<4, gauss_interior>, zoo::spring_pendulum, T> L(zoo::spring_pendulum{});
  const T galerkin = analysis::symplecticity_defect(G, q0, v0, T(1) / T(4));
  const T gauss = analysis::symplecticity_defect(L, q0, v0, T(1) / T(4));
  INFO("Galerkin " << galerkin << ", LPF Gauss " << gauss);
  // The difference Jacobian is accurate to about eps^(4/5) ~ 1e-40 (analysis/symplecticity.hpp).
  CHECK(galerkin < T(1) / T("1e35"));
  CHECK(gauss > T(1) / T("1e12"));
}
