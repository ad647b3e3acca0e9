#pragma once
/// Every front end of the tools for your own systems, as one program with commands:
///
///     int main(int argc, char** argv) { return geomint::cli::main<henon_heiles>(argc, argv); }
///
///     mytool run --system henon-heiles --scheme galerkin --m 4 --digits 50
///     mytool order --digits 16 --system henon-heiles --scheme lpf --nodes gauss-interior --m 2..4
///     mytool symplectic --system henon-heiles --digits 16
///     mytool modified --scheme galerkin --m 2 --system henon-heiles --tau 0.1,0.05 --steps 400
///
/// Each command has the options of the project's program of that name (geomint-run,
/// geomint-order, geomint-symplectic, geomint-modified); `mytool <command> --help` prints them. A
/// command is one entry of `commands` (a front end over a system_list: run_main, order_main,
/// symplectic_main, modified_main).
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "geomint/cli/modified.hpp"
#include "geomint/cli/order.hpp"
#include "geomint/cli/parser.hpp"
#include "geomint/cli/run.hpp"
#include "geomint/cli/symplectic.hpp"
#include "geomint/cli/system_list.hpp"

namespace geomint::cli {

/// One command of a multi-command program: its name, a line saying what it does, and its front
/// end, called with the arguments after the command and the program name "<program> <command>".
struct command {
  std::string name;
  std::string summary;
  std::function<int(int argc, const char* const* argv, const std::string& program)> main;
};

/// The commands over the systems of `list`.
template <class List>
std::vector<command> commands(List list) {
  return {
      {"run", "integrate a system with a scheme or a tableau file (the options of geomint-run)",
       [list](int argc, const char* const* argv, const std::string& program) {
         run_tool tool;
         tool.program = program;
         return run_main(list, argc, argv, tool);
       }},
      {"order", "observed orders and error constants against a reference flow (geomint-order)",
       [list](int argc, const char* const* argv, const std::string& program) {
         study_tool tool;
         tool.program = program;
         return order_main(list, argc, argv, tool);
       }},
      {"symplectic", "symplecticity defect and long-time energy behaviour (geomint-symplectic)",
       [list](int argc, const char* const* argv, const std::string& program) {
         study_tool tool;
         tool.program = program;
         return symplectic_main(list, argc, argv, tool);
       }},
      {"modified", "the modified equation of a method and its predicted energy error (geomint-modified)",
       [list](int argc, const char* const* argv, const std::string& program) {
         study_tool tool;
         tool.program = program;
         return modified_main(list, argc, argv, tool);
       }},
  };
}

/// The program `<argv[0]> <command> [options]` over the systems of `list`: runs the command, or
/// prints the list of commands (exit status 0 for --help or -h, 2 for anything else).
template <class List>
int command_main(List list, int argc, const char* const* argv) {
  const std::string program = argc > 0 && argv[0] ? std::filesystem::path(argv[0]).filename().string() : "geomint-tool";
  const std::vector<command> all = commands(list);
  std::string text = "usage: " + program + " <command> [options]   (" + program + " <command> --help: its options)\n" +
                     "systems: " + comma_list(system_names(list)) + "\ncommands:\n";
  for (const command& c : all) text += "  " + c.name + std::string(c.name.size() < 12 ? 12 - c.name.size() : 1, ' ') + c.summary + '\n';
  const std::string first = argc > 1 && argv[1] ? argv[1] : "";
  for (const command& c : all)
    if (c.name == first) return c.main(argc - 1, argv + 1, program + " " + c.name);
  use_checked_stdout();
  if (first == "--help" || first == "-h") {
    std::cout << text;
    return finish_stdout(program);
  }
  std::cerr << program << ": " << (first.empty() ? std::string("name a command") : "unknown command " + in_quotes(first))
            << '\n' << text;
  return exit_usage;
}

/// command_main over the systems Sys...: the whole program of the header's comment.
template <class... Sys>
int main(int argc, char** argv) {
  return command_main(system_list<Sys...>{}, argc, argv);
}

}  // namespace geomint::cli
