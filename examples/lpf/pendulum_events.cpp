/// Event location on the dense output: the zero crossings theta(t) = 0 of the pendulum
/// theta'' + sin theta = 0 released from rest at theta0, found by root finding (Newton,
/// safeguarded by bisection) on each step's fitted path (integrator::step_with_path), in
/// double and in 50 digits.
///
/// Exact crossings: released at rest, the pendulum passes theta = 0 at t = (2j + 1) K(k),
/// k = sin(theta0 / 2), with K the complete elliptic integral of the first kind, computed here
/// by the arithmetic-geometric mean, K(k) = pi / (2 AGM(1, sqrt(1 - k^2))) (Abramowitz & Stegun
/// 17.6): a reference independent of the integrator.
///
/// For each step size it prints the worst crossing error of the path and, for contrast, of the
/// straight line between the nodes; then the observed orders. LPF on Gauss nodes with m = 4 has
/// nodes of order 2(m - 1) = 6 and a path of order m + 1 = 5 (docs/guide/your_own_system.md,
/// "Dense output"); linear interpolation has order 2 in general (3 at these crossings, where
/// the acceleration -sin theta vanishes). Exits 1 if a crossing is missing or the
/// observed order of the path falls below m + 1 - 1/2.
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"

using namespace geomint;

namespace {

/// The arithmetic-geometric mean of a, b > 0.
template <class T>
T agm(T a, T b) {
  using std::abs;
  using std::sqrt;
  for (int i = 0; i < 100 && abs(T(a - b)) > T(4) * std::numeric_limits<T>::epsilon() * a; ++i) {
    const T next = (a + b) / T(2);
    b = sqrt(T(a * b));
    a = next;
  }
  return a;
}

/// K(k) with k = sin(theta0 / 2): sqrt(1 - k^2) = cos(theta0 / 2).
template <class T>
T quarter_period(const T& theta0) {
  using std::cos;
  return boost::math::constants::pi<T>() / (T(2) * agm(T(1), T(cos(T(theta0 / T(2))))));
}

/// The root of x(t) in [a, b] (x(a), x(b) of opposite signs): Newton on x with xdot from the
/// path, falling back to bisection whenever a Newton step leaves the bracket.
template <class Path, class T>
T crossing(const Path& path, T a, T b) {
  using std::abs;
  const T fa = path.position(a)[0];
  T t = (a + b) / T(2);
  for (int i = 0; i < 200; ++i) {
    const T f = path.position(t)[0];
    if (f == T(0)) return t;
    if ((f < T(0)) == (fa < T(0)))
      a = t;
    else
      b = t;
    const T v = path.velocity(t)[0];
    T next = v != T(0) ? T(t - f / v) : T((a + b) / T(2));
    if (!(next > a && next < b)) next = (a + b) / T(2);
    const bool converged = abs(T(next - t)) <= T(4) * std::numeric_limits<T>::epsilon() * abs(t);
    t = next;
    if (converged) break;
  }
  return t;
}

template <class T>
struct event_errors {
  int found = 0;
  T path = T(0), linear = T(0);
};

/// Integrates over [0, t_end] with `steps_per_unit` steps per unit time and locates every
/// crossing; returns the worst errors of the path's and of the linear interpolant's crossings.
template <class T>
event_errors<T> locate(const T& theta0, int steps_per_unit, const T& t_end, bool print) {
  using std::abs;
  using Scheme = lpf_gauss<4>;
  const T tau = T(1) / T(steps_per_unit), K = quarter_period(theta0);
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto s = I.initial_state(vec<T, 1>::Constant(theta0), vec<T, 1>::Zero());
  event_errors<T> e;
  while (s.t < t_end) {
    const T q0 = s.q[0];
    const auto path = I.step_with_path(s);
    const T q1 = s.q[0];
    if ((q0 < T(0)) == (q1 < T(0))) continue;
    const T t = crossing(path, path.t_begin(), path.t_end());
    const T line = path.t_begin() + path.tau() * q0 / (q0 - q1);  // the secant through the nodes
    const T exact = T(2 * e.found + 1) * K;
    const T err = abs(T(t - exact)), lin = abs(T(line - exact));
    if (err > e.path) e.path = err;
    if (lin > e.linear) e.linear = lin;
    if (print)
      std::printf("  crossing %d: t = %.17g, exact (2j+1)K = %.17g, error %.3e (linear interpolation %.3e)\n",
                  e.found + 1, static_cast<double>(t), static_cast<double>(exact), static_cast<double>(err),
                  static_cast<double>(lin));
    ++e.found;
  }
  return e;
}

template <class T>
bool study(const char* label) {
  using std::log2;
  const T theta0 = T(2);  // a large swing: the period is 1.35 times that of small oscillations
  const T K = quarter_period(theta0);
  const T t_end = T(12) * K;  // three periods: six crossings
  std::printf("%s: theta0 = 2, K(sin 1) = %.17g, period 4K = %.17g, LPF m = 4 on Gauss nodes\n", label,
              static_cast<double>(K), static_cast<double>(T(4) * K));
  const int expected = 6;
  bool ok = true;
  event_errors<T> previous;
  for (int steps : {8, 16, 32}) {
    const bool print = steps == 8;
    if (print) std::printf(" tau = 1/%d:\n", steps);
    const event_errors<T> e = locate(theta0, steps, t_end, print);
    std::printf(" tau = 1/%-3d crossings %d, worst error: path %.3e, linear interpolation %.3e", steps, e.found,
                static_cast<double>(e.path), static_cast<double>(e.linear));
    if (e.found != expected) {
      std::printf("  [expected %d crossings]\n", expected);
      ok = false;
      continue;
    }
    if (steps > 8) {
      const double p = static_cast<double>(T(log2(T(previous.path / e.path))));
      const double l = static_cast<double>(T(log2(T(previous.linear / e.linear))));
      std::printf("; observed orders: path %.2f, linear %.2f", p, l);
      if (p < 4.5) {
        std::printf("  [below m + 1 - 1/2 = 4.5]");
        ok = false;
      }
    }
    std::printf("\n");
    previous = e;
  }
  return ok;
}

}  // namespace

int main() {
  const bool ok_double = study<double>("double");
  const bool ok_50 = study<boost::multiprecision::cpp_bin_float_50>("cpp_bin_float_50");
  return ok_double && ok_50 ? 0 : 1;
}
