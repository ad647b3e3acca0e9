/// The shared command-line parser of the tools (tools/common/cli.hpp).
///
/// Expected values: the integers and reals below are written in the tests as literals and their
/// exact values are known by construction (e.g. 2^63 - 1 = 9223372036854775807 is the largest
/// long long, 1e-320 lies below DBL_MIN = 2.2250738585072014e-308, the IEEE 754 binary64 limit);
/// the CSV failure test derives its expectation from the file's previous content and the
/// file-size limit it set (POSIX setrlimit(RLIMIT_FSIZE)); the reasons are strerror's texts.
#include "cli.hpp"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include "catch.hpp"
#include "cli_fuzz_parser.hpp"

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

/// The number of temporary files `<path>.tmp.*` of csv_file left in the current directory.
int temporary_files(const std::string& path) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator("."))
    if (entry.path().filename().string().rfind(path + ".tmp.", 0) == 0) ++count;
  return count;
}

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
  // test): 100 rows of 11 bytes against a limit of 255 bytes. The rows go to a temporary file,
  // so the target keeps its previous content ("a,b\n1,2\n", written above), the failure is
  // reported by close(), and no temporary file is left behind.
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{255, 255};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(10);
    cli::csv_file f;
    if (!f.open(path)) _exit(11);
    for (int i = 0; i < 100; ++i) f.row("row," + std::to_string(1000 + i) + ",z");  // "row,1000,z\n" = 11 bytes
    if (f.close()) _exit(12);
    _exit(f.error().find("File too large") != std::string::npos ? 0 : 13);  // EFBIG's text names the reason
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);  // close() reported the failure with its reason
  CHECK(read_file(path) == "a,b\n1,2\n");
  CHECK(temporary_files(path) == 0);
  std::remove(path.c_str());
}

TEST_CASE("cli: csv_file is atomic: a reader sees the old file or the whole new one", "[cli]") {
  const std::string path = "geomint_test_cli_atomic.csv";
  {
    cli::csv_file f;
    REQUIRE(f.open(path));
    f.row("old");
    REQUIRE(f.close());
  }
  // Two writers of the same path at once, rows interleaved: each writes its own temporary file;
  // the last close wins, whole.
  cli::csv_file a, b;
  REQUIRE(a.open(path));
  REQUIRE(b.open(path));
  for (int i = 0; i < 5000; ++i) {  // more than one block (64 KiB) each
    a.row("a," + std::to_string(i) + ",aaaaaaaaaaaa");
    b.row("b," + std::to_string(i) + ",bbbbbbbbbbbb");
  }
  CHECK(read_file(path) == "old\n");  // nothing visible before close
  std::string expected_b;
  for (int i = 0; i < 5000; ++i) expected_b += "b," + std::to_string(i) + ",bbbbbbbbbbbb\n";
  REQUIRE(a.close());
  REQUIRE(b.close());
  CHECK(read_file(path) == expected_b);
  CHECK(temporary_files(path) == 0);
  // A directory is refused with its reason; the directory is untouched.
  cli::csv_file dir;
  CHECK_FALSE(dir.open("."));
  CHECK(contains(dir.error(), "Is a directory"));
  std::remove(path.c_str());
}

TEST_CASE("cli: two outputs naming the same file are a usage error naming both flags", "[cli]") {
  std::string csv, drift, centreline;
  // A fresh parser (and empty paths) per command line.
  auto error = [&](std::vector<std::string> args) {
    csv.clear();
    drift.clear();
    centreline.clear();
    cli::parser p("prog", "usage");
    p.output("--csv", csv).output("--drift", drift).output("--centreline", centreline);
    return parse_error(p, std::move(args));
  };
  CHECK(error({"--csv", "F", "--drift", "F"}) == "--csv and --drift name the same file 'F' (each output needs a file of its own)");
  CHECK(contains(error({"--csv", "F", "--centreline", "./F"}), "--csv and --centreline name the same file"));
  CHECK(contains(error({"--csv", "d/../F", "--drift", "F"}), "--csv and --drift name the same file"));
  CHECK(contains(error({"--drift", "-", "--csv", "-"}), "--csv and --drift name the same file '-'"));
  CHECK(error({"--csv", "F", "--drift", "G", "--centreline", "-"}).empty());
  CHECK(csv == "F");
  CHECK(drift == "G");
  CHECK(centreline == "-");
}

TEST_CASE("cli: a failed write to standard output names its reason", "[cli]") {
  std::ifstream probe("/dev/full");
  if (!probe) return;  // /dev/full is Linux's
  // In a child: standard output on /dev/full (ENOSPC on every write), stderr to a file.
  const std::string err_path = "geomint_test_cli_stderr.txt";
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    const int full = ::open("/dev/full", O_WRONLY);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (full < 0 || err < 0 || ::dup2(full, STDOUT_FILENO) < 0 || ::dup2(err, STDERR_FILENO) < 0) _exit(10);
    cli::use_checked_stdout();
    for (int i = 0; i < 10000; ++i) std::cout << "row " << i << '\n';
    const bool stopped = !cli::stdout_ok();
    _exit(cli::finish_stdout("prog") == cli::exit_output && stopped ? 0 : 11);
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(read_file(err_path) == "prog: cannot write to standard output: No space left on device\n");
  std::remove(err_path.c_str());
}

TEST_CASE("cli: random command lines are accepted or refused, nothing else", "[cli][fuzz]") {
  // A bounded randomised run of the fuzz target's contract (cli_fuzz_parser.hpp): argument
  // vectors built from the flag names, near-miss names, '=' forms and values at and beyond the
  // limits (huge and tiny numbers, signs, lists, control bytes). At most 2 s or 200000 vectors.
  namespace fz = geomint::cli_fuzz;
  std::mt19937_64 rng(20261127);
  const std::vector<std::string> values = {
      "", "0", "1", "-1", "+1", "++1", "-+1", "2", "8", "16", "17", "9223372036854775807", "9223372036854775808",
      "-9223372036854775808", "99999999999999999999", "1e308", "1e309", "1e-307", "1e-320", "4.9e-324", "2.2250738585072014e-308",
      "0.0", "-0", "1.5", ".5", "5.", "1e", "1e+", "e5", "nan", "inf", "-inf", "0x10", " 1", "1 ", "1,2", "1,,2", ",", "1,2,3",
      "2..8", "8..2", "..", "2..", "all", "zoo", "lpf", "midpoint", "gauss-interior", "gauss_lobatto", "-", "./F", "F",
      "d/../F", "/dev/null", "--csv", "--help", "-h", "=", "==", std::string(1, '\x01'), std::string("a\x7f" "b"),
      std::string(300, '9'), std::string(70, ',')};
  auto pick = [&](const std::vector<std::string>& v) { return v[rng() % v.size()]; };
  auto random_bytes = [&] {
    std::string s(rng() % 12, ' ');
    for (char& c : s) c = static_cast<char>(1 + rng() % 255);  // no NUL: argv strings end there
    return s;
  };
  auto mutate = [&](std::string s) {  // a near-miss: a character dropped, doubled or changed
    if (s.empty()) return s;
    const std::size_t i = rng() % s.size();
    switch (rng() % 3) {
      case 0: s.erase(i, 1); break;
      case 1: s.insert(i, 1, s[i]); break;
      default: s[i] = static_cast<char>(32 + rng() % 95); break;
    }
    return s;
  };
  std::size_t count[3] = {0, 0, 0};
  const auto start = std::chrono::steady_clock::now();
  long vectors = 0;
  for (; vectors < 200000 && std::chrono::steady_clock::now() - start < std::chrono::seconds(2); ++vectors) {
    std::vector<std::string> args;
    const int n = static_cast<int>(rng() % 7);
    for (int i = 0; i < n; ++i) {
      std::string flag = pick(fz::flag_names());
      if (rng() % 8 == 0) flag = mutate(flag);
      switch (rng() % 6) {
        case 0: args.push_back(flag); break;
        case 1: args.push_back(flag + "=" + pick(values)); break;
        case 2: args.push_back(random_bytes()); break;
        default:
          args.push_back(flag);
          args.push_back(rng() % 4 == 0 ? mutate(pick(values)) : pick(values));
      }
    }
    fz::outcome o{};
    try {
      o = fz::parse_command_line(args);
    } catch (const std::exception& e) {
      std::string line;
      for (const std::string& a : args) line += cli::in_quotes(a) + " ";
      FAIL("escaped: " << e.what() << " for " << line);
    }
    ++count[static_cast<int>(o)];
  }
  // Every outcome occurs (the generator reaches accepted lines, usage errors and --help).
  CHECK(count[static_cast<int>(fz::outcome::accepted)] > 0);
  CHECK(count[static_cast<int>(fz::outcome::usage_error)] > 0);
  CHECK(count[static_cast<int>(fz::outcome::help)] > 0);
  CHECK(vectors > 1000);
}
