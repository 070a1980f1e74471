#pragma once
// Shared by the libFuzzer targets: the input as a string, and the rule every reader target
// enforces. A reader may reject input only with io::InputError; any other exception, a crash,
// undefined behaviour (UBSan), a leak (LeakSanitizer) or a broken invariant of what it
// accepted is a finding: the target prints what it saw and aborts, so libFuzzer saves the
// input as crash-<sha1> (scripts/fuzz.sh puts it under build-fuzz/artifacts/<target>/).
// Bounded work is checked from outside: scripts/fuzz.sh runs every target with -rss_limit_mb and
// -timeout tight enough for inputs up to -max_len (large enough to pass io::kMaxJsonDepth many
// times over), so a reader whose time or memory is not linear in its input is a finding too.
#include "comparisons/io/input_error.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/io/limits.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>
#include <unordered_set>
#include <utility>
#include <vector>

namespace tecido::fuzz {

inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Aborts with a message (libFuzzer reports "deadly signal" and saves the input).
[[noreturn]] inline void finding(const char* target, const std::string& what) {
  std::fprintf(stderr, "\n%s: FINDING: %s\n", target, what.c_str());
  std::fflush(stderr);
  std::abort();
}

/// Runs `body`; InputError is the reader's legitimate answer to bad input, anything else is a finding.
template <class F>
void expect_only_input_errors(const char* target, F&& body) {
  try {
    body();
  } catch (const io::InputError& e) {
    // Every message must name something: file and problem are never empty.
    if (e.file().empty() || e.problem().empty()) finding(target, std::string("InputError with an empty field: ") + e.what());
  } catch (const std::exception& e) {
    finding(target, std::string("exception other than InputError: ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    finding(target, "non-standard exception");
  }
}

/// Nesting depth of an accepted document, without recursion (the reader promises at most
/// io::kMaxJsonDepth).
inline int json_depth(const io::Json& doc) {
  int deepest = 0;
  std::vector<std::pair<const io::Json*, int>> todo{{&doc, 0}};
  while (!todo.empty()) {
    const auto [j, depth] = todo.back();
    todo.pop_back();
    if (!j->is_structured()) continue;
    deepest = depth + 1 > deepest ? depth + 1 : deepest;
    for (const auto& child : *j) todo.push_back({&child, depth + 1});
  }
  return deepest;
}

/// Parses like every JSON reader and checks the depth promise of what was accepted.
inline io::Json parse_checked(const char* target, const std::string& text) {
  io::Json doc = io::parse_json_text(text, "fuzz.json");
  if (json_depth(doc) > io::kMaxJsonDepth) finding(target, "accepted nesting deeper than io::kMaxJsonDepth");
  return doc;
}

/// Accepted entries of a query file have distinct ids (results are keyed by them).
template <class Entries>
void expect_unique_ids(const char* target, const Entries& entries) {
  std::unordered_set<std::string> seen;
  for (const auto& e : entries)
    if (!seen.insert(e.id).second) finding(target, "accepted two entries with id " + e.id);
}

}  // namespace tecido::fuzz
