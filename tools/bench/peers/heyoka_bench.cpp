/// geomint-peer-heyoka: heyoka's adaptive Taylor integrator (taylor_adaptive; Biscani & Izzo
/// 2021, docs/references.md) on geomint-workprecision's problems, with its references and its
/// final-error measure (tools/workprecision: problems.hpp, measurement.hpp, regimes.hpp), so that
/// the two programs' CSV lines and summaries compare directly.
///
/// Each variant runs a tolerance ladder 10^(-k/4). The integrator is compiled (LLVM JIT) once per
/// tolerance, outside the timing; the timed part is propagate_until(T) from the initial state
/// alone (CLOCK_PROCESS_CPUTIME_ID, the fastest of repeated runs, then further passes as
/// geomint-workprecision's). An untimed pass steps to T and records the energy error.
///   --digits 16: double over T = 1000, default and fast-math code, non-compact and compact mode.
///   --digits 50: T = 100 in real128 (quadruple, 113 bits) and MPFR reals of 113 and 166 bits.
/// Built only with -DGEOMINT_PEER_HEYOKA=ON and an installed heyoka (tools/bench/peers).
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <heyoka/heyoka.hpp>
#include <mp++/real.hpp>
#include <mp++/real128.hpp>

#include "cli.hpp"
#include "ensemble_data.hpp"
#include "measurement.hpp"
#include "regimes.hpp"

namespace {

namespace hy = heyoka;
namespace wp = geomint::workprecision;
using wp::arr;

/// One configuration of heyoka's integrator.
struct variant {
  std::string name;
  bool compact = false;
  bool fast_math = false;
  long prec = 0;  ///< MPFR precision in bits (mppp::real only)
};

/// Conversions between the integrator's scalar T and the reference scalar R, through decimal
/// strings of full length where T is not double (exact to T's precision both ways).
template <class T>
struct scalar_io;
template <>
struct scalar_io<double> {
  template <class R>
  static double from(const R& r, long) { return static_cast<double>(r); }
  template <class R>
  static R to(double x) { return R(x); }
};
template <>
struct scalar_io<mppp::real128> {
  template <class R>
  static mppp::real128 from(const R& r, long) {
    return mppp::real128(r.str(std::numeric_limits<R>::max_digits10, std::ios_base::scientific));
  }
  template <class R>
  static R to(const mppp::real128& x) { return R(x.to_string()); }
};
template <>
struct scalar_io<mppp::real> {
  template <class R>
  static mppp::real from(const R& r, long prec) {
    return mppp::real(r.str(std::numeric_limits<R>::max_digits10, std::ios_base::scientific), prec);
  }
  template <class R>
  static R to(const mppp::real& x) { return R(x.to_string()); }
};

/// The equations of motion of geomint-workprecision's problems (problems.hpp): the pendulum
/// qddot = -sin q, Kepler qddot = -q / |q|^3, and the outer solar system (zoo::outer_solar)
/// qddot_i = sum_j G m_j (q_j - q_i) / |q_j - q_i|^3, with state (q, qdot). Its constants G m_j
/// are formed in R from zoo's decimal strings and converted to T (no double literal in real128
/// or MPFR).
template <class T, class R>
std::vector<std::pair<hy::expression, hy::expression>> equations(const std::string& system, long prec) {
  if (system == "pendulum") {
    auto [x, v] = hy::make_vars("x", "v");
    return {hy::prime(x) = v, hy::prime(v) = -hy::sin(x)};
  }
  if (system == "kepler") {
    auto [x, y, vx, vy] = hy::make_vars("x", "y", "vx", "vy");
    const auto r2 = x * x + y * y;
    return {hy::prime(x) = vx, hy::prime(y) = vy, hy::prime(vx) = -x * hy::pow(r2, -1.5),
            hy::prime(vy) = -y * hy::pow(r2, -1.5)};
  }
  using sys = geomint::zoo::outer_solar;
  constexpr int bodies = 6, n = 3 * bodies;
  std::vector<hy::expression> q, v;
  for (int i = 0; i < n; ++i) q.emplace_back(hy::variable("q" + std::to_string(i)));
  for (int i = 0; i < n; ++i) v.emplace_back(hy::variable("v" + std::to_string(i)));
  std::vector<hy::expression> acc(n, hy::expression(scalar_io<T>::template from<R>(R(0), prec)));
  for (int i = 0; i < bodies; ++i)
    for (int j = i + 1; j < bodies; ++j) {
      std::array<hy::expression, 3> d;
      for (int c = 0; c < 3; ++c) d[std::size_t(c)] = q[std::size_t(3 * j + c)] - q[std::size_t(3 * i + c)];
      const auto inv_r3 = hy::pow(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], -1.5);
      const auto gm = [&](int k) {
        return hy::expression(scalar_io<T>::template from<R>(R(sys::gravitational_constant<R>() * sys::mass<R>(k)), prec));
      };
      for (int c = 0; c < 3; ++c) {
        acc[std::size_t(3 * i + c)] += gm(j) * d[std::size_t(c)] * inv_r3;
        acc[std::size_t(3 * j + c)] -= gm(i) * d[std::size_t(c)] * inv_r3;
      }
    }
  std::vector<std::pair<hy::expression, hy::expression>> out;
  for (int i = 0; i < n; ++i) out.push_back(hy::prime(q[std::size_t(i)]) = v[std::size_t(i)]);
  for (int i = 0; i < n; ++i) out.push_back(hy::prime(v[std::size_t(i)]) = acc[std::size_t(i)]);
  return out;
}

/// One tolerance of one variant: the compiled integrator and its measurement.
template <class T>
struct point {
  std::unique_ptr<hy::taylor_adaptive<T>> ta;
  wp::result r;
};

template <class P, class T, class R>
class ladder {
 public:
  static constexpr int n = P::n;

  ladder(const variant& v, const R& t_end) : v_(v), t_end_r_(t_end), t_end_(scalar_io<T>::template from<R>(t_end, v.prec)) {
    const arr<R, n> q0 = P::template q0<R>(), v0 = P::template v0<R>();
    for (int i = 0; i < n; ++i) state0_.push_back(scalar_io<T>::template from<R>(q0[std::size_t(i)], v.prec));
    for (int i = 0; i < n; ++i) state0_.push_back(scalar_io<T>::template from<R>(v0[std::size_t(i)], v.prec));
  }

  /// The integrator at tolerance 10^(-knob/4) (computed in R), compiled here.
  std::unique_ptr<hy::taylor_adaptive<T>> make(long knob) const {
    using std::pow;
    const T tol = scalar_io<T>::template from<R>(R(pow(R(10), R(-knob) / R(4))), v_.prec);
    if constexpr (std::is_same_v<T, double>)
      return std::make_unique<hy::taylor_adaptive<T>>(equations<T, R>(P::name, v_.prec), state0_, hy::kw::tol = tol,
                                                      hy::kw::compact_mode = v_.compact, hy::kw::fast_math = v_.fast_math);
    else if constexpr (std::is_same_v<T, mppp::real>)
      return std::make_unique<hy::taylor_adaptive<T>>(equations<T, R>(P::name, v_.prec), state0_, hy::kw::tol = tol,
                                                      hy::kw::compact_mode = v_.compact, hy::kw::prec = v_.prec);
    else
      return std::make_unique<hy::taylor_adaptive<T>>(equations<T, R>(P::name, v_.prec), state0_, hy::kw::tol = tol,
                                                      hy::kw::compact_mode = v_.compact);
  }

  /// One timed run from the initial state to T: the CPU seconds, or nullopt if it failed.
  std::optional<double> run_once(hy::taylor_adaptive<T>& ta, long& steps) const {
    std::copy(state0_.begin(), state0_.end(), ta.get_state_data());
    ta.set_time(scalar_io<T>::template from<R>(R(0), v_.prec));
    const double t0 = wp::cpu_now();
    const auto res = ta.propagate_until(t_end_);
    const double dt = wp::cpu_now() - t0;
    if (std::get<0>(res) != hy::taylor_outcome::time_limit) return std::nullopt;
    steps = static_cast<long>(std::get<3>(res));
    return dt;
  }

  /// The fastest of repeated timed runs (at least 3, up to 20 or 0.05 s), as wp::fastest_run.
  std::optional<double> fastest(hy::taylor_adaptive<T>& ta, long& steps) const {
    double best = std::numeric_limits<double>::infinity(), spent = 0;
    for (int rep = 0; rep < 20; ++rep) {
      const auto dt = run_once(ta, steps);
      if (!dt) return std::nullopt;
      best = std::min(best, *dt);
      spent += *dt;
      if (spent > 0.2 || (rep >= 2 && spent > 0.05)) break;
    }
    return best;
  }

  /// The final state's phase error against the reference (wp::phase_error, in R) and, from an
  /// untimed pass step by step, the largest energy error (in R).
  void errors(hy::taylor_adaptive<T>& ta, const geomint::analysis::closed_form_state<R, n>& ref, wp::result& r) const {
    arr<R, n> q, p;
    read(ta, q, p);
    r.final_error = wp::phase_error<R, R, n>(q, p, ref);
    std::copy(state0_.begin(), state0_.end(), ta.get_state_data());
    ta.set_time(scalar_io<T>::template from<R>(R(0), v_.prec));
    read(ta, q, p);
    const R e0 = P::energy(q, p);
    R worst(0);
    for (;;) {
      const T left = t_end_ - ta.get_time();
      const auto [outcome, h] = ta.step(left);
      if (outcome != hy::taylor_outcome::success && outcome != hy::taylor_outcome::time_limit) break;
      read(ta, q, p);
      using std::abs;
      worst = std::max(worst, R(abs(R(P::energy(q, p) - e0))));
      if (outcome == hy::taylor_outcome::time_limit) break;
    }
    r.max_energy_error = static_cast<double>(worst);
  }

  const variant& v() const { return v_; }
  const R& t_end() const { return t_end_r_; }

 private:
  void read(const hy::taylor_adaptive<T>& ta, arr<R, n>& q, arr<R, n>& p) const {
    const T* s = ta.get_state_data();
    for (int i = 0; i < n; ++i) {
      q[std::size_t(i)] = scalar_io<T>::template to<R>(s[i]);
      p[std::size_t(i)] = scalar_io<T>::template to<R>(s[n + i]);
    }
  }

  variant v_;
  R t_end_r_;
  T t_end_;
  std::vector<T> state0_;
};

struct options {
  std::string system = "pendulum";
  int digits = 16;
  int ensemble = 0;  ///< --ensemble N: batch mode on N trajectories
  std::uint64_t seed = 1;
  double t_end = 1000;
  bool csv = false;
  int passes = 2;
  std::optional<double> max_seconds;
  std::vector<std::string> only;
};

/// The ladder of one variant: tolerances 10^(-k/4) from `first`, until the final error is below
/// the regime's floor, the tolerance below T's epsilon, eight runs without improvement, or one
/// run slower than max_seconds.
template <class P, class T, class R>
std::vector<point<T>> sweep(const ladder<P, T, R>& l, long first, double floor, double eps, double max_seconds) {
  const auto ref = P::template exact<R>(l.t_end());
  std::vector<point<T>> pts;
  double prev = std::numeric_limits<double>::infinity();
  int worse = 0;
  for (long knob = first; std::pow(10.0, -double(knob) / 4) >= eps; ++knob) {
    point<T> pt;
    pt.ta = l.make(knob);
    long steps = 0;
    const auto cpu = l.fastest(*pt.ta, steps);
    if (!cpu) {
      std::cerr << "geomint-peer-heyoka: " << l.v().name << " failed at tolerance knob " << knob << "\n";
      break;
    }
    pt.r.method = l.v().name;
    pt.r.knob = knob;
    pt.r.cpu = *cpu;
    pt.r.steps = steps;
    pt.r.tau = static_cast<double>(l.t_end() / R(std::max(1L, steps)));
    l.errors(*pt.ta, ref, pt.r);
    const double err = pt.r.final_error;
    pts.push_back(std::move(pt));
    if (err < floor || *cpu > max_seconds) break;
    if (err >= prev && err < 1e-6) {
      if (++worse >= 8) break;
    } else {
      worse = 0;
    }
    prev = std::min(prev, err);
  }
  return pts;
}

template <class P, class T, class R>
void run_variant(const options& o, const wp::regime& g, const variant& v, long first, double eps,
                 std::vector<std::vector<wp::result>>& out) {
  if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), v.name) == o.only.end()) return;
  const double max_seconds = o.max_seconds.value_or(g.digits == 16 ? 1.0 : 4.0);
  const ladder<P, T, R> l(v, R(long(g.t_end * P::horizon)));
  auto pts = sweep<P, T, R>(l, first, g.floor, eps, max_seconds);
  for (int pass = 2; pass <= o.passes; ++pass)
    for (auto& pt : pts) {
      long steps = 0;
      if (const auto cpu = l.fastest(*pt.ta, steps)) pt.r.cpu = std::min(pt.r.cpu, *cpu);
    }
  std::vector<wp::result> rs;
  for (const auto& pt : pts) rs.push_back(pt.r);
  out.push_back(std::move(rs));
}

template <class P>
void run(const options& o) {
  std::vector<std::vector<wp::result>> all;
  using boost::multiprecision::cpp_bin_float_100;
  using boost::multiprecision::cpp_bin_float_50;
  wp::regime g;
  if (o.digits == 16) {
    g = wp::regime_16();
    const double eps = std::numeric_limits<double>::epsilon();
    for (const variant& v : {variant{"heyoka-double", false, false, 0}, variant{"heyoka-double-fast-math", false, true, 0},
                             variant{"heyoka-double-compact", true, false, 0},
                             variant{"heyoka-double-compact-fast-math", true, true, 0}})
      run_variant<P, double, cpp_bin_float_50>(o, g, v, 16, eps, all);
  } else {
    g = wp::regime_50();
    run_variant<P, mppp::real128, cpp_bin_float_100>(o, g, {"heyoka-real128", false, false, 0}, 72, 1.9e-34, all);
    run_variant<P, mppp::real128, cpp_bin_float_100>(o, g, {"heyoka-real128-compact", true, false, 0}, 72, 1.9e-34, all);
    run_variant<P, mppp::real, cpp_bin_float_100>(o, g, {"heyoka-real-113", true, false, 113}, 72, 1.9e-34, all);
    run_variant<P, mppp::real, cpp_bin_float_100>(o, g, {"heyoka-real-166", true, false, 166}, 72, 1.7e-50, all);
  }
  const char* scalar = o.digits == 16 ? "double" : "real128 and MPFR real";
  if (o.csv) std::cout << "method,tau,steps,cpu_seconds,final_error,max_energy_error\n";
  else
    std::cout << "system " << P::name << ", T = " << g.t_end * P::horizon << ", " << scalar << "; heyoka " << HEYOKA_VERSION_STRING
              << "; CPU time of propagate_until only (JIT excluded), fastest of " << o.passes << " passes\n"
              << std::left << std::setw(34) << "method" << std::right << std::setw(12) << "tau" << std::setw(10) << "steps"
              << std::setw(12) << "cpu [s]" << std::setw(12) << "final err" << std::setw(12) << "max dE\n";
  for (const auto& rs : all)
    for (const auto& r : rs) {
      if (o.csv)
        std::cout << std::setprecision(6) << r.method << ',' << r.tau << ',' << r.steps << ',' << r.cpu << ',' << r.final_error
                  << ',' << r.max_energy_error << '\n';
      else
        std::cout << std::left << std::setw(34) << r.method << std::right << std::setprecision(4) << std::setw(12) << r.tau
                  << std::setw(10) << r.steps << std::setw(12) << r.cpu << std::setw(12) << r.final_error << std::setw(12)
                  << r.max_energy_error << "\n";
    }
  const char* pre = o.csv ? "# " : "";
  std::cout << pre << "summary (" << P::name << ", " << scalar << ", T = " << g.t_end * P::horizon
            << "): CPU seconds at final error, log-log interpolation between measured points\n";
  std::vector<double> targets;
  for (const auto& goal : g.goals) targets.push_back(goal.error);
  targets.insert(targets.end(), g.others.begin(), g.others.end());
  for (double target : targets) {
    std::optional<std::pair<std::string, double>> best;
    wp::print_cpu_at(std::cout, all, target, pre, &best);
    std::cout << std::setprecision(4) << " best heyoka " << (best ? best->first : std::string("none")) << " ";
    if (best) std::cout << best->second << " s";
    else std::cout << "n/a";
    std::cout << "\n";
  }
}

/// --ensemble N: heyoka's batch mode (taylor_adaptive_batch, the recommended batch size: one
/// trajectory per SIMD lane) on geomint-ensemble's ensembles, references and error measure
/// (ensemble_data.hpp): the trajectories in blocks of the batch size, each block propagated to T
/// from its initial states; CPU time per trajectory, the fastest of repeated runs; the error the
/// largest final phase error over the trajectories. Variants: default and fast-math code.
int run_ensemble(const options& o) {
  const bool pendulum = o.system == "pendulum";
  const int n = pendulum ? 1 : 2;
  const auto x0 = wp::ensemble_initial_states(o.system, o.ensemble, o.seed);
  const wp::final_states ref =
      pendulum ? wp::references<geomint::systems::pendulum>(x0, o.t_end) : wp::references<geomint::zoo::henon_heiles>(x0, o.t_end);
  const std::uint32_t batch = hy::recommended_simd_size<double>();
  std::vector<std::pair<hy::expression, hy::expression>> eqs;
  if (pendulum) {
    auto [x, v] = hy::make_vars("x", "v");
    eqs = {hy::prime(x) = v, hy::prime(v) = -hy::sin(x)};
  } else {
    auto [x, y, vx, vy] = hy::make_vars("x", "y", "vx", "vy");
    eqs = {hy::prime(x) = vx, hy::prime(y) = vy, hy::prime(vx) = -(x + 2. * x * y), hy::prime(vy) = -(y + x * x - y * y)};
  }
  const auto block_state = [&](std::size_t first) {
    // Variable i of lane l at i * batch + l; lanes past the last trajectory repeat it.
    std::vector<double> st(static_cast<std::size_t>(2 * n) * batch);
    for (std::uint32_t l = 0; l < batch; ++l) {
      const auto& x = x0[std::min(first + l, x0.size() - 1)];
      for (int i = 0; i < 2 * n; ++i) st[std::size_t(i) * batch + l] = x[std::size_t(i)];
    }
    return st;
  };
  // One pass over the ensemble: CPU seconds, the final states in `out`, or nullopt on failure.
  const auto pass = [&](hy::taylor_adaptive_batch<double>& ta, std::vector<wp::ensemble_state>& out) -> std::optional<double> {
    out.assign(x0.size(), wp::ensemble_state(std::size_t(2 * n)));
    double spent = 0;
    for (std::size_t first = 0; first < x0.size(); first += batch) {
      const auto st = block_state(first);
      std::copy(st.begin(), st.end(), ta.get_state_data());
      ta.set_time(0.);
      const double t0 = wp::cpu_now();
      ta.propagate_until(o.t_end);
      spent += wp::cpu_now() - t0;
      for (const auto& res : ta.get_propagate_res())
        if (std::get<0>(res) != hy::taylor_outcome::time_limit) return std::nullopt;
      for (std::uint32_t l = 0; l < batch && first + l < x0.size(); ++l)
        for (int i = 0; i < 2 * n; ++i) out[first + l][std::size_t(i)] = ta.get_state_data()[std::size_t(i) * batch + l];
    }
    return spent;
  };
  std::vector<std::vector<wp::result>> all;
  for (const bool fast_math : {false, true}) {
    const std::string name = fast_math ? "heyoka-batch-fast-math" : "heyoka-batch";
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), name) == o.only.end()) continue;
    std::vector<wp::result> pts;
    std::vector<std::unique_ptr<hy::taylor_adaptive_batch<double>>> tas;
    double prev = std::numeric_limits<double>::infinity();
    int worse = 0;
    for (long knob = 16; std::pow(10.0, -double(knob) / 4) >= std::numeric_limits<double>::epsilon(); ++knob) {
      auto ta = std::make_unique<hy::taylor_adaptive_batch<double>>(eqs, block_state(0), batch, hy::kw::tol = std::pow(10.0, -double(knob) / 4),
                                                                    hy::kw::fast_math = fast_math);
      std::vector<wp::ensemble_state> out;
      double best = std::numeric_limits<double>::infinity(), spent = 0;
      bool failed = false;
      for (int rep = 0; rep < 10; ++rep) {
        const auto dt = pass(*ta, out);
        if (!dt) {
          failed = true;
          break;
        }
        best = std::min(best, *dt);
        spent += *dt;
        if (rep >= 1 && spent > 0.2) break;
      }
      if (failed) {
        std::cerr << "geomint-peer-heyoka: " << name << " failed at tolerance knob " << knob << "\n";
        break;
      }
      wp::result r;
      r.method = name;
      r.knob = knob;
      r.cpu = best / double(x0.size());
      r.final_error = wp::largest_error(out, ref);
      pts.push_back(r);
      tas.push_back(std::move(ta));
      if (r.final_error < 1e-13 || best > o.max_seconds.value_or(2.0)) break;
      if (r.final_error >= prev && r.final_error < 1e-6) {
        if (++worse >= 8) break;
      } else {
        worse = 0;
      }
      prev = std::min(prev, r.final_error);
    }
    for (int p = 2; p <= o.passes; ++p)
      for (std::size_t k = 0; k < pts.size(); ++k) {
        std::vector<wp::ensemble_state> out;
        if (const auto dt = pass(*tas[k], out)) pts[k].cpu = std::min(pts[k].cpu, *dt / double(x0.size()));
      }
    all.push_back(std::move(pts));
  }
  if (o.csv) std::cout << "method,tau,steps,cpu_seconds_per_trajectory,max_final_error\n";
  else
    std::cout << "system " << o.system << ", " << o.ensemble << " trajectories (seed " << o.seed << "), T = " << o.t_end
              << ", double; heyoka " << HEYOKA_VERSION_STRING << " batch mode, batch size " << batch
              << "; CPU time per trajectory of propagate_until only (JIT excluded)\n";
  for (const auto& rs : all)
    for (const auto& r : rs)
      if (o.csv) std::cout << std::setprecision(6) << r.method << ",,," << r.cpu << ',' << r.final_error << '\n';
      else
        std::cout << std::left << std::setw(26) << r.method << std::right << std::setprecision(4) << "  tol 10^(-" << r.knob
                  << "/4)" << std::setw(14) << r.cpu << std::setw(14) << r.final_error << '\n';
  wp::print_ensemble_summary(std::cout, o.system, o.ensemble, all, o.csv);
  return 0;
}

const char* usage =
    "usage: geomint-peer-heyoka [--system pendulum|kepler|outer-solar|henon-heiles] [--digits 16|50] [--csv] [--passes N (1..10)]\n"
    "                           [--ensemble N (1..65536) [--seed K] [--t-end T (0..10^5)]]\n"
    "                           [--max-seconds S (> 0)] [--methods a,b,...]\n"
    "heyoka's taylor_adaptive on geomint-workprecision's problems, references and final-error\n"
    "measure; a ladder of tolerances 10^(-k/4) per variant; CPU time of propagate_until only\n"
    "(the JIT compilation excluded), the fastest of repeated runs and of N passes (default 2).\n"
    "The outer solar system's T is 100 times the regime's, in days (geomint-workprecision's).\n"
    "--digits 16: double, T = 1000: heyoka-double, heyoka-double-fast-math, heyoka-double-compact,\n"
    "heyoka-double-compact-fast-math.\n"
    "--digits 50: T = 100: heyoka-real128, heyoka-real128-compact (quadruple precision),\n"
    "heyoka-real-113, heyoka-real-166 (MPFR, compact mode).\n"
    "--ensemble N: heyoka's batch mode on geomint-ensemble's ensembles of N trajectories (--system\n"
    "pendulum|henon-heiles, --seed K, --t-end T as there): heyoka-batch, heyoka-batch-fast-math;\n"
    "its columns method,tau,steps,cpu_seconds_per_trajectory,max_final_error (tau and steps empty;\n"
    "the table: the tolerance, the CPU seconds per trajectory, the largest final error).\n"
    "--csv prints geomint-workprecision's columns method,tau,steps,cpu_seconds,final_error,\n"
    "max_energy_error and the summary as '#' lines.\n"
    "Exit status: 0, 2 (bad command line), 1 (failure), 4 (output failed).\n";

}  // namespace

int main(int argc, char** argv) {
  options o;
  geomint::cli::parser cl("geomint-peer-heyoka", usage);
  cl.toggle("--csv", [&] { o.csv = true; })
      .value("--system",
             [&](const std::string& v) { o.system = geomint::cli::parse_choice("--system", v, {"pendulum", "kepler", "outer-solar", "henon-heiles"}); })
      .value("--ensemble", [&](const std::string& v) { o.ensemble = geomint::cli::parse_integer<int>("--ensemble", v, 1, 65536); })
      .value("--seed", [&](const std::string& v) { o.seed = geomint::cli::parse_integer<std::uint64_t>("--seed", v, 0, ~std::uint64_t(0)); })
      .value("--t-end",
             [&](const std::string& v) {
               o.t_end = geomint::cli::parse_real("--t-end", v, geomint::cli::real_bound::positive);
               if (o.t_end > 1e5) throw geomint::cli::usage_error("--t-end is out of range: '" + v + "' (expected T <= 10^5)");
             })
      .value("--digits",
             [&](const std::string& v) { o.digits = geomint::cli::parse_choice("--digits", v, {"16", "50"}) == "16" ? 16 : 50; })
      .value("--max-seconds",
             [&](const std::string& v) { o.max_seconds = geomint::cli::parse_real("--max-seconds", v, geomint::cli::real_bound::positive); })
      .value("--methods", [&](const std::string& v) { o.only = geomint::cli::split_list("--methods", v); })
      .value("--passes", [&](const std::string& v) { o.passes = geomint::cli::parse_integer<int>("--passes", v, 1, 10); });
  if (const auto done = cl.parse(argc, argv)) return *done;
  if (o.ensemble == 0 && o.system == "henon-heiles") {
    std::cerr << "geomint-peer-heyoka: --system henon-heiles needs --ensemble N\n" << usage;
    return 2;
  }
  if (o.ensemble > 0 && o.system != "pendulum" && o.system != "henon-heiles") {
    std::cerr << "geomint-peer-heyoka: --ensemble takes --system pendulum or henon-heiles\n" << usage;
    return 2;
  }
  try {
    if (o.ensemble > 0) run_ensemble(o);
    else if (o.system == "kepler") run<wp::kepler_problem>(o);
    else if (o.system == "outer-solar") run<wp::outer_solar_problem>(o);
    else run<wp::pendulum_problem>(o);
    return geomint::cli::finish_stdout("geomint-peer-heyoka", 0);
  } catch (const std::exception& e) {
    std::cerr << "geomint-peer-heyoka: " << e.what() << "\n";
    return geomint::cli::finish_stdout("geomint-peer-heyoka", 1);
  }
}
