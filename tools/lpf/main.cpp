/// geomint-run: integrate a built-in system with an LPF or classical variational integrator.
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "run.hpp"

namespace {

const char* usage =
    "usage: geomint-run [--system harmonic|pendulum|kepler|charged|circle|spherical]\n"
    "                   [--scheme lpf|midpoint|trapezoidal|galerkin|paper23]\n"
    "                   [--nodes equispaced|lobatto|chebyshev|gauss-interior] [--basis lagrange|bernstein]\n"
    "                   [--m M (2..8)] [--tau T (> 0)] [--steps N] [--every K]\n"
    "                   [--q0 a[,b]] [--p0 a[,b]] [--digits 16|50|100] [--csv]\n"
    "Integrates the system with the one-step (q, p) form of the chosen scheme. With --csv prints\n"
    "step,t,q1,...,qn,p1,...,pn,energy every K steps and at the last step, in the full precision\n"
    "of the scalar (16: double, 50/100: cpp_bin_float). p is the canonical momentum dL/dqdot.\n"
    "--nodes and --basis apply to lpf; galerkin is the degree-m Galerkin VI with m-point\n"
    "Gauss-Legendre quadrature of the action.\n"
    "Defaults: harmonic q0=1,qdot0=1; pendulum q0=1,qdot0=0; kepler q0=(0.5,0),qdot0=(0,sqrt 3);\n"
    "charged q0=(1,0),qdot0=(0,1); scheme lpf, equispaced, lagrange, m=2, tau=0.1, steps=100.\n"
    "Constrained systems: circle (L = 1/2|qdot|^2, f = |q|^2 - 1; q0=(1,0), p0=(0,1)) with --scheme\n"
    "lpf (the constrained integrator: f = 0 at every node and step, projected momenta) or paper23\n"
    "(the paper's scheme (23) as printed); spherical (unit spherical pendulum, f = |q|^2 - 1;\n"
    "q0=(sin,0,-cos)(pi/4), p0=(0,0.8,0)) with --scheme lpf. Their CSV adds a constraint column,\n"
    "max |f_l(q)|; initial data off the constraint or with a normal velocity are rejected.\n";

int fail(const std::string& why) {
  std::cerr << "geomint-run: " << why << "\n" << usage;
  return 2;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

bool parse_long(const std::string& s, long& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtol(s.c_str(), &end, 10);
  return end && *end == '\0';
}

}  // namespace

int main(int argc, char** argv) {
  using geomint::run::options;
  options o;
  const std::map<std::string, std::set<std::string>> choices = {
      {"--system", {"harmonic", "pendulum", "kepler", "charged", "circle", "spherical"}},
      {"--scheme", {"lpf", "midpoint", "trapezoidal", "galerkin", "paper23"}},
      {"--nodes", {"equispaced", "lobatto", "chebyshev", "gauss-interior"}},
      {"--basis", {"lagrange", "bernstein"}},
      {"--digits", {"16", "50", "100"}}};
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::cout << usage;
      return 0;
    }
    if (flag == "--csv") {
      o.csv = true;
      continue;
    }
    if (i + 1 >= argc) return fail("missing value after " + flag);
    const std::string value = argv[++i];
    if (auto c = choices.find(flag); c != choices.end()) {
      if (!c->second.count(value)) return fail("invalid value '" + value + "' for " + flag);
      if (flag == "--system") o.system = value;
      else if (flag == "--scheme") o.scheme = value;
      else if (flag == "--nodes") o.nodes = value;
      else if (flag == "--basis") o.basis = value;
      else o.digits = std::stoi(value);
    } else if (flag == "--m") {
      long m = 0;
      if (!parse_long(value, m) || m < 2 || m > 8) return fail("--m must be an integer in 2..8");
      o.m = static_cast<int>(m);
    } else if (flag == "--steps") {
      if (!parse_long(value, o.steps) || o.steps < 0) return fail("--steps must be a non-negative integer");
    } else if (flag == "--every") {
      if (!parse_long(value, o.every) || o.every < 1) return fail("--every must be a positive integer");
    } else if (flag == "--tau") {
      o.tau = value;
    } else if (flag == "--q0") {
      o.q0 = split(value);
    } else if (flag == "--p0") {
      o.p0 = split(value);
    } else {
      return fail("unknown flag " + flag);
    }
  }
  try {
    using namespace geomint::run;
#define GEOMINT_RUN_DISPATCH(sys)                            \
  if (o.system == #sys) {                                    \
    if (o.digits == 16) return run_##sys##_16(o);            \
    if (o.digits == 50) return run_##sys##_50(o);            \
    return run_##sys##_100(o);                               \
  }
    if (o.system == "harmonic" || o.system == "pendulum" || o.system == "kepler" || o.system == "charged") {
      if (o.digits == 16) return run_free_16(o);
      if (o.digits == 50) return run_free_50(o);
      return run_free_100(o);
    }
    GEOMINT_RUN_DISPATCH(circle)
    GEOMINT_RUN_DISPATCH(spherical)
#undef GEOMINT_RUN_DISPATCH
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
  return fail("unknown system");
}
