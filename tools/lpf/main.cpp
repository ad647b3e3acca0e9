/// geomint-run: integrate a built-in system with an LPF or classical variational integrator.
#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/cli/run.hpp"
#include "run.hpp"
#include "stepper.hpp"

namespace {

/// The systems of --system: the free ones (tools/common/stepper.hpp), the constrained ones after
/// the built-in free systems.
std::string system_choices() {
  std::vector<std::string> names = geomint::tools::builtin_systems();
  names.insert(names.end(), {"circle", "spherical"});
  for (const std::string& z : geomint::tools::zoo_systems()) names.push_back(z);
  return geomint::core::detail::joined(names);
}

const std::string usage =
    "usage: geomint-run [--system " + system_choices() + "]\n" +
    "                   [--scheme " + geomint::core::detail::joined(geomint::cli::scheme_list()) + "|paper23 | --scheme NAME | --tableau FILE]\n" +
    "                   [--nodes " + geomint::core::detail::joined(geomint::node_family_names) + " (or gauss_lobatto, ...)]\n" +
    "                   [--basis lagrange|bernstein]\n"
    "                   [--m M (2..16)] [--tau T (> 0)] [--steps N (0..10^12)] [--every K (1..10^12)]\n"
    "                   [--q0 a[,b]] [--p0 a[,b]] [--digits 16|50|100] [--csv]\n"
    "                   [--compensated] [--growth] [--estimate] [--no-monitor]\n"
    "Integrates the system with the one-step (q, p) form of the chosen scheme. With --csv prints\n"
    "step,t,q1,...,qn,p1,...,pn,energy every K steps and at the last step, in the full precision\n"
    "of the scalar (16: double, 50/100: cpp_bin_float). p is the canonical momentum dL/dqdot.\n"
    "--nodes and --basis apply to lpf only (an error with another scheme); galerkin is the\n"
    "degree-m Galerkin VI with m-point Gauss-Legendre quadrature of the action. m = 2..8 for\n"
    "every scheme and node family; m = 9..16 for lpf --nodes gauss-interior --basis lagrange and\n"
    "galerkin on every free system, in 16 and 50 digits.\n"
    "lpf --nodes gauss-interior --basis lagrange on a natural system (" + geomint::cli::comma_list(geomint::tools::natural_free_systems()) + ")\n"
    "takes its steps in the fixed-point form (no Jacobian;\n"
    "coefficients exactly symplectic in the scalar), with Newton for a step beyond its reach.\n"
    "lpf-fixed-point, kept for one release, is that scheme with the fixed-point form alone.\n"
    "Defaults: harmonic q0=1,qdot0=1; pendulum q0=1,qdot0=0; kepler q0=(0.5,0),qdot0=(0,sqrt 3);\n"
    "charged q0=(1,0),qdot0=(0,1); scheme lpf, equispaced, lagrange, m=2, tau=0.1, steps=100.\n"
    "Initial data are a position and a velocity: --q0 replaces the position; --p0 gives the\n"
    "canonical momentum, and without it the momentum is that of the default velocity qdot0 at the\n"
    "(possibly given) position, never the default position's momentum. --m applies to lpf,\n"
    "lpf-fixed-point and galerkin only (an error with another scheme).\n"
    "Constrained systems: circle (L = 1/2|qdot|^2, f = |q|^2 - 1; q0=(1,0), p0=(0,1)) with --scheme\n"
    "lpf (the constrained integrator: f = 0 at every node and step, projected momenta) or paper23\n"
    "(the paper's scheme (23) as printed); spherical (unit spherical pendulum, f = |q|^2 - 1;\n"
    "q0=(sin,0,-cos)(pi/4), p0=(0,0.8,0)) with --scheme lpf. Their CSV adds a constraint column,\n"
    "max |f_l(q)|; initial data off the constraint or with a normal velocity are rejected.\n"
    "--tableau FILE integrates a free system (every system but circle and spherical) with the\n"
    "method written in FILE (an rk, prk, rkn or nystrom tableau with exact entries, optionally over\n"
    "a field Q(r); docs/guide/tableau_files.md), in the --digits chosen; it excludes --scheme,\n"
    "--nodes, --basis and --m, and rkn and prk tableaux need a natural system (not charged). A\n"
    "malformed file is a usage error naming the file and line.\n"
    "--scheme NAME integrates a free system with a method of the catalogue (geomint-scheme\n"
    "--list-methods: gauss-3, radau-iia-5, lobatto-iiia-iiib-4, forest-ruth, demp-rkn64, ...), its\n"
    "coefficients at the full precision of the --digits chosen, under the same rules as --tableau.\n"
    "--compensated adds the increments of q and p with compensated summation (on circle and\n"
    "spherical those of q: the momentum is projected onto the constraint at every step).\n"
    "--growth fits the growth of the energy error (free systems; to stderr with --csv): the RMS\n"
    "of |E - E0| over the windows of steps [2^j, 2^(j+1)), and the least-squares slope of log RMS\n"
    "against log t over the windows from step 1024 on (1/2: round-off as a random walk, Brouwer's\n"
    "law; 1: linear).\n"
    "--estimate runs the same steps at tau/2 alongside and prints Richardson's estimate of the\n"
    "global error, |z(tau) - z(tau/2)|_inf 2^p/(2^p - 1) with p a lower bound of the scheme's\n"
    "order (a catalogue method's published order; free systems; a CSV column error_estimate, the summary to stderr with --csv), and\n"
    "'coarse run' when it exceeds 1/100 of max(|q|, |p|).\n"
    "Work: N steps, 3N with --estimate (N <= 10^12); the run stops at its first failed step or\n"
    "failed write.\n"
    "The step monitor (on by default; --no-monitor turns it off) refuses a step that does not\n"
    "resolve the motion (tau omega_max above the scheme's bound) or whose energy error is\n"
    "comparable to the energy it exchanges (docs/guide/robustness.md); exit status 3.\n"
    "The problem zoo (geomint/mechanics/zoo.hpp): " + geomint::cli::comma_list(geomint::tools::zoo_systems()) + ",\n"
    "each from its documented initial data, with every scheme, m and --digits of the built-in free\n"
    "systems.\n";

/// The constrained systems and the paper's scheme (23): what geomint-run adds to the front end
/// of the free systems (geomint/cli/run.hpp).
int run_constrained_or_paper23(const geomint::run::options& o) {
  using namespace geomint::run;
  if (o.system != "circle" && o.system != "spherical")
    throw std::invalid_argument("--scheme paper23 is the paper's scheme for --system circle only");
  if (o.growth) throw std::invalid_argument("--growth applies to the free systems only");
  if (o.compensated && o.scheme == "paper23")
    throw std::invalid_argument("--compensated applies to the one-step form (--scheme lpf), not to the two-step scheme paper23");
  if (o.estimate) throw std::invalid_argument("--estimate applies to the free systems only");
  if (o.system == "circle")
    return geomint::cli::with_digits(o.digits, [&]<int D>() { return geomint::run::run_constrained<constrained_system::circle, D>(o); });
  return geomint::cli::with_digits(o.digits, [&]<int D>() { return geomint::run::run_constrained<constrained_system::spherical, D>(o); });
}

}  // namespace

int main(int argc, char** argv) {
  geomint::cli::run_tool tool;
  tool.usage = usage;
  tool.default_system = "harmonic";
  tool.extra_systems = {"circle", "spherical"};
  tool.extra_schemes = {{"paper23", "m = 2 by construction"}};
  tool.extra = run_constrained_or_paper23;
  return geomint::cli::run_main(geomint::tools::free_system_types{}, argc, argv, tool);
}
