/// geomint-run: integrate a built-in system with an LPF or classical variational integrator.
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "digits.hpp"
#include "run.hpp"
#include "stepper.hpp"

namespace {

const char* usage =
    "usage: geomint-run [--system harmonic|pendulum|kepler|charged|circle|spherical|henon-heiles|\n"
    "                             spring-pendulum|double-pendulum|toda|outer-solar|arenstorf]\n"
    "                   [--scheme lpf|lpf-fixed-point|midpoint|trapezoidal|galerkin|paper23 | --tableau FILE]\n"
    "                   [--nodes equispaced|lobatto|chebyshev|gauss-interior (or gauss_lobatto, ...)]\n"
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
    "galerkin on the built-in free systems, in 16 and 50 digits.\n"
    "lpf-fixed-point is lpf --nodes gauss-interior --basis lagrange on a natural system in its\n"
    "fixed-point form (no Jacobian; coefficients exactly symplectic in the scalar), on harmonic,\n"
    "pendulum and kepler, with the m and digits of lpf.\n"
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
    "--tableau FILE integrates a free built-in system (harmonic, pendulum, kepler, charged) with the\n"
    "method written in FILE (an rk, prk, rkn or nystrom tableau with exact entries, optionally over\n"
    "a field Q(r); docs/guide/tableau_files.md), in the --digits chosen; it excludes --scheme,\n"
    "--nodes, --basis and --m, and rkn and prk tableaux need a natural system (not charged). A\n"
    "malformed file is a usage error naming the file and line.\n"
    "--compensated adds the increments of q and p with compensated summation (free systems).\n"
    "--growth fits the growth of the energy error (free systems; to stderr with --csv): the RMS\n"
    "of |E - E0| over the windows of steps [2^j, 2^(j+1)), and the least-squares slope of log RMS\n"
    "against log t over the windows from step 1024 on (1/2: round-off as a random walk, Brouwer's\n"
    "law; 1: linear).\n"
    "--estimate runs the same steps at tau/2 alongside and prints Richardson's estimate of the\n"
    "global error, |z(tau) - z(tau/2)|_inf 2^p/(2^p - 1) with p a lower bound of the scheme's\n"
    "order (free systems; a CSV column error_estimate, the summary to stderr with --csv), and\n"
    "'coarse run' when it exceeds 1/100 of max(|q|, |p|).\n"
    "Work: N steps, 3N with --estimate (N <= 10^12); the run stops at its first failed step or\n"
    "failed write.\n"
    "The step monitor (on by default; --no-monitor turns it off) refuses a step that does not\n"
    "resolve the motion (tau omega_max above the scheme's bound) or whose energy error is\n"
    "comparable to the energy it exchanges (docs/guide/robustness.md); exit status 3.\n"
    "The problem zoo (geomint/mechanics/zoo.hpp): henon-heiles, spring-pendulum, double-pendulum,\n"
    "toda, outer-solar, arenstorf, each from its documented initial data, with a restricted scheme\n"
    "set: midpoint; lpf --nodes gauss-interior --basis lagrange --m 2..4; galerkin --m 2..3;\n"
    "--digits 16|50 (outer-solar in 50 digits: m = 2 only). Anything else is a usage error.\n";

/// Runs the chosen system and scheme in the chosen scalar; returns the exit status.
int dispatch(const geomint::run::options& o) {
  using namespace geomint::run;
  const bool constrained = o.system == "circle" || o.system == "spherical";
  if (constrained && (o.compensated || o.growth))
    throw std::invalid_argument("--compensated and --growth apply to the free systems only");
  if (constrained && o.estimate) throw std::invalid_argument("--estimate applies to the free systems only");
  if (o.system == "circle")
    return geomint::tools::with_digits(o.digits, [&]<int D>() { return run_constrained<constrained_system::circle, D>(o); });
  if (o.system == "spherical")
    return geomint::tools::with_digits(o.digits, [&]<int D>() { return run_constrained<constrained_system::spherical, D>(o); });
  return geomint::tools::with_digits(o.digits, [&]<int D>() { return run_free<D>(o); });
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = geomint::cli;
  using geomint::run::options;
  constexpr long max_count = 1'000'000'000'000L;  // the stated bound of --steps and --every
  options o;
  bool nodes_or_basis_given = false;  // --nodes and --basis choose among the lpf schemes only
  bool scheme_given = false, m_given = false;  // --scheme and --m choose a built-in scheme: not with --tableau
  cli::parser cl("geomint-run", usage);
  cl.value("--system", [&](const std::string& v) {
      std::vector<std::string> systems = geomint::tools::free_systems();
      systems.insert(systems.end(), {"circle", "spherical"});
      o.system = cli::parse_choice("--system", v, systems);
    })
      .value("--scheme", [&](const std::string& v) {
        o.scheme = cli::parse_choice("--scheme", v, {"lpf", "lpf-fixed-point", "midpoint", "trapezoidal", "galerkin", "paper23"});
        scheme_given = true;
      })
      .value("--tableau", [&](const std::string& v) { o.tableau = v; })
      .value("--nodes", [&](const std::string& v) {
        o.nodes = cli::parse_node_family("--nodes", v);
        nodes_or_basis_given = true;
      })
      .value("--basis", [&](const std::string& v) {
        o.basis = cli::parse_choice("--basis", v, {"lagrange", "bernstein"});
        nodes_or_basis_given = true;
      })
      .value("--digits", [&](const std::string& v) { o.digits = std::stoi(cli::parse_choice("--digits", v, {"16", "50", "100"})); })
      .value("--m", [&](const std::string& v) {
        o.m = cli::parse_integer<int>("--m", v, 2, 16);
        m_given = true;
      })
      .value("--steps", [&](const std::string& v) { o.steps = cli::parse_integer<long>("--steps", v, 0, max_count); })
      .value("--every", [&](const std::string& v) { o.every = cli::parse_integer<long>("--every", v, 1, max_count); })
      .value("--tau", [&](const std::string& v) { o.tau = cli::checked_real_text("--tau", v, cli::real_bound::positive); })
      .value("--q0", [&](const std::string& v) { o.q0 = cli::parse_real_list("--q0", v, cli::real_bound::finite); })
      .value("--p0", [&](const std::string& v) { o.p0 = cli::parse_real_list("--p0", v, cli::real_bound::finite); })
      .toggle("--csv", [&] { o.csv = true; })
      .toggle("--no-monitor", [&] { o.monitor = false; })
      .toggle("--compensated", [&] { o.compensated = true; })
      .toggle("--growth", [&] { o.growth = true; })
      .toggle("--estimate", [&] { o.estimate = true; });
  if (const auto done = cl.parse(argc, argv)) return *done;
  if (!o.tableau.empty()) {
    if (scheme_given) return cl.fail("--scheme and --tableau exclude each other");
    if (m_given || nodes_or_basis_given) return cl.fail("--m, --nodes and --basis apply to the built-in schemes, not to --tableau");
    if (o.system == "circle" || o.system == "spherical")
      return cl.fail("--tableau runs on the free systems only, not on the constrained system " + o.system);
  }
  if (nodes_or_basis_given && o.scheme != "lpf")
    return cl.fail("--nodes and --basis apply to --scheme lpf only, not to --scheme " + o.scheme +
                   (o.scheme == "lpf-fixed-point" ? " (Gauss-interior nodes by construction)" : ""));
  if (m_given && o.scheme != "lpf" && o.scheme != "lpf-fixed-point" && o.scheme != "galerkin")
    return cl.fail("--m applies to --scheme lpf, lpf-fixed-point and galerkin only, not to --scheme " + o.scheme +
                   (o.scheme == "paper23" ? " (m = 2 by construction)" : " (no degree)"));
  try {
    return geomint::cli::finish_stdout("geomint-run", dispatch(o));
  } catch (const std::invalid_argument& e) {
    // Combinations the parser cannot see alone (--q0 with the wrong count for the system,
    // paper23 off the circle, initial data off the constraint).
    std::cout.flush();
    return geomint::cli::finish_stdout("geomint-run", cl.fail(e.what()));
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "geomint-run: " << e.what() << '\n';
    return geomint::cli::finish_stdout("geomint-run", 1);
  }
}
