#pragma once
/// Command-line parsing shared by geomint-order and geomint-symplectic: the selection of
/// systems, schemes, node families and m, expanded into a list of study cases.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <mutex>
#include <thread>
#include <vector>

#include "stepper.hpp"

namespace geomint::studies {

/// Thrown for a bad command line; the program prints the message, its usage and exits with 2.
struct usage_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

inline std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

inline long parse_integer(const std::string& flag, const std::string& s) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || !end || *end != '\0') throw usage_error(flag + " expects an integer, got '" + s + "'");
  return v;
}

/// `all` or a comma list checked against `allowed`.
inline std::vector<std::string> parse_choice(const std::string& flag, const std::string& value,
                                             const std::vector<std::string>& allowed) {
  if (value == "all") return allowed;
  std::vector<std::string> out = split_list(value);
  if (out.empty()) throw usage_error(flag + " needs a value");
  for (const std::string& v : out)
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) throw usage_error("invalid value '" + v + "' for " + flag);
  return out;
}

/// One study case: a system and a scheme.
struct study_case {
  std::string system;
  tools::scheme_spec spec;
};

/// The flags common to the studies.
struct selection {
  std::vector<std::string> systems = {"pendulum"};
  std::vector<std::string> schemes = {"lpf"};
  std::vector<std::string> nodes = {"equispaced"};
  int m_low = 2, m_high = 2;
  int digits = 50;
  bool csv = false;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());

  /// Consumes flag (and its value from argv) if it is one of the common ones.
  bool parse(const std::string& flag, int& i, int argc, char** argv, const std::vector<std::string>& allowed_systems,
             const std::vector<std::string>& allowed_digits) {
    if (flag == "--csv") {
      csv = true;
      return true;
    }
    const bool known = flag == "--system" || flag == "--scheme" || flag == "--nodes" || flag == "--m" ||
                       flag == "--digits" || flag == "--threads";
    if (!known) return false;
    if (i + 1 >= argc) throw usage_error("missing value after " + flag);
    const std::string value = argv[++i];
    if (flag == "--system") {
      systems = parse_choice(flag, value, allowed_systems);
    } else if (flag == "--scheme") {
      schemes = parse_choice(flag, value, tools::schemes());
    } else if (flag == "--nodes") {
      nodes = parse_choice(flag, value, tools::node_families());
    } else if (flag == "--m") {
      const std::size_t dots = value.find("..");
      const long lo = parse_integer(flag, value.substr(0, dots));
      const long hi = dots == std::string::npos ? lo : parse_integer(flag, value.substr(dots + 2));
      if (lo < 2 || hi > 8 || lo > hi) throw usage_error("--m must be an integer in 2..8 or a range a..b within it");
      m_low = static_cast<int>(lo);
      m_high = static_cast<int>(hi);
    } else if (flag == "--digits") {
      if (std::find(allowed_digits.begin(), allowed_digits.end(), value) == allowed_digits.end())
        throw usage_error("invalid value '" + value + "' for --digits");
      digits = static_cast<int>(parse_integer(flag, value));
    } else {
      const long t = parse_integer(flag, value);
      if (t < 1 || t > 64) throw usage_error("--threads must be in 1..64");
      threads = static_cast<unsigned>(t);
    }
    return true;
  }

  /// Every (system, scheme, family, m) of the selection; midpoint and trapezoidal have no m
  /// and no family, galerkin has no family.
  std::vector<study_case> cases() const {
    std::vector<study_case> out;
    for (const std::string& system : systems)
      for (const std::string& scheme : schemes) {
        tools::scheme_spec s;
        s.scheme = scheme;
        if (!s.has_m()) {
          out.push_back({system, s});
          continue;
        }
        const std::vector<std::string> families = scheme == "lpf" ? nodes : std::vector<std::string>{"-"};
        for (const std::string& family : families)
          for (int m = m_low; m <= m_high; ++m) {
            s.nodes = scheme == "lpf" ? family : "equispaced";
            s.m = m;
            out.push_back({system, s});
          }
      }
    return out;
  }
};

/// The command-line loop of a study: --help prints the usage and returns false (exit 0); the
/// common flags go to `sel`; each flag in `extra_flags` is passed with its value to
/// `extra(flag, value)`; anything else is a usage_error.
template <class Extra>
bool parse_command_line(int argc, char** argv, const char* usage, selection& sel, const std::vector<std::string>& digits,
                        const std::vector<std::string>& extra_flags, Extra&& extra) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::cout << usage;
      return false;
    }
    if (sel.parse(flag, i, argc, argv, tools::free_systems(), digits)) continue;
    if (std::find(extra_flags.begin(), extra_flags.end(), flag) == extra_flags.end())
      throw usage_error("unknown flag " + flag);
    if (i + 1 >= argc) throw usage_error("missing value after " + flag);
    extra(flag, std::string(argv[++i]));
  }
  return true;
}

/// The m column of the tables ("-" for midpoint and trapezoidal).
inline std::string m_label(const tools::scheme_spec& s) { return s.has_m() ? std::to_string(s.m) : "-"; }

/// Runs job(i) for i in [0, count) on `threads` threads (each job owns its own stepper).
template <class Job>
void parallel_for(std::size_t count, unsigned threads, Job&& job) {
  std::vector<std::thread> pool;
  std::size_t next = 0;
  std::mutex lock;
  auto worker = [&] {
    for (;;) {
      std::size_t i;
      {
        std::lock_guard<std::mutex> guard(lock);
        if (next >= count) return;
        i = next++;
      }
      job(i);
    }
  };
  for (unsigned t = 0; t < std::max(1u, threads); ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
}

}  // namespace geomint::studies
