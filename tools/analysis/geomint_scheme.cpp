// geomint-scheme: exact analysis of the library's schemes from their RKN tableaux
// (include/geomint/analysis: rkn_tableau, order_conditions, scheme_structure, linear_stability).
//
//   geomint-scheme [--m M|all] [--nodes F] [--scheme S] [--csv]
//       the exact two-step form x^{k+1} = R(tau) x^k - x^{k-1} for y'' = -y (every family)
//   geomint-scheme --analyse [--scheme S] [--nodes F[,F...]|all] [--m M|A..B|all] [--csv]
//       order (Nystrom trees), stage order, symplecticity, symmetry, error constants, linear
//       stability (interval of periodicity or of absolute stability), dissipation, phase lag
//   geomint-scheme --analyse --tableau FILE [--csv]
//       order (B-/P-series against the exact flow; per component), error constants and exact
//       symplecticity (the algebraic conditions on the irreducible method, tableau_symplecticity.hpp) of the method
//       of a tableau file, exactly over its coefficients (include/geomint/analysis/bseries:
//       method_analysis.hpp, error_constants.hpp), symmetry, stage order and linear stability over
//       Q or Q(r) (analysis/method_verdicts.hpp, rk_stability.hpp, field_stability.hpp)
//   geomint-scheme --print-tableau [--scheme S] [--nodes F[,F...]|all] [--m M|A..B|all]
//       the exact tableau (node polynomial and monomial-basis matrices, or rationals)
//   geomint-scheme --analyse|--print-tableau --scheme NAME [--csv]; geomint-scheme --list-methods
//       a method of the catalogue (include/geomint/methods/catalogue.hpp): analysed as a tableau
//       file is, or printed as a tableau file (docs/guide/tableau_files.md); the list of names
//
// --m applies to lpf and galerkin, --nodes to lpf only: given to another scheme they are usage
// errors (exit 2), never ignored; every m of a range is printed.
//
// The analysis uses the constexpr functions of the headers, evaluated here at run time (the
// compile-time side is tests/analysis/static_scheme_analysis.cpp).
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "../common/cli.hpp"
#include "geomint/analysis/bseries/error_constants.hpp"
#include "geomint/analysis/collocation_algebra_analysis.hpp"
#include "geomint/analysis/bseries/method_analysis.hpp"
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/method_verdicts.hpp"
#include "geomint/analysis/order_conditions.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/analysis/scheme_structure.hpp"
#include "geomint/analysis/tableau_symplecticity.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "geomint/schemes/registry.hpp"

namespace {

using namespace geomint;
using decimal = boost::multiprecision::cpp_bin_float_50;

const std::string usage_text =
    "usage: geomint-scheme [--analyse|--print-tableau] [--scheme " + scheme_names_where([](const scheme_entry& e) { return e.exact_tableau; }, "|", "|") + "]\n"
    "                      [--nodes F[,F...]|all] [--m M|A..B|all] [--csv]\n"
    "       geomint-scheme --analyse --tableau FILE [--csv]\n"
    "       geomint-scheme --analyse|--print-tableau --scheme NAME [--csv]\n"
    "       geomint-scheme --list-methods\n"
    "  Exact analysis of a scheme from its Runge-Kutta-Nystrom tableau (natural systems).\n"
    "  default     the two-step form x^{k+1} = R(tau) x^k - x^{k-1} for L = xdot^2/2 - x^2/2:\n"
    "              R = P(tau^2)/Q(tau^2) in lowest terms and R - 2 cos tau = c tau^(p+2) + ...\n"
    "              (--csv: m,numerator,denominator,order,leading_coefficient)\n"
    "  --analyse   order by Nystrom trees, exact symplecticity and symmetry (up to any stage\n"
    "              permutation), principal error constant C (2-norm of the tau^(p+1) error\n"
    "              coefficients; also per component: position C_q, velocity C_p), stability on\n"
    "              y'' = -y: interval of periodicity (det M = 1) or of absolute stability (0, tau*),\n"
    "              dissipation and phase-lag orders (van der Houwen-Sommeijer). --csv: scheme,nodes,\n"
    "              m,stages,order,symplectic,symmetric,error_constant,stability_interval,\n"
    "              phase_lag_order,kind,stage_order,stability,dissipation_order with stability\n"
    "              periodic|absolute|none (a-stable is for RK methods on y' = lambda y), interval\n"
    "              inf, 0 (empty) or tau* to 30 digits, dissipation_order inf when det M = 1\n"
    "  --tableau FILE  with --analyse: the method of a tableau file (docs/guide/tableau_files.md),\n"
    "              analysed exactly over its coefficients: order from the B-series (rk, trees to\n"
    "              order 10) or P-series (prk; rkn and nystrom on their Nystrom trees; to order 8)\n"
    "              against the exact flow, and of each component (local); symplecticity by the\n"
    "              exact conditions on the irreducible method (rk: b_i a_ij + b_j a_ji = b_i b_j;\n"
    "              prk: b_i ahat_ij + bhat_j a_ji = b_i bhat_j, b = bhat; rkn, nystrom: Suris's),\n"
    "              the first nonzero defect where they fail; symmetry up to any stage\n"
    "              permutation, stage order; rk: R(z) on y' = lambda y, A- and L-stability, the\n"
    "              imaginary-axis interval (stability a-stable, else its kind); every kind: the step\n"
    "              on y'' = -y (prk, rkn, nystrom: stability periodic|absolute|none), exactly over Q\n"
    "              and over Q(r) (the interval end an algebraic number, 30 digits); error constant\n"
    "              C at order p + 1 (rk: rooted trees; prk: bi-coloured, per component C_1, C_2;\n"
    "              rkn, nystrom: Nystrom trees, position C_q and velocity C_p as published). The\n"
    "              same CSV columns; '-' where a value is not decided (error_constant: order a\n"
    "              lower bound; stability: sum b != 1, or a condition polynomial (over Q(r): its\n"
    "              norm) of degree above 22); excludes --scheme, --nodes and --m\n"
    "  --print-tableau  the exact tableau of a built-in scheme: node polynomial N and the\n"
    "              matrices on Q[x]/(N) in the monomial basis (or rationals), with 30-digit\n"
    "              decimals of c, a, bbar, b\n"
    "  --scheme S  lpf (default), midpoint, trapezoidal or galerkin (Gauss quadrature, m = 1..8),\n"
    "              or NAME, a method of the catalogue from the literature (gauss-3, radau-iia-3,\n"
    "              lobatto-iiia-iiib-4, forest-ruth, demp-rkn64, ...): with --analyse the same\n"
    "              analysis and CSV as --tableau FILE; with --print-tableau its exact tableau as a\n"
    "              tableau file (--m and --nodes do not apply). gauss-4, gauss-5, radau-iia-4,\n"
    "              radau-ia-4 (entries in fields of degree 8 and 6) are analysed over their stage\n"
    "              algebra Q[x]/(N), with rooted trees to max(10, 2s + 1); radau-iia-5, radau-ia-5\n"
    "              too, and, their entries lying in a field of degree 24, --print-tableau prints\n"
    "              their operators on Q[x]/(N) and a 30-digit tableau\n"
    "  --list-methods  the catalogue: name, kind, stages, published order, title, source (CSV)\n"
    "  --nodes F   equispaced (default), gauss-interior, lobatto, chebyshev (also gauss_interior,\n"
    "              gauss-lobatto, chebyshev-lobatto, ...), a comma list, or all (lpf only)\n"
    "  --m M       degree 2..8 for lpf, 1..8 for galerkin; A..B or all (default 2; not for\n"
    "              midpoint and trapezoidal)\n"
    "  --csv       CSV output\n"
    "  --help      this text\n";

/// The tableau of a scheme (computed at run time by the constexpr functions).
exact_rkn_tableau tableau_of(const std::string& scheme, const std::string& family, int m) {
  if (scheme == "midpoint") return midpoint_tableau();
  if (scheme == "trapezoidal") return trapezoidal_tableau();
  if (scheme == "galerkin") return with_int<1, max_exact_stages>(m, []<int M>() { return galerkin_tableau<M>(); });
  return with_int<2, max_exact_m>(
      m, [&]<int M>() { return with_node_family(family, []<class Family>() { return lpf_tableau<M, Family>(); }); });
}

/// The interior nodes of an LPF family in ascending order, in 50 digits (for the decimal tableau).
std::vector<decimal> interior_nodes_of(const std::string& family, int m) {
  return with_int<2, max_exact_m + 1>(m, [&]<int M>() {
    return with_node_family(family, []<class Family>() {
      const auto c = nodes<Family, M, decimal>();
      return std::vector<decimal>(c.begin() + 1, c.end() - 1);
    });
  });
}
/// The stages in ascending order, in 50 digits: Galerkin's m Gauss points are the interior
/// nodes of gauss_interior with m + 1.
std::vector<decimal> stages_of(const std::string& scheme, const std::string& family, int m) {
  if (scheme == "galerkin") return interior_nodes_of(std::string(gauss_interior::name), m + 1);
  if (scheme == "midpoint" || scheme == "trapezoidal") return {};
  return interior_nodes_of(family, m);
}

decimal to_decimal(const exact_number& x) { return decimal(x.num.str()) / decimal(x.den().str()); }

std::string digits30(const decimal& x) {
  std::ostringstream s;
  s << std::setprecision(30) << x;
  return s.str();
}
std::string digits3(const decimal& x) {
  std::ostringstream s;
  s << std::setprecision(3) << std::scientific << x;
  return s.str();
}

std::string integer_list(const stability_polynomial& p) {
  std::string out;
  for (int k = 0; k <= p.degree; ++k) out += (k ? ";" : "") + p[k].str();
  return out;
}

/// "16 - 6 tau^2 + ...": ascending powers of tau (z = tau^2).
std::string polynomial_in_tau(const stability_polynomial& p, const char* var = "tau", int power_step = 2) {
  std::string out;
  for (int k = 0; k <= p.degree; ++k) {
    if (p[k].is_zero()) continue;
    const bool negative = p[k].sign() < 0;
    const std::string magnitude = abs(p[k]).str();
    if (out.empty()) {
      if (negative) out += '-';
    } else {
      out += negative ? " - " : " + ";
    }
    if (k == 0 || magnitude != "1") out += magnitude;
    if (k != 0) {
      if (magnitude != "1") out += ' ';
      out += var;
      if (power_step * k != 1) {
        out += '^';
        out += std::to_string(power_step * k);
      }
    }
  }
  return out.empty() ? "0" : out;
}

/// tau* of a stability interval (0, tau*) (its bound is tau*^2): inf, 0 when empty, or 30 digits.
std::string interval_text(const stability_interval& interval) {
  const stability_interval iv = interval.refined(120);
  if (iv.empty) return "0";
  if (iv.unbounded) return "inf";
  using std::sqrt;
  return digits30(sqrt(to_decimal(iv.low())));
}
std::string stability_text(const linear_stability_result& r) { return interval_text(linear_stability_interval(r)); }

/// "periodic", "absolute" or "none" (empty interval).
std::string stability_kind_text(const linear_stability_result& r) {
  if (linear_stability_interval(r).empty) return "none";
  return r.determinant_is_one ? "periodic" : "absolute";
}

struct options {
  std::string mode = "two-step";
  std::string tableau_file;  ///< --tableau FILE
  std::string catalogue_name;  ///< --scheme NAME of the catalogue
  std::string method_label;    ///< "tableau FILE" or "catalogue method NAME" (text output)
  std::string scheme = "lpf";
  std::vector<std::string> families = {"equispaced"};
  int m_first = 2, m_last = 2;
  bool m_given = false;
  bool nodes_given = false;
  bool csv = false;
  std::string m_text = "2";
};

int two_step(const options& o) {
  if (o.csv) std::cout << "m,numerator,denominator,order,leading_coefficient\n";
  const bool single = !find_scheme(o.scheme)->has_m;
  for (const std::string& family : o.families)
    for (int m = o.m_first; m <= (single ? o.m_first : o.m_last); ++m) {
      const linear_stability_result r = linear_stability(tableau_of(o.scheme, family, m));
      const std::string m_label = single ? "-" : std::to_string(m);
      if (o.csv) {
        std::cout << m_label << "," << integer_list(r.numerator) << "," << integer_list(r.denominator) << "," << r.order << ","
                  << r.leading_coefficient.str() << "\n";
        continue;
      }
      if (o.scheme == "lpf") {
        std::cout << "scheme: lpf, m = " << m << ", " << family << " nodes";
        if (family == "equispaced" && m == 2) std::cout << " (eq. 16)";
        if (family == "equispaced" && m == 3) std::cout << " (eq. 18)";
        if (family == "equispaced" && m == 4) std::cout << " (eq. 19)";
        std::cout << "\n";
      } else if (o.scheme == "midpoint") {
        std::cout << "scheme: midpoint variational integrator (eq. 17)\n";
      } else {
        std::cout << "scheme: " << o.scheme << (o.scheme == "galerkin" ? ", m = " + std::to_string(m) : "") << "\n";
      }
      std::cout << "x^{k+1} = R(tau) x^k - " << (r.determinant_is_one ? "" : "det(M) ") << "x^{k-1}\n";
      std::cout << "R(tau) = (" << polynomial_in_tau(r.numerator) << ")/(" << polynomial_in_tau(r.denominator) << ")\n";
      std::cout << "R(tau) - 2 cos(tau) = " << r.leading_coefficient.str() << " tau^" << r.order + 2 << " + O(tau^" << r.order + 4
                << ")\n";
      std::cout << "order p = " << r.order << "\n\n";
    }
  return cli::finish_stdout("geomint-scheme");
}

/// A polynomial in r with rational coefficients (constant first) in the tableau file's syntax,
/// in ascending powers (or descending: `highest_first`).
std::string polynomial_text(const std::vector<methods::exact_rational>& c, bool highest_first = false) {
  std::string out;
  for (std::size_t n = 0; n < c.size(); ++n) {
    const std::size_t k = highest_first ? c.size() - 1 - n : n;
    if (c[k] == 0) continue;
    std::string coefficient = c[k].str();
    if (k > 0 && (c[k] == 1 || c[k] == -1)) coefficient = c[k] == 1 ? "" : "-";
    std::string term = coefficient;
    if (k > 0) term += (coefficient.empty() || coefficient == "-" ? "" : "*") + std::string("r") + (k > 1 ? "^" + std::to_string(k) : "");
    out += (out.empty() || term[0] == '-') ? term : "+" + term;
  }
  return out.empty() ? "0" : out;
}
std::string entry_text(const methods::field_element& x) { return polynomial_text(x.coefficients()); }

const char* analyse_header =
    "scheme,nodes,m,stages,order,symplectic,symmetric,error_constant,stability_interval,phase_lag_order,kind,"
    "stage_order,stability,dissipation_order\n";

/// An exact constant: a rational, or an element of Q(r) as its polynomial in r and 30 digits.
std::string exact_text(const exact_number& x) { return x.str(); }
std::string exact_text(const methods::field_element& x) {
  if (x.is_rational()) return x.rational_value().str();
  return entry_text(x) + " = " + digits30(x.to<decimal>());
}
/// A polynomial over Q(r), ascending coefficients, in z: "1 + (1/2-r) z + ...".
std::string field_polynomial_text(const std::vector<methods::field_element>& p) {
  std::string out;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p[k].is_zero()) continue;
    out += (out.empty() ? "" : " + ") + std::string(k ? "(" : "") + entry_text(p[k]) + (k ? ") z" : "") +
           (k > 1 ? "^" + std::to_string(k) : "");
  }
  return out.empty() ? "0" : out;
}
/// sqrt of a squared error constant to 4 digits (the CSV column's precision).
std::string constant_text(const methods::field_element& squared) {
  using std::sqrt;
  return digits3(sqrt(squared.to<decimal>()));
}

/// The step on y'' = -y of a method (linear_stability_result or field_linear_stability_result).
template <class Result>
void print_oscillator(const Result& ls, const stability_interval& interval) {
  std::cout << "  y'' = -y: " << (ls.determinant_is_one ? "det M = 1, interval of periodicity" : "det M != 1, interval of absolute stability")
            << " tau* = " << interval_text(interval) << "; phase-lag order " << ls.phase_lag_order << ", constant "
            << exact_text(ls.phase_lag_constant) << "; dissipation "
            << (ls.determinant_is_one ? std::string("none")
                                      : "order " + std::to_string(ls.dissipation_order) + ", constant " + exact_text(ls.dissipation_constant))
            << "\n";
}

/// --analyse --tableau FILE: the exact series analysis of the file's method (the tableau read
/// by read_tableau_file, the data geomint-run --tableau integrates), its principal error
/// constants (analysis/bseries/error_constants.hpp) and its verdicts
/// (analysis/method_verdicts.hpp): symmetry, stage order, linear stability.
/// One method's analysis, from a tableau or from a stage algebra, as analyse_report prints it.
struct method_report {
  std::string name, kind;
  methods::method_kind kind_id = methods::method_kind::rk;
  int stages = 0;
  analysis::bseries::method_analysis r;
  method_verdicts v;
  bool has_constants = false;
  analysis::bseries::error_constants<methods::field_element> ec;
  std::string constants_reason = "the order is a lower bound";
  std::vector<std::string> defects;  ///< where the symplecticity conditions fail
};

/// The error constants of `r` when its order is exact (`constants(order)`).
template <class Constants>
void add_constants(method_report& m, Constants constants) {
  if (m.r.order_is_lower_bound) return;
  try {
    m.ec = constants(m.r.order);
    m.has_constants = true;
  } catch (const std::exception& e) {
    m.constants_reason = e.what();
  }
}

method_report report_of(const methods::tableau_data<methods::field_element>& t) {
  method_report m;
  m.r = analysis::bseries::analyse_method(t);
  m.v = verdicts(t);
  m.name = t.name.empty() ? std::string("-") : t.name;
  m.kind_id = t.kind;
  m.kind = std::string(methods::to_string(t.kind));
  m.stages = t.stages;
  add_constants(m, [&](int order) { return analysis::bseries::principal_error_constants(t, order); });
  if (!m.r.symplectic) {
    const auto sy = analysis::symplecticity_conditions(t);
    if (sy.defect_i >= 0)
      m.defects.push_back("defect of " + sy.matrix_condition + " at (i, j) = (" + std::to_string(sy.defect_i + 1) + ", " +
                          std::to_string(sy.defect_j + 1) + "): " +
                          exact_text(sy.defect[static_cast<std::size_t>(sy.defect_i)][static_cast<std::size_t>(sy.defect_j)]));
    if (sy.weight_defect_i >= 0)
      m.defects.push_back("defect of " + sy.weight_condition + " at i = " + std::to_string(sy.weight_defect_i + 1) + ": " +
                          exact_text(sy.weight_defect[static_cast<std::size_t>(sy.weight_defect_i)]));
  }
  return m;
}

/// A method over its stage algebra (analysis/collocation_algebra_analysis.hpp: the catalogue's
/// Gauss s = 4, 5 and Radau s = 4, 5).
method_report report_of(const methods::rk_stage_algebra& a) {
  method_report m;
  m.r = analysis::bseries::analyse_method(a);
  m.v = analysis::verdicts(a);
  m.name = a.name;
  m.kind = "rk";
  m.stages = a.stages;
  add_constants(m, [&](int order) { return analysis::bseries::principal_error_constants(a, order); });
  const auto sy = analysis::symplecticity_conditions(a);
  if (sy.defect_k >= 0)
    m.defects.push_back("defect of G A + A^T G - beta beta^T on (x^k, x^l) at (k, l) = (" + std::to_string(sy.defect_k) + ", " +
                        std::to_string(sy.defect_l) + "): " +
                        exact_text(methods::field_element(sy.defect[static_cast<std::size_t>(sy.defect_k)][static_cast<std::size_t>(sy.defect_l)])));
  return m;
}

int analyse_report(const options& o, const method_report& m) {
  const auto& r = m.r;
  const auto& v = m.v;
  const auto& ec = m.ec;
  const std::string order = std::to_string(r.order) + (r.order_is_lower_bound ? "+" : "");
  const bool oscillator = v.has_oscillator || v.oscillator_in_field;
  const bool determinant_is_one = v.has_oscillator ? v.oscillator.determinant_is_one : v.field_oscillator.determinant_is_one;
  const int phase_lag_order = v.has_oscillator ? v.oscillator.phase_lag_order : v.field_oscillator.phase_lag_order;
  const int dissipation_order = v.has_oscillator ? v.oscillator.dissipation_order : v.field_oscillator.dissipation_order;
  const std::string dissipation = !oscillator ? "-" : (determinant_is_one ? "inf" : std::to_string(dissipation_order));
  if (o.csv) {
    std::cout << analyse_header << m.name << ",-,-," << m.stages << "," << order << "," << (r.symplectic ? "yes" : "no") << ","
              << (v.symmetric ? "yes" : "no") << "," << (m.has_constants ? constant_text(ec.squared) : "-") << ","
              << (v.has_stability ? interval_text(v.interval) : "-") << "," << (oscillator ? std::to_string(phase_lag_order) : "-") << ","
              << m.kind << "," << v.stage_order << "," << (v.has_stability ? std::string(to_string(v.stability)) : "-") << ","
              << dissipation << "\n";
    return cli::finish_stdout("geomint-scheme");
  }
  const bool nystrom_trees = m.kind_id == methods::method_kind::rkn || m.kind_id == methods::method_kind::nystrom;
  std::cout << o.method_label << ": " << m.name << " (" << m.kind << ", " << m.stages << " stages)\n"
            << "  order " << order << " ("
            << (nystrom_trees ? "Nystrom trees" : r.colours == 1 ? "B-series, rooted trees" : "P-series, bi-coloured trees")
            << " up to order " << r.tree_order << "), stage order " << v.stage_order << "\n";
  if (r.colours == 2) {
    const bool prk = m.kind_id == methods::method_kind::prk;
    auto component = [&](std::size_t k) {
      return std::to_string(r.component_order[k]) + (r.component_order_is_lower_bound[k] ? "+" : "");
    };
    std::cout << "  order of each component: " << (prk ? "first (A, b) " : "position ") << component(0)
              << (prk ? ", second (Ahat, bhat) " : ", velocity ") << component(1) << " (local)\n";
  }
  std::cout << "  symplectic: " << (r.symplectic ? "yes" : "no") << " (" << r.symplecticity_basis << "); symmetric: "
            << (v.symmetric ? "yes" : "no") << " (up to a permutation of the stages)\n";
  for (const std::string& d : m.defects) std::cout << "  " << d << "\n";
  if (m.has_constants) {
    std::cout << "  principal error constant C = " << constant_text(ec.squared);
    if (ec.squared.is_rational()) std::cout << ", C^2 = " << exact_text(ec.squared);
    if (m.kind_id == methods::method_kind::prk)
      std::cout << " (first component (A, b) C_1 = " << constant_text(ec.first_squared) << ", second (Ahat, bhat) C_2 = "
                << constant_text(ec.second_squared) << ")";
    else if (ec.components == 2)
      std::cout << " (position C_q = " << constant_text(ec.first_squared) << ", velocity C_p = " << constant_text(ec.second_squared) << ")";
    std::cout << " at order " << ec.order + 1 << "\n";
  } else {
    std::cout << "  principal error constant: not computed (" << m.constants_reason << ")\n";
  }
  if (m.kind_id == methods::method_kind::rk) {
    if (v.has_rk || v.rk_in_field) {
      const bool a_stable = v.has_rk ? v.rk.a_stable : v.field_rk.a_stable, l_stable = v.has_rk ? v.rk.l_stable : v.field_rk.l_stable;
      std::cout << "  y' = lambda y: R(z) = ("
                << (v.has_rk ? polynomial_in_tau(v.rk.numerator, "z", 1) : field_polynomial_text(v.field_rk.numerator)) << ")/("
                << (v.has_rk ? polynomial_in_tau(v.rk.denominator, "z", 1) : field_polynomial_text(v.field_rk.denominator))
                << "); A-stable: " << (a_stable ? "yes" : "no") << ", L-stable: " << (l_stable ? "yes" : "no")
                << "; |R(iy)| <= 1 for 0 <= y <= " << interval_text(v.has_rk ? v.rk.imaginary_axis : v.field_rk.imaginary_axis) << "\n";
    } else {
      std::cout << "  y' = lambda y: not decided (" << v.rk_reason << ")\n";
    }
  }
  if (v.has_oscillator)
    print_oscillator(v.oscillator, linear_stability_interval(v.oscillator));
  else if (v.oscillator_in_field)
    print_oscillator(v.field_oscillator, v.field_oscillator.interval);
  else
    std::cout << "  y'' = -y: not decided (" << v.oscillator_reason << ")\n";
  if (v.has_stability) std::cout << "  stability: " << to_string(v.stability) << ", interval " << interval_text(v.interval) << "\n";
  return cli::finish_stdout("geomint-scheme");
}

int analyse_file(const options& o, const methods::tableau_data<methods::field_element>& t) { return analyse_report(o, report_of(t)); }

int analyse(const options& o) {
  if (o.csv) std::cout << analyse_header;
  const bool single = !find_scheme(o.scheme)->has_m;
  const std::vector<std::string> families = takes_nodes(o.scheme) ? o.families : std::vector<std::string>{"-"};
  for (const std::string& family : families)
    for (int m = o.m_first; m <= (single ? o.m_first : o.m_last); ++m) {
      const exact_rkn_tableau t = tableau_of(o.scheme, family, m);
      const order_summary ord = order_analysis(t);
      const symplecticity_result sy = symplecticity(t);
      const symmetry_result sm = symmetry(t);
      const linear_stability_result ls = linear_stability(t);
      using std::sqrt;
      auto constant = [&](const exact_number& squared) {
        return ord.order_is_lower_bound ? std::string("-") : digits3(sqrt(to_decimal(squared)));
      };
      const std::string error_constant = constant(ord.error_constant_squared);
      const std::string dissipation = ls.determinant_is_one ? "inf" : std::to_string(ls.dissipation_order);
      const std::string order = std::to_string(ord.order) + (ord.order_is_lower_bound ? "+" : "");
      const std::string nodes_label = o.scheme == "lpf" ? family : (o.scheme == "galerkin" ? "gauss" : "-");
      const std::string m_label = single ? "-" : std::to_string(m);
      if (o.csv) {
        std::cout << o.scheme << "," << nodes_label << "," << m_label << "," << t.stages << "," << order << ","
                  << (sy.symplectic ? "yes" : "no") << "," << (sm.symmetric ? "yes" : "no") << "," << error_constant << ","
                  << stability_text(ls) << "," << ls.phase_lag_order << ",rkn," << stage_order(t) << ","
                  << stability_kind_text(ls) << "," << dissipation << "\n";
      } else {
        std::cout << o.scheme << " " << nodes_label << " m = " << m_label << ": " << t.stages << " stages, order " << order
                  << " (quadrature order " << quadrature_order(t) << ", " << ord.conditions_checked << " tree conditions, "
                  << ord.nonzero_defects << " nonzero at order " << ord.order + 1 << "), C = " << error_constant
                  << ", C^2 = " << ord.error_constant_squared.str() << " (position C_q = "
                  << constant(ord.position_error_constant_squared) << ", velocity C_p = "
                  << constant(ord.velocity_error_constant_squared) << "); stage order " << stage_order(t) << "\n"
                  << "  symplectic: " << (sy.symplectic ? "yes" : "no") << " (bbar = b (1 - c): "
                  << (sy.first_condition ? "yes" : "no") << ", b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji): "
                  << (sy.second_condition ? "yes" : "no") << "); symmetric: " << (sm.symmetric ? "yes" : "no") << "\n"
                  << "  " << (ls.determinant_is_one ? "det M = 1, interval of periodicity" : "det M != 1, interval of absolute stability")
                  << " tau* = " << stability_text(ls) << " (" << stability_kind_text(ls) << "); phase-lag order "
                  << ls.phase_lag_order << ", constant " << ls.phase_lag_constant.str() << "; dissipation "
                  << (ls.determinant_is_one ? std::string("none") : "order " + dissipation + ", constant " + ls.dissipation_constant.str())
                  << "\n";
      }
    }
  return cli::finish_stdout("geomint-scheme");
}

void print_one_tableau(const options& o, const std::string& family, int m) {
  const exact_rkn_tableau t = tableau_of(o.scheme, family, m);
  const int s = t.stages;
  const bool single = !find_scheme(o.scheme)->has_m;
  std::cout << "scheme " << o.scheme << (o.scheme == "lpf" ? " " + family : std::string())
            << (single ? std::string() : " m = " + std::to_string(m)) << ", " << s << " stages\n";
  if (t.basis == stage_basis::monomial) {
    std::cout << "stages: the roots of N(x) = ";
    for (int k = s; k >= 0; --k)
      if (!t.node_polynomial[k].num.is_zero())
        std::cout << (k == s ? "" : " + (") << t.node_polynomial[k].str() << (k == s ? "" : ")") << (k ? " x^" + std::to_string(k) : "");
    std::cout << "\nexact tableau on Q[x]/(N), monomial basis 1, x, ..., x^" << s - 1 << " (column k: the image of x^k)\n";
  } else {
    std::cout << "exact tableau (stage values)\nc:";
    for (int i = 0; i < s; ++i) std::cout << " " << t.c[i].str();
    std::cout << "\n";
  }
  std::cout << "A:\n";
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) std::cout << (j ? "  " : "  ") << t.a[i][j].str();
    std::cout << "\n";
  }
  std::cout << "bbar:";
  for (int k = 0; k < s; ++k) std::cout << " " << t.bbar[k].str();
  std::cout << "\nb:";
  for (int k = 0; k < s; ++k) std::cout << " " << t.b[k].str();
  std::cout << "\n";
  std::vector<decimal> c = stages_of(o.scheme, family, m);
  const methods::tableau_data<decimal> n = numeric_tableau<decimal>(t, c.data());
  std::cout << "decimal tableau (30 digits; nodes from core/nodes.hpp)\n";
  for (int i = 0; i < s; ++i) {
    std::cout << "c_" << i + 1 << " = " << digits30(n.c[static_cast<std::size_t>(i)]) << "\n  a:";
    for (int j = 0; j < s; ++j) std::cout << " " << digits30(n.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
    std::cout << "\n  bbar = " << digits30(n.bbar[static_cast<std::size_t>(i)]) << ", b = " << digits30(n.b[static_cast<std::size_t>(i)])
              << "\n";
  }
}

int print_tableau(const options& o) {
  const bool single = !find_scheme(o.scheme)->has_m;
  const std::vector<std::string> families = takes_nodes(o.scheme) ? o.families : std::vector<std::string>{"-"};
  for (const std::string& family : families)
    for (int m = o.m_first; m <= (single ? o.m_first : o.m_last); ++m) print_one_tableau(o, family, m);
  return cli::finish_stdout("geomint-scheme");
}

/// --list-methods: the catalogue as CSV.
int list_methods() {
  std::cout << "name,kind,stages,order,title,source\n";
  for (const methods::catalogue_entry& e : methods::catalogue())
    std::cout << e.name << "," << methods::to_string(e.kind) << "," << e.stages << "," << e.order << ",\"" << e.title << "\",\""
              << e.source << "\"\n";
  return cli::finish_stdout("geomint-scheme");
}

/// --print-tableau --scheme NAME of a method over its stage algebra (Radau with s = 5): the
/// exact operators on Q[x]/(N), as for the built-in schemes, and the decimal tableau in 30
/// digits. Not a tableau file: its entries lie in a field of degree 24.
int print_catalogue_algebra(const methods::catalogue_entry& e) {
  const methods::rk_stage_algebra m = e.algebra();
  const int s = m.stages;
  std::cout << "# " << e.title << ": " << e.source << "\n# the entries lie in a number field of degree 24, so this is the exact "
            << "method on its stage algebra, not a tableau file\nkind rk, " << s << " stages, name " << m.name
            << "\nstages: the roots of N(x) = ";
  for (int k = s; k >= 0; --k) {
    const auto& nk = m.node_polynomial[static_cast<std::size_t>(k)];
    if (!nk.is_zero()) std::cout << (k == s ? "" : " + (") << nk.str() << (k == s ? "" : ")") << (k ? " x^" + std::to_string(k) : "");
  }
  std::cout << "\nexact tableau on Q[x]/(N), monomial basis 1, x, ..., x^" << s - 1 << " (column k: the image of x^k)\nA:\n";
  for (const auto& row : m.a) {
    for (const auto& x : row) std::cout << "  " << x.str();
    std::cout << "\n";
  }
  std::cout << "b:";
  for (const auto& x : m.b) std::cout << " " << x.str();
  const methods::tableau_data<decimal> n = methods::numeric_tableau<decimal>(m);
  std::cout << "\ndecimal tableau (30 digits; nodes from core/nodes.hpp)\n";
  for (std::size_t i = 0; i < static_cast<std::size_t>(s); ++i) {
    std::cout << "c_" << i + 1 << " = " << digits30(n.c[i]) << "\n  a:";
    for (std::size_t j = 0; j < static_cast<std::size_t>(s); ++j) std::cout << " " << digits30(n.a[i][j]);
    std::cout << "\n  b = " << digits30(n.b[i]) << "\n";
  }
  return cli::finish_stdout("geomint-scheme");
}

/// --print-tableau --scheme NAME: the catalogue method as a tableau file (read back by
/// --analyse --tableau and geomint-run --tableau).
int print_catalogue_tableau(const methods::catalogue_entry& e) {
  if (!e.tableau) return print_catalogue_algebra(e);
  const methods::tableau_data<methods::field_element> t = e.tableau();
  std::shared_ptr<const methods::algebraic_field> field;
  auto note = [&](const std::vector<methods::field_element>& v) {
    for (const auto& x : v)
      if (x.field()) field = x.field();
  };
  for (const auto* v : {&t.c, &t.b, &t.bbar, &t.bhat}) note(*v);
  for (const auto* m : {&t.a, &t.ap, &t.ahat})
    for (const auto& row : *m) note(row);
  std::cout << "# " << e.title << ": " << e.source << "\n"
            << "kind " << methods::to_string(t.kind) << "\nstages " << t.stages << "\nname " << t.name << "\n";
  if (field) {
    // r is the largest real root unless the reader must be told which ("near", the midpoint of
    // the root's isolating interval).
    std::cout << "field " << polynomial_text(field->polynomial(), true);
    const auto largest = methods::algebraic_field::make(field->polynomial());
    if (!(largest->lower() == field->lower() && largest->upper() == field->upper()))
      std::cout << " near " << methods::exact_rational((field->lower() + field->upper()) / 2).str();
    std::cout << "\n";
  }
  auto line = [](const char* key, const std::vector<methods::field_element>& v) {
    if (v.empty()) return;
    std::cout << key;
    for (const auto& x : v) std::cout << " " << entry_text(x);
    std::cout << "\n";
  };
  auto square = [&](const char* key, const std::vector<std::vector<methods::field_element>>& m) {
    std::vector<methods::field_element> flat;
    for (const auto& row : m) flat.insert(flat.end(), row.begin(), row.end());
    line(key, flat);
  };
  line("c", t.c);
  square("a", t.a);
  square("ap", t.ap);
  square("ahat", t.ahat);
  line("bbar", t.bbar);
  line("b", t.b);
  line("bhat", t.bhat);
  return cli::finish_stdout("geomint-scheme");
}

}  // namespace

int main(int argc, char** argv) {
  options o;
  cli::parser cl("geomint-scheme", usage_text);
  cl.toggle("--analyse", [&] { o.mode = "analyse"; });
  cl.toggle("--analyze", [&] { o.mode = "analyse"; });
  cl.toggle("--print-tableau", [&] { o.mode = "tableau"; });
  cl.toggle("--list-methods", [&] { o.mode = "list"; });
  cl.value("--tableau", [&](const std::string& v) { o.tableau_file = v; });
  cl.toggle("--csv", [&] { o.csv = true; });
  cl.toggle("--all", [&] {
    o.m_text = "all";
    o.m_given = true;
  });
  bool scheme_given = false;
  cl.value("--scheme", [&](const std::string& v) {
    scheme_given = true;
    if (methods::find_in_catalogue(v)) {
      o.catalogue_name = v;
      return;
    }
    // The built-in schemes with an exact tableau of their own (schemes/registry.hpp).
    if (const scheme_entry* e = find_scheme(v); e && e->exact_tableau) o.scheme = v;
    if (o.scheme != v)
      throw cli::usage_error("--scheme must be one of " + scheme_names_where([](const scheme_entry& e) { return e.exact_tableau; }) +
                             " or a method of the catalogue (geomint-scheme --list-methods); got " + cli::in_quotes(v));
  });
  cl.value("--nodes", [&](const std::string& v) {
    o.families = cli::parse_node_family_list("--nodes", v);
    o.nodes_given = true;
  });
  cl.value("--m", [&](const std::string& v) { o.m_text = v; o.m_given = true; });
  // --tableau takes a FILE; a bare --tableau names --print-tableau (a built-in scheme's tableau).
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--tableau" && (i + 1 == argc || std::string(argv[i + 1]).rfind("--", 0) == 0))
      return cl.fail("--tableau needs a value: a tableau FILE (to print a built-in scheme's tableau use --print-tableau)");
  if (const auto done = cl.parse(argc, argv)) return *done;
  if (o.mode == "list") {
    if (scheme_given || o.m_given || o.nodes_given || !o.tableau_file.empty())
      return cl.fail("--list-methods takes no other option");
    return list_methods();
  }
  if (!o.catalogue_name.empty()) {
    if (o.m_given || o.nodes_given)
      return cl.fail("--m and --nodes do not apply to --scheme " + o.catalogue_name + " (a method of the catalogue)");
    if (!o.tableau_file.empty()) return cl.fail("--scheme and --tableau FILE exclude each other");
    if (o.mode != "analyse" && o.mode != "tableau")
      return cl.fail("--scheme " + o.catalogue_name + " (a method of the catalogue) is used with --analyse or --print-tableau");
    const methods::catalogue_entry& e = *methods::find_in_catalogue(o.catalogue_name);
    o.method_label = "catalogue method " + e.name + " (" + e.title + "; " + e.source + ")";
    try {
      if (o.mode == "tableau") return print_catalogue_tableau(e);
      return e.algebra ? analyse_report(o, report_of(e.algebra())) : analyse_file(o, e.tableau());
    } catch (const std::exception& ex) {
      std::cerr << "geomint-scheme: " << o.catalogue_name << ": " << ex.what() << "\n";
      return cli::finish_stdout("geomint-scheme", cli::exit_run_failure);
    }
  }
  if (!o.tableau_file.empty()) {
    o.method_label = "tableau " + o.tableau_file;
    if (o.mode != "analyse") return cl.fail("--tableau FILE is analysed with --analyse (--print-tableau prints a built-in scheme)");
    if (o.m_given || o.nodes_given || scheme_given)
      return cl.fail("--scheme, --nodes and --m choose a built-in scheme: they exclude --tableau FILE");
    methods::tableau_data<methods::field_element> t;
    try {
      t = methods::read_tableau_file(o.tableau_file);
    } catch (const methods::tableau_file_error& e) {
      return cl.fail(e.what());
    }
    try {
      return analyse_file(o, t);
    } catch (const std::exception& e) {
      std::cerr << "geomint-scheme: " << o.tableau_file << ": " << e.what() << "\n";
      return cli::finish_stdout("geomint-scheme", cli::exit_run_failure);
    }
  }
  try {
    const scheme_entry& entry = *find_scheme(o.scheme);
    const int lo = entry.exact_min_m;
    const int hi = o.scheme == "galerkin" ? max_exact_stages : max_exact_m;  // galerkin's m is its number of stages
    if (o.m_given && !entry.has_m)
      throw cli::usage_error("--m does not apply to --scheme " + o.scheme + " (it has no degree; --m is for " +
                             schemes_with_m(true) + ")");
    if (o.nodes_given && !entry.has_nodes)
      throw cli::usage_error("--nodes does not apply to --scheme " + o.scheme + " (--nodes is for " + schemes_with_nodes(true) + " only" +
                             (entry.nodes_note.empty() ? ")" : "; " + std::string(entry.nodes_note) + ")"));
    const auto range = cli::parse_integer_range<int>("--m", o.m_text, lo, hi);
    o.m_first = range.first;
    o.m_last = range.second;
  } catch (const std::exception& e) {
    return cl.fail(e.what());
  }
  try {
    if (o.mode == "analyse") return analyse(o);
    if (o.mode == "tableau") return print_tableau(o);
    return two_step(o);
  } catch (const std::exception& e) {
    std::cerr << "geomint-scheme: " << e.what() << "\n";
    return cli::finish_stdout("geomint-scheme", cli::exit_run_failure);
  }
}
