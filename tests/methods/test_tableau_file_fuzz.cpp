/// A bounded randomised test of the tableau file reader (methods/tableau_file.hpp): mutations of
/// the example files (examples/tableaux/) and random token sequences must each be read or
/// refused with a tableau_file_error naming a line of the input, never another exception (a
/// crash, hang or sanitizer report fails the test run itself). The libFuzzer target
/// tests/cli/fuzz_tableau.cpp checks the same contract on coverage-guided inputs.
#include <chrono>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "catch.hpp"
#include "geomint/methods/tableau_file.hpp"

using namespace geomint::methods;

namespace {

/// Reads `text`; returns "" when it is read or refused as the contract says, else the finding.
std::string contract_violation(const std::string& text) {
  int lines = 0;
  for (char ch : text) lines += ch == '\n';
  std::istringstream in(text);
  try {
    (void)read_tableau(in, "fuzz.tableau");
  } catch (const tableau_file_error& e) {
    const std::string prefix = "fuzz.tableau:" + std::to_string(e.line()) + ": ";
    if (std::string(e.what()).rfind(prefix, 0) != 0) return std::string("message without its line: ") + e.what();
    if (e.line() < 0 || e.line() > lines + 1) return "line " + std::to_string(e.line()) + " outside the input: " + e.what();
  } catch (const std::exception& e) {
    return std::string("an exception other than tableau_file_error: ") + e.what();
  }
  return "";
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

}  // namespace

TEST_CASE("tableau file: the example files are read", "[tableau_file][fuzz]") {
  for (const char* name : {"gauss2", "stormer_verlet", "forest_ruth"}) {
    const std::string text = read_file(std::string(GEOMINT_TABLEAU_EXAMPLES) + "/" + name + ".tableau");
    REQUIRE_FALSE(text.empty());
    std::istringstream in(text);
    CHECK_NOTHROW(read_tableau(in, name));
  }
}

TEST_CASE("tableau file: mutated files and random tokens are read or refused naming a line", "[tableau_file][fuzz]") {
  std::vector<std::string> seeds;
  for (const char* name : {"gauss2", "stormer_verlet", "forest_ruth"})
    seeds.push_back(read_file(std::string(GEOMINT_TABLEAU_EXAMPLES) + "/" + name + ".tableau"));
  const std::vector<std::string> tokens = {
      "kind", "stages", "name", "field", "near", "c", "a", "b", "bbar", "ap", "ahat", "bhat", "rk", "prk", "rkn",
      "nystrom", "r", "r^2", "-", "+", "*", "/", "^", "(", ")", "0", "1", "2", "3", "1/2", "1/0", "0/0", "r/0",
      "2^64", "2^-64", "10^400", "1e5", "-1", "64", "65", "99999999999999999999", "#", "\n", "\n", "\n", " ", "\t",
      "r^2 - 3", "r^3 - 2", "r^2 + 1", "r^2", "1/2-r/6", "((((", "))))", "1.5", ".", "e", "x"};
  std::mt19937_64 rng(20261127);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  auto mutate = [&](std::string text) {
    const std::size_t edits = 1 + pick(4);
    for (std::size_t k = 0; k < edits; ++k) {
      const std::size_t at = text.empty() ? 0 : pick(text.size() + 1);
      switch (pick(6)) {
        case 0: if (!text.empty() && at < text.size()) text.erase(at, 1 + pick(8)); break;        // delete bytes
        case 1: text.insert(at, " " + tokens[pick(tokens.size())] + " "); break;                    // insert a token
        case 2: if (at < text.size()) text[at] = static_cast<char>(rng() & 0xff); break;           // flip a byte
        case 3: text.insert(at, 1, static_cast<char>(rng() & 0xff)); break;                         // insert a byte
        case 4: {                                                                                  // duplicate a line
          const std::size_t from = text.rfind('\n', at == 0 ? 0 : at - 1), to = text.find('\n', at);
          const std::size_t s = from == std::string::npos ? 0 : from + 1;
          text.insert(at, text.substr(s, to == std::string::npos ? std::string::npos : to - s + 1));
          break;
        }
        default: text = text.substr(0, at); break;                                                  // truncate
      }
    }
    return text;
  };
  auto random_tokens = [&] {
    std::string text;
    const std::size_t n = pick(40);
    for (std::size_t k = 0; k < n; ++k) text += tokens[pick(tokens.size())] + (pick(3) == 0 ? "\n" : " ");
    return text;
  };
  // Bounded in count and in time (about 2 s): the reader's own limits (digits, exponents,
  // bits, stages) keep every input cheap, so neither bound is a tolerance.
  const auto start = std::chrono::steady_clock::now();
  long inputs = 0, read = 0;
  double slowest = 0;
  while (inputs < 200000 && std::chrono::steady_clock::now() - start < std::chrono::seconds(2)) {
    const std::string text = pick(3) == 0 ? random_tokens() : mutate(seeds[pick(seeds.size())]);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string finding = contract_violation(text);
    slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    ++inputs;
    if (!finding.empty()) {
      INFO("input:\n" << text);
      FAIL(finding);
    }
    std::istringstream in(text);
    try {
      (void)read_tableau(in, "count");
      ++read;
    } catch (const tableau_file_error&) {
    }
  }
  WARN("tableau reader: " << inputs << " inputs, " << read << " read, slowest " << slowest << " s");
  CHECK(inputs > 100);
}
