/// Symmetric compositions of Stormer-Verlet: the refined coefficients satisfy their order
/// conditions to the scalar's precision, stay next to the published values, and the methods
/// (and the Odeint peers of the work-precision tool) show their nominal order on the pendulum.
#include <array>
#include <cmath>
#include <vector>

#include <boost/numeric/odeint/stepper/base/symplectic_rkn_stepper_base.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>

#include "catch.hpp"
#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/analysis/composition.hpp"
#include "scalar_types.hpp"

using namespace geomint;
using boost::multiprecision::cpp_bin_float_50;

namespace {

template <class T>
std::vector<analysis::symmetric_composition<T>> all_compositions() {
  return {analysis::symmetric_composition<T>::yoshida6(), analysis::symmetric_composition<T>::kahan_li8(),
          analysis::symmetric_composition<T>::sofroniou_spaletta10()};
}

/// The first published coefficient of each method (Yoshida 1990; Kahan & Li 1997, s17odr8a;
/// Sofroniou & Spaletta 2005), 26 digits.
const char* const published_first[] = {"0.78451361047755726381949763", "0.13020248308889008087881763",
                                       "0.07879572252168641926390768"};

template <class T>
void pendulum_force(const std::array<T, 1>& q, std::array<T, 1>& f) {
  using std::sin;
  f[0] = -sin(q[0]);
}

/// Final error at t = 4 of a method with `steps` steps, pendulum from theta0 = 1 at rest
/// (reference: the closed form, Jacobi elliptic functions).
template <class T, class Step>
T pendulum_error(long steps, const Step& step) {
  std::array<T, 1> q{T(1)}, p{T(0)};
  const T t_end(4), h = t_end / T(steps);
  for (long k = 0; k < steps; ++k) step(q, p, h);
  const auto ref = analysis::pendulum_from_rest<T>(T(1), t_end);
  using std::abs;
  return T(abs(T(q[0] - ref.q[0])) + abs(T(p[0] - ref.p[0])));
}

template <class T, class Step>
double observed_order(long steps, const Step& step) {
  using std::log2;
  return static_cast<double>(T(log2(T(pendulum_error<T>(steps, step) / pendulum_error<T>(2 * steps, step)))));
}

}  // namespace

TEMPLATE_TEST_CASE("composition coefficients satisfy their order conditions", "[analysis][composition]", double,
                   cpp_bin_float_50) {
  using T = TestType;
  const auto methods = all_compositions<T>();
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const auto& c = methods[i];
    INFO(c.name());
    // Order conditions (free-algebra words up to the order) to the scalar's precision.
    CHECK(c.order_defect() <= geomint::test::eps_tol<T>(64));
    // Not of higher order: some condition of order + 2 fails by far more than round-off.
    CHECK(c.next_order_defect() > geomint::test::eps_tol<T>(1 << 20));
    // Symmetric, consistent.
    T sum(0);
    for (int k = 0; k < c.stages(); ++k) {
      sum += c.gamma()[std::size_t(k)];
      CHECK(c.gamma()[std::size_t(k)] == c.gamma()[std::size_t(c.stages() - 1 - k)]);
    }
    CHECK(geomint::test::abs_diff(sum, T(1)) <= geomint::test::eps_tol<T>(64));
    // Newton stays at the published solution (26 digits): within 1e-24 of it in 50 digits,
    // within a few ulps in double.
    const T published = from_decimal<T>(published_first[i]);
    const T tol = std::numeric_limits<T>::digits10 > 30 ? from_decimal<T>("1e-24") : geomint::test::eps_tol<T>(16);
    CHECK(geomint::test::abs_diff(c.gamma()[0], published) <= tol);
  }
}

TEST_CASE("work-precision peers show their nominal order", "[analysis][composition]") {
  // cpp_bin_float_50 so that round-off stays far below the truncation errors (1e-10..1e-20).
  using T = cpp_bin_float_50;
  const auto force = [](const std::array<T, 1>& q, std::array<T, 1>& f) { pendulum_force<T>(q, f); };
  const long steps[] = {16, 16, 16};
  const auto methods = all_compositions<T>();
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const auto& c = methods[i];
    INFO(c.name());
    const double order = observed_order<T>(steps[i], [&](std::array<T, 1>& q, std::array<T, 1>& p, const T& h) {
      std::array<T, 1> f;
      force(q, f);
      analysis::composition_step(c.gamma(), q, p, f, h, force);
    });
    CHECK(std::abs(order - c.order()) < 0.5);
  }
  namespace odeint = boost::numeric::odeint;
  {
    INFO("odeint runge_kutta_fehlberg78 (fixed steps: order 8)");
    using state = std::array<T, 2>;
    const double order = observed_order<T>(32, [](std::array<T, 1>& q, std::array<T, 1>& p, const T& h) {
      odeint::runge_kutta_fehlberg78<state, T, state, T> rk;
      state x{q[0], p[0]};
      using std::sin;
      rk.do_step([](const state& y, state& dy, const T&) { dy = {y[1], T(-sin(y[0]))}; }, x, T(0), h);
      q[0] = x[0];
      p[0] = x[1];
    });
    CHECK(std::abs(order - 8) < 0.5);
  }
  {
    INFO("odeint symplectic_rkn_sb3a_m4_mclachlan (order 4)");
    const double order = observed_order<T>(64, [](std::array<T, 1>& q, std::array<T, 1>& p, const T& h) {
      odeint::symplectic_rkn_sb3a_m4_mclachlan<std::array<T, 1>, std::array<T, 1>, T> st;
      auto coor = [](const std::array<T, 1>& pp, std::array<T, 1>& dq) { dq = pp; };
      auto mom = [](const std::array<T, 1>& qq, std::array<T, 1>& dp) { pendulum_force<T>(qq, dp); };
      st.do_step(std::make_pair(coor, mom), std::make_pair(std::ref(q), std::ref(p)), T(0), h);
    });
    CHECK(std::abs(order - 4) < 0.5);
  }
}
