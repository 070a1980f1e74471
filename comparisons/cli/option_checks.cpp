#include "comparisons/cli/option_checks.h"

#include "comparisons/cli/shard_option.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace tecido::cli {

namespace {

std::string show(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

/// Strict decimal integer: [+-]digits, the whole text; false on anything else or overflow.
bool parse_integer(const std::string& text, long long& out) {
  if (text.empty() || text.find_first_not_of("+-0123456789") != std::string::npos) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtoll(text.c_str(), &end, 10);
  return end != text.c_str() && *end == '\0' && errno != ERANGE;
}

}  // namespace

CLI::Validator number_in(double lo, bool lo_open, double hi) {
  const std::string desc = std::string(lo_open ? "> " : ">= ") + show(lo) + ", <= " + show(hi);
  return CLI::Validator(
      [lo, lo_open, hi](std::string& text) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        if (text.empty() || end == text.c_str() || *end != '\0') return "must be a number (got \"" + text + "\")";
        if (!std::isfinite(x)) return "must be a finite number (got " + text + ")";
        if (lo_open ? !(x > lo) : !(x >= lo)) return std::string("must be ") + (lo_open ? "> " : ">= ") + show(lo) + " (got " + text + ")";
        if (!(x <= hi)) return "must be <= " + show(hi) + " (got " + text + ")";
        return "";
      },
      desc);
}

CLI::Validator integer_in(long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        long long x = 0;
        if (!parse_integer(text, x)) return "must be an integer in " + range + " (got \"" + text + "\")";
        if (x < lo || x > hi) return "must be in " + range + " (got " + text + ")";
        return "";
      },
      "integer in " + range);
}

CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string bad = "must be an integer in [0, 18446744073709551615] (got \"" + text + "\")";
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return bad;
        char* end = nullptr;
        errno = 0;
        std::strtoull(text.c_str(), &end, 10);
        return errno == ERANGE ? bad : "";
      },
      "integer >= 0");
}

CLI::Validator non_empty() {
  return CLI::Validator([](std::string& text) -> std::string { return text.empty() ? "must not be empty" : ""; }, "");
}

CLI::Validator one_of(std::initializer_list<const char*> names) {
  std::vector<std::string> list(names.begin(), names.end());
  std::string all;
  for (const auto& n : list) all += (all.empty() ? "" : ", ") + n;
  return CLI::Validator(
      [list, all](std::string& text) -> std::string {
        for (const auto& n : list)
          if (text == n) return "";
        return "must be one of " + all + " (got \"" + text + "\")";
      },
      "one of " + all);
}

CLI::Validator shard_spec() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          parse_shard(text);
          return "";
        } catch (const io::UsageError& e) {
          const std::string msg = e.what();
          const auto colon = msg.find(": ");
          return colon == std::string::npos ? msg : msg.substr(colon + 2);  // CLI11 prefixes the option
        }
      },
      "i/n");
}

}  // namespace tecido::cli
