/// The tools' progress line (tools/common/progress.hpp): its text, and its silence when stderr is
/// not a terminal (the "is a terminal" decision injected). Expected texts are written out by hand
/// from the format's definition: 75 s = 1:15, 3725 s = 1:02:05; 10 of 40 runs in 30 s leave 30
/// runs, 90 s at the same rate.
#include "progress.hpp"

#include <sstream>
#include <string>
#include <thread>

#include "catch.hpp"

namespace progress_test {

using geomint::tools::format_duration;
using geomint::tools::progress;
using geomint::tools::progress_line;

TEST_CASE("format_duration: m:ss below an hour, h:mm:ss from one hour on", "[progress]") {
  CHECK(format_duration(0) == "0:00");
  CHECK(format_duration(-3) == "0:00");
  CHECK(format_duration(9.4) == "0:09");
  CHECK(format_duration(9.6) == "0:10");
  CHECK(format_duration(75) == "1:15");
  CHECK(format_duration(3599) == "59:59");
  CHECK(format_duration(3725) == "1:02:05");
}

TEST_CASE("progress_line: done/total, elapsed, and the remaining time at the average rate", "[progress]") {
  CHECK(progress_line("geomint-order", 10, 40, "runs", 30) == "geomint-order: 10/40 runs, 0:30 elapsed, about 1:30 left");
  // No estimate before the first unit is done, nor after the last.
  CHECK(progress_line("tool", 0, 40, "runs", 5) == "tool: 0/40 runs, 0:05 elapsed");
  CHECK(progress_line("tool", 40, 40, "runs", 3725) == "tool: 40/40 runs, 1:02:05 elapsed");
}

TEST_CASE("progress: nothing at all when stderr is not a terminal", "[progress]") {
  std::ostringstream out;
  {
    progress bar("tool", 3, "runs", /*shown=*/false, out);
    bar.advance();
    bar.set(2);
    bar.advance();
    bar.finish();
  }
  CHECK(out.str().empty());
}

TEST_CASE("progress: on a terminal, the line is drawn in place and erased at the end", "[progress]") {
  std::ostringstream out;
  {
    progress bar("tool", 3, "runs", /*shown=*/true, out);
    bar.advance();  // the first update draws at once
    CHECK(out.str().rfind("\r\033[Ktool: 1/3 runs, 0:00 elapsed, about 0:00 left", 0) == 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // past the redraw interval
    bar.set(2);
    CHECK(out.str().find("\r\033[Ktool: 2/3 runs") != std::string::npos);
  }  // the destructor erases the line
  const std::string text = out.str();
  CHECK(text.size() >= 4);
  CHECK(text.substr(text.size() - 4) == "\r\033[K");
}

}  // namespace progress_test
