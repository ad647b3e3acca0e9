#pragma once
/// The tableau file: a method written as text, read exactly (docs/guide/tableau_files.md).
///
///   # Gauss collocation, s = 2, as an RKN tableau
///   kind rkn
///   stages 2
///   name gauss-2
///   field r^2 - 3
///   c    1/2-r/6  1/2+r/6
///   a    1/36  5/36-r/12  5/36+r/12  1/36
///   bbar 1/4+r/12  1/4-r/12
///   b    1/2  1/2
///
/// One item per line, `#` starts a comment. `kind rk|prk|rkn|nystrom`, `stages S`, optional
/// `name NAME`, optional `field POLY [near X]` (r is the real root of the rational polynomial
/// POLY nearest X, default the largest), then one line per coefficient array, its key and its
/// entries separated by spaces: `c` (S), `a` (S*S, row by row), `b` (S), and per kind `bbar`
/// (rkn, nystrom), `ap` (nystrom, S*S), `ahat` (prk, S*S), `bhat` (prk). An entry is an exact
/// expression without spaces: integers, rationals p/q of any size, exact decimals such as
/// 0.125, r, + - * / ^ ( ). Every malformed or inconsistent file is a tableau_file_error
/// naming the file and the line.

#include <cctype>
#include <fstream>
#include <istream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geomint/methods/number_field.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

/// A malformed tableau file: the message is "FILE:LINE: reason" (LINE 0: the file as a whole).
class tableau_file_error : public std::invalid_argument {
 public:
  tableau_file_error(const std::string& source, int line, const std::string& reason)
      : std::invalid_argument(source + ":" + std::to_string(line) + ": " + reason), line_(line) {}
  int line() const { return line_; }

 private:
  int line_;
};

/// Limits that keep an entry's exact arithmetic small: digits of a literal, |exponent|, and the
/// bits of the numerators and denominators of a result.
inline constexpr std::size_t tableau_max_literal_digits = 400;
inline constexpr long tableau_max_exponent = 64;
inline constexpr unsigned tableau_max_bits = 4096;
inline constexpr int tableau_max_stages = 64;

namespace detail {

/// Polynomials in r with rational coefficients (the field line's POLY), with the operations the
/// expression parser needs; division by a nonzero constant only.
struct poly_value {
  poly c;
  poly_value() = default;
  explicit poly_value(const exact_rational& x) : c{x} { trim(c); }
  static poly_value generator() {
    poly_value g;
    g.c = {exact_rational(0), exact_rational(1)};
    return g;
  }
  friend poly_value operator+(const poly_value& a, const poly_value& b) { return from(add(a.c, b.c)); }
  friend poly_value operator-(const poly_value& a, const poly_value& b) { return from(subtract(a.c, b.c)); }
  friend poly_value operator*(const poly_value& a, const poly_value& b) { return from(multiply(a.c, b.c)); }
  friend poly_value operator/(const poly_value& a, const poly_value& b) {
    if (b.c.empty()) throw std::domain_error("division by zero");
    if (b.c.size() > 1) throw std::invalid_argument("the field polynomial can be divided by constants only");
    poly out = a.c;
    for (auto& x : out) x /= b.c[0];
    return from(out);
  }
  bool is_rational() const { return c.size() <= 1; }
  exact_rational rational_value() const { return c.empty() ? exact_rational(0) : c[0]; }
  const poly& coefficients() const { return c; }
  static poly_value from(poly p) {
    poly_value v;
    v.c = std::move(p);
    return v;
  }
};

/// Recursive descent over one entry: expr = term {(+|-) term}; term = unary {(*|/) unary};
/// unary = (+|-) unary | power; power = primary [^ unary] (an integer exponent);
/// primary = number | r | ( expr ). Errors are std::invalid_argument / std::domain_error with
/// the reason; the caller adds the line.
template <class Value>
class expression_parser {
 public:
  expression_parser(const std::string& text, std::optional<Value> generator) : s_(text), r_(std::move(generator)) {}

  Value parse() {
    if (s_.empty()) throw std::invalid_argument("empty entry");
    Value v = expr();
    if (pos_ != s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
    check_size(v);
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw std::invalid_argument("entry '" + s_ + "': " + why + " at character " + std::to_string(pos_ + 1));
  }
  bool at(char ch) const { return pos_ < s_.size() && s_[pos_] == ch; }
  static unsigned bits(const boost::multiprecision::cpp_int& x) {
    return x == 0 ? 0U : static_cast<unsigned>(boost::multiprecision::msb(boost::multiprecision::abs(x))) + 1U;
  }
  static void check_size(const Value& v) {
    for (const auto& c : v.coefficients())
      if (bits(boost::multiprecision::numerator(c)) > tableau_max_bits || bits(boost::multiprecision::denominator(c)) > tableau_max_bits)
        throw std::invalid_argument("entry too large (more than " + std::to_string(tableau_max_bits) + " bits)");
  }
  Value expr() {
    Value v = term();
    while (at('+') || at('-')) {
      const char op = s_[pos_++];
      const Value w = term();
      v = op == '+' ? Value(v + w) : Value(v - w);
      check_size(v);
    }
    return v;
  }
  Value term() {
    Value v = unary();
    while (at('*') || at('/')) {
      const char op = s_[pos_++];
      const Value w = unary();
      if (op == '*') {
        v = v * w;
      } else {
        try {
          v = v / w;
        } catch (const std::domain_error&) {
          throw std::domain_error("entry '" + s_ + "': division by zero");
        }
      }
      check_size(v);
    }
    return v;
  }
  Value unary() {
    if (at('-')) {
      ++pos_;
      return Value(Value(exact_rational(0)) - unary());
    }
    if (at('+')) {
      ++pos_;
      return unary();
    }
    return power();
  }
  Value power() {
    Value base = primary();
    if (!at('^')) return base;
    ++pos_;
    const Value e = unary();
    if (!e.is_rational() || boost::multiprecision::denominator(e.rational_value()) != 1) fail("the exponent must be an integer");
    const exact_rational k = e.rational_value();
    if (k > tableau_max_exponent || k < -tableau_max_exponent)
      fail("exponent beyond +-" + std::to_string(tableau_max_exponent) + " (entry too large)");
    long count = boost::multiprecision::numerator(k).template convert_to<long>();
    Value out(exact_rational(1));
    const bool invert = count < 0;
    for (count = invert ? -count : count; count > 0; --count) {
      out = out * base;
      check_size(out);
    }
    if (invert) {
      try {
        out = Value(exact_rational(1)) / out;
      } catch (const std::domain_error&) {
        throw std::domain_error("entry '" + s_ + "': division by zero");
      }
    }
    return out;
  }
  Value primary() {
    if (at('(')) {
      ++pos_;
      Value v = expr();
      if (!at(')')) fail("expected ')'");
      ++pos_;
      return v;
    }
    if (at('r')) {
      ++pos_;
      if (!r_) fail("'r' needs a field line before the entries");
      return *r_;
    }
    if (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) return number();
    if (pos_ >= s_.size()) fail("unexpected end");
    fail("unexpected '" + std::string(1, s_[pos_]) + "'");
  }
  /// digits [. digits]: an exact decimal.
  Value number() {
    std::string digits, fraction;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) digits += s_[pos_++];
    if (at('.')) {
      ++pos_;
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) fraction += s_[pos_++];
      if (fraction.empty()) fail("a decimal point needs digits after it");
    }
    if (digits.size() + fraction.size() > tableau_max_literal_digits)
      fail("a literal of more than " + std::to_string(tableau_max_literal_digits) + " digits (entry too large)");
    // Digit by digit (a string with a leading 0 would be read as octal).
    boost::multiprecision::cpp_int whole = 0, scale = 1;
    for (char ch : digits + fraction) whole = whole * 10 + (ch - '0');
    for (std::size_t i = 0; i < fraction.size(); ++i) scale *= 10;
    return Value(exact_rational(whole, scale));
  }

  std::string s_;
  std::size_t pos_ = 0;
  std::optional<Value> r_;
};

/// The space-separated words of a line without its comment.
inline std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace detail

/// Reads a tableau from `in`; `source` names it in errors (tableau_file_error, "source:line: ...").
inline tableau_data<field_element> read_tableau(std::istream& in, const std::string& source) {
  struct item {
    int line;
    std::vector<std::string> words;
  };
  std::map<std::string, item> items;
  int number = 0;
  for (std::string text; std::getline(in, text);) {
    ++number;
    const auto w = detail::words_of(text);
    if (w.empty()) continue;
    static const std::vector<std::string> keys = {"kind", "stages", "name", "field", "c",    "a",
                                                  "b",    "bbar",   "ap",   "ahat",  "bhat"};
    bool known = false;
    for (const auto& k : keys) known = known || k == w[0];
    if (!known)
      throw tableau_file_error(source, number,
                               "unknown key '" + w[0] + "' (kind, stages, name, field, c, a, b, bbar, ap, ahat, bhat)");
    if (items.count(w[0])) throw tableau_file_error(source, number, "'" + w[0] + "' given twice (first at line " + std::to_string(items[w[0]].line) + ")");
    items[w[0]] = {number, std::vector<std::string>(w.begin() + 1, w.end())};
  }
  if (in.bad()) throw tableau_file_error(source, number, "read error");
  const int last = number;
  auto need = [&](const std::string& key) -> const item& {
    const auto it = items.find(key);
    if (it == items.end()) throw tableau_file_error(source, last, "no '" + key + "' line");
    return it->second;
  };
  tableau_data<field_element> t;
  // kind and stages
  const item& kind = need("kind");
  if (kind.words.size() != 1) throw tableau_file_error(source, kind.line, "kind takes one word: rk, prk, rkn or nystrom");
  const std::string& k = kind.words[0];
  if (k == "rk") t.kind = method_kind::rk;
  else if (k == "prk") t.kind = method_kind::prk;
  else if (k == "rkn") t.kind = method_kind::rkn;
  else if (k == "nystrom") t.kind = method_kind::nystrom;
  else throw tableau_file_error(source, kind.line, "unknown kind '" + k + "' (rk, prk, rkn or nystrom)");
  const item& stages = need("stages");
  {
    const std::string s = stages.words.size() == 1 ? stages.words[0] : std::string();
    bool digits = !s.empty() && s.size() <= 3;
    for (char ch : s) digits = digits && std::isdigit(static_cast<unsigned char>(ch));
    const int value = digits ? std::stoi(s) : 0;
    if (value < 1 || value > tableau_max_stages)
      throw tableau_file_error(source, stages.line, "stages takes one integer in 1.." + std::to_string(tableau_max_stages));
    t.stages = value;
  }
  if (items.count("name")) {
    const item& name = items["name"];
    if (name.words.empty()) throw tableau_file_error(source, name.line, "name needs a word");
    for (const auto& w : name.words) t.name += (t.name.empty() ? "" : " ") + w;
  }
  // the field
  std::optional<field_element> r;
  if (items.count("field")) {
    const item& f = items["field"];
    std::string poly_text, near_text;
    bool after_near = false;
    for (const auto& w : f.words) {
      if (w == "near") {
        if (after_near) throw tableau_file_error(source, f.line, "'near' given twice");
        after_near = true;
      } else {
        (after_near ? near_text : poly_text) += w;
      }
    }
    if (poly_text.empty()) throw tableau_file_error(source, f.line, "field needs a polynomial in r, e.g. 'field r^2 - 3'");
    if (after_near && near_text.empty()) throw tableau_file_error(source, f.line, "'near' needs a number");
    try {
      const detail::poly_value p = detail::expression_parser<detail::poly_value>(poly_text, detail::poly_value::generator()).parse();
      std::optional<exact_rational> near;
      if (after_near) {
        const detail::poly_value x = detail::expression_parser<detail::poly_value>(near_text, std::nullopt).parse();
        near = x.rational_value();
      }
      r = field_element::generator(algebraic_field::make(p.coefficients(), near));
    } catch (const std::exception& e) {
      throw tableau_file_error(source, f.line, std::string("field: ") + e.what());
    }
  }
  // the arrays of the kind
  const auto S = static_cast<std::size_t>(t.stages);
  std::vector<std::string> wanted = {"c", "a", "b"};
  if (t.kind == method_kind::rkn || t.kind == method_kind::nystrom) wanted.push_back("bbar");
  if (t.kind == method_kind::nystrom) wanted.push_back("ap");
  if (t.kind == method_kind::prk) {
    wanted.push_back("ahat");
    wanted.push_back("bhat");
  }
  for (const char* key : {"c", "a", "b", "bbar", "ap", "ahat", "bhat"}) {
    bool used = false;
    for (const auto& w : wanted) used = used || w == key;
    if (!used && items.count(key))
      throw tableau_file_error(source, items[key].line, "'" + std::string(key) + "' does not belong to kind " + k);
  }
  auto entries = [&](const std::string& key) {
    const item& it = need(key);
    const bool square = key == "a" || key == "ap" || key == "ahat";
    const std::size_t count = square ? S * S : S;
    if (it.words.size() != count)
      throw tableau_file_error(source, it.line,
                               key + " needs " + std::to_string(count) + " entries (" + (square ? "S*S" : "S") + ", S = " +
                                   std::to_string(S) + "), found " + std::to_string(it.words.size()));
    std::vector<field_element> out;
    for (std::size_t i = 0; i < count; ++i) {
      try {
        out.push_back(detail::expression_parser<field_element>(it.words[i], r).parse());
      } catch (const std::exception& e) {
        throw tableau_file_error(source, it.line, key + " entry " + std::to_string(i + 1) + ": " + e.what());
      }
    }
    return out;
  };
  auto square = [&](const std::string& key) {
    const auto flat = entries(key);
    std::vector<std::vector<field_element>> out(S);
    for (std::size_t i = 0; i < S; ++i) out[i].assign(flat.begin() + static_cast<long>(i * S), flat.begin() + static_cast<long>((i + 1) * S));
    return out;
  };
  t.c = entries("c");
  t.a = square("a");
  t.b = entries("b");
  if (t.kind == method_kind::rkn || t.kind == method_kind::nystrom) t.bbar = entries("bbar");
  if (t.kind == method_kind::nystrom) t.ap = square("ap");
  if (t.kind == method_kind::prk) {
    t.ahat = square("ahat");
    t.bhat = entries("bhat");
  }
  return t;
}

/// Reads the tableau file at `path` (tableau_file_error with line 0 if it cannot be opened).
inline tableau_data<field_element> read_tableau_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw tableau_file_error(path, 0, "cannot open the file");
  return read_tableau(in, path);
}

}  // namespace geomint::methods
