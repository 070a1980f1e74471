#pragma once
/// The error of an outside engine that cannot be used or misbehaves: a plug-in that cannot be
/// loaded (path, symbol), an ABI mismatch, a process that dies, hangs past its timeout or answers
/// malformed JSON (command and its stderr tail). It is an io::InputError, so the command line
/// prints it as one line and exits 2, and a suite's sweep stops instead of recording a case error:
/// nothing is half written.
#include "comparisons/io/input_error.h"

#include <string>

namespace tecido::outside {

class EngineError : public io::InputError {
 public:
  /// `door`: "plug-in PATH" or "engine NAME (command `CMD`)"; `where`: the symbol or request;
  /// `problem`: what went wrong.
  EngineError(const std::string& door, const std::string& where, const std::string& problem)
      : io::InputError(door, where, problem) {}
};

}  // namespace tecido::outside
