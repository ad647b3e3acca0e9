/// geomint-order: observed local and global orders and error constants of the schemes on the
/// nonlinear systems, in multiprecision arithmetic against an independent Taylor-series flow (the
/// built-in systems) or in double against a Galerkin reference in 50 digits (the zoo): the
/// installed front end `order` (geomint/cli/order.hpp) over the tools' systems.
#include "geomint/cli/order.hpp"
#include "stepper.hpp"

namespace {

const std::string usage = std::string(
    "usage: geomint-order [--system S[,S...]|all] [--scheme S[,S...]|all] [--nodes F[,F...]|all]\n"
    "                     [--m M|A..B (2..8)] [--digits 16|50|100] [--steps N1,N2,... ] [--t-end T]\n"
    "                     [--threads K (1..64)] [--csv] [--no-monitor]\n"
    "Local error (one step) and global error (at t = T) of each scheme against the exact flow, for\n"
    "tau = T/N over the ladder N1 < N2 < ... (default T = 1, N = 8,16,32,64), in --digits digit\n"
    "arithmetic; the reference flow is an adaptive Taylor series method with closed-form\n"
    "accelerations in twice the working digits (50 -> 100, 100 -> 150).\n"
    "Reports the observed orders between the two finest steps (local_order = exponent of the local\n"
    "error, p + 1; global_order = p) and the error constant C = global error / tau^round(p).\n") +
    geomint::cli::selection_usage(geomint::tools::builtin_systems()) +
    "Zoo systems (zoo): " + geomint::cli::comma_list(geomint::tools::zoo_systems()) + ",\n"
    "with every scheme (lpf-fixed-point: " + geomint::cli::comma_list(geomint::tools::natural_zoo_systems()) + "), are studied in double\n"
    "(--digits 16, which they require); their reference flow is the Galerkin VI of degree 3\n"
    "(outer-solar: 2) in 50 digits, the step halved until two runs agree to 16 eps of double. The\n"
    "built-in systems need --digits 50|100.\n"
    "--steps: 2 to 16 increasing counts in 1..10^9, bounded up front: the steps of one case (the\n"
    "ladder's runs, sum of N plus one local step per N) and, for the zoo systems, the least work of\n"
    "their reference (3 max(2, N_max) + 6 per N) must not exceed 10^7 in total (else exit 2); the\n"
    "zoo reference's doublings stop at that bound with an error, the built-in systems' Taylor\n"
    "reference at 10^8 steps per state (analysis/reference_flow.hpp).\n"
    "CSV header: system,scheme,nodes,m,local_order,global_order,error_constant,regime,order_spread,\n"
    "finest_error (m and nodes are '-' where a scheme has none; order_spread: |difference| of the last\n"
    "two successive global orders, the order's uncertainty; finest_error: the global error at the\n"
    "finest step against the reference). regime is 'ok' only in the asymptotic regime\n"
    "(analysis/order_study.hpp, asymptotic_regime): at least three steps with errors above\n"
    "round-off, their global errors below 1/10 of the solution's size, the last two successive\n"
    "global orders within 1/4 of each other, the global order within 1/4 of an integer >= 1, the\n"
    "local order >= 1.75 and >= global order + 1/2. Otherwise 'failed' or 'outside: <reason>':\n"
    "such a row is no measurement, and any row not 'ok' makes the exit status 3. The table also\n"
    "prints the successive global orders (their spread is the uncertainty of the order).\n"
    "The step monitor (geomint/solvers/step_monitor.hpp: resolution tau omega_max and energy\n"
    "change) is on; a step that leaves the scheme's regime fails the case; --no-monitor turns it off.\n";

}  // namespace

int main(int argc, char** argv) {
  return geomint::cli::order_main(geomint::tools::free_system_types{}, argc, argv,
                                  geomint::tools::study_tool("geomint-order", usage));
}
