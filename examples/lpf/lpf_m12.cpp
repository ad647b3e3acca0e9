/// LPF of degree m = 12 on Gauss-interior nodes (order 2m - 2 = 22) for the pendulum in double:
/// theta0 = 1 at rest, tau = 0.5, 2000 steps (t = 1000); prints the largest energy error.
/// Also a compile-time check: this program instantiates one m = 12 engine (docs/results/compile_time.md reports its
/// compile time).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"

int main() {
  using namespace geomint;
  using T = double;
  using Scheme = lpf<12, gauss_interior, lagrange>;
  const T tau = T(1) / T(2);
  const long steps = 2000;
  integrator<Scheme, systems::pendulum, T> I(systems::pendulum{}, tau);
  auto s = I.initial_state(vec<T, 1>(T(1)), vec<T, 1>(T(0)));
  const T E0 = I.energy(s);
  T worst = 0;
  long iterations = 0;
  for (long k = 0; k < steps; ++k) {
    const step_status st = I.try_step(s);
    if (!st) {
      std::fprintf(stderr, "%s\n", st.message().c_str());
      return 1;
    }
    iterations += st.iterations;
    worst = std::max(worst, std::abs(I.energy(s) - E0));
  }
  std::printf("%s, pendulum, double, tau = %g, %ld steps (t = %g): theta = %.17g, max |E - E0| = %.3e, "
              "%.2f Newton iterations per step\n",
              Scheme::name().c_str(), tau, steps, double(s.t), s.q[0], worst, double(iterations) / double(steps));
  return 0;
}
