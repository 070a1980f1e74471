#pragma once
// Shared by the libFuzzer targets: the input as a string, and the rule every reader target
// enforces. A reader may reject input only with io::InputError; any other exception, a crash,
// undefined behaviour (UBSan), a leak (LeakSanitizer) or a broken invariant of what it
// accepted is a finding: the target prints what it saw and aborts, so libFuzzer saves the
// input as crash-<sha1> (scripts/fuzz.sh puts it under build-fuzz/artifacts/<target>/).
#include "comparisons/io/input_error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

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

}  // namespace tecido::fuzz
