/// Kepler problem, e = 0.5 (a = 1, period 2 pi), tau = 0.01, 10^5 steps (about 159 orbits):
/// energy and angular momentum errors for LPF schemes and the classical variational integrators.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"

using namespace geomint;
using T = double;
using V = vec<T, 2>;

namespace {
struct series {
  std::string name;
  std::vector<T> dE, dJ, x, y;
  T max_dE = 0, max_dJ = 0, seconds = 0;
};

template <class Scheme>
series run(const std::string& name, long steps, long every) {
  const T tau = T(1) / T(100);
  integrator<Scheme, systems::kepler, T> I(systems::kepler{}, tau);
  V q0, qdot0;
  systems::kepler::initial_data(q0, qdot0);  // e = 1/2 at pericentre
  auto s = I.initial_state(q0, qdot0);
  const T E0 = I.energy(s), J0 = systems::kepler::conserved<T>(s.q, s.p);
  series r;
  r.name = name;
  const auto start = std::chrono::steady_clock::now();
  for (long k = 1; k <= steps; ++k) {
    I.step(s);
    const T dE = I.energy(s) - E0, dJ = systems::kepler::conserved<T>(s.q, s.p) - J0;
    r.max_dE = std::max(r.max_dE, std::abs(dE));
    r.max_dJ = std::max(r.max_dJ, std::abs(dJ));
    if (k % every == 0) {
      r.dE.push_back(dE);
      r.dJ.push_back(dJ);
      r.x.push_back(s.q[0]);
      r.y.push_back(s.q[1]);
    }
  }
  r.seconds = std::chrono::duration<T>(std::chrono::steady_clock::now() - start).count();
  return r;
}
}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  const long steps = 100000, every = 100;
  std::vector<series> all;
  all.push_back(run<lpf<2, equispaced>>("lpf_m2", steps, every));
  all.push_back(run<lpf<3, gauss_interior>>("lpf_m3_gauss", steps, every));
  all.push_back(run<lpf<3, equispaced>>("lpf_m3_equispaced", steps, every));
  all.push_back(run<midpoint_vi>("midpoint", steps, every));
  all.push_back(run<trapezoidal_vi>("trapezoidal", steps, every));
  std::ofstream csv(dir + "/kepler.csv");
  csv.precision(17);
  csv << "t";
  for (const auto& r : all) csv << ',' << r.name << "_x," << r.name << "_y," << r.name << "_dE," << r.name << "_dJ";
  csv << '\n';
  for (std::size_t i = 0; i < all[0].dE.size(); ++i) {
    csv << T(static_cast<long>(i + 1) * every) / T(100);
    for (const auto& r : all) csv << ',' << r.x[i] << ',' << r.y[i] << ',' << r.dE[i] << ',' << r.dJ[i];
    csv << '\n';
  }
  std::printf("Kepler e = 0.5, tau = 0.01, %ld steps (t = %ld)\n", steps, steps / 100);
  std::printf("%-20s %-14s %-14s %s\n", "scheme", "max|dE|", "max|dJ|", "seconds");
  for (const auto& r : all) std::printf("%-20s %-14.3e %-14.3e %.2f\n", r.name.c_str(), r.max_dE, r.max_dJ, r.seconds);
  std::printf("wrote %s/kepler.csv\n", dir.c_str());
  return 0;
}
