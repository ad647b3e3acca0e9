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
///  - output is checked: standard output goes through a buffer that records the reason (errno
///    text) of the first failed write, and is flushed and tested before the exit
///    (finish_stdout); output files (csv_file) are written to a temporary file in the same
///    directory and renamed over the target only when every write succeeded (removed
///    otherwise), so that a reader never sees a partial or interleaved file; a failed write is
///    reported with its reason and a non-zero exit (exit_output);
///  - two output flags naming the same file (parser::output) are a usage error.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <streambuf>
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

inline void use_checked_stdout();

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
  parser(std::string program, std::string usage) : program_(std::move(program)), usage_(std::move(usage)) {
    use_checked_stdout();
  }

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
  /// An output file flag: its value (a path, "-" for standard output) is stored in `path`.
  /// Two output flags that name the same file are a usage error naming both.
  parser& output(const std::string& flag, std::string& path) {
    add(flag, {true, [&path](const std::string& v) { path = v; }, {}});
    outputs_.push_back({flag, &path});
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
    parse_flags(argc, argv);
    for (std::size_t a = 0; a < outputs_.size(); ++a)
      for (std::size_t b = a + 1; b < outputs_.size(); ++b)
        if (same_output(*outputs_[a].path, *outputs_[b].path))
          throw usage_error(outputs_[a].flag + " and " + outputs_[b].flag + " name the same file " +
                            in_quotes(*outputs_[b].path) + " (each output needs a file of its own)");
  }

  /// Whether two output paths name the same file: both standard output ("-"), the same path
  /// after resolving ".", ".." and symbolic links, or the same existing file (hard links).
  static bool same_output(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty()) return false;
    if (a == "-" || b == "-") return a == b;
    struct stat sa{}, sb{};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    std::error_code ea, eb;
    const auto ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ea), ea);
    const auto cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b, eb), eb);
    return ea || eb ? a == b : ca == cb;
  }

 private:
  void parse_flags(int argc, const char* const* argv) const {
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

  struct output_flag {
    std::string flag;
    const std::string* path;
  };
  std::string program_, usage_;
  std::map<std::string, entry> flags_;
  std::vector<output_flag> outputs_;
};

// ---------------------------------------------------------------------------------------------
// Checked output
// ---------------------------------------------------------------------------------------------

namespace detail {

/// "cannot write to <where>: <strerror(err)>".
inline std::string write_error(const std::string& where, int err) {
  return "cannot write to " + where + ": " + std::strerror(err != 0 ? err : EIO);
}

/// Writes all of [data, data + size) to fd (retrying after EINTR and short writes); the number
/// of bytes written, and in `err` the errno of a failure (0 if none).
inline std::size_t write_all(int fd, const char* data, std::size_t size, int& err) {
  std::size_t written = 0;
  err = 0;
  while (written < size) {
    const ssize_t n = ::write(fd, data + written, size - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    written += static_cast<std::size_t>(n);
  }
  return written;
}

/// The buffer of std::cout: write(2) to a file descriptor, keeping the errno of the first failed
/// write so that the message can name the reason (an iostream keeps only a failbit, and errno is
/// long overwritten when the tool reports). After a failure every write fails.
class checked_fd_buffer : public std::streambuf {
 public:
  explicit checked_fd_buffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    if (error_ != 0) return -1;
    const std::size_t size = static_cast<std::size_t>(pptr() - pbase());
    int err = 0;
    write_all(fd_, pbase(), size, err);
    setp(buffer_, buffer_ + sizeof buffer_);
    if (err != 0) error_ = err;
    return error_ != 0 ? -1 : 0;
  }

 private:
  int fd_;
  int error_ = 0;
  char buffer_[1 << 14];
};

/// The checked buffer of std::cout, installed once (never destroyed: std::cout is flushed at
/// exit, after the destruction of function-local statics).
inline checked_fd_buffer& stdout_buffer() {
  static checked_fd_buffer* buffer = [] {
    auto* b = new checked_fd_buffer(STDOUT_FILENO);
    std::cout.flush();
    std::cout.rdbuf(b);
    return b;
  }();
  return *buffer;
}

}  // namespace detail

/// Routes std::cout through the checked buffer (idempotent; parser's constructor calls it, so
/// every tool has it before it writes).
inline void use_checked_stdout() { (void)detail::stdout_buffer(); }

/// Flushes std::cout and tests it. Returns `status` when every write succeeded; otherwise prints
/// `<program>: cannot write to standard output: <reason>` on stderr and returns exit_output
/// (unless status already reports a failure, which is kept).
inline int finish_stdout(const std::string& program, int status = exit_ok) {
  errno = 0;
  std::cout.flush();
  const int err = detail::stdout_buffer().error() != 0 ? detail::stdout_buffer().error() : errno;
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) || detail::stdout_buffer().error() != 0;
  if (!failed) return status;
  std::cerr << program << ": " << detail::write_error("standard output", err != 0 ? err : errno) << '\n';
  return status != exit_ok ? status : exit_output;
}

inline int parser::finish_stdout_impl(const std::string& program) { return finish_stdout(program, exit_ok); }

/// True while std::cout is writable; long loops call it to stop early on a dead output.
inline bool stdout_ok() { return static_cast<bool>(std::cout) && !std::ferror(stdout) && detail::stdout_buffer().error() == 0; }

/// A CSV output written in whole rows, atomically. A file is written to a temporary file
/// `<path>.tmp.XXXXXX` in the same directory and renamed over `path` by close() when every
/// write succeeded, so that a reader (or another process writing the same path) never sees a
/// partial or interleaved file; on a failed write the temporary file is removed and `path` is
/// left as it was. An existing target that is not a regular file (a device such as /dev/null or
/// /dev/full, a FIFO) is written directly; a symbolic link is followed. "-" writes to standard
/// output (flushing std::cout first so that the order is kept). The first failure records its
/// reason (errno text) in error() and makes every later call a no-op.
class csv_file {
 public:
  csv_file() = default;
  csv_file(const csv_file&) = delete;
  csv_file& operator=(const csv_file&) = delete;
  ~csv_file() { (void)close(); }

  /// Opens `path` for writing; false with error() set when that fails.
  bool open(const std::string& path) {
    (void)close();
    path_ = path;
    target_ = path;
    temporary_.clear();
    error_.clear();
    if (path == "-") {
      std::cout.flush();
      fd_ = STDOUT_FILENO;
      owned_ = false;
      return true;
    }
    owned_ = true;
    struct stat st{};
    const bool exists = ::stat(path.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) return fail_open(EISDIR);
    if (exists && !S_ISREG(st.st_mode)) {  // a device or FIFO: written in place
      fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
      return fd_ >= 0 || fail_open(errno);
    }
    if (exists) {
      std::error_code ec;
      const auto resolved = std::filesystem::canonical(path, ec);  // follow a symbolic link
      if (!ec) target_ = resolved.string();
    }
    std::string name = target_ + ".tmp.XXXXXX";
    fd_ = ::mkstemp(name.data());
    if (fd_ < 0) return fail_open(errno);
    temporary_ = name;
    (void)::fcntl(fd_, F_SETFD, FD_CLOEXEC);
    // The permissions a plain open(O_CREAT, 0666) would give, or the existing file's.
    mode_t mode = exists ? (st.st_mode & 07777) : 0;
    if (!exists) {
      const mode_t mask = ::umask(0);
      ::umask(mask);
      mode = 0666 & ~mask;
    }
    (void)::fchmod(fd_, mode);
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
    int err = 0;
    detail::write_all(fd_, buffer_.data(), buffer_.size(), err);
    buffer_.clear();
    if (err != 0) error_ = detail::write_error(path_ == "-" ? std::string("standard output") : "'" + path_ + "'", err);
    return ok();
  }

  /// Flushes and closes; on success renames the temporary file over the target, on failure
  /// removes it. True when every row was written.
  bool close() {
    if (fd_ < 0) return ok();
    (void)flush();
    if (owned_ && ::close(fd_) != 0 && ok()) error_ = "cannot close '" + path_ + "': " + std::strerror(errno);
    fd_ = -1;
    if (!temporary_.empty()) {
      if (ok() && ::rename(temporary_.c_str(), target_.c_str()) != 0)
        error_ = "cannot rename the temporary file to '" + path_ + "': " + std::strerror(errno);
      if (!ok()) (void)::unlink(temporary_.c_str());
      temporary_.clear();
    }
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
  bool fail_open(int err) {
    error_ = "cannot open '" + path_ + "' for writing: " + std::strerror(err);
    fd_ = -1;
    return false;
  }

  int fd_ = -1;
  bool owned_ = false;
  std::string path_, target_, temporary_, error_, buffer_;
};

}  // namespace geomint::cli
