/// libFuzzer target of the tableau file reader (methods/tableau_file.hpp): the input bytes are a
/// tableau file. It must be read or refused with a tableau_file_error whose message starts with
/// "fuzz.tableau:<line>: " for a line of the input; any other exception is a finding (abort), so
/// is any sanitizer report. Built with Clang by -DGEOMINT_FUZZ=ON (tests/cli/CMakeLists.txt);
/// seed it with examples/tableaux/, e.g. `geomint_fuzz_tableau -max_total_time=60 examples/tableaux`.
/// tests/methods/test_tableau_file_fuzz.cpp checks the same contract on random mutations.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "geomint/methods/tableau_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  int lines = 0;
  for (char ch : text) lines += ch == '\n';
  std::istringstream in(text);
  try {
    (void)geomint::methods::read_tableau(in, "fuzz.tableau");
  } catch (const geomint::methods::tableau_file_error& e) {
    const std::string prefix = "fuzz.tableau:" + std::to_string(e.line()) + ": ";
    if (std::string(e.what()).rfind(prefix, 0) != 0 || e.line() < 0 || e.line() > lines + 1) std::abort();
  } catch (...) {
    std::abort();  // an exception other than tableau_file_error escaped the reader
  }
  return 0;
}
