#include "comparisons/io/json_reader.h"

#include "comparisons/io/edit_distance.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/text_file.h"

#include <cmath>
#include <set>
#include <sstream>
#include <vector>

namespace tecido::io {

namespace {
const char* type_name(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "a number";
    default: return "something else";
  }
}

/// JSON pointer escaping (RFC 6901).
std::string escape(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

/// Thrown from the SAX handler; turned into an InputError once the parser has unwound.
struct Rejected {
  std::string where;
  std::string problem;
};

/// What the handler keeps per open array or object: O(1) besides the object's keys, so that
/// tracking costs time and memory linear in the text (the JSON pointer of a level is built only
/// when an error is reported).
struct Level {
  bool is_object = false;
  std::size_t index = 0;        ///< arrays: the index of the next element
  std::set<std::string> keys;   ///< objects: keys seen so far (duplicates are errors)
  std::string last_key;         ///< objects: the key of the value being parsed
};

/// The JSON pointer of the value being parsed: the path through the first `levels` open levels.
std::string pointer_of(const std::vector<Level>& stack, std::size_t levels) {
  std::string where;
  for (std::size_t k = 0; k < levels; ++k)
    where = stack[k].is_object ? child(where, stack[k].last_key) : child(where, stack[k].index);
  return where;
}

/// nlohmann::json's SAX events, checked, then handed to its own document builder: nesting past
/// kMaxJsonDepth is rejected at its first level and duplicate keys at the second (nlohmann::json
/// would keep the last value silently). Not the parser callback: in this nlohmann::json (3.11)
/// it scans the enclosing container at every object's end, quadratic in an array of objects.
class StrictSax {
 public:
  using Builder = nlohmann::detail::json_sax_dom_parser<Json>;
  explicit StrictSax(Json& result) : dom_(result, /*allow_exceptions=*/true) {}

  bool null() { return scalar(dom_.null()); }
  bool boolean(bool b) { return scalar(dom_.boolean(b)); }
  bool number_integer(Json::number_integer_t x) { return scalar(dom_.number_integer(x)); }
  bool number_unsigned(Json::number_unsigned_t x) { return scalar(dom_.number_unsigned(x)); }
  bool number_float(Json::number_float_t x, const Json::string_t& text) { return scalar(dom_.number_float(x, text)); }
  bool string(Json::string_t& s) { return scalar(dom_.string(s)); }
  bool binary(Json::binary_t& b) { return scalar(dom_.binary(b)); }
  bool start_object(std::size_t n) { return open(true) && dom_.start_object(n); }
  bool start_array(std::size_t n) { return open(false) && dom_.start_array(n); }
  bool end_object() { return close() && dom_.end_object(); }
  bool end_array() { return close() && dom_.end_array(); }
  bool key(Json::string_t& k) {
    Level& level = stack_.back();
    if (!level.keys.insert(k).second) throw Rejected{pointer_of(stack_, stack_.size() - 1), "duplicate key \"" + k + "\""};
    level.last_key = k;
    return dom_.key(k);
  }
  template <class Exception>
  bool parse_error(std::size_t pos, const std::string& token, const Exception& e) {
    return dom_.parse_error(pos, token, e);  // throws e
  }

  /// The pointer of the value being parsed (for the parser's own errors too).
  std::string pointer() const { return pointer_of(stack_, stack_.size()); }

 private:
  bool open(bool is_object) {
    if (stack_.size() >= static_cast<std::size_t>(kMaxJsonDepth))
      throw Rejected{pointer(), "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels (the limit)"};
    stack_.push_back(Level{is_object, 0, {}, {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return scalar(true);
  }
  /// A complete value: the enclosing array moves on to its next index.
  bool scalar(bool ok) {
    if (!stack_.empty() && !stack_.back().is_object) ++stack_.back().index;
    return ok;
  }

  Builder dom_;
  std::vector<Level> stack_;
};

/// nlohmann's messages look like "[json.exception.parse_error.101] parse error at line 1, ...":
/// the part from `marker` on.
std::string from_marker(const std::string& what, const char* marker) {
  const auto pos = what.find(marker);
  return pos == std::string::npos ? what : what.substr(pos);
}
/// "parse error at line 3, column 12: syntax error while ..." -> {"line 3, column 12", "syntax error
/// while ..."}; a message of another shape is kept whole as the problem, at the top ("/").
struct SyntaxError {
  std::string where, problem;
};
SyntaxError split_syntax_error(const std::string& message) {
  const std::string at = "parse error at ";
  const auto colon = message.find(": ");
  if (message.rfind(at, 0) != 0 || colon == std::string::npos) return {"", message};
  return {message.substr(at.size(), colon - at.size()), message.substr(colon + 2)};
}
}  // namespace

std::string child(const std::string& where, const std::string& key) { return where + "/" + escape(key); }
std::string child(const std::string& where, std::size_t index) { return where + "/" + std::to_string(index); }

Json parse_json_text(const std::string& text, const std::string& file) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(file, "", "empty file, expected JSON");
  Json result;
  StrictSax strict(result);
  try {
    Json::sax_parse(text, &strict, Json::input_format_t::json, /*strict=*/true, /*ignore_comments=*/false);
    return result;
  } catch (const Rejected& r) {
    throw InputError(file, r.where, r.problem);
  } catch (const Json::parse_error& e) {
    // Where the text stops being JSON, not a JSON pointer: the value there does not exist yet.
    const SyntaxError s = split_syntax_error(from_marker(e.what(), "parse error"));
    throw InputError(file, s.where, "not valid JSON: " + s.problem);
  } catch (const Json::out_of_range& e) {
    // nlohmann reports 1e400 and the like as "number overflow": name where it happened.
    throw InputError(file, strict.pointer(), "number is not finite (" + from_marker(e.what(), "number overflow") + ")");
  } catch (const Json::exception& e) {
    throw InputError(file, strict.pointer(), std::string("not valid JSON: ") + e.what());
  }
}

Json read_json_file(const std::string& path) { return parse_json_text(read_text_file(path), path); }

void JsonReader::fail(const std::string& where, const std::string& problem) const {
  throw InputError(file_, where, problem);
}

const Json& JsonReader::require(const Json& obj, const std::string& where, const char* key) const {
  require_object(obj, where);
  auto it = obj.find(key);
  if (it == obj.end()) fail(child(where, key), "missing required key");
  return *it;
}

const Json& JsonReader::require_object(const Json& j, const std::string& where) const {
  if (!j.is_object()) fail(where, std::string("expected an object, got ") + type_name(j));
  return j;
}

const Json& JsonReader::require_array(const Json& j, const std::string& where) const {
  if (!j.is_array()) fail(where, std::string("expected an array, got ") + type_name(j));
  return j;
}

double JsonReader::number(const Json& j, const std::string& where, double max_abs) const {
  if (!j.is_number()) fail(where, std::string("expected a number, got ") + type_name(j));
  const double x = j.get<double>();
  if (!std::isfinite(x)) fail(where, "number is not finite (overflows a double)");
  if (std::abs(x) > max_abs) {
    std::ostringstream s;
    s << "number " << x << " is out of range (|x| <= " << max_abs << ")";
    fail(where, s.str());
  }
  return x;
}

double JsonReader::number_in(const Json& j, const std::string& where, double lo, double hi) const {
  const double x = number(j, where, 1e300);
  if (!(x >= lo && x <= hi)) {
    std::ostringstream s;
    s << "value " << x << " is outside [" << lo << ", " << hi << "]";
    fail(where, s.str());
  }
  return x;
}

std::int64_t JsonReader::integer(const Json& j, const std::string& where, std::int64_t lo, std::int64_t hi) const {
  if (j.is_number_float()) {
    const double x = j.get<double>();
    if (!std::isfinite(x) || std::floor(x) != x) fail(where, "expected an integer");
    if (x < static_cast<double>(lo) || x > static_cast<double>(hi)) {
      fail(where, "integer out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return static_cast<std::int64_t>(x);
  }
  if (!j.is_number_integer()) fail(where, std::string("expected an integer, got ") + type_name(j));
  if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) {
    fail(where, "integer out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  const std::int64_t x = j.get<std::int64_t>();
  if (x < lo || x > hi) fail(where, "integer out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return x;
}

bool JsonReader::boolean(const Json& j, const std::string& where) const {
  if (!j.is_boolean()) fail(where, std::string("expected true or false, got ") + type_name(j));
  return j.get<bool>();
}

std::string JsonReader::string(const Json& j, const std::string& where) const {
  if (!j.is_string()) fail(where, std::string("expected a string, got ") + type_name(j));
  return j.get<std::string>();
}

Vec3 JsonReader::vec3(const Json& j, const std::string& where, double max_abs) const {
  if (!j.is_array() || j.size() != 3) fail(where, "expected an array of 3 numbers");
  return Vec3(number(j[0], child(where, 0), max_abs), number(j[1], child(where, 1), max_abs),
              number(j[2], child(where, 2), max_abs));
}

Vec2 JsonReader::vec2(const Json& j, const std::string& where, double max_abs) const {
  if (!j.is_array() || j.size() != 2) fail(where, "expected an array of 2 numbers");
  return Vec2(number(j[0], child(where, 0), max_abs), number(j[1], child(where, 1), max_abs));
}

void JsonReader::at_most(std::size_t count, const std::string& where, std::size_t limit, const std::string& what) const {
  if (count > limit)
    fail(where, std::to_string(count) + " " + what + ", more than the limit of " + std::to_string(limit));
}

void JsonReader::only_keys(const Json& obj, const std::string& where, std::initializer_list<const char*> known) const {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string& k = it.key();
    if (!k.empty() && k[0] == '_') continue;
    bool ok = false;
    for (const char* name : known) ok = ok || k == name;
    if (!ok) fail(child(where, k), unknown_key_problem(k, std::vector<std::string>(known.begin(), known.end())));
  }
}

std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& allowed) {
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  std::string guess;
  const std::vector<std::string> nearest = nearest_words(key, allowed);
  for (std::size_t k = 0; k < nearest.size(); ++k)
    guess += std::string(k == 0 ? "; did you mean " : " or ") + "\"" + nearest[k] + "\"";
  return "unknown key \"" + key + "\" (allowed: " + list + (guess.empty() ? "" : guess + "?") +
         "); keys starting with '_' are comments";
}

}  // namespace tecido::io
