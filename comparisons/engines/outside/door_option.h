#pragma once
/// The command-line option that brings an outside engine back, for the replay commands a report
/// prints: `--plugin /abs/lib.so` (the path made absolute, so the command works from any
/// directory) or `--engine-cmd 'NAME=COMMAND'` (the command as given: it runs in the directory
/// tecido is started from, as it did). Each word is quoted for a POSIX shell.
#include <string>

namespace tecido::outside {

/// `s` as one word of a POSIX shell: unchanged when it holds only [A-Za-z0-9_./=,:+-] (and is not
/// empty), otherwise in single quotes, each ' written '\''.
std::string shell_word(const std::string& s);

/// "--plugin <absolute path>".
std::string plugin_option(const std::string& path);

/// "--engine-cmd <NAME=COMMAND as one shell word>".
std::string engine_cmd_option(const std::string& name, const std::string& command);

}  // namespace tecido::outside
