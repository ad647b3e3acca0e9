/// The exact RKN tableaux (include/geomint/analysis/rkn_tableau.hpp) against the integrators.
///
/// Independent source: the integrators (include/geomint/schemes) solve their own defining
/// equations (LPF: eq. 10-12 by Newton on the path's control points; Galerkin: stationarity of
/// the quadrature action; midpoint and trapezoidal: their discrete Lagrangians) and never form a
/// tableau. One step of the RKN method built from the exact tableau (converted to
/// cpp_bin_float_50 with the family's nodes) must reproduce one step of the integrator on the
/// pendulum (f = -sin q) to the precision of cpp_bin_float_50, for each family and m = 2..8.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <string>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/any_system.hpp"
#include "geomint/analysis/order_conditions.hpp"
#include "geomint/analysis/order_study.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/analysis/scheme_structure.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_50;

namespace {

using T = cpp_bin_float_50;

/// One RKN step for q'' = -sin q: stages by fixed-point iteration until they stop changing
/// (contraction factor ~ tau^2 max|a| < 1/10 at tau = 1/4).
std::pair<T, T> rkn_step(const methods::tableau_data<T>& t, const T& q, const T& p, const T& tau) {
  using std::abs;
  using std::sin;
  const int s = t.stages;
  std::array<T, max_exact_stages> Q{}, F{};
  for (int i = 0; i < s; ++i) Q[static_cast<std::size_t>(i)] = q + t.c[static_cast<std::size_t>(i)] * tau * p;
  for (int iteration = 0; iteration < 400; ++iteration) {
    for (int j = 0; j < s; ++j) F[static_cast<std::size_t>(j)] = -sin(Q[static_cast<std::size_t>(j)]);
    T change(0);
    for (int i = 0; i < s; ++i) {
      T sum(0);
      for (int j = 0; j < s; ++j) sum += t.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * F[static_cast<std::size_t>(j)];
      const T next = q + t.c[static_cast<std::size_t>(i)] * tau * p + tau * tau * sum;
      change = std::max(change, T(abs(next - Q[static_cast<std::size_t>(i)])));
      Q[static_cast<std::size_t>(i)] = next;
    }
    if (change == T(0)) break;
  }
  for (int j = 0; j < s; ++j) F[static_cast<std::size_t>(j)] = -sin(Q[static_cast<std::size_t>(j)]);
  T sb(0), sbb(0);
  for (int j = 0; j < s; ++j) {
    sb += t.b[static_cast<std::size_t>(j)] * F[static_cast<std::size_t>(j)];
    sbb += t.bbar[static_cast<std::size_t>(j)] * F[static_cast<std::size_t>(j)];
  }
  return {q + tau * p + tau * tau * sbb, p + tau * sb};
}

template <class Scheme>
void check_step(const methods::tableau_data<T>& t, const std::string& label) {
  using std::abs;
  const T tau = T(1) / T(4);
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto st = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(1) / T(2)));
  const T q = st.q[0], p = st.p[0];
  I.step(st);
  const auto [q1, p1] = rkn_step(t, q, p, tau);
  INFO(label << ": integrator (" << st.q[0] << ", " << st.p[0] << "), tableau (" << q1 << ", " << p1 << ")");
  // The Vandermonde conversion of the monomial-basis tableau loses up to ~5 digits for s = 8.
  const T tol = T(1000000) * std::numeric_limits<T>::epsilon();
  CHECK(abs(st.q[0] - q1) <= tol);
  CHECK(abs(st.p[0] - p1) <= tol);
}

template <class Family, int M>
void check_lpf() {
  check_step<lpf<M, Family>>(lpf_numeric_tableau<M, Family, T>(), "lpf m=" + std::to_string(M) + " " + std::string(Family::name));
  if constexpr (M < max_exact_m) check_lpf<Family, M + 1>();
}

template <int M>
void check_galerkin() {
  check_step<galerkin_vi<M>>(galerkin_numeric_tableau<M, T>(), "galerkin m=" + std::to_string(M));
  if constexpr (M < max_exact_m) check_galerkin<M + 1>();
}

}  // namespace

TEST_CASE("rkn tableau: one step equals the LPF integrator's step (50 digits)", "[analysis][tableau]") {
  check_lpf<equispaced, 2>();
  check_lpf<gauss_interior, 2>();
  check_lpf<gauss_lobatto, 2>();
  check_lpf<chebyshev_lobatto, 2>();
}

TEST_CASE("rkn tableau: one step equals the classical VIs' step (50 digits)", "[analysis][tableau]") {
  check_step<midpoint_vi>(numeric_tableau<T>(midpoint_tableau(), nullptr), "midpoint");
  check_step<trapezoidal_vi>(numeric_tableau<T>(trapezoidal_tableau(), nullptr), "trapezoidal");
  check_galerkin<1>();
}

// ---------------------------------------------------------------------------------------------
// Three independent orders per family and m = 2..8:
// - the tree order: every Nystrom order condition evaluated exactly on the tableau
//   (analysis/order_conditions.hpp);
// - the quadrature order of the interior nodes, from the node polynomial N alone (not from the
//   tableau's weights): the interpolatory quadrature on the s roots of N integrates x^j exactly
//   for j < s + k iff int_0^1 N(x) x^i dx = 0 for i < k (its error on x^j is the integral of
//   the remainder of x^j by N, a combination of N x^i); the moments are exact rationals. The
//   roots of that N are checked against the integrator's nodes (core/nodes.hpp) in 50 digits;
// - the order measured by the order study of geomint-order (analysis/order_study.hpp) with the
//   integrator in cpp_bin_float_50 on the pendulum against the Taylor reference flow.
// Collocation theory says the first two agree (HNW I, Theorem II.7.9 and section II.14), and
// the third is what the integrator actually does.
namespace {

/// The tableau through a non-constexpr function, so that the exact evaluations on it below run
/// at run time: GCC would otherwise try to fold them at compile time (its arguments being
/// constants) under the test suite's large -fconstexpr-ops-limit, for minutes.
[[gnu::noinline]] exact_rkn_tableau at_run_time(const exact_rkn_tableau& t) { return t; }

/// Quadrature order s + k of the roots of the monic N (degree s), k = number of vanishing
/// leading moments int_0^1 N(x) x^i dx, i = 0, 1, ... (exact).
int quadrature_order_from_node_polynomial(const exact_number* n, int s) {
  int k = 0;
  for (; k <= s; ++k) {
    exact_number moment;
    for (int j = 0; j <= s; ++j) moment = moment + n[j] * exact_number(rational(1, j + k + 1));
    if (!moment.num.is_zero()) break;
  }
  return s + k;
}

/// max |N(c_i)| over the family's interior nodes in T (N from the exact tableau).
template <int M, class Family>
T node_polynomial_residual(const exact_rkn_tableau& t) {
  using std::abs;
  const auto c = nodes<Family, M, T>();
  T worst(0);
  for (int i = 1; i < M; ++i) {
    T value(0);
    for (int k = t.stages; k >= 0; --k) value = value * c[static_cast<std::size_t>(i)] + T(t.node_polynomial[k].num.str()) / T(t.node_polynomial[k].den().str());
    worst = std::max(worst, T(abs(value)));
  }
  return worst;
}

/// Observed global and local orders of Scheme on the pendulum from (q, p) = (1, 1/2), T = 1,
/// N = 4, 8, 16, against the Taylor reference flow (the machinery of geomint-order).
template <class Scheme>
analysis::order_result<T> measured_orders() {
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, T(1));
  analysis::reference_function<T> reference = [](const T& t, analysis::dynamic_vector<T>& q, analysis::dynamic_vector<T>& p) {
    analysis::reference_flow<systems::pendulum, T> flow(vec<T, 1>(T(1)), vec<T, 1>(T(1) / T(2)));
    flow.advance_to(t);
    q = analysis::dynamic_vector<T>::Constant(1, flow.q()[0]);
    p = analysis::dynamic_vector<T>::Constant(1, flow.p()[0]);
  };
  const analysis::dynamic_vector<T> q0 = analysis::dynamic_vector<T>::Constant(1, T(1)),
                                    p0 = analysis::dynamic_vector<T>::Constant(1, T(1) / T(2));
  return analysis::order_study<T>(*erase(I), reference, q0, p0, T(1), {4, 8, 16});
}

template <class Family, int M, int Last = max_exact_m>
void check_orders_agree() {
  const exact_rkn_tableau t = at_run_time(lpf_tableau<M, Family>());
  const int trees = tree_order(t);
  const int quadrature = quadrature_order_from_node_polynomial(t.node_polynomial, t.stages);
  const auto measured = measured_orders<lpf<M, Family>>();
  INFO("lpf m=" << M << " " << Family::name << ": tree order " << trees << ", quadrature order " << quadrature
                << ", measured global " << measured.global_order << ", local " << measured.local_order);
  CHECK(node_polynomial_residual<M, Family>(t) <= geomint::test::eps_tol<T>(1000));
  CHECK(trees == quadrature);
  REQUIRE(measured.ok);
  using std::abs;
  // The order is the global one (as geomint-order reports it): within 1/4 of the integer at
  // these steps. The local error is O(tau^(p+1)) at least (equispaced m = 5 shows 5.5 at N = 16).
  CHECK(abs(measured.global_order - T(trees)) < T(1) / T(4));
  CHECK(measured.local_order > T(trees + 1) - T(1) / T(4));
  if constexpr (M < Last) check_orders_agree<Family, M + 1, Last>();
}

}  // namespace

TEST_CASE("tree order == quadrature order of the interior nodes == measured order, every family, m = 2..8 (Radau: 2..7)",
          "[analysis][tableau][order]") {
  check_orders_agree<equispaced, 2>();
  check_orders_agree<gauss_interior, 2>();
  check_orders_agree<gauss_lobatto, 2>();
  check_orders_agree<chebyshev_lobatto, 2>();
  // The Radau families to m = 7: their order is m - 1 (the m - 1 interior nodes alone are only
  // an interpolatory rule), and at m = 8 the local error between N = 8 and 16 is still
  // pre-asymptotic (6.2; 7.5 between N = 16 and 32, 7.8 between 32 and 64).
  check_orders_agree<radau_right, 2, 7>();
  check_orders_agree<radau_left, 2, 7>();
}

// ---------------------------------------------------------------------------------------------
// The exact symplecticity verdicts (analysis/scheme_structure.hpp: Suris' conditions on the
// exact tableau) against the numerical defect max |J^T Omega J - Omega| of one integrator step
// (analysis::symplecticity_defect, the function behind geomint-symplectic), on the pendulum
// (nonlinear, natural) in cpp_bin_float_50 at tau = 1/2 from (q, qdot) = (1, 1/2). The
// difference Jacobian is accurate to about eps^(4/5) (1e-40): a symplectic verdict must give a
// defect at that noise level, a non-symplectic one a defect far above it.
namespace {

struct defect_record {
  std::string label;
  bool exact_symplectic = false;
  T defect;
};

template <class Scheme>
defect_record measured_defect(const exact_rkn_tableau& t, const std::string& label) {
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, T(1) / T(2));
  const T defect = analysis::symplecticity_defect(I, vec<T, 1>(T(1)), vec<T, 1>(T(1) / T(2)), T(1) / T(2));
  return {label, symplecticity(at_run_time(t)).symplectic, defect};
}

template <class Family, int M>
void collect_lpf_defects(std::vector<defect_record>& out) {
  out.push_back(measured_defect<lpf<M, Family>>(lpf_tableau<M, Family>(), "lpf m=" + std::to_string(M) + " " + std::string(Family::name)));
  if constexpr (M < max_exact_m) collect_lpf_defects<Family, M + 1>(out);
}

template <int M>
void collect_galerkin_defects(std::vector<defect_record>& out) {
  out.push_back(measured_defect<galerkin_vi<M>>(galerkin_tableau<M>(), "galerkin m=" + std::to_string(M)));
  if constexpr (M < max_exact_m) collect_galerkin_defects<M + 1>(out);
}

}  // namespace

TEST_CASE("exact symplecticity verdicts agree with the numerical defects of the integrators", "[analysis][tableau][symplectic]") {
  std::vector<defect_record> records;
  collect_lpf_defects<equispaced, 2>(records);
  collect_lpf_defects<gauss_interior, 2>(records);
  collect_lpf_defects<gauss_lobatto, 2>(records);
  collect_lpf_defects<chebyshev_lobatto, 2>(records);
  collect_galerkin_defects<1>(records);
  records.push_back(measured_defect<midpoint_vi>(midpoint_tableau(), "midpoint"));
  records.push_back(measured_defect<trapezoidal_vi>(trapezoidal_tableau(), "trapezoidal"));
  using std::pow;
  const T noise = T(1024) * pow(std::numeric_limits<T>::epsilon(), T(4) / T(5));
  int symplectic_count = 0;
  for (const auto& r : records) {
    INFO(r.label << ": exact verdict " << (r.exact_symplectic ? "symplectic" : "not symplectic") << ", numerical defect " << r.defect);
    if (r.exact_symplectic) {
      ++symplectic_count;
      CHECK(r.defect <= noise);
    } else {
      CHECK(r.defect > noise * T(1000000));
    }
  }
  // Gauss interior (7), m = 2 of the other three families, Galerkin (8), midpoint, trapezoidal.
  CHECK(symplectic_count == 7 + 3 + 8 + 2);
}

TEST_CASE("user tableaux built at run time equal the ones built at compile time", "[analysis][tableau]") {
  // Run-time construction from run-time data exercises the code paths that GCC 12 once
  // miscompiled (default-initialised local arrays of exact numbers, zero-filled); the
  // compile-time value is the independent reference.
  volatile int k = 5;  // not a constant
  const int a = k;
  const exact_rkn_tableau from_nodes =
      collocation_tableau_from_nodes<3>({rational(a, 40), rational(1, 2), rational(40 - a, 40)});
  constexpr exact_rkn_tableau expected = collocation_tableau_from_nodes<3>({rational(5, 40), rational(1, 2), rational(35, 40)});
  CHECK(from_nodes == expected);
  const exact_rkn_tableau from_polynomial =
      collocation_tableau_from_polynomial<2>({rational(a, 30), rational(-1), rational(1)});  // x^2 - x + 1/6
  CHECK(from_polynomial == lpf_tableau<3, gauss_interior>());
  CHECK(tree_order(from_nodes) == 4);
}

TEST_CASE("symmetry verdicts agree with stepping forward and back (repeated nodes)", "[analysis][tableau][symmetric]") {
  // A method is symmetric iff Phi_{-tau} o Phi_tau = id (HLW, section II.3). Checked on the
  // pendulum in 50 digits for the composition Phi*_{tau/2} o Phi_{tau/2} (nodes 1/2, 1/2, the
  // adjoint swaps the stages; see static_scheme_analysis.cpp) and for the same tableau with
  // a22 = 0, which is not symmetric.
  const auto tableau = [](const rational& a22) {
    return rational_rkn_tableau<2>({rational(1, 2), rational(1, 2)}, {{{rational(0), rational(0)}, {rational(1, 12), a22}}},
                                   {rational(1, 3), rational(1, 6)}, {rational(1, 2), rational(1, 2)});
  };
  using std::abs;
  const T tau = T(1) / T(4), q0(1), p0 = T(1) / T(2);
  for (const rational& a22 : {rational(-1, 12), rational(0)}) {
    const exact_rkn_tableau exact = at_run_time(tableau(a22));
    const methods::tableau_data<T> t = numeric_tableau<T>(exact, nullptr);
    const auto [q1, p1] = rkn_step(t, q0, p0, tau);
    const auto [q2, p2] = rkn_step(t, q1, p1, -tau);
    const T back = std::max(T(abs(q2 - q0)), T(abs(p2 - p0)));
    INFO("a22 = " << a22 << ": |Phi_{-tau} Phi_tau (q0, p0) - (q0, p0)| = " << back);
    if (symmetry(exact).symmetric) CHECK(back <= geomint::test::eps_tol<T>(1000));
    else CHECK(back > T(1) / T(1000000));
    CHECK(symmetry(exact).symmetric == (a22 == rational(-1, 12)));
  }
}
