#pragma once
/// The command line of every geomint tool: one parser, one set of value checks, checked output.
///
/// Conventions (the same in every tool):
///  - `--flag value` and `--flag=value` are equivalent; a switch (`--csv`) takes no value;
///  - an unknown flag, a missing or empty value, or a value out of its stated range is a usage
///    error: the tool prints `<program>: <message naming the flag>`, then its usage text, on
///    stderr and exits with status 2 (exit_usage);
///  - numbers are read exactly once, here, with every failure caught: integers with
///    std::from_chars (no saturation: a value beyond the stated bound is reported, never
///    clamped), reals in plain decimal notation with overflow and underflow reported (a value
///    that does not survive the conversion to double is refused, not rounded to 0 or infinity);
///  - output is checked: standard output is flushed and its state tested before the exit
///    (finish_stdout), and CSV files are written in whole rows (csv_file), so that a failed write
///    is reported with a non-zero exit (exit_output) and leaves a file that ends with its last
///    complete row.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "geomint/core/dispatch.hpp"

namespace geomint::cli {

/// Exit statuses shared by the tools.
inline constexpr int exit_ok = 0;
inline constexpr int exit_usage = 2;        ///< bad command line (message + usage text)
inline constexpr int exit_run_failure = 3;  ///< a step failed or left the scheme's regime
inline constexpr int exit_output = 4;       ///< writing the output failed

/// A bad command line. The message names the flag; the parser adds the program name and usage.
struct usage_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// ---------------------------------------------------------------------------------------------
// Values
// ---------------------------------------------------------------------------------------------

/// The text of a value as quoted in messages (control characters are not echoed raw).
inline std::string printable(std::string_view text);
inline std::string in_quotes(std::string_view text) {
  std::string out(1, '\'');
  out.append(printable(text));
  out.push_back('\'');
  return out;
}

/// `text` with control characters replaced by '?' (for messages).
inline std::string printable(std::string_view text) {
  std::string out;
  for (const char c : text) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
  return out;
}

/// An integer in [lo, hi]. Refuses empty text, signs other than a leading '-' or '+', spaces,
/// trailing characters and values outside [lo, hi] (including those beyond the range of Int,
/// which std::strtol would silently saturate).
template <class Int>
Int parse_integer(std::string_view flag, std::string_view text, Int lo, Int hi) {
  static_assert(std::is_integral_v<Int> && !std::is_same_v<Int, bool>, "parse_integer: Int must be an integer type");
  const std::string expected = "an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  if (!digits.empty() && (digits.front() == '+' || (digits.front() == '-' && text.front() == '+')))
    throw usage_error(std::string(flag) + " expects " + expected + ", got " + in_quotes(text));
  long long value = 0;
  const char* first = digits.data();
  const char* last = digits.data() + digits.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  if (digits.empty() || ec == std::errc::invalid_argument || end != last)
    throw usage_error(std::string(flag) + " expects " + expected + ", got " + in_quotes(text));
  if (ec == std::errc::result_out_of_range || value < static_cast<long long>(lo) || value > static_cast<long long>(hi))
    throw usage_error(std::string(flag) + " is out of range: " + in_quotes(text) + " (expected " + expected + ")");
  return static_cast<Int>(value);
}

/// The admissible set of a real value.
enum class real_bound {
  finite,        ///< any finite number
  positive,      ///< finite and > 0
  non_negative,  ///< finite and >= 0
};

namespace detail {

/// Plain decimal notation: [+-] digits [. digits] [(e|E) [+-] digits], with at least one digit
/// in the mantissa. Excludes what std::strtod would also accept (inf, nan, hexadecimal, leading
/// spaces), so that the same text parses identically in double and in the multiprecision types.
inline bool is_decimal(std::string_view s) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t start = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - start;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == s.size();
}

inline const char* describe(real_bound b) {
  switch (b) {
    case real_bound::positive: return "a finite number > 0";
    case real_bound::non_negative: return "a finite number >= 0";
    case real_bound::finite: break;
  }
  return "a finite number";
}

}  // namespace detail

/// A real number in plain decimal notation within `bound`, as a double. Overflow (1e400) and
/// underflow to a subnormal or zero (1e-320) are reported as out of range: the value would not
/// be the one the user wrote.
inline double parse_real(std::string_view flag, std::string_view text, real_bound bound = real_bound::finite) {
  const std::string expected = detail::describe(bound);
  if (!detail::is_decimal(text))
    throw usage_error(std::string(flag) + " expects " + expected + " in decimal notation, got " + in_quotes(text));
  const std::string copy(text);
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(copy.c_str(), &end);
  const std::string_view mantissa = text.substr(0, text.find_first_of("eE"));
  const bool zero_text = mantissa.find_first_of("123456789") == std::string_view::npos;
  if (errno == ERANGE || !std::isfinite(value) || (value == 0 && !zero_text) ||
      (value != 0 && std::fabs(value) < std::numeric_limits<double>::min()))
    throw usage_error(std::string(flag) + " is out of range: " + in_quotes(text) + " (expected " + expected +
                      " within the normal range of double, about 2.2e-308 to 1.8e308 in magnitude)");
  if (end != copy.c_str() + copy.size())
    throw usage_error(std::string(flag) + " expects " + expected + ", got " + in_quotes(text));
  const bool ok = bound == real_bound::finite || (bound == real_bound::positive && value > 0) ||
                  (bound == real_bound::non_negative && value >= 0);
  if (!ok) throw usage_error(std::string(flag) + " must be " + expected + ", got " + in_quotes(text));
  return value;
}

/// Checks `text` as parse_real does and returns it unchanged: for values that a tool reads
/// later in its own scalar type (50 or 100 digits), so that they are not rounded to double.
inline std::string checked_real_text(std::string_view flag, std::string_view text, real_bound bound = real_bound::finite) {
  (void)parse_real(flag, text, bound);
  return std::string(text);
}

/// A comma-separated list of at least 1 and at most max_items non-empty items.
inline std::vector<std::string> split_list(std::string_view flag, std::string_view text, std::size_t max_items = 1024) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string_view item = text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    if (item.empty()) throw usage_error(std::string(flag) + " has an empty item in the list " + in_quotes(text));
    out.emplace_back(item);
    if (out.size() > max_items)
      throw usage_error(std::string(flag) + " takes at most " + std::to_string(max_items) + " item(s), got more in " +
                        in_quotes(text));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

/// A list of integers, each in [lo, hi], with between min_items and max_items entries.
template <class Int>
std::vector<Int> parse_integer_list(std::string_view flag, std::string_view text, Int lo, Int hi, std::size_t min_items = 1,
                                    std::size_t max_items = 64) {
  std::vector<Int> out;
  for (const std::string& item : split_list(flag, text, max_items)) out.push_back(parse_integer<Int>(flag, item, lo, hi));
  if (out.size() < min_items)
    throw usage_error(std::string(flag) + " needs at least " + std::to_string(min_items) + " value(s), got " + in_quotes(text));
  return out;
}

/// A list of reals within `bound`, returned as their (checked) texts, with exactly `count`
/// items (count 0: any number between 1 and 64).
inline std::vector<std::string> parse_real_list(std::string_view flag, std::string_view text, real_bound bound,
                                                std::size_t count = 0) {
  std::vector<std::string> out = split_list(flag, text, 64);
  for (const std::string& item : out) (void)parse_real(flag, item, bound);
  if (count != 0 && out.size() != count)
    throw usage_error(std::string(flag) + " needs " + std::to_string(count) + " value(s), got " + std::to_string(out.size()) +
                      " in " + in_quotes(text));
  return out;
}

/// "a", "a..b" (a <= b) or, when all_allowed, "all" (= lo..hi): an integer range within [lo, hi].
template <class Int>
std::pair<Int, Int> parse_integer_range(std::string_view flag, std::string_view text, Int lo, Int hi, bool all_allowed = true) {
  if (all_allowed && text == "all") return {lo, hi};
  const std::size_t dots = text.find("..");
  if (dots == std::string_view::npos) {
    const Int v = parse_integer<Int>(flag, text, lo, hi);
    return {v, v};
  }
  const Int a = parse_integer<Int>(flag, text.substr(0, dots), lo, hi);
  const Int b = parse_integer<Int>(flag, text.substr(dots + 2), lo, hi);
  if (a > b) throw usage_error(std::string(flag) + " range " + in_quotes(text) + " is empty (expected a..b with a <= b)");
  return {a, b};
}

/// One of `allowed`.
inline std::string parse_choice(std::string_view flag, std::string_view text, const std::vector<std::string>& allowed) {
  for (const std::string& a : allowed)
    if (a == text) return a;
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw usage_error(std::string(flag) + " must be one of " + list + "; got " + in_quotes(text));
}

/// "all" (every allowed value) or a comma list of allowed values.
inline std::vector<std::string> parse_choice_list(std::string_view flag, std::string_view text,
                                                  const std::vector<std::string>& allowed) {
  if (text == "all") return allowed;
  std::vector<std::string> out;
  for (const std::string& item : split_list(flag, text, allowed.size() * 4 + 4)) out.push_back(parse_choice(flag, item, allowed));
  return out;
}

/// The node families' printed names (geomint/core/dispatch.hpp).
inline const std::vector<std::string>& node_family_list() {
  static const std::vector<std::string> names(geomint::node_family_names.begin(), geomint::node_family_names.end());
  return names;
}

/// A node family under any of its spellings (gauss-interior, gauss_interior, ...), returned as
/// its printed name.
inline std::string parse_node_family(std::string_view flag, std::string_view text) {
  if (const auto name = geomint::canonical_node_family(text)) return std::string(*name);
  return parse_choice(flag, text, node_family_list());  // not a family: the usage error names them
}

/// "all" or a comma list of node families (any spelling).
inline std::vector<std::string> parse_node_family_list(std::string_view flag, std::string_view text) {
  if (text == "all") return node_family_list();
  std::vector<std::string> out;
  for (const std::string& item : split_list(flag, text, node_family_list().size() * 4 + 4))
    out.push_back(parse_node_family(flag, item));
  return out;
}

// ---------------------------------------------------------------------------------------------
// The parser
// ---------------------------------------------------------------------------------------------

/// The flags of one tool. Register each flag with a handler, then call parse():
///
///     cli::parser cl("geomint-run", usage);
///     cl.value("--m", [&](const std::string& v) { o.m = cli::parse_integer(v_flag, v, 2, 8); });
///     cl.toggle("--csv", [&] { o.csv = true; });
///     if (const auto done = cl.parse(argc, argv)) return *done;  // --help (0) or an error (2)
///
/// Handlers report bad values by throwing usage_error (or any std::exception, whose message is
/// prefixed with the flag).
class parser {
 public:
  parser(std::string program, std::string usage) : program_(std::move(program)), usage_(std::move(usage)) {}

  /// A flag that takes a value (`--flag value` or `--flag=value`; never empty).
  parser& value(const std::string& flag, std::function<void(const std::string&)> handler) {
    add(flag, {true, std::move(handler), {}});
    return *this;
  }
  /// A switch without a value.
  parser& toggle(const std::string& flag, std::function<void()> handler) {
    add(flag, {false, {}, std::move(handler)});
    return *this;
  }

  const std::string& program() const { return program_; }
  const std::string& usage() const { return usage_; }

  /// Prints `<program>: <message>` and the usage text on stderr; returns exit_usage.
  int fail(const std::string& message) const {
    std::cerr << program_ << ": " << message << '\n' << usage_;
    if (!usage_.empty() && usage_.back() != '\n') std::cerr << '\n';
    std::cerr.flush();
    return exit_usage;
  }

  /// Parses argv[1..argc). Returns nothing when the tool should go on, exit_ok after printing
  /// the usage for --help or -h (exit_output if that write fails), or exit_usage after
  /// reporting a usage error.
  std::optional<int> parse(int argc, const char* const* argv) const {
    try {
      parse_or_throw(argc, argv);
    } catch (const help_requested&) {
      std::cout << usage_;
      return finish_stdout_impl(program_);
    } catch (const usage_error& e) {
      return fail(e.what());
    }
    return std::nullopt;
  }
  std::optional<int> parse(int argc, char** argv) const { return parse(argc, const_cast<const char* const*>(argv)); }

  /// As parse(), but throws usage_error instead of printing (for tests); --help throws
  /// help_requested.
  struct help_requested {};
  void parse_or_throw(int argc, const char* const* argv) const {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i] ? argv[i] : "";
      if (arg == "--help" || arg == "-h") throw help_requested{};
      if (arg.size() < 3 || arg.compare(0, 2, "--") != 0)
        throw usage_error("unexpected argument " + in_quotes(arg) + " (flags start with --)");
      const std::size_t eq = arg.find('=');
      const std::string name = arg.substr(0, eq);
      const auto f = flags_.find(name);
      if (f == flags_.end()) throw usage_error("unknown flag " + printable(name));
      const entry& e = f->second;
      if (!e.takes_value) {
        if (eq != std::string::npos) throw usage_error(name + " takes no value, got " + in_quotes(arg.substr(eq + 1)));
        e.on_switch();
        continue;
      }
      std::string text;
      if (eq != std::string::npos) {
        text = arg.substr(eq + 1);
      } else {
        if (i + 1 >= argc || !argv[i + 1]) throw usage_error(name + " needs a value");
        text = argv[++i];
        const std::string next_name = text.substr(0, text.find('='));
        if (flags_.count(next_name) || text == "--help")
          throw usage_error(name + " needs a value (got the flag " + in_quotes(text) + ")");
      }
      if (text.empty()) throw usage_error(name + " needs a non-empty value");
      try {
        e.on_value(text);
      } catch (const usage_error& err) {
        const std::string what = err.what();
        // Name the flag in every message, whoever threw it.
        throw usage_error(what.find(name) == std::string::npos ? name + ": " + what : what);
      } catch (const std::exception& err) {
        throw usage_error(name + ": " + err.what() + " (value " + in_quotes(text) + ")");
      }
    }
  }

 private:
  struct entry {
    bool takes_value = false;
    std::function<void(const std::string&)> on_value;
    std::function<void()> on_switch;
  };
  void add(const std::string& flag, entry e) {
    if (flag.size() < 3 || flag.compare(0, 2, "--") != 0 || flag.find('=') != std::string::npos)
      throw std::logic_error("cli::parser: flag names are --name, got '" + flag + "'");
    if (!flags_.emplace(flag, std::move(e)).second) throw std::logic_error("cli::parser: flag " + flag + " registered twice");
  }
  static int finish_stdout_impl(const std::string& program);

  std::string program_, usage_;
  std::map<std::string, entry> flags_;
};

// ---------------------------------------------------------------------------------------------
// Checked output
// ---------------------------------------------------------------------------------------------

/// Flushes std::cout and tests it. Returns `status` when every write succeeded; otherwise prints
/// `<program>: cannot write to standard output: <reason>` on stderr and returns exit_output
/// (unless status already reports a failure, which is kept).
inline int finish_stdout(const std::string& program, int status = exit_ok) {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed) return status;
  const int err = errno;
  std::cerr << program << ": cannot write to standard output" << (err ? std::string(": ") + std::strerror(err) : "") << '\n';
  return status != exit_ok ? status : exit_output;
}

inline int parser::finish_stdout_impl(const std::string& program) { return finish_stdout(program, exit_ok); }

/// True while std::cout is writable; long loops call it to stop early on a dead output.
inline bool stdout_ok() { return static_cast<bool>(std::cout) && !std::ferror(stdout); }

/// A CSV output written in whole rows. Rows are buffered and written with write(2) in blocks of
/// complete rows; a failed or partial write truncates a regular file back to its last complete
/// row, records the reason and makes every later call a no-op. close() (or the destructor)
/// writes what is buffered; its result and error() tell whether every row reached the file.
/// "-" writes to standard output (flushing std::cout first so that the order is kept; a pipe
/// cannot be truncated, so a partial last row is possible there).
class csv_file {
 public:
  csv_file() = default;
  csv_file(const csv_file&) = delete;
  csv_file& operator=(const csv_file&) = delete;
  ~csv_file() { (void)close(); }

  /// Opens (creates or truncates) `path`; false with error() set when that fails.
  bool open(const std::string& path) {
    (void)close();
    path_ = path;
    error_.clear();
    committed_ = 0;
    if (path == "-") {
      fd_ = STDOUT_FILENO;
      owned_ = false;
      std::cout.flush();
    } else {
      fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
      owned_ = true;
      if (fd_ < 0) {
        error_ = "cannot open '" + path + "' for writing: " + std::strerror(errno);
        fd_ = -1;
        return false;
      }
    }
    struct stat st{};
    truncatable_ = ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode);
    return true;
  }

  bool is_open() const { return fd_ >= 0; }
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  const std::string& path() const { return path_; }

  /// Appends one row (without its newline; a newline inside `line` is refused as a logic error).
  void row(std::string_view line) {
    if (fd_ < 0 || !ok()) return;
    if (line.find('\n') != std::string_view::npos) throw std::logic_error("csv_file::row: newline inside a row");
    buffer_.append(line);
    buffer_.push_back('\n');
    if (buffer_.size() >= block_size) (void)flush();
  }

  /// Writes the buffered rows; false (with error()) when a write failed.
  bool flush() {
    if (fd_ < 0 || !ok()) return ok();
    std::size_t written = 0;
    while (written < buffer_.size()) {
      const ssize_t n = ::write(fd_, buffer_.data() + written, buffer_.size() - written);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        const int err = n < 0 ? errno : EIO;
        // Keep the rows that reached the file whole: cut back to the last newline written.
        const std::size_t complete = written == 0 ? 0 : buffer_.rfind('\n', written - 1) + 1;
        if (truncatable_) (void)!::ftruncate(fd_, static_cast<off_t>(committed_ + complete));
        committed_ += complete;
        error_ = "cannot write to " + (path_ == "-" ? std::string("standard output") : "'" + path_ + "'") + ": " +
                 std::strerror(err);
        buffer_.clear();
        return false;
      }
      written += static_cast<std::size_t>(n);
    }
    committed_ += buffer_.size();
    buffer_.clear();
    return true;
  }

  /// Flushes and closes; true when every row was written.
  bool close() {
    if (fd_ < 0) return ok();
    (void)flush();
    if (owned_ && ::close(fd_) != 0 && ok()) error_ = "cannot close '" + path_ + "': " + std::strerror(errno);
    fd_ = -1;
    return ok();
  }

  /// Closes and, on failure, prints `<program>: <error>`; returns `status`, or exit_output when
  /// the file failed and status was exit_ok.
  int finish(const std::string& program, int status = exit_ok) {
    if (close()) return status;
    std::cerr << program << ": " << error_ << '\n';
    return status != exit_ok ? status : exit_output;
  }

  static constexpr std::size_t block_size = std::size_t{1} << 16;

 private:
  int fd_ = -1;
  bool owned_ = false, truncatable_ = false;
  std::string path_, error_, buffer_;
  std::size_t committed_ = 0;  ///< bytes of complete rows in the file
};

}  // namespace geomint::cli
