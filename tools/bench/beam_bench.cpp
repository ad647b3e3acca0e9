// Benchmarks of the beam integrator (double, single thread).
//
//   BM_beam_paper_1000_steps/<scheme>: 1000 steps of the beam paper's section 4 case
//       (101 nodes, dt = 1e-4); the paper's table 2: 13.55 s (MATLAB), 15.95 s (Python).
//   BM_beam_node_scaling/<nodes>: one step of the section 4 case with J + 1 nodes and a time
//       step scaled with ds (same CFL number as the paper); the counter ns_per_node_step must
//       stay flat from 101 to 12801 nodes (linear total cost).
// ns_per_node_step is shown in seconds with an SI prefix (e.g. 250n = 250 ns).
#include <benchmark/benchmark.h>

#include "geomint/beam/beam.hpp"

namespace {

namespace gb = geomint::beam;

void BM_beam_paper_1000_steps(benchmark::State& state) {
  const auto method = state.range(0) == 0 ? gb::scheme::poisson : gb::scheme::hamel;
  const gb::paper_case<double> pc(101);
  for (auto _ : state) {
    state.PauseTiming();
    auto b = pc.make(method);
    state.ResumeTiming();
    b.advance(1000);
    benchmark::DoNotOptimize(b.mu().data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(gb::to_string(method));
  state.counters["ns_per_node_step"] =
      benchmark::Counter(1000.0 * 101.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_beam_paper_1000_steps)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_beam_node_scaling(benchmark::State& state) {
  const int nodes = static_cast<int>(state.range(0));
  const gb::paper_case<double> pc(nodes);
  gb::options<double> opt;
  opt.dt = gb::paper_case<double>::paper_dt() * 100.0 / double(nodes - 1);  // CFL number of the paper
  auto b = pc.make(opt);
  for (auto _ : state) {
    b.step();
    benchmark::DoNotOptimize(b.mu().data());
  }
  state.counters["ns_per_node_step"] =
      benchmark::Counter(double(nodes), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["nodes"] = nodes;
}
BENCHMARK(BM_beam_node_scaling)->Arg(101)->Arg(201)->Arg(401)->Arg(801)->Arg(1601)->Arg(3201)->Arg(6401)->Arg(12801)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
