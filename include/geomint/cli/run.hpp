#pragma once
/// The `run` front end (geomint-run): integrates a system of a system_list with a scheme chosen
/// on the command line (every scheme of geomint/stepper.hpp, m = 2..16, or a tableau file), in 16,
/// 50 or 100 digits, printing a summary or CSV rows. `run_main<List>(argc, argv)` is the whole
/// program; `run_tool` names it, gives its usage text and adds systems the list cannot hold (the
/// project's geomint-run: the constrained systems and their scheme paper23).
#include <algorithm>
#include <cmath>
#include <ctime>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "geomint/cli/digits.hpp"
#include "geomint/cli/energy_growth.hpp"
#include "geomint/cli/parser.hpp"
#include "geomint/cli/progress.hpp"
#include "geomint/cli/steppers.hpp"
#include "geomint/methods/catalogue.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/methods/tableau_file.hpp"

namespace geomint::cli {

/// The command line of `run`.
struct run_options {
  std::string program = "geomint-run";  ///< the name in messages
  std::string system;                   ///< empty: the list's first system
  std::string scheme = "lpf";
  std::string tableau;  ///< --tableau FILE: the method of a tableau file instead of a built-in scheme
  std::string method;   ///< --scheme NAME of a method of the catalogue (methods/catalogue.hpp), or empty
  std::string nodes = "equispaced";
  std::string basis = "lagrange";
  int m = 2;
  std::string tau = "0.1";
  long steps = 100;
  long every = 1;
  std::vector<std::string> q0, p0;  ///< empty: the system's default initial data
  int digits = 16;
  bool csv = false;
  bool monitor = true;  ///< the step monitor (geomint/solvers/step_monitor.hpp); --no-monitor turns it off
  bool compensated = false;  ///< --compensated: compensated summation of the q, p update
  bool growth = false;       ///< --growth: fit the exponent of the energy error's growth in t
  bool estimate = false;     ///< --estimate: Richardson's estimate of the global error (run at tau/2)
};

/// A number the command-line parser has already checked (plain decimal, finite, within the
/// range of double), read in the scalar T at full precision.
template <class T>
T parse_scalar(const std::string& s) {
  if constexpr (std::is_floating_point_v<T>) {
    return T(std::strtod(s.c_str(), nullptr));
  } else {
    std::istringstream in(s);
    T v;
    in >> v;
    if (in.fail() || !in.eof()) throw std::invalid_argument("not a number: " + s);
    return v;
  }
}

/// The monitor of the run: on unless --no-monitor.
template <class T>
step_monitor<T> run_monitor(const run_options& o) {
  return o.monitor ? step_monitor<T>::on() : step_monitor<T>{};
}

/// Reports a failed step on stderr (after what was written to stdout).
inline int report_failure(const run_options& o, const step_status& st) {
  std::cout.flush();
  std::cerr << o.program << ": " << st.message() << '\n';
  if (st.reason == step_failure::left_regime) std::cerr << o.program << ": (--no-monitor disables this check)\n";
  return exit_run_failure;
}

/// The initial state (q0, p0): q0 from --q0 or the system's default; p0 from --p0 (the
/// canonical momentum) or, if not given, the momentum dL/dqdot(q0, qdot0) of the default
/// velocity at that q0 (steppers.hpp, default_initial_state): a user's position
/// is never paired with the momentum of the default position.
template <class T, class List>
std::pair<dynamic_vector<T>, dynamic_vector<T>> initial_data(List list, const run_options& o, const any_stepper<T>& stepper) {
  return default_initial_state<T>(list, o.system, stepper, o.q0, o.p0,
                                         [](const std::string& s) { return parse_scalar<T>(s); });
}

/// A lower bound of the order of the scheme of `spec`: midpoint and trapezoidal 2, galerkin 2m,
/// lpf on Gauss-interior nodes and its fixed-point form 2(m - 1), lpf on other nodes 2 (a
/// symmetric consistent scheme; their order is at least that). For Richardson's estimate a
/// lower bound is the safe side: its factor 2^p / (2^p - 1) only grows as p decreases.
inline int order_lower_bound(const scheme_spec& spec) {
  if (spec.scheme == "galerkin") return 2 * spec.m;
  if (spec.scheme == "lpf-fixed-point" || (spec.scheme == "lpf" && canonical_node_family(spec.nodes) == gauss_interior::name))
    return 2 * (spec.m - 1);
  return 2;
}

/// --estimate: the same run at tau/2 (two steps per step of the run), and Richardson's estimate
/// of the run's global error at each step k, |z_k(tau) - z_2k(tau/2)|_inf 2^p / (2^p - 1) with
/// p = order_lower_bound (the error of z(tau) when e(tau) = C tau^p: the asymptotic regime).
template <class T>
struct error_estimate {
  dynamic_vector<T> q, p, q_carry, p_carry;
  T factor;
  explicit error_estimate(const dynamic_vector<T>& q0, const dynamic_vector<T>& p0, int order)
      : q(q0), p(p0), q_carry(dynamic_vector<T>::Zero(q0.size())), p_carry(dynamic_vector<T>::Zero(q0.size())) {
    using std::pow;
    const T two_p = pow(T(2), T(order));
    factor = two_p / (two_p - T(1));
  }
  /// Two steps of tau/2; false (with the status in st) on failure.
  bool advance(any_stepper<T>& stepper, const T& tau, bool compensated, const newton_options<T>& opt,
               step_status& st) {
    dynamic_vector<T> q1 = q, p1 = p;
    for (int half = 0; half < 2; ++half) {
      st = compensated ? stepper.try_step_compensated(q, p, q_carry, p_carry, tau / T(2), q1, p1, opt)
                       : stepper.try_step(q, p, tau / T(2), q1, p1, opt);
      if (!st) return false;
      q = q1;
      p = p1;
    }
    return true;
  }
  /// The estimate of the error of (qk, pk).
  T of(const dynamic_vector<T>& qk, const dynamic_vector<T>& pk) const {
    using std::max;
    return T(factor * max(T((qk - q).template lpNorm<Eigen::Infinity>()), T((pk - p).template lpNorm<Eigen::Infinity>())));
  }
};

/// The integration loop of geomint-run for a system of the list, in the scalar T.
template <class T, class List>
int run_free_system(List list, const run_options& o) {
  scheme_spec spec;
  spec.scheme = o.scheme;
  spec.nodes = o.nodes;
  spec.basis = o.basis;
  spec.m = o.m;
  // --scheme NAME of the catalogue: its coefficients in T (methods::numeric_form); --tableau
  // FILE: the method of the file (a malformed file is a tableau_file_error naming its line, an
  // std::invalid_argument: a usage error).
  const methods::catalogue_entry* method = o.method.empty() ? nullptr : methods::find_in_catalogue(o.method);
  const auto stepper =
      method ? make_tableau_stepper<T>(list, o.system, methods::numeric_form<T>(*method))
      : o.tableau.empty()
          ? make_stepper<T>(list, o.system, spec)
          : make_tableau_stepper<T>(list, o.system, methods::to_scalar<T>(methods::nystrom_form_of(methods::read_tableau_file(o.tableau))));
  // Richardson's order: a catalogue method's published order, else the scheme's lower bound.
  const int order = method ? method->order : order_lower_bound(spec);
  stepper->set_monitor(run_monitor<T>(o));
  const int n = stepper->dof();
  const T tau = parse_scalar<T>(o.tau);
  // Not a structured binding: the lambdas below capture q and p (Clang 14 cannot).
  dynamic_vector<T> q, p;
  std::tie(q, p) = initial_data<T>(list, o, *stepper);
  std::optional<error_estimate<T>> estimate;
  if (o.estimate) estimate.emplace(q, p, order);
  long step = 0;
  T t(0);
  std::cout << std::setprecision(std::numeric_limits<T>::max_digits10);
  auto row = [&] {
    std::cout << step << ',' << t;
    for (int i = 0; i < n; ++i) std::cout << ',' << q[i];
    for (int i = 0; i < n; ++i) std::cout << ',' << p[i];
    std::cout << ',' << stepper->energy(q, p);
    if (estimate) std::cout << ',' << estimate->of(q, p);
    std::cout << '\n';
  };
  const T E0 = stepper->energy(q, p);
  if (o.csv) {
    std::cout << "step,t";
    for (int i = 1; i <= n; ++i) std::cout << ",q" << i;
    for (int i = 1; i <= n; ++i) std::cout << ",p" << i;
    std::cout << ",energy" << (estimate ? ",error_estimate" : "") << "\n";
    row();
  }
  const newton_options<T> opt;
  T max_dE(0), max_estimate(0);
  dynamic_vector<T> q1 = q, p1 = p;
  dynamic_vector<T> q_carry = dynamic_vector<T>::Zero(n), p_carry = dynamic_vector<T>::Zero(n);
  energy_growth growth;
  // CPU time of the stepping loop (steps, energy monitor and rows), printed to stderr as
  // cpu_seconds=X so that outside tools can time a run without the process start-up.
  timespec cpu_start{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu_start);
  progress bar(o.program, static_cast<std::size_t>(o.steps), "steps");
  for (long k = 0; k < o.steps; ++k) {
    if (k % 4096 == 0) bar.set(static_cast<std::size_t>(k));  // (a terminal only)
    step_status st = o.compensated ? stepper->try_step_compensated(q, p, q_carry, p_carry, tau, q1, p1, opt)
                                   : stepper->try_step(q, p, tau, q1, p1, opt);
    st.step = step;
    if (!st) {
      bar.finish();  // the message on a line of its own
      return report_failure(o, st);
    }
    if (estimate && !estimate->advance(*stepper, tau, o.compensated, opt, st)) {
      bar.finish();
      std::cout.flush();
      std::cerr << o.program << ": --estimate: the run at tau/2 failed in its steps " << 2 * step << " and "
                << 2 * step + 1 << ":\n";
      st.step = 2 * step;
      return report_failure(o, st);
    }
    q = q1;
    p = p1;
    ++step;
    t = T(step) * tau;  // t_k = k tau, not accumulated
    using std::abs;
    const T dE = abs(stepper->energy(q, p) - E0);
    if (dE > max_dE) max_dE = dE;
    if (estimate && estimate->of(q, p) > max_estimate) max_estimate = estimate->of(q, p);
    if (o.growth) growth.add(step, static_cast<double>(dE));
    if (o.csv && (step % o.every == 0 || k + 1 == o.steps)) {
      row();
      if (!stdout_ok()) return exit_output;  // reported by main (finish_stdout)
    }
  }
  bar.finish();
  timespec cpu_end{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu_end);
  std::cerr << "cpu_seconds="
            << double(cpu_end.tv_sec - cpu_start.tv_sec) + double(cpu_end.tv_nsec - cpu_start.tv_nsec) * 1e-9 << '\n';
  if (!o.csv) {
    std::cout << "system " << o.system << ", scheme " << stepper->name() << ", tau " << tau << ", steps " << o.steps
              << ", digits " << o.digits << "\n";
    std::cout << "t = " << t << "\nq =";
    for (int i = 0; i < n; ++i) std::cout << ' ' << q[i];
    std::cout << "\np =";
    for (int i = 0; i < n; ++i) std::cout << ' ' << p[i];
    std::cout << "\nenergy = " << stepper->energy(q, p) << "\nmax |energy - energy0| = " << max_dE << "\n";
    if (o.compensated) std::cout << "compensated summation\n";
  }
  if (estimate) {
    // A coarse run says so: an estimated error above 1/100 of the solution's size.
    using std::max;
    const T size = max(T(q.template lpNorm<Eigen::Infinity>()), T(p.template lpNorm<Eigen::Infinity>()));
    const T final_estimate = estimate->of(q, p);
    std::ostream& out = o.csv ? std::cerr : std::cout;  // keeps a CSV clean
    out << std::setprecision(3) << "estimated global error at t = " << static_cast<double>(t) << ": "
        << static_cast<double>(final_estimate) << " (max over the run " << static_cast<double>(max_estimate)
        << "; Richardson, tau against tau/2, order " << (method ? "" : ">= ") << order << ")\n";
    if (final_estimate > size / T(100) || max_estimate > size / T(100))
      out << "coarse run: the estimated error is " << static_cast<double>(T(max_estimate / size)) * 100
          << "% of the solution's size max(|q|, |p|) = " << static_cast<double>(size) << "; reduce --tau\n";
  }
  if (o.growth) growth.print(o.csv ? std::cerr : std::cout, static_cast<double>(tau));  // keeps a CSV clean
  return 0;
}

/// What makes one `run` program: its name, usage text (empty: run_usage) and default system
/// (empty: the list's first), and systems and schemes outside the list that `extra` runs (the
/// project's geomint-run: the constrained systems circle and spherical, and paper23).
struct run_tool {
  std::string program = "geomint-run";
  std::string usage;
  std::string default_system;
  std::vector<std::string> extra_systems;
  /// Schemes that only `extra` runs, each with what --m means for it (e.g. "m = 2 by construction").
  std::vector<std::pair<std::string, std::string>> extra_schemes;
  std::function<int(const run_options&)> extra;
};

/// The usage text of a `run` program over the systems `names`.
inline std::string run_usage(const std::string& program, const std::vector<std::string>& names) {
  const std::string pad(program.size() + 8, ' ');
  return "usage: " + program + " [--system " + comma_list(names) + "]\n" + pad +
         "[--scheme " + scheme_choices() + " | --scheme NAME | --tableau FILE]\n" + pad +
         "[--nodes " + core::detail::joined(node_family_names) + "] [--basis lagrange|bernstein]\n" + pad +
         "[--m M (2..16)] [--tau T (> 0)] [--steps N (0..10^12)] [--every K (1..10^12)]\n" + pad +
         "[--q0 a[,b...]] [--p0 a[,b...]] [--digits 16|50|100] [--csv]\n" + pad +
         "[--compensated] [--growth] [--estimate] [--no-monitor]\n"
         "Integrates the system with the one-step (q, p) form of the chosen scheme from its initial data\n"
         "(--q0 replaces the position, --p0 gives the canonical momentum dL/dqdot, else the momentum of the\n"
         "default velocity at that position); defaults: the first system, lpf, equispaced, lagrange, m=2,\n"
         "tau=0.1, steps=100. --csv prints step,t,q1,...,qn,p1,...,pn,energy every K steps in the full\n"
         "precision of the scalar. m = 2..8 for every scheme and node family; m = 9..16 for lpf --nodes\n"
         "gauss-interior --basis lagrange, lpf-fixed-point and galerkin, in 16 and 50 digits.\n"
         "lpf --nodes gauss-interior --basis lagrange takes the fixed-point form's steps on a natural system;\n"
         "lpf-fixed-point (kept for one release) is that form alone and needs a natural system.\n"
         "--scheme NAME integrates with a method of the catalogue (geomint-scheme --list-methods: gauss-3,\n"
         "radau-iia-5, forest-ruth, ...), --tableau FILE with the method written in FILE\n"
         "(docs/guide/tableau_files.md), both at the scalar's full precision. --compensated: compensated summation; --growth: the growth of the\n"
         "energy error; --estimate: Richardson's estimate of the global error (a run at tau/2). The step\n"
         "monitor refuses steps that do not resolve the motion (exit status 3; --no-monitor turns it off).\n"
         "The options are those of geomint-run (docs/guide/your_own_tools.md).\n";
}

/// The `run` program over the systems of `list` (see the header's comment); returns the exit
/// status: 0, 2 (usage, with the message naming the flag), 3 (a failed step), 4 (output).
template <class List>
int run_main(List list, int argc, const char* const* argv, const run_tool& tool = {}) {
  constexpr long max_count = 1'000'000'000'000L;  // the stated bound of --steps and --every
  run_options o;
  o.program = tool.program;
  o.system = tool.default_system.empty() ? system_names(list).front() : tool.default_system;
  std::vector<std::string> systems = system_names(list), schemes = scheme_list();
  systems.insert(systems.end(), tool.extra_systems.begin(), tool.extra_systems.end());
  for (const auto& s : tool.extra_schemes) schemes.push_back(s.first);
  auto is_extra_system = [&](const std::string& s) {
    return std::find(tool.extra_systems.begin(), tool.extra_systems.end(), s) != tool.extra_systems.end();
  };
  bool nodes_or_basis_given = false;  // --nodes and --basis choose among the lpf schemes only
  bool scheme_given = false, m_given = false;  // --scheme and --m choose a built-in scheme: not with --tableau
  parser cl(tool.program, tool.usage.empty() ? run_usage(tool.program, system_names(list)) : tool.usage);
  cl.value("--system", [&](const std::string& v) { o.system = parse_choice("--system", v, systems); })
      .value("--scheme", [&](const std::string& v) {
        scheme_given = true;
        if (methods::find_in_catalogue(v)) {
          o.method = v;
          return;
        }
        if (std::find(schemes.begin(), schemes.end(), v) == schemes.end())
          throw usage_error("--scheme must be one of " + comma_list(schemes) +
                            " or a method of the catalogue (geomint-scheme --list-methods); got " + in_quotes(v));
        o.scheme = v;
      })
      .value("--tableau", [&](const std::string& v) { o.tableau = v; })
      .value("--nodes", [&](const std::string& v) {
        o.nodes = parse_node_family("--nodes", v);
        nodes_or_basis_given = true;
      })
      .value("--basis", [&](const std::string& v) {
        o.basis = parse_choice("--basis", v, {"lagrange", "bernstein"});
        nodes_or_basis_given = true;
      })
      .value("--digits", [&](const std::string& v) { o.digits = std::stoi(parse_choice("--digits", v, {"16", "50", "100"})); })
      .value("--m", [&](const std::string& v) {
        o.m = parse_integer<int>("--m", v, 2, 16);
        m_given = true;
      })
      .value("--steps", [&](const std::string& v) { o.steps = parse_integer<long>("--steps", v, 0, max_count); })
      .value("--every", [&](const std::string& v) { o.every = parse_integer<long>("--every", v, 1, max_count); })
      .value("--tau", [&](const std::string& v) { o.tau = checked_real_text("--tau", v, real_bound::positive); })
      .value("--q0", [&](const std::string& v) { o.q0 = parse_real_list("--q0", v, real_bound::finite); })
      .value("--p0", [&](const std::string& v) { o.p0 = parse_real_list("--p0", v, real_bound::finite); })
      .toggle("--csv", [&] { o.csv = true; })
      .toggle("--no-monitor", [&] { o.monitor = false; })
      .toggle("--compensated", [&] { o.compensated = true; })
      .toggle("--growth", [&] { o.growth = true; })
      .toggle("--estimate", [&] { o.estimate = true; });
  if (const auto done = cl.parse(argc, argv)) return *done;
  if (!o.method.empty()) {
    if (!o.tableau.empty()) return cl.fail("--scheme and --tableau exclude each other");
    if (m_given || nodes_or_basis_given)
      return cl.fail("--m, --nodes and --basis apply to the built-in schemes, not to --scheme " + o.method + " (a method of the catalogue)");
    if (is_extra_system(o.system))
      return cl.fail("--scheme " + o.method + " (a method of the catalogue) runs on the free systems only, not on the constrained system " + o.system);
  }
  if (!o.tableau.empty()) {
    if (scheme_given) return cl.fail("--scheme and --tableau exclude each other");
    if (m_given || nodes_or_basis_given) return cl.fail("--m, --nodes and --basis apply to the built-in schemes, not to --tableau");
    if (is_extra_system(o.system))
      return cl.fail("--tableau runs on the free systems only, not on the constrained system " + o.system);
  }
  const scheme_entry* entry = find_scheme(o.scheme);  // null for the tool's extra schemes
  if (nodes_or_basis_given && !(entry && entry->has_nodes))
    return cl.fail("--nodes and --basis apply to --scheme " + schemes_with_nodes() +
                   " only, not to --scheme " + o.scheme +
                   (entry && !entry->nodes_note.empty() ? " (" + std::string(entry->nodes_note) + ")" : std::string()));
  if (m_given && !scheme_spec{o.scheme}.has_m()) {
    std::string note = "no degree";
    for (const auto& s : tool.extra_schemes)
      if (s.first == o.scheme) note = s.second;
    return cl.fail("--m applies to --scheme " + schemes_with_m() +
                   " only, not to --scheme " + o.scheme + " (" + note + ")");
  }
  try {
    int status = 0;
    const bool extra_scheme = std::any_of(tool.extra_schemes.begin(), tool.extra_schemes.end(),
                                          [&](const auto& s) { return s.first == o.scheme; });
    if (is_extra_system(o.system) || extra_scheme)
      status = tool.extra(o);  // (it refuses an extra scheme on a system of the list)
    else
      status = with_digits(o.digits, [&]<int D>() { return run_free_system<scalar_for_digits<D>>(list, o); });
    return finish_stdout(o.program, status);
  } catch (const std::invalid_argument& e) {
    // Combinations the parser cannot see alone (--q0 with the wrong count for the system, a
    // malformed tableau file, initial data off a constraint).
    std::cout.flush();
    return finish_stdout(o.program, cl.fail(e.what()));
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << o.program << ": " << e.what() << '\n';
    return finish_stdout(o.program, 1);
  }
}

}  // namespace geomint::cli
