#pragma once
/// Strict JSON reading shared by every reader (scenes, pairs, cases, tolerances, shards): the file
/// is parsed whole (a directory, a missing or unreadable file, malformed JSON, duplicate keys,
/// a file over kMaxInputBytes and nesting deeper than kMaxJsonDepth are errors; see
/// comparisons/io/limits.h), in time and memory linear in the text, and typed accessors report
/// the JSON pointer of the bad value.
#include "comparisons/io/input_error.h"
#include "core/geometry/types.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::io {

using Json = nlohmann::json;

/// Reads and parses a JSON file; throws InputError naming the file and the problem.
Json read_json_file(const std::string& path);
/// Parses JSON text (duplicate keys and nesting deeper than kMaxJsonDepth rejected while parsing,
/// at the first offending key or level; a syntax error at its "line L, column C", not a JSON
/// pointer); `file` is used in messages only.
Json parse_json_text(const std::string& text, const std::string& file);

/// Typed access with the JSON pointer of each value, for error messages.
class JsonReader {
 public:
  explicit JsonReader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const;

  const Json& require(const Json& obj, const std::string& where, const char* key) const;
  const Json& require_object(const Json& j, const std::string& where) const;
  const Json& require_array(const Json& j, const std::string& where) const;
  /// A finite number whose magnitude is at most `max_abs`.
  double number(const Json& j, const std::string& where, double max_abs = 1e12) const;
  double number_in(const Json& j, const std::string& where, double lo, double hi) const;
  std::int64_t integer(const Json& j, const std::string& where, std::int64_t lo, std::int64_t hi) const;
  bool boolean(const Json& j, const std::string& where) const;
  std::string string(const Json& j, const std::string& where) const;
  Vec3 vec3(const Json& j, const std::string& where, double max_abs = 1e12) const;
  Vec2 vec2(const Json& j, const std::string& where, double max_abs = 1e12) const;

  /// Fails at `where` when a list holds more than `limit` entries: "N particles, more than the
  /// limit of L" (the limits of comparisons/io/limits.h).
  void at_most(std::size_t count, const std::string& where, std::size_t limit, const std::string& what) const;

  /// Rejects keys of obj that are not in `known` (keys starting with '_' are comments), naming the
  /// allowed keys and the nearest of them (unknown_key_problem).
  void only_keys(const Json& obj, const std::string& where, std::initializer_list<const char*> known) const;

 private:
  std::string file_;
};

/// The problem of an unknown key: `unknown key "stiffness" (allowed: rows, ...; did you mean
/// "stiffness_a" or "stiffness_b"?); keys starting with '_' are comments`, the guess only when close
/// enough to be a typo (edit_distance.h, nearest_words).
std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& allowed);

/// "/a/b" + "c" -> "/a/b/c"; also for array indices.
std::string child(const std::string& where, const std::string& key);
std::string child(const std::string& where, std::size_t index);

}  // namespace tecido::io
