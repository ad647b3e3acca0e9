#pragma once
/// Progress of a long run, on stderr and only when stderr is a terminal:
///
///     geomint-order: 12/40 runs, 0:35 elapsed, about 1:22 left
///
/// rewritten in place at most four times a second and erased when the run ends. A redirected or
/// piped stderr (a log, CI, the demonstration) gets nothing, and stdout (CSV) is never touched.
/// The tools call advance() (one unit done, thread-safe) or set(done) in their loops; both
/// return at once when the line is not shown.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>

#include <unistd.h>

namespace geomint::cli {

/// Whether stderr is a terminal (the default decision of `progress`).
inline bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

/// A duration as "m:ss", or "h:mm:ss" from one hour on (rounded to whole seconds).
inline std::string format_duration(double seconds) {
  const long s = seconds > 0 ? static_cast<long>(seconds + 0.5) : 0;
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

/// One progress line: "<label>: <done>/<total> <unit>, <elapsed> elapsed, about <left> left".
/// The estimate assumes the remaining units cost what the finished ones did on average; there
/// is none before the first unit is done, nor once all are.
inline std::string progress_line(std::string_view label, std::size_t done, std::size_t total, std::string_view unit,
                                 double elapsed_seconds) {
  std::string line = std::string(label) + ": " + std::to_string(done) + "/" + std::to_string(total) + " " +
                     std::string(unit) + ", " + format_duration(elapsed_seconds) + " elapsed";
  if (done > 0 && done < total)
    line += ", about " +
            format_duration(elapsed_seconds * static_cast<double>(total - done) / static_cast<double>(done)) + " left";
  return line;
}

/// The progress of `total` units of work (runs, steps, sweeps) named `unit`.
class progress {
 public:
  using clock = std::chrono::steady_clock;

  /// `shown`: whether to draw at all (default: stderr is a terminal); `out`: where (default
  /// std::cerr). Both are parameters so that a test can decide them.
  progress(std::string label, std::size_t total, std::string unit, bool shown = stderr_is_terminal(),
           std::ostream& out = std::cerr)
      : label_(std::move(label)), unit_(std::move(unit)), total_(total), shown_(shown), out_(out) {}
  progress(const progress&) = delete;
  progress& operator=(const progress&) = delete;
  ~progress() { finish(); }

  /// `n` more units done (thread-safe).
  void advance(std::size_t n = 1) {
    if (!shown_) return;
    const std::lock_guard<std::mutex> guard(lock_);
    update(done_ + n);
  }
  /// `done` units done in all (thread-safe; cheap enough to call on every step of a loop).
  void set(std::size_t done) {
    if (!shown_) return;
    const std::lock_guard<std::mutex> guard(lock_);
    update(done);
  }
  /// Erases the line (once; the destructor calls it).
  void finish() {
    if (!shown_) return;
    const std::lock_guard<std::mutex> guard(lock_);
    if (finished_) return;
    finished_ = true;
    if (drawn_) out_ << "\r\033[K" << std::flush;
  }

 private:
  void update(std::size_t done) {
    done_ = done;
    if (finished_ || done_ < next_check_) return;
    const clock::time_point now = clock::now();
    const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
    if (drawn_ && since_draw < redraw_seconds) {
      // Read the clock again after about as many units as fit in the rest of the interval.
      const double rate = static_cast<double>(done_ - drawn_done_) / std::max(since_draw, 1e-9);
      next_check_ = done_ + 1 + static_cast<std::size_t>(rate * (redraw_seconds - since_draw));
      return;
    }
    out_ << "\r\033[K" << progress_line(label_, done_, total_, unit_, std::chrono::duration<double>(now - start_).count())
         << std::flush;
    drawn_ = true;
    drawn_done_ = done_;
    last_draw_ = now;
    next_check_ = done_ + 1;
  }

  static constexpr double redraw_seconds = 0.25;
  std::string label_, unit_;
  std::size_t total_;
  bool shown_;
  std::ostream& out_;
  std::mutex lock_;
  std::size_t done_ = 0, drawn_done_ = 0, next_check_ = 0;
  bool drawn_ = false, finished_ = false;
  clock::time_point start_ = clock::now(), last_draw_ = start_;
};

}  // namespace geomint::cli
