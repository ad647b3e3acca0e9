// Benchmarks of one step of geomint's variational integrators (single thread).
//
//   <system>/<scalar>/<scheme>: one step of the one-step form (q_k, p_k) -> (q_{k+1}, p_{k+1})
//   along the trajectory (each iteration continues from the previous state):
//     pendulum: theta0 = 1, thetadot0 = 0, tau = 0.1;
//     kepler:   e = 0.5, q0 = (0.5, 0), qdot0 = (0, sqrt 3), tau = 0.05;
//   schemes: lpf m = 2..8 on each node family (equispaced, lobatto, chebyshev, gauss-interior;
//   Lagrange basis), midpoint, trapezoidal, galerkin m = 2..4; scalars double and
//   cpp_bin_float_50.
// Counter newton_its: average Newton iterations per step.
//
//   workprecision/<system>/<scalar>/<scheme>/<steps>: one whole run of geomint-workprecision's
//   geomint_method at its best point on the pendulum (double, T = 1000, 715 steps: final error
//   6e-11; cpp_bin_float_50, T = 100, 142 steps: 1.4e-30; tools/workprecision): the
//   integrator constructed, then the steps from the initial data, compensated summation on.
//   Counters: sweeps (iterations) per step and the run's CPU time per step; `construct` alone: the
//   integrator's construction (the scheme's coefficients), which the run includes.
//
//   stage-forces/<system>/<scheme>/<steps>/packs|one-by-one: the same whole run in double with the
//   fixed-point sweeps' stage forces on SIMD packs (core/simd.hpp) or one by one
//   (newton_options::simd_forces), for the systems that opt in and for Kepler on packs, which the
//   library's Kepler does not opt in to: the measurement behind that choice.
// Filter with --benchmark_filter, e.g. --benchmark_filter='double/lpf-m[468]-gauss'.
#include <string>
#include <string_view>
#include <utility>

#include <benchmark/benchmark.h>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "geomint/integrator.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"

namespace {

/// systems::kepler with its forces on SIMD packs.
struct kepler_on_packs : geomint::natural<kepler_on_packs, 2> {
  static constexpr std::string_view name = "kepler-on-packs";
  static constexpr bool stage_parallel_forces = true;
  template <class T>
  static void initial_data(geomint::vec<T, 2>& q, geomint::vec<T, 2>& qdot) { geomint::systems::kepler::initial_data(q, qdot); }
  template <class S>
  static S potential(const geomint::vec<S, 2>& q) { return geomint::systems::kepler::potential<S>(q); }
  template <class S>
  static geomint::vec<S, 2> potential_gradient(const geomint::vec<S, 2>& q) { return geomint::systems::kepler::potential_gradient<S>(q); }
  template <class T>
  static geomint::mat<T, 2> mass_matrix() { return geomint::mat<T, 2>::Identity(); }
};

using mp50 = boost::multiprecision::cpp_bin_float_50;

/// The system's initial data (mechanics/systems.hpp).
template <class Sys, class T>
std::pair<geomint::vec<T, Sys::dof>, geomint::vec<T, Sys::dof>> initial() {
  geomint::vec<T, Sys::dof> q, v;
  Sys::initial_data(q, v);
  return {q, v};
}

template <class Sys, class T>
T step_size() {
  return Sys::dof == 1 ? T(1) / T(10) : T(1) / T(20);
}

template <class Scheme, class Sys, class T>
void BM_step(benchmark::State& state) {
  geomint::integrator<Scheme, Sys, T> I(Sys{}, step_size<Sys, T>());
  const auto [q0, v0] = initial<Sys, T>();
  auto s = I.initial_state(q0, v0);
  long iterations = 0, steps = 0;
  for (auto _ : state) {
    const geomint::step_status st = I.try_step(s);
    if (!st) {
      state.SkipWithError(st.message().c_str());
      break;
    }
    iterations += st.iterations;
    ++steps;
    benchmark::DoNotOptimize(s.q.data());
    benchmark::DoNotOptimize(s.p.data());
  }
  state.counters["newton_its"] = steps ? double(iterations) / double(steps) : 0.0;
}

/// A whole run as geomint-workprecision's geomint_method times it (tools/workprecision/methods.hpp).
template <class Scheme, class Sys, class T>
void BM_run(benchmark::State& state, long steps, long t_end, bool stop_on_rate, bool simd_forces) {
  const auto [q0, v0] = initial<Sys, T>();
  long iterations = 0, taken = 0;
  for (auto _ : state) {
    geomint::integrator<Scheme, Sys, T> I(Sys{}, T(T(t_end) / T(steps)));
    I.set_compensated_summation(true);
    if (stop_on_rate) I.options().stop_on_rate = true;
    I.options().simd_forces = simd_forces;
    auto s = I.initial_state(q0, v0);
    for (long k = 0; k < steps; ++k) {
      const geomint::step_status st = I.try_step(s);
      if (!st) {
        state.SkipWithError(st.message().c_str());
        return;
      }
      iterations += st.iterations;
      ++taken;
    }
    benchmark::DoNotOptimize(s.q.data());
  }
  state.counters["sweeps_per_step"] = taken ? double(iterations) / double(taken) : 0.0;
  // CPU seconds of the whole run (construction included) per step, printed with an SI prefix.
  state.counters["time_per_step"] =
      benchmark::Counter(double(steps), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// The integrator's construction alone.
template <class Scheme, class Sys, class T>
void BM_construct(benchmark::State& state) {
  for (auto _ : state) {
    geomint::integrator<Scheme, Sys, T> I(Sys{}, T(1) / T(10));
    benchmark::DoNotOptimize(&I);
  }
}

template <class Scheme, class Sys, class T>
void add_run(const std::string& scalar, const std::string& scheme, long steps, long t_end, bool stop_on_rate) {
  const std::string name = "workprecision/" + std::string(Sys::name) + "/" + scalar + "/" + scheme + "/";
  benchmark::RegisterBenchmark((name + std::to_string(steps)).c_str(), &BM_run<Scheme, Sys, T>, steps, t_end, stop_on_rate, true)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark((name + "construct").c_str(), &BM_construct<Scheme, Sys, T>)->Unit(benchmark::kMicrosecond);
}

template <class Scheme, class Sys>
void add_stage_forces(const std::string& scheme, long steps, long t_end) {
  const std::string name = "stage-forces/" + std::string(Sys::name) + "/" + scheme + "/" + std::to_string(steps) + "/";
  for (const bool packs : {true, false})
    benchmark::RegisterBenchmark((name + (packs ? "packs" : "one-by-one")).c_str(), &BM_run<Scheme, Sys, double>, steps, t_end,
                                 false, packs)
        ->Unit(benchmark::kMicrosecond);
}

template <class Scheme, class Sys, class T>
void add(const std::string& scalar, const std::string& scheme) {
  const std::string name = std::string(Sys::name) + "/" + scalar + "/" + scheme;
  benchmark::RegisterBenchmark(name.c_str(), &BM_step<Scheme, Sys, T>)->Unit(benchmark::kMicrosecond);
}

template <int M, class Sys, class T>
void add_lpf(const std::string& scalar) {
  using namespace geomint;
  const std::string m = "lpf-m" + std::to_string(M) + "-";
  add<lpf<M, equispaced>, Sys, T>(scalar, m + "equispaced");
  add<lpf<M, gauss_lobatto>, Sys, T>(scalar, m + "lobatto");
  add<lpf<M, chebyshev_lobatto>, Sys, T>(scalar, m + "chebyshev");
  add<lpf<M, gauss_interior>, Sys, T>(scalar, m + "gauss-interior");
}

template <class Sys, class T>
void add_all(const std::string& scalar) {
  using namespace geomint;
  add<midpoint_vi, Sys, T>(scalar, "midpoint");
  add<trapezoidal_vi, Sys, T>(scalar, "trapezoidal");
  add<galerkin_vi<2>, Sys, T>(scalar, "galerkin-m2");
  add<galerkin_vi<3>, Sys, T>(scalar, "galerkin-m3");
  add<galerkin_vi<4>, Sys, T>(scalar, "galerkin-m4");
  [&]<int... M>(std::integer_sequence<int, M...>) { (add_lpf<M + 2, Sys, T>(scalar), ...); }
  (std::make_integer_sequence<int, 7>{});
}

}  // namespace

int main(int argc, char** argv) {
  add_all<geomint::systems::pendulum, double>("double");
  add_all<geomint::systems::kepler, double>("double");
  add_all<geomint::systems::pendulum, mp50>("cpp_bin_float_50");
  add_all<geomint::systems::kepler, mp50>("cpp_bin_float_50");
  using geomint::lpf_fixed_point;
  add_run<lpf_fixed_point<10>, geomint::systems::pendulum, double>("double", "lpf-fixed-point-m10-stop-on-rate", 715, 1000, true);
  add_run<lpf_fixed_point<16>, geomint::systems::pendulum, mp50>("cpp_bin_float_50", "lpf-fixed-point-m16", 142, 100, false);
  // The runs near 1e-10 of geomint-workprecision's ladders (T = 1000; the outer solar system 10^5 days).
  add_stage_forces<lpf_fixed_point<10>, geomint::systems::pendulum>("lpf-fixed-point-m10", 715, 1000);
  add_stage_forces<lpf_fixed_point<12>, kepler_on_packs>("lpf-fixed-point-m12", 2402, 1000);
  add_stage_forces<lpf_fixed_point<10>, geomint::zoo::outer_solar>("lpf-fixed-point-m10", 1000, 100000);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
