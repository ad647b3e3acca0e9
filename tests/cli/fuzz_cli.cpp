/// libFuzzer target of the shared command-line parser (tools/common/cli.hpp): the input bytes,
/// split at '\n' into arguments, go through a parser with every kind of flag
/// (cli_fuzz_parser.hpp). Any outcome but acceptance, a usage error or --help is a finding
/// (abort); so is any sanitizer report. Built with Clang by -DGEOMINT_FUZZ=ON
/// (tests/cli/CMakeLists.txt); run e.g. `geomint_fuzz_cli -max_total_time=60`.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli_fuzz_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') args.emplace_back();
    else if (data[i] != 0) args.back().push_back(static_cast<char>(data[i]));  // argv strings end at NUL
  }
  if (args.size() == 1 && args.front().empty()) args.clear();
  try {
    (void)geomint::cli_fuzz::parse_command_line(args);
  } catch (...) {
    std::abort();  // an exception other than usage_error escaped the parser
  }
  return 0;
}
