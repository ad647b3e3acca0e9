#pragma once
/// The ensembles of geomint-ensemble and of geomint-peer-heyoka --ensemble: the same initial
/// states (doubles, bit for bit) in both programs, from a seed, their references and the error
/// measure.
///   pendulum:     released from rest, theta0 = 1/10 + 12/5 u (amplitudes 0.1 to 2.5 rad);
///   henon-heiles: from the origin with energy E = (1 + u) / 24 (1/24 to 1/12, below the
///                 chaotic sea of E = 1/8 and 1/6; Henon & Heiles 1964) in the direction
///                 phi = 2 pi u';
/// u, u' uniform in [0, 1): the top 53 bits of std::mt19937_64, whose output the standard fixes
/// (unlike uniform_real_distribution's).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "geomint/analysis/closed_form_flows.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"
#include "points.hpp"

namespace geomint::workprecision {

/// One initial state: q then qdot (dof entries each).
using ensemble_state = std::vector<double>;

inline std::vector<ensemble_state> ensemble_initial_states(const std::string& system, int trajectories, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  const auto u = [&g] { return static_cast<double>(g() >> 11) * 0x1p-53; };
  std::vector<ensemble_state> out;
  for (int k = 0; k < trajectories; ++k) {
    if (system == "pendulum") {
      out.push_back({0.1 + 2.4 * u(), 0.0});
    } else if (system == "henon-heiles") {
      const double energy = (1 + u()) / 24, phi = 2 * std::numbers::pi * u(), speed = std::sqrt(2 * energy);
      out.push_back({0.0, 0.0, speed * std::cos(phi), speed * std::sin(phi)});
    } else {
      throw std::invalid_argument("ensemble_initial_states: unknown system " + system);
    }
  }
  return out;
}

/// The final (q, qdot) of every trajectory: long double (the error measure's scalar).
using final_states = std::vector<std::vector<long double>>;

/// The final states at t_end from the initial states: the pendulum's closed form in
/// cpp_bin_float_50, otherwise the Taylor-series flow in long double (about 1e-19 per step).
template <class Sys>
final_states references(const std::vector<ensemble_state>& x0, double t_end) {
  constexpr int n = Sys::dof;
  final_states out;
  for (const ensemble_state& x : x0) {
    std::vector<long double> r(2 * n);
    if constexpr (std::is_same_v<Sys, systems::pendulum>) {
      using R = boost::multiprecision::cpp_bin_float_50;
      const auto s = analysis::pendulum_from_rest<R>(R(x[0]), R(t_end));
      r[0] = static_cast<long double>(s.q[0]);
      r[1] = static_cast<long double>(s.p[0]);
    } else {
      using V = vec<long double, n>;
      V q, v;
      for (int i = 0; i < n; ++i) {
        q[i] = x[static_cast<std::size_t>(i)];
        v[i] = x[static_cast<std::size_t>(n + i)];
      }
      analysis::reference_flow<Sys, long double> flow(q, v);  // unit mass: p = qdot
      flow.advance_to(static_cast<long double>(t_end));
      for (int i = 0; i < n; ++i) {
        r[static_cast<std::size_t>(i)] = flow.q()[i];
        r[static_cast<std::size_t>(n + i)] = flow.qdot()[i];
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

/// The largest final phase error |(q, qdot) - (q, qdot)_ref| over the trajectories (x: q then
/// qdot of each), formed in long double.
inline double largest_error(const std::vector<ensemble_state>& x, const final_states& ref) {
  double worst = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    long double sum = 0;
    for (std::size_t i = 0; i < x[k].size(); ++i) {
      const long double d = static_cast<long double>(x[k][i]) - ref[k][i];
      sum += d * d;
    }
    worst = std::max(worst, static_cast<double>(std::sqrt(sum)));
  }
  return worst;
}

/// The summary lines of both programs (as '#' lines with csv): CPU seconds per trajectory at
/// the largest final errors 1e-6, 1e-10, 1e-12, interpolated between each method's runs.
inline void print_ensemble_summary(std::ostream& out, const std::string& system, int trajectories,
                                   const std::vector<std::vector<result>>& methods, bool csv) {
  const char* pre = csv ? "# " : "";
  out << pre << "summary (" << system << ", " << trajectories
      << " trajectories): CPU seconds per trajectory at the largest final error, log-log interpolation\n";
  for (double target : {1e-6, 1e-10, 1e-12}) {
    print_cpu_at(out, methods, target, pre);
    out << "\n";
  }
}

}  // namespace geomint::workprecision
