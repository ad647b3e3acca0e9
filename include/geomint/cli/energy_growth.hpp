#pragma once
/// The growth of the energy error with t (geomint-run --growth, geomint-brouwer): the RMS of
/// |E - E0| over the windows of steps [2^j, 2^(j+1)), and the least-squares slope of log RMS
/// against log t (t at the window's geometric middle) over the windows from step 2^10 on.
/// Round-off that accumulates as a random walk gives 1/2 (Brouwer's law), a systematic one 1.
/// Samples of several trajectories added to one object give the ensemble RMS per window.
#include <cmath>
#include <optional>
#include <ostream>
#include <vector>

namespace geomint::cli {

struct energy_growth {
  static constexpr int first_window = 10;
  std::vector<double> sum_squares, count;

  void add(long step, double dE) {
    int j = 0;
    while ((2L << j) <= step) ++j;  // 2^j <= step < 2^(j+1)
    if (static_cast<int>(sum_squares.size()) <= j) {
      sum_squares.resize(static_cast<std::size_t>(j) + 1, 0.0);
      count.resize(static_cast<std::size_t>(j) + 1, 0.0);
    }
    sum_squares[static_cast<std::size_t>(j)] += dE * dE;
    count[static_cast<std::size_t>(j)] += 1.0;
  }
  /// The RMS over window j (0 for an empty window).
  double rms(std::size_t j) const { return count[j] == 0 ? 0.0 : std::sqrt(sum_squares[j] / count[j]); }
  /// t at the geometric middle of window j.
  static double t_mid(std::size_t j, double tau) { return tau * std::ldexp(std::sqrt(2.0), static_cast<int>(j)); }
  /// The fitted exponent over the windows from 2^from on, with the number of windows used;
  /// nothing if fewer than two windows qualify.
  std::optional<std::pair<double, int>> exponent(double tau, int from = first_window) const {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
    for (std::size_t j = 0; j < sum_squares.size(); ++j) {
      const double r = rms(j);
      if (static_cast<int>(j) < from || !(r > 0)) continue;
      const double x = std::log(t_mid(j, tau)), y = std::log(r);
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
      m += 1;
    }
    if (m < 2) return std::nullopt;
    return std::pair<double, int>((m * sxy - sx * sy) / (m * sxx - sx * sx), static_cast<int>(m));
  }
  void print(std::ostream& out, double tau) const {
    out << "window,steps_from,t_mid,rms_energy_error\n";
    for (std::size_t j = 0; j < sum_squares.size(); ++j)
      if (count[j] != 0) out << j << ',' << (1L << j) << ',' << t_mid(j, tau) << ',' << rms(j) << '\n';
    if (const auto e = exponent(tau))
      out << "growth_exponent=" << e->first << " (windows from step " << (1L << first_window) << ": " << e->second << ")\n";
    else
      out << "growth_exponent=undefined (fewer than two windows from step " << (1L << first_window) << ")\n";
  }
};

}  // namespace geomint::cli
