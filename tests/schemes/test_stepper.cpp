/// stepper.hpp: the type-erased stepper made by name. Expected values come from a second route
/// to the same step: the typed `integrator` of the scheme the name denotes (its own tests check it
/// against exact flows); the error cases against the documented contract.
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "catch.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/stepper.hpp"
#include "scalar_types.hpp"

using namespace geomint;

namespace {
template <class Scheme>
vec<double, 2> typed_step(const vec<double, 2>& q, const vec<double, 2>& p, double tau) {
  integrator<Scheme, systems::kepler, double> I(systems::kepler{}, tau);
  phase_state<double, 2> s;
  s.q = q;
  s.p = p;
  I.step(s);
  return s.q;
}
}  // namespace

TEST_CASE("stepper: a scheme chosen by name steps exactly like the typed integrator", "[stepper]") {
  const double tau = 1.0 / 16;
  vec<double, 2> q0, qdot0;
  systems::kepler::initial_data(q0, qdot0);
  const dynamic_vector<double> q = q0, p = qdot0;  // unit mass: p = qdot
  auto by_name = [&](const scheme_spec& spec) {
    const auto stepper = make_stepper<systems::kepler, double>(spec);
    dynamic_vector<double> q1, p1;
    REQUIRE(stepper->try_step(q, p, tau, q1, p1));
    REQUIRE(q1.size() == 2);
    return vec<double, 2>(q1);
  };
  // Same scheme, same arithmetic: bitwise equal.
  CHECK(by_name({"lpf", "gauss_interior", "lagrange", 4}) == typed_step<lpf<4, gauss_interior>>(q0, qdot0, tau));
  CHECK(by_name({"lpf", "gauss-interior", "lagrange", 4}) == typed_step<lpf<4, gauss_interior>>(q0, qdot0, tau));
  CHECK(by_name({"lpf", "lobatto", "bernstein", 3}) == typed_step<lpf<3, gauss_lobatto, bernstein>>(q0, qdot0, tau));
  CHECK(by_name({"lpf", "radau-left", "lagrange", 3}) == typed_step<lpf<3, radau_left>>(q0, qdot0, tau));
  CHECK(by_name({"galerkin", "equispaced", "lagrange", 5}) == typed_step<galerkin_vi<5>>(q0, qdot0, tau));
  CHECK(by_name({"midpoint", "equispaced", "lagrange", 2}) == typed_step<midpoint_vi>(q0, qdot0, tau));
  CHECK(make_stepper<systems::kepler, double>({"lpf", "chebyshev_lobatto", "lagrange", 6})->name() ==
        lpf<6, chebyshev_lobatto>::name());
  // LPF's fixed-point form (Kepler is a natural system); --nodes and --basis do not apply.
  CHECK(by_name({"lpf-fixed-point", "equispaced", "lagrange", 4}) == typed_step<lpf_fixed_point<4>>(q0, qdot0, tau));
  CHECK(by_name({"lpf-fixed-point", "equispaced", "lagrange", 8}) == typed_step<lpf_fixed_point<8>>(q0, qdot0, tau));
  CHECK(make_stepper<systems::kepler, double>({"lpf-fixed-point", "equispaced", "lagrange", 8})->name() ==
        lpf_fixed_point<8>::name());
  // The node families and bases of one LPF method share one engine type (compiled once); each
  // stepper keeps its own weights: the steps differ and each equals its typed integrator.
  static_assert(std::is_same_v<detail::stepper_engine_t<lpf<4, gauss_interior>, systems::kepler, double>,
                               detail::stepper_engine_t<lpf<4, equispaced>, systems::kepler, double>>);
  static_assert(std::is_same_v<detail::stepper_engine_t<lpf<4, gauss_interior>, systems::kepler, double>,
                               detail::stepper_engine_t<lpf<4, gauss_interior, bernstein>, systems::kepler, double>>);
  static_assert(!std::is_same_v<detail::stepper_engine_t<lpf<4, gauss_interior>, systems::kepler, double>,
                                detail::stepper_engine_t<lpf<5, gauss_interior>, systems::kepler, double>>);
  CHECK(by_name({"lpf", "equispaced", "lagrange", 4}) == typed_step<lpf<4, equispaced>>(q0, qdot0, tau));
  CHECK(by_name({"lpf", "equispaced", "lagrange", 4}) != by_name({"lpf", "gauss_interior", "lagrange", 4}));
  CHECK(by_name({"lpf", "equispaced", "bernstein", 4}) == typed_step<lpf<4, equispaced, bernstein>>(q0, qdot0, tau));
}

TEST_CASE("stepper: unknown names and m out of range are errors; a failed step leaves the output alone", "[stepper]") {
  using S = systems::kepler;  // one factory per test source: the one of the test above
  CHECK_THROWS_AS((make_stepper<S, double>({"rk4", "equispaced", "lagrange", 2})), std::invalid_argument);
  CHECK_THROWS_AS((make_stepper<S, double>({"lpf", "gauss", "lagrange", 2})), std::invalid_argument);
  CHECK_THROWS_AS((make_stepper<S, double>({"lpf", "equispaced", "hermite", 2})), std::invalid_argument);
  CHECK_THROWS_AS((make_stepper<S, double>({"lpf", "equispaced", "lagrange", 1})), std::invalid_argument);
  CHECK_THROWS_AS((make_stepper<S, double>({"galerkin", "equispaced", "lagrange", 9})), std::invalid_argument);
  CHECK_THROWS_AS((make_stepper<S, double>({"lpf-fixed-point", "equispaced", "lagrange", 9})), std::invalid_argument);

  const auto stepper = make_stepper<S, double>({"lpf", "equispaced", "lagrange", 3});
  const dynamic_vector<double> q = dynamic_vector<double>::Constant(2, 1.0), p = dynamic_vector<double>::Zero(2);
  dynamic_vector<double> q1 = dynamic_vector<double>::Constant(2, 7.0), p1 = q1;
  for (const double tau : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    const step_status st = stepper->try_step(q, p, tau, q1, p1);
    CHECK(st.reason == step_failure::invalid_step_size);
    CHECK(q1[0] == 7.0);
    CHECK(p1[0] == 7.0);
  }
  const dynamic_vector<double> bad = dynamic_vector<double>::Constant(2, std::numeric_limits<double>::infinity());
  CHECK(stepper->try_step(bad, p, 0.1, q1, p1).reason == step_failure::non_finite_input);
  CHECK(q1[0] == 7.0);
  const dynamic_vector<double> wrong_size = dynamic_vector<double>::Zero(3);
  CHECK_THROWS_AS(stepper->try_step(wrong_size, wrong_size, 0.1, q1, p1), std::invalid_argument);
}

TEST_CASE("stepper: the scheme registry and make_stepper know the same schemes", "[stepper][registry]") {
  // The registry (schemes/registry.hpp) is the one list of the built-in schemes: every entry is
  // a stepper on a natural system at every m in stepper_min_m..stepper_max_m where it has an m,
  // and a name outside it is refused with the registry's names in the message.
  using S = systems::kepler;  // the factory of the tests above
  for (const scheme_entry& e : scheme_registry) {
    INFO(e.name);
    const std::string name(e.name);
    for (int m = stepper_min_m; m <= stepper_max_m; ++m) {
      const auto stepper = make_stepper<S, double>({name, "equispaced", "lagrange", m});
      REQUIRE(stepper);
      if (!e.has_m) break;  // its m is ignored
    }
    CHECK(scheme_spec{name}.has_m() == e.has_m);
    if (e.has_m) CHECK_THROWS_AS((make_stepper<S, double>({name, "equispaced", "lagrange", stepper_max_m + 1})), std::invalid_argument);
  }
  try {
    (void)make_stepper<S, double>({"rk4", "equispaced", "lagrange", 2});
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "unknown scheme 'rk4' (lpf|lpf-fixed-point|midpoint|trapezoidal|galerkin)");
  }
  CHECK(scheme_names_where([](const scheme_entry& e) { return e.has_m; }, ", ", " and ") == "lpf, lpf-fixed-point and galerkin");
  CHECK(scheme_names_where([](const scheme_entry& e) { return e.has_nodes; }, ", ", " and ") == "lpf");
  CHECK(find_scheme("rk4") == nullptr);
}
