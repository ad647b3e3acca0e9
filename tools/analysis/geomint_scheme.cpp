// geomint-scheme: the exact two-step form of a scheme for the harmonic oscillator (eq. 15),
// x^{k+1} = R(tau) x^k - x^{k-1}, R = P(tau^2)/Q(tau^2) in lowest terms, and its leading
// local error term R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4)) (order p). Every number
// printed was derived at compile time (include/geomint/analysis/exact_scheme.hpp).
//
//   geomint-scheme [--m M|all] [--nodes equispaced] [--scheme lpf|midpoint] [--csv]
#include <array>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>

#include "geomint/analysis/exact_scheme.hpp"

namespace {

using geomint::exact_two_step_scheme;

const char* usage_text =
    "usage: geomint-scheme [--m M|all] [--nodes equispaced] [--scheme lpf|midpoint] [--csv]\n"
    "  Prints the exact two-step form x^{k+1} = R(tau) x^k - x^{k-1} of a scheme for the\n"
    "  harmonic oscillator L = xdot^2/2 - x^2/2 (R = P(tau^2)/Q(tau^2) in lowest terms, Q(0) > 0)\n"
    "  and the leading local error term R(tau) - 2 cos(tau) = c tau^(p+2) + O(tau^(p+4)), order p.\n"
    "  All of it is derived exactly at compile time.\n"
    "  --m M         LPF interpolation degree, 2..8 (default 2), or all for m = 2..8\n"
    "  --nodes N     node family: equispaced (default; the only exact family)\n"
    "  --scheme S    lpf (default; eqs. 16, 18, 19 are m = 2, 3, 4) or midpoint (the midpoint\n"
    "                VI, eq. 17; --m does not apply and m is printed as '-')\n"
    "  --csv         m,numerator,denominator,order,leading_coefficient: the coefficients of P\n"
    "                and Q in ascending powers of tau^2, separated by ';'\n"
    "  --help        this text\n";

int usage_error(const std::string& msg) {
  std::cerr << "geomint-scheme: " << msg << "\n" << usage_text;
  return 2;
}

template <int... K>
constexpr std::array<exact_two_step_scheme, sizeof...(K)> lpf_table(std::integer_sequence<int, K...>) {
  return {geomint::exact_two_step_v<K + 2>...};
}
/// m = 2..8 on equispaced nodes, evaluated at compile time.
constexpr auto lpf_schemes = lpf_table(std::make_integer_sequence<int, geomint::max_exact_m - 1>{});

std::string csv_coefficients(const std::array<std::int64_t, exact_two_step_scheme::capacity>& c, int degree) {
  std::string out;
  for (int k = 0; k <= degree; ++k) {
    if (k != 0) out += ';';
    out += std::to_string(c[static_cast<std::size_t>(k)]);
  }
  return out;
}

/// "16 - 6 tau^2 + 22 tau^4": ascending powers of tau.
std::string polynomial_in_tau(const std::array<std::int64_t, exact_two_step_scheme::capacity>& c, int degree) {
  std::string out;
  for (int k = 0; k <= degree; ++k) {
    const std::int64_t v = c[static_cast<std::size_t>(k)];
    if (v == 0) continue;
    const bool negative = v < 0;
    const std::string magnitude = std::to_string(negative ? -v : v);
    if (out.empty()) {
      if (negative) out += '-';
    } else {
      out += negative ? " - " : " + ";
    }
    if (k == 0 || magnitude != "1") out += magnitude;
    if (k != 0) {
      if (magnitude != "1") out += ' ';
      out += "tau^";
      out += std::to_string(2 * k);
    }
  }
  return out.empty() ? "0" : out;
}

std::string m_label(const exact_two_step_scheme& s) { return s.m == 0 ? "-" : std::to_string(s.m); }

void print_csv_row(const exact_two_step_scheme& s) {
  std::cout << m_label(s) << "," << csv_coefficients(s.numerator, s.numerator_degree) << ","
            << csv_coefficients(s.denominator, s.denominator_degree) << "," << s.order << ","
            << s.leading_coefficient.str() << "\n";
}

void print_human(const exact_two_step_scheme& s) {
  if (s.m == 0) {
    std::cout << "scheme: midpoint variational integrator (eq. 17)\n";
  } else {
    std::cout << "scheme: lpf, m = " << s.m << ", equispaced nodes";
    if (s.m == 2) std::cout << " (eq. 16)";
    if (s.m == 3) std::cout << " (eq. 18)";
    if (s.m == 4) std::cout << " (eq. 19)";
    std::cout << "\n";
  }
  std::cout << "x^{k+1} = R(tau) x^k - x^{k-1}\n";
  std::cout << "R(tau) = (" << polynomial_in_tau(s.numerator, s.numerator_degree) << ")/("
            << polynomial_in_tau(s.denominator, s.denominator_degree) << ")\n";
  std::cout << "R(tau) - 2 cos(tau) = " << s.leading_coefficient.str() << " tau^" << s.leading_power() << " + O(tau^"
            << s.leading_power() + 2 << ")\n";
  std::cout << "order p = " << s.order << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string m_arg = "2", nodes = "equispaced", scheme = "lpf";
  bool csv = false;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&](std::string& target) {
      if (i + 1 >= argc) return false;
      target = argv[++i];
      return true;
    };
    if (flag == "--help" || flag == "-h") {
      std::cout << usage_text;
      return 0;
    } else if (flag == "--csv") {
      csv = true;
    } else if (flag == "--all") {
      m_arg = "all";
    } else if (flag == "--m") {
      if (!value(m_arg)) return usage_error("--m needs a value");
    } else if (flag == "--nodes") {
      if (!value(nodes)) return usage_error("--nodes needs a value");
    } else if (flag == "--scheme") {
      if (!value(scheme)) return usage_error("--scheme needs a value");
    } else {
      return usage_error("unknown argument '" + flag + "'");
    }
  }
  if (scheme != "lpf" && scheme != "midpoint") return usage_error("--scheme must be lpf or midpoint");
  if (nodes == "lobatto" || nodes == "chebyshev" || nodes == "gauss-interior")
    return usage_error("node family '" + nodes + "' has irrational nodes; the exact derivation needs equispaced nodes");
  if (nodes != "equispaced") return usage_error("unknown node family '" + nodes + "'");

  int first = 2, last = geomint::max_exact_m;
  if (m_arg != "all") {
    const bool digits = !m_arg.empty() && m_arg.size() <= 2 && m_arg.find_first_not_of("0123456789") == std::string::npos;
    const int m = digits ? std::atoi(m_arg.c_str()) : -1;
    if (m < 2 || m > geomint::max_exact_m) return usage_error("--m must be an integer in 2..8 (or all), got '" + m_arg + "'");
    first = last = m;
  }

  if (csv) std::cout << "m,numerator,denominator,order,leading_coefficient\n";
  if (scheme == "midpoint") {
    if (csv) print_csv_row(geomint::exact_midpoint_two_step_v);
    else print_human(geomint::exact_midpoint_two_step_v);
    return 0;
  }
  for (int m = first; m <= last; ++m) {
    const exact_two_step_scheme& s = lpf_schemes[static_cast<std::size_t>(m - 2)];
    if (csv) {
      print_csv_row(s);
    } else {
      if (m != first) std::cout << "\n";
      print_human(s);
    }
  }
  return 0;
}
