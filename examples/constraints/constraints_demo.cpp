/// Holonomic constraints (LPF paper, example 3.3; docs/design.md, "Constraints"), three studies written as CSV:
///   circle.csv     the particle on the unit circle, tau = 0.1: the constrained LPF integrator
///                  (m = 2), constraint violation and energy error against time;
///   circle_paper23.csv  the paper's scheme (23) as printed (two-step), until it leaves the circle;
///   spherical.csv  the spherical pendulum: energy, vertical angular momentum, constraint;
///   double.csv     the planar double pendulum in Cartesian coordinates (two rods, constrained
///                  LPF) and in angles (unconstrained LPF), positions side by side.
/// Usage: geomint-constraints-demo OUT_DIR [--circle-steps N]
#include <geomint/core/multiprecision.hpp>  // Boost.Multiprecision scalars (included after geomint below)
#include <geomint/constrained_integrator.hpp>
#include <geomint/integrator.hpp>
#include <geomint/mechanics/constrained_systems.hpp>
#include <geomint/schemes/paper23.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>

namespace {
using geomint::vec;
using T = double;

int usage(const char* message) {
  if (message) std::cerr << "geomint-constraints-demo: " << message << "\n";
  std::cerr << "usage: geomint-constraints-demo OUT_DIR [--circle-steps N]\n"
               "  writes OUT_DIR/circle.csv, spherical.csv, double.csv and prints a summary\n";
  return 2;
}

std::ofstream open_csv(const std::string& path, const char* header) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << std::setprecision(std::numeric_limits<T>::max_digits10) << header << "\n";
  return out;
}

/// Scheme (23) as printed, from x^0 = (1, 0) and x^1 = (cos tau, sin tau), in the scalar T_:
/// the first step at which | |x^k|^2 - 1 | exceeds 1e-3, or -1 if it never does within `steps`.
/// Linearised about the circle, (23) leaves the radial component r of a perturbation with
/// r_{k-1} + 6 r_k + r_{k+1} = 0 (the normalisations remove it), whose roots are -3 -+ 2 sqrt 2:
/// any radial defect, the scheme's own truncation error included, grows by 3 + 2 sqrt 2 = 5.83
/// per step. Running it in 16, 50 and 100 digits separates round-off from that instability.
template <class T_>
long paper23_escape_step(long steps, std::ofstream* csv) {
  const T_ tau = T_(1) / T_(10);
  using std::cos;
  using std::sin;
  vec<T_, 2> prev(T_(1), T_(0)), curr(T_(cos(tau)), T_(sin(tau)));
  const T_ threshold = T_(1) / T_(1000);
  long escape = -1;
  for (long k = 1; k <= steps; ++k) {
    vec<T_, 2> next;
    try {
      next = geomint::paper23_step<T_>(prev, curr, k);
    } catch (const geomint::integration_error&) {
      break;  // Newton fails once the iterates are far off the circle; the escape is recorded
    }
    prev = curr;
    curr = next;
    using std::abs;
    const T_ violation = abs(T_(curr.squaredNorm() - T_(1)));
    if (csv && violation <= T_(1)) {
      // The scheme's own velocity at t_k: the fitted parabola's slope (x^{k-1} - 4 eta + 3 x^k)/tau
      // with eta = (x^{k-1} + x^k)/|x^{k-1} + x^k| (section 3.1 and example 3.3).
      const vec<T_, 2> eta = (prev + curr).normalized();
      const vec<T_, 2> velocity = (prev - T_(4) * eta + T_(3) * curr) / tau;
      *csv << k + 1 << ',' << T_(k + 1) * tau << ',' << violation << ',' << abs(T_(velocity.squaredNorm() / T_(2) - T_(1) / T_(2))) << "\n";
    }
    if (violation > threshold && escape < 0) escape = k + 1;
    if (violation > T_(1)) break;  // far off the circle: the CSV has shown the growth
  }
  return escape;
}

void circle_study(const std::string& dir, long steps) {
  using geomint::systems::free_particle_2d;
  using geomint::systems::unit_circle;
  const T tau = T(1) / 10;
  geomint::constrained_integrator<geomint::constrained_lpf<2>, free_particle_2d, unit_circle, T> lpf({}, {}, tau);
  auto s = lpf.initial_state(vec<T, 2>(1, 0), vec<T, 2>(0, 1));
  const T energy0 = lpf.energy(s);
  auto out = open_csv(dir + "/circle.csv", "step,t,lpf_constraint,lpf_energy_error");
  const long every = std::max(1L, steps / 2000);
  T worst_f = 0, worst_e = 0;
  const auto start = std::chrono::steady_clock::now();
  for (long k = 1; k <= steps; ++k) {
    lpf.step(s);
    const T f = lpf.violation(s), e = std::abs(lpf.energy(s) - energy0);
    worst_f = std::max(worst_f, f);
    worst_e = std::max(worst_e, e);
    if (k % every == 0 || k == steps) out << k << ',' << T(k) * tau << ',' << f << ',' << e << "\n";
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << std::setprecision(3) << "circle, tau = 0.1, constrained LPF (m = 2), " << steps << " steps (t = "
            << T(steps) * tau << ", " << seconds << " s): max | |q|^2 - 1 | = " << worst_f
            << ", max |H - H0| = " << worst_e << ", final angle error = "
            << std::abs(std::remainder(std::atan2(s.q[1], s.q[0]) - T(steps) * tau, 2 * std::numbers::pi)) << "\n";
  auto csv23 = open_csv(dir + "/circle_paper23.csv", "step,t,paper23_constraint,paper23_energy_error");
  const long escape16 = paper23_escape_step<T>(steps, &csv23);
  const long escape50 = paper23_escape_step<boost::multiprecision::cpp_bin_float_50>(steps, nullptr);
  const long escape100 = paper23_escape_step<boost::multiprecision::cpp_bin_float_100>(steps, nullptr);
  std::cout << "circle, scheme (23) as printed: | |x^k|^2 - 1 | passes 1e-3 at step " << escape16 << " in double, "
            << escape50 << " in 50 digits, " << escape100 << " in 100 digits (radial defects grow by 3 + 2 sqrt 2 per step)\n";
}

void spherical_study(const std::string& dir) {
  using geomint::systems::spherical_pendulum;
  using geomint::systems::unit_sphere;
  const T tau = T(1) / 20;
  const long steps = 100000;
  geomint::constrained_integrator<geomint::constrained_lpf<3, geomint::gauss_interior>, spherical_pendulum,
                                        unit_sphere, T>
      lpf({}, {}, tau);
  const T r = std::sqrt(T(1) / 2);
  auto s = lpf.initial_state(vec<T, 3>(r, 0, -r), vec<T, 3>(0, T(4) / 5, 0));
  const T energy0 = lpf.energy(s), momentum0 = spherical_pendulum::conserved<T>(s.q, s.p);
  auto out = open_csv(dir + "/spherical.csv", "step,t,x,y,z,energy_error,momentum_error,constraint");
  T worst_e = 0, worst_l = 0, worst_f = 0;
  for (long k = 1; k <= steps; ++k) {
    lpf.step(s);
    const T e = std::abs(lpf.energy(s) - energy0), l = std::abs(spherical_pendulum::conserved<T>(s.q, s.p) - momentum0);
    worst_e = std::max(worst_e, e);
    worst_l = std::max(worst_l, l);
    worst_f = std::max(worst_f, lpf.violation(s));
    if (k % 50 == 0) out << k << ',' << T(k) * tau << ',' << s.q[0] << ',' << s.q[1] << ',' << s.q[2] << ',' << e << ',' << l << ',' << lpf.violation(s) << "\n";
  }
  std::cout << std::setprecision(3) << "spherical pendulum, constrained LPF m = 3 Gauss interior, tau = 0.05, " << steps
            << " steps: max |H - H0| = " << worst_e << ", max |L_z - L_z0| = " << worst_l << ", max |f| = " << worst_f << "\n";
}

void double_pendulum_study(const std::string& dir) {
  using geomint::systems::double_pendulum_angles;
  using geomint::systems::double_pendulum_cartesian;
  using geomint::systems::double_pendulum_rods;
  const T tau = T(1) / 100, a = 1, b = T(1) / 2;
  const long steps = 2000;
  geomint::constrained_integrator<geomint::constrained_lpf<3, geomint::gauss_lobatto>, double_pendulum_cartesian,
                                        double_pendulum_rods, T>
      cartesian({}, {}, tau);
  geomint::integrator<geomint::lpf<3, geomint::gauss_lobatto>, double_pendulum_angles, T> angular({}, tau);
  auto sc = cartesian.initial_state(vec<T, 4>(std::sin(a), -std::cos(a), std::sin(a) + std::sin(b), -std::cos(a) - std::cos(b)),
                                    vec<T, 4>::Zero());
  auto sa = angular.initial_state(vec<T, 2>(a, b), vec<T, 2>::Zero());
  const T energy0 = cartesian.energy(sc);
  auto out = open_csv(dir + "/double.csv", "step,t,x2_cartesian,y2_cartesian,x2_angles,y2_angles,difference,energy_error,constraint");
  T worst_d = 0, worst_e = 0, worst_f = 0;
  for (long k = 1; k <= steps; ++k) {
    cartesian.step(sc);
    angular.step(sa);
    const T x2 = std::sin(sa.q[0]) + std::sin(sa.q[1]), y2 = -std::cos(sa.q[0]) - std::cos(sa.q[1]);
    const T d = std::hypot(sc.q[2] - x2, sc.q[3] - y2), e = std::abs(cartesian.energy(sc) - energy0);
    worst_d = std::max(worst_d, d);
    worst_e = std::max(worst_e, e);
    worst_f = std::max(worst_f, cartesian.violation(sc));
    out << k << ',' << T(k) * tau << ',' << sc.q[2] << ',' << sc.q[3] << ',' << x2 << ',' << y2 << ',' << d << ',' << e << ',' << cartesian.violation(sc) << "\n";
  }
  std::cout << std::setprecision(3) << "double pendulum, m = 3 Lobatto, tau = 0.01, t = 0..20: max distance between the "
            << "Cartesian (constrained) and angle (unconstrained) lower bobs = " << worst_d
            << ", Cartesian max |H - H0| = " << worst_e << ", max |f| = " << worst_f << "\n";
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return usage(argc < 2 ? "missing OUT_DIR" : "OUT_DIR must come first");
  const std::string dir = argv[1];
  long circle_steps = 1000000;
  for (int i = 2; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--circle-steps" && i + 1 < argc) {
      char* end = nullptr;
      circle_steps = std::strtol(argv[++i], &end, 10);
      if (*end != '\0' || circle_steps < 1) return usage("--circle-steps needs a positive integer");
    } else {
      return usage(("unknown argument '" + flag + "'").c_str());
    }
  }
  try {
    circle_study(dir, circle_steps);
    spherical_study(dir);
    double_pendulum_study(dir);
  } catch (const std::exception& e) {
    std::cerr << "geomint-constraints-demo: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
