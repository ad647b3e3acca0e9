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
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geomint/beam/beam.hpp"

namespace {

using T = double;
namespace gb = geomint::beam;

const char* usage_text =
    "usage: geomint-beam [options]\n"
    "  Runs the geometrically exact beam of the beam paper (Chen & Shi 2025, section 4).\n"
    "  --steps N          number of time steps (default 1000)\n"
    "  --dt DT            time step in s (default 1e-4)\n"
    "  --nodes N          number of nodes J+1 (default 101); the initial data of section 4\n"
    "                     use sin(j pi / J)\n"
    "  --scheme S         poisson (eq. 53, default) or hamel (trapezoidal bracket term)\n"
    "  --every K          write a CSV row every K steps, step 0 included (default 1)\n"
    "  --csv FILE         write step,t,kinetic,potential,total,Px,Py,Pz,Lx,Ly,Lz to FILE\n"
    "  --centreline FILE  write step,t,node,s,x,y,z of the centreline at --snapshots times\n"
    "  --snapshots M      number of evenly spaced centreline snapshots (default 6, >= 2)\n"
    "  --drift FILE       write step,t,max_position,max_rotation: per-node reconstruction (55)\n"
    "                     against the strain-consistent one, every K steps\n"
    "  --cayley V         velocity in (55): previous (zeta^n, as printed; default), current\n"
    "                     (zeta^{n+1}) or midpoint\n"
    "  --reconstruction R per-node (default) or strain: configurations used for the momentum\n"
    "                     and the centreline\n"
    "  --help             this text\n";

[[noreturn]] void usage_error(const std::string& msg) {
  std::cerr << "geomint-beam: " << msg << "\n" << usage_text;
  std::exit(2);
}

long parse_long(const std::string& flag, const std::string& v, long min) {
  char* end = nullptr;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || x < min) usage_error("bad value '" + v + "' for " + flag + " (integer >= " + std::to_string(min) + ")");
  return x;
}

double parse_double(const std::string& flag, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x)) usage_error("bad value '" + v + "' for " + flag);
  return x;
}

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

config parse(int argc, char** argv) {
  config c;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage_text;
      std::exit(0);
    }
    if (a.rfind("--", 0) != 0) usage_error("unexpected argument '" + a + "'");
    if (i + 1 >= argc) usage_error("missing value for " + a);
    const std::string v = argv[++i];
    if (a == "--steps") c.steps = parse_long(a, v, 0);
    else if (a == "--dt") c.dt = parse_double(a, v);
    else if (a == "--nodes") c.nodes = parse_long(a, v, 2);
    else if (a == "--every") c.every = parse_long(a, v, 1);
    else if (a == "--snapshots") c.snapshots = parse_long(a, v, 2);
    else if (a == "--csv") c.csv = v;
    else if (a == "--centreline") c.centreline = v;
    else if (a == "--drift") c.drift = v;
    else if (a == "--scheme") {
      if (v == "poisson") c.method = gb::scheme::poisson;
      else if (v == "hamel") c.method = gb::scheme::hamel;
      else usage_error("--scheme must be poisson or hamel, not '" + v + "'");
    } else if (a == "--cayley") {
      if (v == "previous") c.velocity = gb::cayley_velocity::previous;
      else if (v == "current") c.velocity = gb::cayley_velocity::current;
      else if (v == "midpoint") c.velocity = gb::cayley_velocity::midpoint;
      else usage_error("--cayley must be previous, current or midpoint, not '" + v + "'");
    } else if (a == "--reconstruction") {
      if (v == "per-node") c.recon = gb::reconstruction::per_node;
      else if (v == "strain") c.recon = gb::reconstruction::strain_consistent;
      else usage_error("--reconstruction must be per-node or strain, not '" + v + "'");
    } else {
      usage_error("unknown option '" + a + "'");
    }
  }
  if (!(c.dt > 0)) usage_error("--dt must be > 0");
  if (c.nodes > 1000000) usage_error("--nodes is limited to 1000000");
  return c;
}

std::unique_ptr<std::ofstream> open_out(const std::string& path) {
  if (path.empty()) return nullptr;
  auto f = std::make_unique<std::ofstream>(path);
  if (!*f) {
    std::cerr << "geomint-beam: cannot open '" << path << "' for writing\n";
    std::exit(1);
  }
  *f << std::setprecision(std::numeric_limits<T>::max_digits10);
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const config c = parse(argc, argv);
  using clock = std::chrono::steady_clock;
  const auto t_start = clock::now();

  const gb::paper_case<T> pc(static_cast<int>(c.nodes));
  gb::options<T> opt;
  opt.dt = c.dt;
  opt.method = c.method;
  opt.velocity = c.velocity;
  opt.configurations = c.recon;
  gb::integrator<T> beam = pc.make(opt);

  auto csv = open_out(c.csv);
  auto cl = open_out(c.centreline);
  auto dr = open_out(c.drift);
  if (csv) *csv << "step,t,kinetic,potential,total,Px,Py,Pz,Lx,Ly,Lz\n";
  if (cl) *cl << "step,t,node,s,x,y,z\n";
  if (dr) *dr << "step,t,max_position,max_rotation\n";

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
        *csv << d.step << ',' << d.t << ',' << d.kinetic << ',' << d.potential << ',' << d.total << ',' << d.P(0) << ','
             << d.P(1) << ',' << d.P(2) << ',' << d.L(0) << ',' << d.L(1) << ',' << d.L(2) << '\n';
      if (dr && n % c.every == 0) {
        const auto x = beam.drift();
        *dr << n << ',' << beam.time() << ',' << x.max_position << ',' << x.max_rotation << '\n';
      }
    }
    if (cl && std::find(snap.begin(), snap.end(), n) != snap.end()) {
      const auto g = beam.configurations();
      for (std::size_t j = 0; j < g.size(); ++j)
        *cl << n << ',' << beam.time() << ',' << j << ',' << pc.grid.node_s(static_cast<int>(j)) << ',' << g[j].x(0) << ','
            << g[j].x(1) << ',' << g[j].x(2) << '\n';
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
    }
  } catch (const geomint::integration_error& e) {
    std::cerr << e.what() << "\n";
    status = 3;
  }
  if (csv) csv->flush();
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
  return status;
}
