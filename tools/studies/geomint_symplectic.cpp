/// geomint-symplectic: the symplecticity defect ||J^T Omega J - Omega|| of the one-step map of
/// each scheme, and (with --long-steps) its long-time energy behaviour: the installed front end
/// `symplectic` (geomint/cli/symplectic.hpp) over the tools' systems.
#include "geomint/cli/symplectic.hpp"
#include "stepper.hpp"

namespace {

const std::string usage = std::string(
    "usage: geomint-symplectic [--system S[,S...]|all] [--scheme S[,S...]|all] [--nodes F[,F...]|all]\n"
    "                          [--m M|A..B (2..8)] [--digits 16|50|100] [--tau T[,T2...]] [--q0 a[,b]] [--p0 a[,b]]\n"
    "                          [--long-steps N (0..10^9)] [--long-tau T] [--threads K (1..64)] [--csv]\n"
    "                          [--no-monitor]\n"
    "The Jacobian J of the one-step map (q, p) -> (q1, p1) at (q0, p0) with step tau, by central\n"
    "differences with Richardson extrapolation (step eps^(1/5)) in --digits digit arithmetic\n"
    "(default 50, tau 0.25), and the defect max |(J^T Omega J - Omega)_ij|: zero up to about\n"
    "eps^(4/5) for a symplectic map. With --long-steps N (> 0) also N steps of size --long-tau\n"
    "(default tau) in double precision: max |H - H0| and the least-squares drift slope of H - H0.\n"
    "With a ladder --tau T1,T2,... (at most 64 values; no --long-steps) one row per case and tau,\n"
    "with fitted_order = log(d_k/d_{k-1}) / log(tau_k/tau_{k-1}) from the defects at this tau and the\n"
    "one before (nan on the first) and predicted_order, the exact order r of the leading term C tau^r\n"
    "of the defect (analysis/bseries/lpf_symplecticity_defect.hpp, docs/results/schemes.md): lpf on\n"
    "a system that is not natural the quadrature order of its interior nodes plus one (2m-1 on\n"
    "gauss-interior), likewise on a natural system unless the scheme is symplectic there; inf where\n"
    "the defect vanishes identically (midpoint, trapezoidal, galerkin; symplectic lpf on natural).\n") +
    geomint::cli::selection_usage(geomint::tools::builtin_systems()) +
    "  zoo systems: " + geomint::cli::comma_list(geomint::tools::zoo_systems()) + "\n"
    "  (zoo) with every scheme and --digits (lpf-fixed-point: " + geomint::cli::comma_list(geomint::tools::natural_zoo_systems()) + ").\n"
    "Error estimates (a posteriori, always printed): defect_estimate, the change of the defect when\n"
    "the difference step is doubled (the size of the defect's own numerical error); with\n"
    "--long-steps, the same long run at tau/2 (2N steps) and state_error_estimate = 2 |z_N(tau) -\n"
    "z_2N(tau/2)|_inf, Richardson's estimate of the global error at t = N tau for any order >= 1;\n"
    "above 1/100 of the solution's size max(|q|, |p|) the run is called coarse (stderr, table).\n"
    "Work: the defect 4 maps per phase coordinate at each of its two difference steps; the long\n"
    "run 3N steps per case (--long-steps N at most 10^9).\n"
    "CSV header: system,scheme,nodes,m,tau,defect  (plus max_energy_error,energy_drift with\n"
    "--long-steps), regime, defect_estimate (plus state_error_estimate with --long-steps; plus\n"
    "fitted_order,predicted_order with a ladder of tau).\n"
    "regime is 'ok', 'failed', or 'outside: ...' for a result that is no\n"
    "measurement (a defect above 1: tau far outside the scheme's regime); any case not 'ok' makes\n"
    "the exit status 3. The step monitor (geomint/solvers/step_monitor.hpp: resolution tau omega_max\n"
    "and energy change) is on; a step that leaves the scheme's regime fails the case with the\n"
    "monitor's reason; --no-monitor turns it off. Initial data as geomint-run: --p0 is the\n"
    "momentum, else the default velocity's momentum at --q0. --m applies to lpf,\n"
    "lpf-fixed-point and galerkin, --nodes to lpf (an error if no selected scheme uses it).\n";

}  // namespace

int main(int argc, char** argv) {
  return geomint::cli::symplectic_main(geomint::tools::free_system_types{}, argc, argv,
                                       geomint::tools::study_tool("geomint-symplectic", usage));
}
