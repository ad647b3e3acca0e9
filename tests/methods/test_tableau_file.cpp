/// The tableau file reader (methods/tableau_file.hpp): exact entries, and every malformed file
/// an error naming its line.
#include <sstream>
#include <string>

#include "catch.hpp"
#include "geomint/methods/nystrom_form.hpp"
#include "geomint/methods/tableau_file.hpp"
#include "field_numbers.hpp"

using namespace geomint::methods;

namespace {
tableau_data<field_element> read_text(const std::string& text) {
  std::istringstream in(text);
  return read_tableau(in, "test.tableau");
}
/// The line a malformed text is reported at (0 if it is read without error).
int error_line(const std::string& text, const std::string& reason) {
  try {
    read_text(text);
  } catch (const tableau_file_error& e) {
    CHECK(std::string(e.what()).find(reason) != std::string::npos);
    CHECK(std::string(e.what()).rfind("test.tableau:" + std::to_string(e.line()) + ": ", 0) == 0);
    return e.line();
  }
  return 0;
}
using geomint::test::field_numbers::q;
}  // namespace

TEST_CASE("tableau file: a Gauss RKN tableau over Q(sqrt 3), read exactly", "[methods]") {
  const auto t = read_text(
      "# Gauss collocation, s = 2\n"
      "kind rkn\n"
      "stages 2\n"
      "name gauss 2\n"
      "field r^2 - 3   # sqrt 3\n"
      "c    1/2-r/6  1/2+r/6\n"
      "a    1/36  5/36-r/12  5/36+r/12  1/36\n"
      "bbar 1/4+r/12  0.25-r/12\n"
      "b    0.5  1/2\n");
  CHECK(t.kind == method_kind::rkn);
  CHECK(t.stages == 2);
  CHECK(t.name == "gauss 2");
  const field_element r = t.c[1] - q(1, 2);  // sqrt 3 / 6
  CHECK(r * r == q(1, 12));
  CHECK(t.bbar[1] == q(1, 4) - r / field_element(2));
  CHECK(t.b[0] == q(1, 2));
  CHECK(t.a[0][1] == q(5, 36) - r / field_element(2));
  CHECK(t.a[1][1] == q(1, 36));
  // The Gauss weights satisfy bbar_i = b_i (1 - c_i) (the symplecticity condition of an RKN method).
  for (std::size_t i = 0; i < 2; ++i) CHECK(t.bbar[i] == t.b[i] * (field_element(1) - t.c[i]));
}

TEST_CASE("tableau file: exact expressions of any size, the root near a point", "[methods]") {
  const auto t = read_text(
      "kind rk\nstages 1\nfield r^2 - 2 near -1\n"
      "c 123456789012345678901234567890/123456789012345678901234567891\n"
      "a (1-r)^2*(1+r)^-2\nb 2^-3+0.125\n");
  CHECK(t.c[0] == field_element(exact_rational(boost::multiprecision::cpp_int("123456789012345678901234567890"),
                                               boost::multiprecision::cpp_int("123456789012345678901234567891"))));
  // r = -sqrt 2 (the root near -1): ((1 - r)/(1 + r))^2 = (3 - 2 r)^2 = 17 - 12 r = 17 + 12 sqrt 2.
  const field_element r = field_element::generator(t.a[0][0].field());
  CHECK(r.to<double>() < 0);
  CHECK(r * r == field_element(2));
  CHECK(t.a[0][0] == field_element(17) - field_element(12) * r);
  CHECK(t.b[0] == q(1, 4));
}

TEST_CASE("tableau file: every malformed file names its line", "[methods]") {
  const std::string head = "kind rkn\nstages 2\n";
  const std::string good_rest = "c 0 1\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n";
  CHECK(error_line(head + good_rest, "") == 0);
  // missing and extra entries
  CHECK(error_line(head + "c 0\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "c needs 2 entries") == 3);
  CHECK(error_line(head + "c 0 1\na 0 0 1/2 0 7\nbbar 1/2 0\nb 1/2 1/2\n", "a needs 4 entries") == 4);
  // a missing array, reported at the end of the file; a missing kind
  CHECK(error_line(head + "c 0 1\na 0 0 1/2 0\nb 1/2 1/2\n", "no 'bbar' line") == 5);
  CHECK(error_line("stages 2\n" + good_rest, "no 'kind' line") == 5);
  // unknown key, a key of another kind, a key given twice, an unknown kind, bad stages
  CHECK(error_line(head + "c 0 1\nbogus 1\n", "unknown key 'bogus'") == 4);
  CHECK(error_line(head + good_rest + "ap 0 0 0 0\n", "'ap' does not belong to kind rkn") == 7);
  CHECK(error_line(head + good_rest + "c 0 1\n", "'c' given twice (first at line 3)") == 7);
  CHECK(error_line("kind rkm\nstages 2\n" + good_rest, "unknown kind 'rkm'") == 1);
  CHECK(error_line("kind rkn\nstages 0\n" + good_rest, "stages takes one integer") == 2);
  // the field: no real root, not a polynomial, equally near roots
  CHECK(error_line(head + "field r^2 + 1\n" + good_rest, "no real root") == 3);
  CHECK(error_line(head + "field r^2 - 1 near 0\n" + good_rest, "equally near") == 3);
  CHECK(error_line(head + "field 1/r\n" + good_rest, "divided by constants only") == 3);
  // entries: division by zero (also at r = sqrt 2 exactly), r without a field, syntax, size
  CHECK(error_line(head + "c 0 1/(1-1)\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "division by zero") == 3);
  CHECK(error_line(head + "field r^2 - 2\nc 0 1/(r^2-2)\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "division by zero") == 4);
  CHECK(error_line(head + "c 0 r\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "'r' needs a field line") == 3);
  CHECK(error_line(head + "c 0 (1\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "expected ')'") == 3);
  CHECK(error_line(head + "c 0 1x\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "unexpected 'x'") == 3);
  CHECK(error_line(head + "c 0 2^1000\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "entry too large") == 3);
  CHECK(error_line(head + "c 0 (2^64)^64\na 0 0 1/2 0\nbbar 1/2 0\nb 1/2 1/2\n", "entry too large") == 3);
}

TEST_CASE("tableau file: a read tableau has its Nystrom form", "[methods]") {
  // Classical RK4: on q'' = F its form has A A as positions (HNW I, section II.14): row 3 of A A
  // is a_32 a_21 = 1/4, and bbar = b^T A = (1/6, 1/6, 1/6, 0).
  const auto t = read_text(
      "kind rk\nstages 4\nc 0 1/2 1/2 1\n"
      "a 0 0 0 0  1/2 0 0 0  0 1/2 0 0  0 0 1 0\n"
      "b 1/6 1/3 1/3 1/6\n");
  const auto f = nystrom_form_of(t);
  CHECK(f.a[2][0] == q(1, 4));
  CHECK(f.bbar == std::vector<field_element>{q(1, 6), q(1, 6), q(1, 6), field_element(0)});
  CHECK(f.explicit_positions);
  CHECK(f.explicit_velocities);
}
