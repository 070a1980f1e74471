#include "comparisons/io/json_reader.h"

#include "comparisons/io/text_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
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

struct DuplicateKey {
  std::string where;
  std::string key;
};
}  // namespace

std::string child(const std::string& where, const std::string& key) { return where + "/" + escape(key); }
std::string child(const std::string& where, std::size_t index) { return where + "/" + std::to_string(index); }

Json parse_json_text(const std::string& text, const std::string& file) {
  // Track the keys of each open object (and the JSON pointer to it) to reject duplicates, which
  // nlohmann::json would otherwise resolve silently to the last value.
  struct Frame {
    std::string where;
    bool is_object;
    std::size_t index = 0;
    std::set<std::string> keys;
    std::string last_key;
  };
  std::vector<Frame> stack;
  auto current_child = [&]() -> std::string {
    if (stack.empty()) return "";
    Frame& f = stack.back();
    return f.is_object ? child(f.where, f.last_key) : child(f.where, f.index);
  };
  auto cb = [&](int, Json::parse_event_t ev, Json& parsed) -> bool {
    switch (ev) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start: {
        std::string where = current_child();
        stack.push_back(Frame{where, ev == Json::parse_event_t::object_start, 0, {}, {}});
        break;
      }
      case Json::parse_event_t::key: {
        Frame& f = stack.back();
        const std::string k = parsed.get<std::string>();
        if (!f.keys.insert(k).second) throw DuplicateKey{f.where, k};
        f.last_key = k;
        break;
      }
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        stack.pop_back();
        if (!stack.empty() && !stack.back().is_object) ++stack.back().index;
        break;
      case Json::parse_event_t::value:
        if (!stack.empty() && !stack.back().is_object) ++stack.back().index;
        break;
    }
    return true;
  };
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(file, "", "empty file, expected JSON");
  try {
    return Json::parse(text, cb, /*allow_exceptions=*/true, /*ignore_comments=*/false);
  } catch (const DuplicateKey& d) {
    throw InputError(file, d.where, "duplicate key \"" + d.key + "\"");
  } catch (const Json::parse_error& e) {
    std::string msg = e.what();
    // nlohmann messages look like "[json.exception.parse_error.101] parse error at line 1, column 5: ...".
    const auto pos = msg.find("parse error");
    if (pos != std::string::npos) msg = msg.substr(pos);
    throw InputError(file, current_child(), "not valid JSON: " + msg);
  } catch (const Json::out_of_range& e) {
    // nlohmann reports 1e400 and the like as "number overflow": name where it happened.
    std::string msg = e.what();
    const auto pos = msg.find("number overflow");
    if (pos != std::string::npos) msg = msg.substr(pos);
    throw InputError(file, current_child(), "number is not finite (" + msg + ")");
  } catch (const Json::exception& e) {
    throw InputError(file, current_child(), std::string("not valid JSON: ") + e.what());
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

void JsonReader::only_keys(const Json& obj, const std::string& where, std::initializer_list<const char*> known) const {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string& k = it.key();
    if (!k.empty() && k[0] == '_') continue;
    bool ok = false;
    for (const char* name : known) ok = ok || k == name;
    if (!ok) fail(child(where, k), "unknown key (keys starting with '_' are comments)");
  }
}

}  // namespace tecido::io
