// geomint-beam: the geometrically exact beam of the beam paper (section 4 by default) with the
// Poisson integrator (scheme 53-55) or the Hamel (trapezoidal) variant.
//
//   geomint-beam [--steps N] [--dt DT] [--nodes J+1] [--scheme poisson|hamel] [--every K]
//                [--csv FILE] [--centreline FILE] [--snapshots M] [--drift FILE]
//                [--cayley previous|current|midpoint] [--reconstruction per-node|strain]
//
// CSV: step,t,kinetic,potential,total,Px,Py,Pz,Lx,Ly,Lz every K steps, step 0 included, with
// max_digits10 digits. The wall time of the stepping (without diagnostics and output) and of
// the whole run is printed.
#include <chrono>
#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>
#include <string>
#include <vector>

#include "cli.hpp"
#include "geomint/beam/beam.hpp"

namespace {

using T = double;
namespace gb = geomint::beam;

const char* usage_text =
    "usage: geomint-beam [options]\n"
    "  Runs the geometrically exact beam of the beam paper (Chen & Shi 2025, section 4).\n"
    "  --steps N          number of time steps (default 1000; 0..10^12)\n"
    "  --dt DT            time step in s (default 1e-4)\n"
    "  --nodes N          number of nodes J+1 (default 101; 2..10^6); the initial data of section 4\n"
    "                     use sin(j pi / J)\n"
    "  --scheme S         poisson (eq. 53, default) or hamel (trapezoidal bracket term)\n"
    "  --every K          write a CSV row every K steps, step 0 included (default 1)\n"
    "  --csv FILE         write step,t,kinetic,potential,total,Px,Py,Pz,Lx,Ly,Lz to FILE\n"
    "  --centreline FILE  write step,t,node,s,x,y,z of the centreline at --snapshots times\n"
    "  --snapshots M      number of evenly spaced centreline snapshots (default 6, 2..10^4)\n"
    "  --drift FILE       write step,t,max_position,max_rotation: per-node reconstruction (55)\n"
    "                     against the strain-consistent one, every K steps\n"
    "                     (FILE '-' is standard output; each output needs a file of its own;\n"
    "                     a file appears, whole, when the run ends)\n"
    "  --cayley V         velocity in (55): previous (zeta^n, as printed; default), current\n"
    "                     (zeta^{n+1}) or midpoint\n"
    "  --reconstruction R per-node (default) or strain: configurations used for the momentum\n"
    "                     and the centreline\n"
    "  --help             this text\n"
    "  Flags take their value as --flag V or --flag=V. Exit status: 0 ok, 2 bad command line,\n"
    "  3 a step failed (message on stderr), 4 an output could not be written.\n";

struct config {
  long steps = 1000;
  double dt = 1e-4;
  long nodes = 101;
  gb::scheme method = gb::scheme::poisson;
  long every = 1;
  std::string csv, centreline, drift;
  long snapshots = 6;
  gb::cayley_velocity velocity = gb::cayley_velocity::previous;
  gb::reconstruction recon = gb::reconstruction::per_node;
};

/// The stated bounds of the counts.
constexpr long max_steps = 1'000'000'000'000L, max_nodes = 1000000;

/// Fills c from the command line; returns the exit status when the tool should stop (--help,
/// usage error).
std::optional<int> parse(int argc, char** argv, config& c) {
  namespace cli = geomint::cli;
  cli::parser cl("geomint-beam", usage_text);
  cl.value("--steps", [&](const std::string& v) { c.steps = cli::parse_integer<long>("--steps", v, 0, max_steps); })
      .value("--dt", [&](const std::string& v) { c.dt = cli::parse_real("--dt", v, cli::real_bound::positive); })
      .value("--nodes", [&](const std::string& v) { c.nodes = cli::parse_integer<long>("--nodes", v, 2, max_nodes); })
      .value("--every", [&](const std::string& v) { c.every = cli::parse_integer<long>("--every", v, 1, max_steps); })
      .value("--snapshots", [&](const std::string& v) { c.snapshots = cli::parse_integer<long>("--snapshots", v, 2, 10000); })
      .output("--csv", c.csv)
      .output("--centreline", c.centreline)
      .output("--drift", c.drift)
      .value("--scheme", [&](const std::string& v) {
        c.method = cli::parse_choice("--scheme", v, {"poisson", "hamel"}) == "poisson" ? gb::scheme::poisson : gb::scheme::hamel;
      })
      .value("--cayley", [&](const std::string& v) {
        const std::string x = cli::parse_choice("--cayley", v, {"previous", "current", "midpoint"});
        c.velocity = x == "previous"  ? gb::cayley_velocity::previous
                     : x == "current" ? gb::cayley_velocity::current
                                      : gb::cayley_velocity::midpoint;
      })
      .value("--reconstruction", [&](const std::string& v) {
        c.recon = cli::parse_choice("--reconstruction", v, {"per-node", "strain"}) == "per-node"
                      ? gb::reconstruction::per_node
                      : gb::reconstruction::strain_consistent;
      });
  return cl.parse(argc, argv);
}

/// Values joined by commas, at max_digits10 digits (a CSV row without its newline).
template <class... Values>
std::string csv_row(const Values&... values) {
  std::ostringstream out;
  out << std::setprecision(std::numeric_limits<T>::max_digits10);
  bool first = true;
  ((out << (first ? "" : ",") << values, first = false), ...);
  return out.str();
}

}  // namespace

namespace cli = geomint::cli;

/// The run of a parsed command line; returns the exit status.
int run(const config& c) {
  using clock = std::chrono::steady_clock;
  const auto t_start = clock::now();

  const gb::paper_case<T> pc(static_cast<int>(c.nodes));
  gb::options<T> opt;
  opt.dt = c.dt;
  opt.method = c.method;
  opt.velocity = c.velocity;
  opt.configurations = c.recon;
  gb::integrator<T> beam = pc.make(opt);

  // The output files, each written to a temporary file and renamed over its path when every
  // row was written (a failed write stops the run with its reason and leaves the path as it was).
  cli::csv_file csv_file, centreline_file, drift_file;
  for (auto [file, path] : {std::pair{&csv_file, &c.csv}, {&centreline_file, &c.centreline}, {&drift_file, &c.drift}})
    if (!path->empty() && !file->open(*path)) {
      std::cerr << "geomint-beam: " << file->error() << '\n';
      return cli::exit_output;
    }
  cli::csv_file* csv = csv_file.is_open() ? &csv_file : nullptr;
  cli::csv_file* cl = centreline_file.is_open() ? &centreline_file : nullptr;
  cli::csv_file* dr = drift_file.is_open() ? &drift_file : nullptr;
  if (csv) csv->row("step,t,kinetic,potential,total,Px,Py,Pz,Lx,Ly,Lz");
  if (cl) cl->row("step,t,node,s,x,y,z");
  if (dr) dr->row("step,t,max_position,max_rotation");
  auto outputs_ok = [&] { return (!csv || csv->ok()) && (!cl || cl->ok()) && (!dr || dr->ok()); };

  std::vector<long> snap;
  for (long i = 0; i < c.snapshots; ++i) snap.push_back((c.steps * i) / (c.snapshots - 1));

  const gb::diagnostics<T> d0 = beam.diagnose();
  T max_energy_error = 0, max_dP = 0, max_dL = 0;
  auto record = [&](long n) {
    if (n % c.every == 0 || n == c.steps) {
      const gb::diagnostics<T> d = beam.diagnose();
      max_energy_error = std::max(max_energy_error, std::abs(d.total - d0.total));
      max_dP = std::max(max_dP, (d.P - d0.P).norm());
      max_dL = std::max(max_dL, (d.L - d0.L).norm());
      if (csv && n % c.every == 0)
        csv->row(csv_row(d.step, d.t, d.kinetic, d.potential, d.total, d.P(0), d.P(1), d.P(2), d.L(0), d.L(1), d.L(2)));
      if (dr && n % c.every == 0) {
        const auto x = beam.drift();
        dr->row(csv_row(n, beam.time(), x.max_position, x.max_rotation));
      }
    }
    if (cl && std::find(snap.begin(), snap.end(), n) != snap.end()) {
      const auto g = beam.configurations();
      for (std::size_t j = 0; j < g.size(); ++j)
        cl->row(csv_row(n, beam.time(), j, pc.grid.node_s(static_cast<int>(j)), g[j].x(0), g[j].x(1), g[j].x(2)));
    }
  };

  record(0);
  clock::duration stepping{0};
  int status = 0;
  try {
    for (long n = 1; n <= c.steps; ++n) {
      const auto a = clock::now();
      beam.step();
      stepping += clock::now() - a;
      record(n);
      if (!outputs_ok()) break;  // reported below
    }
  } catch (const geomint::integration_error& e) {
    std::cerr << e.what() << "\n";
    status = cli::exit_run_failure;
  }
  const double ms_step = std::chrono::duration<double, std::milli>(stepping).count();
  const double ms_total = std::chrono::duration<double, std::milli>(clock::now() - t_start).count();

  const auto& st = beam.newton();
  std::cout << std::setprecision(6);
  std::cout << "geomint-beam: scheme " << gb::to_string(c.method) << ", " << c.nodes << " nodes, dt = " << c.dt << ", "
            << beam.steps_taken() << " of " << c.steps << " steps (t = " << beam.time() << ")\n";
  std::cout << "  wall time: " << std::setprecision(4) << ms_step << " ms stepping (" << (beam.steps_taken() > 0 ? 1e6 * ms_step / double(beam.steps_taken()) / double(c.nodes) : 0.0)
            << " ns per node-step), " << ms_total << " ms total with diagnostics and output\n";
  std::cout << std::setprecision(6) << "  energy: E0 = " << d0.total << ", max |E - E0| = " << max_energy_error << " (relative "
            << max_energy_error / d0.total << ")\n";
  std::cout << "  momentum: |P0| = " << d0.P.norm() << ", max |P - P0| = " << max_dP << "; |L0| = " << d0.L.norm()
            << ", max |L - L0| = " << max_dL << "\n";
  std::cout << "  Newton: " << (st.solves ? double(st.iterations) / double(st.solves) : 0.0) << " iterations per node solve (max "
            << st.max_iterations << ")\n";
  for (cli::csv_file* f : {csv, cl, dr})
    if (f) status = f->finish("geomint-beam", status);
  return cli::finish_stdout("geomint-beam", status);
}

int main(int argc, char** argv) {
  config c;
  if (const auto done = parse(argc, argv, c)) return *done;
  try {
    return run(c);
  } catch (const std::exception& e) {  // e.g. std::invalid_argument from the integrator's checks
    std::cout.flush();
    std::cerr << "geomint-beam: " << e.what() << '\n';
    return 1;
  }
}
