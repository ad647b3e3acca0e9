/// The shared command-line parser of the tools (tools/common/cli.hpp).
///
/// Expected values: the integers and reals below are written in the tests as literals and their
/// exact values are known by construction (e.g. 2^63 - 1 = 9223372036854775807 is the largest
/// long long, 1e-320 lies below DBL_MIN = 2.2250738585072014e-308, the IEEE 754 binary64 limit);
/// the CSV truncation test derives its expectation from the rows it wrote and the file-size limit
/// it set (POSIX setrlimit(RLIMIT_FSIZE)).
#include "cli.hpp"

#include <csignal>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>

#include "catch.hpp"

namespace cli = geomint::cli;

namespace {

/// Runs the parser on `args` (without the program name) and returns the usage_error message, or
/// "" when the arguments were accepted.
std::string parse_error(const cli::parser& p, std::vector<std::string> args) {
  std::vector<const char*> argv{"prog"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    p.parse_or_throw(static_cast<int>(argv.size()), argv.data());
  } catch (const cli::usage_error& e) {
    return e.what();
  }
  return "";
}

/// The message of the usage_error that f throws ("" when it throws none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const cli::usage_error& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

}  // namespace

TEST_CASE("cli: integers are range-checked, never saturated", "[cli]") {
  CHECK(cli::parse_integer<long>("--steps", "0", 0, 100) == 0);
  CHECK(cli::parse_integer<long>("--steps", "+100", 0, 100) == 100);
  CHECK(cli::parse_integer<long long>("--n", "9223372036854775807", 0, std::numeric_limits<long long>::max()) ==
        std::numeric_limits<long long>::max());
  CHECK(cli::parse_integer<int>("--m", "-3", -5, 5) == -3);
  // strtol would return LONG_MAX with ERANGE for this text; it must be refused, naming the flag.
  for (const char* bad : {"99999999999999999999", "9223372036854775808", "101", "-1"}) {
    try {
      (void)cli::parse_integer<long>("--steps", bad, 0, 100);
      FAIL("accepted " << bad);
    } catch (const cli::usage_error& e) {
      CHECK(contains(e.what(), "--steps"));
      CHECK(contains(e.what(), "out of range"));
    }
  }
  for (const char* bad : {"", "abc", "12abc", " 12", "12 ", "1.5", "1e3", "+-1", "++1", "0x10", "+"}) {
    try {
      (void)cli::parse_integer<long>("--steps", bad, 0, 100);
      FAIL("accepted '" << bad << "'");
    } catch (const cli::usage_error& e) {
      CHECK(contains(e.what(), "--steps expects an integer in 0..100"));
    }
  }
}

TEST_CASE("cli: reals catch range, format and bound errors", "[cli]") {
  CHECK(cli::parse_real("--tau", "0.25", cli::real_bound::positive) == 0.25);
  CHECK(cli::parse_real("--tau", "1e-300", cli::real_bound::positive) == 1e-300);
  CHECK(cli::parse_real("--q0", "-1.5E+2") == -150.0);
  CHECK(cli::parse_real("--q0", "0") == 0.0);
  CHECK(cli::parse_real("--q0", "0.000e-999") == 0.0);  // an exact zero is no underflow
  CHECK(cli::parse_real("--q0", ".5") == 0.5);
  CHECK(cli::parse_real("--q0", "5.") == 5.0);
  // Out of the normal range of double: overflow and (gradual or total) underflow.
  for (const char* bad : {"1e400", "-1e400", "1e-320", "1e-400"}) {
    try {
      (void)cli::parse_real("--tau", bad, cli::real_bound::finite);
      FAIL("accepted " << bad);
    } catch (const cli::usage_error& e) {
      CHECK(contains(e.what(), "--tau is out of range"));
    }
  }
  // Not plain decimal: what strtod would read (hex, inf, nan, leading space) or nothing at all.
  for (const char* bad : {"", "abc", "1.5x", "nan", "inf", "-inf", "0x1p3", " 1", "1 ", "e5", ".", "1e", "1e+", "--1"}) {
    try {
      (void)cli::parse_real("--tau", bad, cli::real_bound::positive);
      FAIL("accepted '" << bad << "'");
    } catch (const cli::usage_error& e) {
      CHECK(contains(e.what(), "--tau expects a finite number > 0"));
    }
  }
  for (const char* bad : {"0", "-1", "-0.0"}) {
    try {
      (void)cli::parse_real("--tau", bad, cli::real_bound::positive);
      FAIL("accepted " << bad);
    } catch (const cli::usage_error& e) {
      CHECK(contains(e.what(), "--tau must be a finite number > 0"));
    }
  }
  CHECK(cli::parse_real("--x", "0", cli::real_bound::non_negative) == 0.0);
  CHECK_THROWS_AS(cli::parse_real("--x", "-1e-3", cli::real_bound::non_negative), cli::usage_error);
  CHECK(cli::checked_real_text("--tau", "0.1000000000000000000000000000001", cli::real_bound::positive) ==
        "0.1000000000000000000000000000001");
}

TEST_CASE("cli: lists, ranges and choices", "[cli]") {
  CHECK(cli::parse_integer_list<long>("--steps", "8,16,32", 1, 1000) == std::vector<long>{8, 16, 32});
  CHECK(contains(error_of([&] { (void)cli::parse_integer_list<long>("--steps", "8,,16", 1, 1000); }), "empty item"));
  CHECK(contains(error_of([&] { (void)cli::parse_integer_list<long>("--steps", "8,", 1, 1000); }), "--steps"));
  CHECK(contains(error_of([&] { (void)cli::parse_integer_list<long>("--steps", "8,99999999999999999999", 1, 1000); }), "--steps is out of range"));
  CHECK(contains(error_of([&] { (void)cli::parse_integer_list<long>("--steps", "8", 1, 1000, 2); }), "at least 2"));
  CHECK(contains(error_of([&] { (void)cli::split_list("--x", "1,2,3", 2); }), "at most 2"));
  CHECK(cli::parse_real_list("--q0", "1,-2.5", cli::real_bound::finite, 2) == std::vector<std::string>{"1", "-2.5"});
  CHECK(contains(error_of([&] { (void)cli::parse_real_list("--q0", "1", cli::real_bound::finite, 2); }), "needs 2 value"));
  CHECK(contains(error_of([&] { (void)cli::parse_real_list("--q0", "1,nan", cli::real_bound::finite, 2); }), "--q0"));

  CHECK(cli::parse_integer_range<int>("--m", "2..8", 2, 8) == std::pair<int, int>{2, 8});
  CHECK(cli::parse_integer_range<int>("--m", "4", 2, 8) == std::pair<int, int>{4, 4});
  CHECK(cli::parse_integer_range<int>("--m", "all", 2, 8) == std::pair<int, int>{2, 8});
  CHECK(contains(error_of([&] { (void)cli::parse_integer_range<int>("--m", "5..3", 2, 8); }), "is empty"));
  CHECK(contains(error_of([&] { (void)cli::parse_integer_range<int>("--m", "2..9", 2, 8); }), "out of range"));
  CHECK(contains(error_of([&] { (void)cli::parse_integer_range<int>("--m", "2...4", 2, 8); }), "--m expects"));
  CHECK_THROWS_AS(cli::parse_integer_range<int>("--m", "all", 2, 8, false), cli::usage_error);

  const std::vector<std::string> allowed{"lpf", "midpoint"};
  CHECK(cli::parse_choice("--scheme", "midpoint", allowed) == "midpoint");
  CHECK(contains(error_of([&] { (void)cli::parse_choice("--scheme", "rk4", allowed); }), "--scheme must be one of lpf, midpoint; got 'rk4'"));
  CHECK(cli::parse_choice_list("--scheme", "all", allowed) == allowed);
  CHECK(cli::parse_choice_list("--scheme", "midpoint,lpf", allowed) == std::vector<std::string>{"midpoint", "lpf"});
}

TEST_CASE("cli: the parser", "[cli]") {
  int m = 0;
  bool csv = false;
  std::string name;
  cli::parser p("prog", "usage: prog [--m M] [--name S] [--csv]\n");
  p.value("--m", [&](const std::string& v) { m = cli::parse_integer<int>("--m", v, 2, 8); })
      .value("--name", [&](const std::string& v) { name = v; })
      .toggle("--csv", [&] { csv = true; });

  CHECK(parse_error(p, {"--m", "4", "--csv", "--name=a=b"}).empty());
  CHECK(m == 4);
  CHECK(csv);
  CHECK(name == "a=b");  // only the first '=' separates
  CHECK(parse_error(p, {"--m=5"}).empty());
  CHECK(m == 5);

  CHECK(parse_error(p, {"--bogus"}) == "unknown flag --bogus");
  CHECK(parse_error(p, {"--bogus=3"}) == "unknown flag --bogus");
  CHECK(parse_error(p, {"--bogus", "3"}) == "unknown flag --bogus");
  CHECK(parse_error(p, {"--m"}) == "--m needs a value");
  CHECK(parse_error(p, {"--m", "--csv"}) == "--m needs a value (got the flag '--csv')");
  CHECK(parse_error(p, {"--name", ""}) == "--name needs a non-empty value");
  CHECK(parse_error(p, {"--name="}) == "--name needs a non-empty value");
  CHECK(parse_error(p, {"--csv=1"}) == "--csv takes no value, got '1'");
  CHECK(parse_error(p, {"stray"}) == "unexpected argument 'stray' (flags start with --)");
  CHECK(parse_error(p, {"-m"}) == "unexpected argument '-m' (flags start with --)");
  CHECK(contains(parse_error(p, {"--m", "9"}), "--m is out of range"));

  // A handler that throws something other than usage_error still yields a message with the flag.
  cli::parser q("prog", "usage");
  q.value("--x", [](const std::string&) { throw std::runtime_error("boom"); });
  CHECK(parse_error(q, {"--x", "1"}) == "--x: boom (value '1')");
  // A handler's usage_error without the flag gets it as a prefix.
  cli::parser r("prog", "usage");
  r.value("--y", [](const std::string&) { throw cli::usage_error("not allowed here"); });
  CHECK(parse_error(r, {"--y", "1"}) == "--y: not allowed here");

  std::vector<const char*> help{"prog", "--help"};
  CHECK_THROWS_AS(p.parse_or_throw(2, help.data()), cli::parser::help_requested);
  CHECK_THROWS_AS(cli::parser("p", "u").value("m", [](const std::string&) {}), std::logic_error);
  CHECK_THROWS_AS(cli::parser("p", "u").toggle("--a", [] {}).toggle("--a", [] {}), std::logic_error);
}

TEST_CASE("cli: csv_file writes whole rows and reports failures", "[cli]") {
  const std::string path = "geomint_test_cli_rows.csv";
  {
    cli::csv_file f;
    REQUIRE(f.open(path));
    f.row("a,b");
    f.row("1,2");
    CHECK(f.close());
  }
  CHECK(read_file(path) == "a,b\n1,2\n");

  cli::csv_file bad;
  CHECK_FALSE(bad.open("/nonexistent-directory/x.csv"));
  CHECK(contains(bad.error(), "cannot open"));

  // /dev/full: every write fails with ENOSPC (Linux); the failure is reported, not swallowed.
  std::ifstream probe("/dev/full");
  if (probe) {
    cli::csv_file full;
    REQUIRE(full.open("/dev/full"));
    full.row("x,y");
    CHECK_FALSE(full.close());
    CHECK(contains(full.error(), "cannot write to '/dev/full'"));
  }

  // A write cut short by the file-size limit (in a child, so the limit does not outlive the
  // test): 100 rows of 11 bytes ("row,1000,z\n") against a limit of 255 bytes; the kernel writes
  // the first 255 bytes, and the file must be cut back to the floor(255 / 11) = 23 complete rows
  // (253 bytes) that fit, the last one being row 1022.
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{255, 255};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(10);
    cli::csv_file f;
    if (!f.open(path)) _exit(11);
    for (int i = 0; i < 100; ++i) f.row("row," + std::to_string(1000 + i) + ",z");  // "row,1000,z\n" = 11 bytes
    _exit(f.close() ? 12 : 0);
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);  // close() reported the failure
  const std::string text = read_file(path);
  CHECK(text.size() == 253);
  REQUIRE(!text.empty());
  CHECK(text.back() == '\n');
  CHECK(text.substr(242) == "row,1022,z\n");
  std::remove(path.c_str());
}
