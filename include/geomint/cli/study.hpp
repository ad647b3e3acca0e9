#pragma once
/// The flags shared by the study front ends `order` and `symplectic` (geomint-order,
/// geomint-symplectic; on the common parser, parser.hpp): the selection of systems, schemes, node
/// families and m over a system_list, expanded into a list of study cases.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <tuple>
#include <utility>
#include <stdexcept>
#include <sstream>
#include <string>
#include <mutex>
#include <thread>
#include <vector>

#include "geomint/cli/digits.hpp"
#include "geomint/cli/parser.hpp"
#include "geomint/cli/progress.hpp"
#include "geomint/cli/steppers.hpp"

namespace geomint::cli {

/// What makes one study program: its name, usage text (empty: the front end's own), default
/// system (empty: the list's first) and --digits (0: the front end's), and the names that
/// `--system` expands to groups (default: "all", every system of the list).
struct study_tool {
  std::string program;
  std::string usage;
  std::string default_system;
  int default_digits = 0;
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
};

/// A number already checked by the parser (parser.hpp), read in the scalar T at full precision.
template <class T>
T parse_number(const std::string& flag, const std::string& s) {
  std::istringstream in(s);
  T v;
  in >> v;
  if (in.fail() || !in.eof() || !geomint::is_finite(v))
    throw usage_error(flag + " expects a finite number, got '" + s + "'");
  return v;
}

/// One study case: a system and a scheme.
struct study_case {
  std::string system;
  scheme_spec spec;
};

/// The flags common to the studies, over the systems of List.
template <class List>
struct selection {
  std::vector<std::string> systems;
  std::vector<std::string> schemes = {"lpf"};
  std::vector<std::string> nodes = {"equispaced"};
  int m_low = 2, m_high = 2;
  int digits = 50;
  bool csv = false;
  bool m_given = false, nodes_given = false;  ///< whether --m, --nodes were given (check_cases)
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());

  /// The defaults of `tool` (system, digits).
  explicit selection(const study_tool& tool, int default_digits) {
    systems = {tool.default_system.empty() ? system_names(List{}).front() : tool.default_system};
    digits = tool.default_digits != 0 ? tool.default_digits : default_digits;
  }

  /// Registers the flags common to the studies on the tool's parser; `--system` takes a comma
  /// list of names or a group of `tool` (default: "all", every system).
  void register_flags(parser& cl, std::vector<std::string> allowed_digits, const study_tool& tool) {
    auto groups = tool.groups;
    if (groups.empty()) groups.push_back({"all", system_names(List{})});
    cl.toggle("--csv", [this] { csv = true; })
        .value("--system", [this, groups](const std::string& v) {
          for (const auto& g : groups)
            if (v == g.first) {
              systems = g.second;
              return;
            }
          systems = parse_choice_list("--system", v, system_names(List{}));
        })
        .value("--scheme", [this](const std::string& v) {
          // "all": the schemes of every system; lpf-fixed-point (natural systems only) is named.
          schemes = v == "all" ? schemes_of_every_system() : parse_choice_list("--scheme", v, scheme_list());
        })
        .value("--nodes", [this](const std::string& v) {
          nodes = parse_node_family_list("--nodes", v);
          nodes_given = true;
        })
        .value("--m", [this](const std::string& v) {
          std::tie(m_low, m_high) = parse_integer_range<int>("--m", v, 2, 8);
          m_given = true;
        })
        .value("--digits", [this, allowed_digits](const std::string& v) {
          digits = std::stoi(parse_choice("--digits", v, allowed_digits));
        })
        .value("--threads", [this](const std::string& v) { threads = parse_integer<unsigned>("--threads", v, 1, 64); });
  }

  /// Throws usage_error (exit status 2) for a case whose system has no stepper for its scheme in
  /// `digits` digits (lpf-fixed-point on a system that is not natural).
  void check_cases() const {
    // Options that no selected scheme uses are errors, not ignored.
    auto any_scheme = [&](auto&& pred) { return std::any_of(schemes.begin(), schemes.end(), pred); };
    std::string listed;
    for (const std::string& s : schemes) listed += (listed.empty() ? "" : ",") + s;
    if (m_given && !any_scheme([](const std::string& s) { return scheme_spec{s}.has_m(); }))
      throw usage_error("--m applies to --scheme " + schemes_with_m() +
                        " only, not to --scheme " + listed);
    if (nodes_given && !any_scheme([](const std::string& s) { return takes_nodes(s); }))
      throw usage_error("--nodes applies to --scheme " + schemes_with_nodes() + " only, not to --scheme " + listed + " (" +
                        nodes_notes() + ")");
    for (const study_case& c : cases()) {
      try {
        with_digits(digits, [&]<int D>() { check_scheme<scalar_for_digits<D>>(List{}, c.system, c.spec); });
      } catch (const std::invalid_argument& e) {
        throw usage_error(e.what());
      }
    }
  }

  /// Every (system, scheme, family, m) of the selection; midpoint and trapezoidal have no m
  /// and no family, galerkin has no family.
  std::vector<study_case> cases() const {
    std::vector<study_case> out;
    for (const std::string& system : systems)
      for (const std::string& scheme : schemes) {
        scheme_spec s;
        s.scheme = scheme;
        if (!s.has_m()) {
          out.push_back({system, s});
          continue;
        }
        const std::vector<std::string> families = takes_nodes(scheme) ? nodes : std::vector<std::string>{"-"};
        for (const std::string& family : families)
          for (int m = m_low; m <= m_high; ++m) {
            s.nodes = takes_nodes(scheme) ? family : "equispaced";
            s.m = m;
            out.push_back({system, s});
          }
      }
    return out;
  }
};

/// The node families' printed names, comma-separated.
inline std::string node_family_text() {
  return comma_list(node_family_list());
}

/// The lines of a study's usage text that name its selection over the systems `names`.
inline std::string selection_usage(const std::vector<std::string>& names) {
  return "  systems: " + comma_list(names) + " (all); initial data as geomint-run\n"
         "  schemes: " + comma_list(schemes_of_every_system()) + " (all); lpf-fixed-point (natural systems;\n"
         "           kept for one release: lpf on gauss-interior takes its steps on natural systems)\n"
         "  nodes (lpf): " + node_family_text() + " (all)\n";
}

/// The width of the tables' scheme column: 13, or wider for a longer scheme name.
inline int scheme_column_width(const std::vector<study_case>& cases) {
  std::size_t width = 13;
  for (const study_case& c : cases) width = std::max(width, c.spec.scheme.size() + 2);
  return static_cast<int>(width);
}

/// The m column of the tables ("-" for midpoint and trapezoidal).
inline std::string m_label(const scheme_spec& s) { return s.has_m() ? std::to_string(s.m) : "-"; }

/// Runs job(i) for i in [0, count) on `threads` threads (each job owns its own stepper), with
/// the progress line of `tool` on a terminal (progress.hpp).
template <class Job>
void parallel_for(std::size_t count, unsigned threads, Job&& job, const char* tool) {
  progress bar(tool, count, "runs");
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
      bar.advance();
    }
  };
  for (unsigned t = 0; t < std::max(1u, threads); ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
}

}  // namespace geomint::cli
