#pragma once
/// geomint-workprecision's measured points, shared with geomint-ensemble and the heyoka peer:
/// the CPU clock, one run's result, and the CPU time at a target error interpolated between runs.
#include <algorithm>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <ostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geomint::workprecision {

/// CPU seconds of this process (CLOCK_PROCESS_CPUTIME_ID).
inline double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

/// One run: its method, knob (the sweep's index), step size, steps, CPU seconds, final error and
/// largest energy error.
struct result {
  std::string method;
  long knob = 0;
  double tau = 0;
  long steps = 0;
  double cpu = 0;
  double final_error = 0;
  double max_energy_error = 0;
};

/// CPU time at a target final error, interpolated log-log between the two measured points that
/// bracket it (the first crossing from above); a single run (Taylor) counts if it is below.
inline std::optional<double> cpu_at(const std::vector<result>& pts, double target) {
  if (pts.size() == 1) {
    if (pts[0].final_error <= target) return pts[0].cpu;
    return std::nullopt;
  }
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const result &a = pts[i], &b = pts[i + 1];
    if (a.final_error >= target && b.final_error <= target && a.final_error > 0 && b.final_error > 0) {
      if (a.final_error == b.final_error) return std::min(a.cpu, b.cpu);
      const double s = (std::log(target) - std::log(a.final_error)) / (std::log(b.final_error) - std::log(a.final_error));
      return std::exp(std::log(a.cpu) + s * (std::log(b.cpu) - std::log(a.cpu)));
    }
  }
  if (!pts.empty() && pts.front().final_error <= target) return pts.front().cpu;  // first run already below
  return std::nullopt;
}

/// One summary line "PRE  error E: NAME X s; NAME n/a; ..." over the methods' runs (each
/// vector one method's, in ladder order), without its end of line; the fastest method and its
/// CPU time, if any reaches the error, in `best`.
inline void print_cpu_at(std::ostream& out, const std::vector<std::vector<result>>& methods, double target, const char* pre,
                         std::optional<std::pair<std::string, double>>* best = nullptr) {
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << pre << "  error " << std::setprecision(0) << std::scientific << target << std::defaultfloat << std::setprecision(4) << ":";
  for (const auto& pts : methods) {
    if (pts.empty()) continue;
    const auto c = cpu_at(pts, target);
    out << " " << pts.front().method << " ";
    if (c) out << *c << " s;";
    else out << "n/a;";
    if (best && c && (!*best || *c < (*best)->second)) *best = std::make_pair(pts.front().method, *c);
  }
  out.flags(flags);
  out.precision(precision);
}

}  // namespace geomint::workprecision
