/// The energy error predicted by the modified field (analysis/bseries/energy_prediction.hpp)
/// against the energy error the integrators measure, by independent routes: the prediction
/// comes from the method's exact P-series, its modified field and the pendulum's derivatives by
/// AD, evaluated along the numerical solution; the measurement is H(y_n) - H(y_0) of the
/// integrator's own steps. For a symplectic method of order p backward error analysis (HLW:
/// Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006, Theorem IX.8.1)
/// gives H(y_n) - H(y_0) = -h^p (H_{p+1}(y_n) - H_{p+1}(y_0)) + O(h^(p+1)), so the ratio of the
/// maxima over a run tends to 1 as h -> 0; the tests ask for 2% at the smaller step and a
/// smaller deviation there than at twice the step.
///
/// Case: the pendulum from q = 1 at rest (H = 1 - cos 1) over t in [0, 8] (more than one
/// period, about 6.7).
#include <boost/multiprecision/cpp_int.hpp>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "catch.hpp"
#include "geomint/analysis/bseries/energy_prediction.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/analysis/bseries/rkn_series.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/methods/coefficients.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "geomint/methods/tableau_stepper.hpp"
#include "geomint/stepper.hpp"

namespace bseries_energy_prediction_test {

using namespace geomint::analysis::bseries;
using geomint::vec;
using pendulum = geomint::systems::pendulum;
using field = natural_field<pendulum, double>;

struct maxima {
  double predicted = 0, measured = 0, quadrature = 0;
};

/// Runs the stepper for 8 time units at step tau from (1, 0) and compares.
maxima run(geomint::any_stepper<double>& stepper, const modified_terms<double>& terms, double tau) {
  const int steps = static_cast<int>(std::lround(8 / tau));
  geomint::dynamic_vector<double> q(1), p(1), q1, p1;
  q << 1;
  p << 0;
  const double h0 = stepper.energy(q, p);
  std::vector<vec<double, 2>> ys = {vec<double, 2>(q[0], p[0])};
  maxima out;
  for (int n = 0; n < steps; ++n) {
    if (!stepper.try_step(q, p, tau, q1, p1)) FAIL("step " << n << " failed");
    q = q1;
    p = p1;
    ys.emplace_back(q[0], p[0]);
    out.measured = std::max(out.measured, std::abs(stepper.energy(q, p) - h0));
  }
  const auto prediction = predict_energy_error(terms, field{}, ys, tau);
  for (double e : prediction.error) out.predicted = std::max(out.predicted, std::abs(e));
  out.quadrature = prediction.quadrature_estimate;
  return out;
}

/// The ratio predicted/measured within 2% at tau and closer to 1 than at 2 tau.
void check_convergence(geomint::any_stepper<double>& stepper, const modified_terms<double>& terms, double tau) {
  const maxima coarse = run(stepper, terms, 2 * tau), fine = run(stepper, terms, tau);
  INFO("tau " << 2 * tau << ": predicted " << coarse.predicted << ", measured " << coarse.measured);
  INFO("tau " << tau << ": predicted " << fine.predicted << ", measured " << fine.measured);
  CHECK(std::abs(fine.predicted / fine.measured - 1) < 0.02);
  CHECK(std::abs(fine.predicted / fine.measured - 1) < std::abs(coarse.predicted / coarse.measured - 1));
  CHECK(fine.quadrature < 1e-6 * fine.predicted);
}

template <class K>
modified_terms<double> terms_of(const tree_set& trees, const std::vector<K>& a, int order) {
  const std::vector<bool> wanted = nystrom_trees(trees);
  return make_modified_terms<double>(trees, modified_field(trees, a), wanted, order, 1,
                                     geomint::methods::coefficient_converter<double>{});
}

TEST_CASE("energy prediction: Stormer-Verlet (tableau file) on the pendulum", "[bseries]") {
  const auto method = geomint::methods::read_tableau_file(std::string(GEOMINT_SOURCE_DIR) +
                                                          "/examples/tableaux/stormer_verlet.tableau");
  const tree_set trees(3, 2);
  const std::vector<bool> wanted = nystrom_trees(trees);
  const auto terms = terms_of(trees, elementary_weights(trees, partitioned_form_of(method), &wanted), 2);
  auto stepper = geomint::make_tableau_stepper<pendulum, double>(geomint::methods::nystrom_form_of(method));
  check_convergence(*stepper, terms, 0.05);
}

TEST_CASE("energy prediction: LPF on Gauss-interior nodes, m = 3 (order 4), on the pendulum", "[bseries]") {
  const tree_set trees(5, 2);
  const auto terms = terms_of(trees, elementary_weights(trees, geomint::lpf_tableau<3, geomint::gauss_interior>()), 4);
  auto stepper = geomint::make_scheme_stepper<geomint::lpf<3, geomint::gauss_interior, geomint::lagrange>, pendulum, double>();
  check_convergence(*stepper, terms, 0.1);
}

TEST_CASE("energy prediction: the order is checked against the modified field", "[bseries]") {
  const tree_set trees(5, 2);
  const auto a = elementary_weights(trees, geomint::trapezoidal_tableau());
  CHECK_THROWS_AS(terms_of(trees, a, 3), std::invalid_argument);  // Stormer-Verlet has order 2
  const tree_set small(2, 2);  // trees too small for order p + 1 = 3
  CHECK_THROWS_AS(terms_of(small, elementary_weights(small, geomint::trapezoidal_tableau()), 2), std::invalid_argument);
}

TEST_CASE("energy prediction: the cumulative integral of the rate is exact for cubics", "[bseries]") {
  // r(t) = 1 - 2t + 3t^2 - t^3 has the integral t - t^2 + t^3 - t^4/4 (exact mathematics); the
  // rule is the cubic through four samples on every step, so it is exact in exact arithmetic.
  using Q = boost::multiprecision::cpp_rational;
  const Q h = Q(1) / 3;
  const auto r = [](const Q& t) { return Q(1 - 2 * t + 3 * t * t - t * t * t); };
  const auto integral = [](const Q& t) { return Q(t - t * t + t * t * t - t * t * t * t / 4); };
  for (int N : {1, 2, 3, 4, 7}) {
    std::vector<Q> samples;
    for (int k = 0; k <= N; ++k) samples.push_back(N < 3 ? Q(2 - Q(k) * h) : r(Q(k) * h));  // N < 3: a line (trapezoidal rule)
    const std::vector<Q> I = cumulative_integral(samples, h);
    REQUIRE(I.size() == samples.size());
    for (int k = 0; k <= N; ++k) {
      INFO("N = " << N << ", k = " << k);
      const Q t = Q(k) * h;
      CHECK(I[static_cast<std::size_t>(k)] == (N < 3 ? Q(2 * t - t * t / 2) : integral(t)));
    }
  }
}

}  // namespace bseries_energy_prediction_test
