#pragma once
/// The `order` front end (geomint-order): observed local and global orders and error constants
/// of the schemes on the systems of a system_list, against a reference flow: the four built-in
/// systems (mechanics/systems.hpp) in 50 or 100 digits against an independent Taylor-series flow
/// in twice the digits (analysis/reference_flow.hpp); every other system (the zoo, a user's) in
/// double against the Galerkin VI in 50 digits (zoo_reference_states).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "geomint/analysis/order_study.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/cli/study.hpp"
#include "geomint/mechanics/systems.hpp"

namespace geomint::cli {

namespace order_detail {

using boost::multiprecision::cpp_bin_float_100;
using boost::multiprecision::cpp_bin_float_50;
using boost::multiprecision::number;
using boost::multiprecision::backends::cpp_bin_float;

/// Whether `order` studies Sys against the Taylor-series flow in 50 or 100 digits: the four
/// built-in systems. Every other system is studied in double against zoo_reference_states.
template <class Sys>
inline constexpr bool taylor_reference =
    std::is_same_v<Sys, systems::harmonic> || std::is_same_v<Sys, systems::pendulum> ||
    std::is_same_v<Sys, systems::kepler> || std::is_same_v<Sys, systems::charged>;

/// The degree of the Galerkin reference of a system without a Taylor reference: 3, and 2 for
/// systems above 8 degrees of freedom (the outer solar system), whose Newton matrix of (dof m)^2
/// entries in 50 digits is large.
template <class Sys>
inline constexpr int galerkin_reference_degree = Sys::dof > 8 ? 2 : 3;

template <class T>
std::string fixed2(const T& v) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << static_cast<double>(v);
  return out.str();
}
template <class T>
std::string sci3(const T& v) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(2) << static_cast<double>(v);
  return out.str();
}

/// The uncertainty of a row's order: |difference| of its last two successive global orders.
template <class T>
std::string order_spread(const analysis::order_result<T>& r) {
  if (!r.ok || r.global_orders.size() < 2) return "nan";
  using std::abs;
  return fixed2(T(abs(T(r.global_orders.back() - r.global_orders[r.global_orders.size() - 2]))));
}

/// The bound on the steps of one case: the ladder's runs and, for a zoo system, its reference.
constexpr long max_case_steps = 10'000'000;

/// The steps of the ladder's runs: N steps to T and one local step per count.
long ladder_steps(const std::vector<long>& counts) {
  long sum = 0;
  for (long N : counts) sum += N + 1;  // counts <= 10^9, at most 16 of them: no overflow
  return sum;
}

/// The least work of a zoo system's reference: two runs to T from the finest count, two runs of
/// 2 and 4 steps to each T/N.
long least_zoo_reference_steps(const std::vector<long>& counts) {
  return 3 * std::max(2L, counts.back()) + 6 * static_cast<long>(counts.size());
}

/// The reference states at t_end / N (and t_end), computed once per system in the scalar R.
template <class Sys, class T, class R>
std::map<long, std::pair<analysis::dynamic_vector<T>, analysis::dynamic_vector<T>>> reference_states(
    const T& t_end, const std::vector<long>& counts) {
  constexpr int n = Sys::dof;
  vec<T, n> q0t, qdot0t;
  Sys::initial_data(q0t, qdot0t);
  vec<R, n> q0, qdot0;
  for (int i = 0; i < n; ++i) {
    q0[i] = R(q0t[i]);
    qdot0[i] = R(qdot0t[i]);
  }
  // Start from exactly the working-precision data the schemes start from.
  const vec<R, n> p0 = momentum<Sys, R>(Sys{}, q0, qdot0);
  std::map<long, std::pair<analysis::dynamic_vector<T>, analysis::dynamic_vector<T>>> out;
  auto store = [&](long key, const R& t) {
    analysis::reference_flow<Sys, R> flow(q0, p0);
    flow.advance_to(t);
    analysis::dynamic_vector<T> q(n), p(n);
    const vec<R, n> pr = flow.p();
    for (int i = 0; i < n; ++i) {
      q[i] = T(flow.q()[i]);
      p[i] = T(pr[i]);
    }
    out[key] = {q, p};
  };
  store(0, R(t_end));
  for (long N : counts) store(N, R(t_end) / R(N));
  return out;
}

/// The reference states at t_end / N (and t_end) of a system without a Taylor reference (the zoo,
/// a user's), computed in the scalar R by the Galerkin VI of degree galerkin_reference_degree from
/// the study's initial state (q0, p0), with the step count doubled (from the study's finest step)
/// until two successive runs agree to 16 eps of T relative to max(1, |q|, |p|); the same check
/// as analysis::galerkin_reference (analysis/any_system.hpp), which uses degree 8.
template <class Sys, class T, class R, class List>
std::map<long, std::pair<analysis::dynamic_vector<T>, analysis::dynamic_vector<T>>> zoo_reference_states(
    List list, const analysis::dynamic_vector<T>& q0, const analysis::dynamic_vector<T>& p0, const T& t_end, const std::vector<long>& counts) {
  long budget = max_case_steps - ladder_steps(counts);  // the reference's share of the work bound
  scheme_spec spec;
  spec.scheme = "galerkin";
  spec.m = galerkin_reference_degree<Sys>;
  const auto stepper = make_stepper<R>(list, Sys::name, spec);
  const dynamic_vector<R> qr0 = q0.template cast<R>(), pr0 = p0.template cast<R>();
  const R tolerance = R(16) * R(std::numeric_limits<T>::epsilon());
  auto run_steps = [&](const R& t, long steps, dynamic_vector<R>& q, dynamic_vector<R>& p) {
    q = qr0;
    p = pr0;
    dynamic_vector<R> q1, p1;
    if (steps > budget)
      throw std::runtime_error("reference flow of " + std::string(Sys::name) + ": no agreement within the work bound (" +
                               std::to_string(max_case_steps) + " steps summed over the ladder and its reference; --steps)");
    budget -= steps;
    const R tau = t / R(steps);
    for (long k = 0; k < steps; ++k) {
      const step_status st = stepper->try_step(q, p, tau, q1, p1);
      if (!st) throw std::runtime_error("reference flow (" + stepper->name() + ", 50 digits): " + st.message());
      q = q1;
      p = p1;
    }
  };
  std::map<long, std::pair<analysis::dynamic_vector<T>, analysis::dynamic_vector<T>>> out;
  auto store = [&](long key, long start_steps) {
    const R t = key == 0 ? R(t_end) : R(t_end) / R(key);
    long steps = std::max(2L, start_steps);
    dynamic_vector<R> qa, pa, qb, pb;
    run_steps(t, steps, qa, pa);
    for (int refinement = 0; refinement < 20; ++refinement) {
      steps *= 2;
      run_steps(t, steps, qb, pb);
      using std::max;
      const R change = max(R((qb - qa).template lpNorm<Eigen::Infinity>()), R((pb - pa).template lpNorm<Eigen::Infinity>()));
      const R scale = max(R(1), max(R(qb.template lpNorm<Eigen::Infinity>()), R(pb.template lpNorm<Eigen::Infinity>())));
      if (change <= tolerance * scale) {
        out[key] = {qb.template cast<T>(), pb.template cast<T>()};
        return;
      }
      qa = qb;
      pa = pb;
    }
    throw std::runtime_error("reference flow of " + std::string(Sys::name) + ": no agreement after 20 refinements");
  };
  store(0, counts.back());
  for (long N : counts) store(N, 1);
  return out;
}

template <class T, class R, class List>
int run(const std::string& program, const selection<List>& sel, const T& t_end, const std::vector<long>& counts,
        bool monitor) {
  const List list;
  const auto cases = sel.cases();
  // Reference states per system (key 0: t_end; key N: t_end / N).
  std::map<std::string, std::map<long, std::pair<analysis::dynamic_vector<T>, analysis::dynamic_vector<T>>>> refs;
  for (const std::string& system : sel.systems) {
    with_system(list, system, [&]<class Sys>() {
      if constexpr (!taylor_reference<Sys>) {
        if constexpr (std::is_same_v<T, double>) {
          const auto midpoint = make_stepper<T>(list, system, scheme_spec{"midpoint"});
          const auto [q0, qdot0] = default_initial_data<T>(list, system);
          refs[system] = zoo_reference_states<Sys, T, R>(list, q0, midpoint->momentum(q0, qdot0), t_end, counts);
        } else {
          throw usage_error("--system " + system + ": the zoo systems are studied in 16 digits (--digits 16)");
        }
      } else if constexpr (std::is_same_v<T, double>) {
        throw usage_error("--system " + system + ": the built-in systems are studied in 50 or 100 digits");
      } else {
        refs[system] = reference_states<Sys, T, R>(t_end, counts);
      }
    });
  }
  std::vector<analysis::order_result<T>> results(cases.size());
  std::vector<std::string> names(cases.size());
  const auto start = std::chrono::steady_clock::now();
  parallel_for(cases.size(), sel.threads, [&](std::size_t i) {
    const auto& c = cases[i];
    try {
      const auto stepper = make_stepper<T>(list, c.system, c.spec);
      if (monitor) stepper->set_monitor(step_monitor<T>::on());
      names[i] = stepper->name();
      const auto& ref = refs.at(c.system);
      auto [q0, qdot0] = default_initial_data<T>(list, c.system);
      const analysis::dynamic_vector<T> q0d = q0, p0d = stepper->momentum(q0, qdot0);
      analysis::reference_function<T> reference = [&](const T& t, analysis::dynamic_vector<T>& q,
                                                      analysis::dynamic_vector<T>& p) {
        long key = -1;
        if (t == t_end) key = 0;
        for (long N : counts)
          if (t == t_end / T(N)) key = N;
        const auto& qp = ref.at(key);
        q = qp.first;
        p = qp.second;
      };
      results[i] = analysis::order_study<T>(*stepper, reference, q0d, p0d, t_end, counts);
    } catch (const std::exception& e) {
      results[i].failure = e.what();
    }
  }, program.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int status = 0;
  const int scheme_w = scheme_column_width(cases);
  if (sel.csv) std::cout << "system,scheme,nodes,m,local_order,global_order,error_constant,regime,order_spread,finest_error\n";
  else
    std::cout << std::left << std::setw(16) << "system" << std::setw(scheme_w) << "scheme" << std::setw(16) << "nodes"
              << std::setw(4) << "m" << std::right << std::setw(8) << "local" << std::setw(8) << "global"
              << std::setw(12) << "constant" << "   global errors at tau = T/N; successive global orders\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    const auto& r = results[i];
    if (!r.ok) {
      std::cerr << program << ": " << c.system << ", " << names[i] << ": " << r.failure << '\n';
      status = exit_run_failure;
    }
    const std::string regime = analysis::asymptotic_regime(r);
    if (r.ok && regime != "ok") {
      std::cerr << program << ": " << c.system << ", " << names[i] << ": result " << regime
                << " (not a finding: a ladder in the asymptotic regime needs other --steps, --t-end or --digits)\n";
      status = exit_run_failure;
    }
    const std::string lo = r.ok ? fixed2(r.local_order) : "nan", go = r.ok ? fixed2(r.global_order) : "nan",
                      ec = r.ok ? sci3(r.error_constant) : "nan";
    if (sel.csv) {
      std::cout << c.system << ',' << c.spec.scheme << ',' << c.spec.nodes_label() << ','
                << m_label(c.spec) << ',' << lo << ',' << go << ',' << ec << ',' << regime << ','
                << order_spread(r) << ',' << (r.ok && !r.global_errors.empty() ? sci3(r.global_errors.back()) : "nan") << '\n';
    } else {
      std::cout << std::left << std::setw(16) << c.system << std::setw(scheme_w) << c.spec.scheme << std::setw(16)
                << c.spec.nodes_label() << std::setw(4) << m_label(c.spec) << std::right
                << std::setw(8) << lo << std::setw(8) << go << std::setw(12) << ec << "  ";
      for (const T& e : r.global_errors) std::cout << ' ' << sci3(e);
      std::cout << ';';
      for (const T& p : r.global_orders) std::cout << ' ' << fixed2(p);
      if (!r.ok) std::cout << "  FAILED";
      else if (regime != "ok") std::cout << "  OUTSIDE THE ASYMPTOTIC REGIME (" << regime << ")";
      std::cout << '\n';
    }
  }
  std::cerr << program << ": " << cases.size() << " case(s), " << std::numeric_limits<T>::digits10
            << " digits, T = " << static_cast<double>(t_end) << ", N =";
  for (long N : counts) std::cerr << ' ' << N;
  std::cerr << "; " << std::fixed << std::setprecision(1) << seconds << " s on " << sel.threads << " thread(s)\n";
  return status;
}

}  // namespace order_detail

/// The usage text of an `order` program over the systems `names`.
inline std::string order_usage(const std::string& program, const std::vector<std::string>& names) {
  const std::string pad(program.size() + 8, ' ');
  return "usage: " + program + " [--system S[,S...]|all] [--scheme S[,S...]|all] [--nodes F[,F...]|all]\n" + pad +
         "[--m M|A..B (2..8)] [--digits 16|50|100] [--steps N1,N2,... ] [--t-end T]\n" + pad +
         "[--threads K (1..64)] [--csv] [--no-monitor]\n"
         "Local error (one step) and global error (at t = T) of each scheme against a reference flow, for\n"
         "tau = T/N over the ladder N1 < N2 < ... (default T = 1, N = 8,16,32,64), and the observed orders\n"
         "between the two finest steps (local_order = p + 1, global_order = p) with the error constant\n"
         "C = global error / tau^round(p); the rows of geomint-order (docs/guide/your_own_tools.md).\n"
         + selection_usage(names) +
         "These systems are studied in double (--digits 16); their reference flow is the Galerkin VI of\n"
         "degree 3 (above 8 degrees of freedom: 2) in 50 digits, the step halved until two runs agree to\n"
         "16 eps of double. --steps: 2 to 16 increasing counts; the ladder and its reference must stay\n"
         "within 10^7 steps per case. regime is 'ok' only in the asymptotic regime; any row not 'ok' makes\n"
         "the exit status 3. The step monitor is on (--no-monitor turns it off).\n";
}

/// The `order` program over the systems of `list`; returns the exit status (0, 2 usage, 3 a
/// row outside the asymptotic regime or failed, 4 output).
template <class List>
int order_main(List list, int argc, const char* const* argv, study_tool tool = {}) {
  using namespace order_detail;
  if (tool.program.empty()) tool.program = "geomint-order";
  const bool any_taylor = []<class... Sys>(system_list<Sys...>) { return (taylor_reference<Sys> || ...); }(list);
  auto uses_taylor = [&](const std::string& name) { return with_system(list, name, []<class Sys>() { return taylor_reference<Sys>; }); };
  selection<List> sel(tool, any_taylor ? 50 : 16);
  std::vector<long> counts = {8, 16, 32, 64};
  std::string t_end_text = "1";
  bool monitor = true;
  parser cl(tool.program, tool.usage.empty() ? order_usage(tool.program, system_names(list)) : tool.usage);
  sel.register_flags(cl, {"16", "50", "100"}, tool);
  cl.value("--t-end", [&](const std::string& v) { t_end_text = checked_real_text("--t-end", v, real_bound::positive); })
      .value("--steps", [&](const std::string& v) {
        counts = parse_integer_list<long>("--steps", v, 1, 1'000'000'000L, 2, 16);
        for (std::size_t k = 1; k < counts.size(); ++k)
          if (counts[k] <= counts[k - 1]) throw usage_error("--steps must be positive and increasing");
      })
      .toggle("--no-monitor", [&] { monitor = false; });
  if (const auto done = cl.parse(argc, argv)) return *done;
  {
    const bool zoo = std::any_of(sel.systems.begin(), sel.systems.end(), [&](const std::string& s) { return !uses_taylor(s); });
    const long work = ladder_steps(counts) + (zoo ? least_zoo_reference_steps(counts) : 0);
    if (work > max_case_steps)
      return cl.fail("--steps: the ladder" + std::string(zoo ? " and its zoo reference need" : " needs") + " at least " +
                     std::to_string(work) + " steps per case, more than the bound " + std::to_string(max_case_steps));
  }
  try {
    auto parse_time = [&](auto zero) {
      using T = decltype(zero);
      std::istringstream in(t_end_text);  // checked by the parser: decimal, finite, > 0
      T t;
      in >> t;
      return t;
    };
    for (const std::string& system : sel.systems)
      if (!uses_taylor(system) != (sel.digits == 16))
        throw usage_error("--system " + system + ": " + tool.program + " studies the " +
                               (sel.digits == 16 ? std::string("built-in systems in 50 or 100 digits")
                                                 : std::string("zoo systems in 16 digits (--digits 16)")));
    sel.check_cases();
    int status = 0;
    if (sel.digits == 16) {
      status = run<double, cpp_bin_float_50>(tool.program, sel, parse_time(double()), counts, monitor);
    } else if (sel.digits == 50) {
      status = run<cpp_bin_float_50, cpp_bin_float_100>(tool.program, sel, parse_time(cpp_bin_float_50()), counts, monitor);
    } else {
      using float150 = number<cpp_bin_float<150>>;
      status = run<cpp_bin_float_100, float150>(tool.program, sel, parse_time(cpp_bin_float_100()), counts, monitor);
    }
    return finish_stdout(tool.program, status);
  } catch (const usage_error& e) {
    return finish_stdout(tool.program, cl.fail(e.what()));
  } catch (const std::exception& e) {
    std::cerr << tool.program << ": " << e.what() << '\n';
    return finish_stdout(tool.program, 1);
  }
}

}  // namespace geomint::cli
