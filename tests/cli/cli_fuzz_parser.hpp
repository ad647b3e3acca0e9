#pragma once
/// The shared command-line parser (tools/common/cli.hpp) with one flag of every kind the tools
/// use, for the fuzz target (fuzz_cli.cpp, libFuzzer) and the randomised test (test_cli.cpp).
/// The contract under test: any argument vector is accepted, or refused with cli::usage_error
/// (or --help); nothing else may escape, and no input may crash, hang or trip a sanitizer.
#include <string>
#include <vector>

#include "cli.hpp"

namespace geomint::cli_fuzz {

/// The flag names of the parser below (for generators).
inline const std::vector<std::string>& flag_names() {
  static const std::vector<std::string> names = {
      "--steps", "--m",     "--m-range", "--tau",   "--t-end",  "--q0",  "--counts", "--digits", "--scheme",
      "--nodes", "--nodes-list", "--systems", "--csv", "--drift", "--centreline", "--name", "--switch", "--threads"};
  return names;
}

/// How parse_command_line ended.
enum class outcome { accepted, usage_error, help };

/// Parses `args` (without the program name) with a parser that has every kind of flag; throws
/// only what the contract forbids (a logic error, a standard exception other than
/// usage_error), which the callers turn into a failure.
inline outcome parse_command_line(const std::vector<std::string>& args) {
  long steps = 0;
  int m = 0;
  std::pair<int, int> m_range;
  double tau = 0;
  std::string t_end, csv, drift, centreline, name, digits, scheme, nodes;
  std::vector<std::string> q0, node_list, systems;
  std::vector<long> counts;
  unsigned threads = 1;
  bool on = false;
  cli::parser p("fuzz", "usage: fuzz [flags]\n");
  p.value("--steps", [&](const std::string& v) { steps = cli::parse_integer<long>("--steps", v, 0, 1'000'000'000'000L); })
      .value("--m", [&](const std::string& v) { m = cli::parse_integer<int>("--m", v, 2, 16); })
      .value("--m-range", [&](const std::string& v) { m_range = cli::parse_integer_range<int>("--m-range", v, 2, 8); })
      .value("--tau", [&](const std::string& v) { tau = cli::parse_real("--tau", v, cli::real_bound::positive); })
      .value("--t-end", [&](const std::string& v) { t_end = cli::checked_real_text("--t-end", v, cli::real_bound::non_negative); })
      .value("--q0", [&](const std::string& v) { q0 = cli::parse_real_list("--q0", v, cli::real_bound::finite, 2); })
      .value("--counts", [&](const std::string& v) { counts = cli::parse_integer_list<long>("--counts", v, 1, 1'000'000'000L, 2, 16); })
      .value("--digits", [&](const std::string& v) { digits = cli::parse_choice("--digits", v, {"16", "50", "100"}); })
      .value("--scheme", [&](const std::string& v) { scheme = cli::parse_choice("--scheme", v, {"lpf", "midpoint", "galerkin"}); })
      .value("--nodes", [&](const std::string& v) { nodes = cli::parse_node_family("--nodes", v); })
      .value("--nodes-list", [&](const std::string& v) { node_list = cli::parse_node_family_list("--nodes-list", v); })
      .value("--systems", [&](const std::string& v) { systems = cli::parse_choice_list("--systems", v, {"pendulum", "kepler"}); })
      .value("--name", [&](const std::string& v) { name = v; })
      .value("--threads", [&](const std::string& v) { threads = cli::parse_integer<unsigned>("--threads", v, 1, 64); })
      .output("--csv", csv)
      .output("--drift", drift)
      .output("--centreline", centreline)
      .toggle("--switch", [&] { on = true; });
  std::vector<const char*> argv{"fuzz"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    p.parse_or_throw(static_cast<int>(argv.size()), argv.data());
  } catch (const cli::usage_error&) {
    return outcome::usage_error;
  } catch (const cli::parser::help_requested&) {
    return outcome::help;
  }
  return outcome::accepted;
}

}  // namespace geomint::cli_fuzz
