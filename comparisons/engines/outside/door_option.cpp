#include "comparisons/engines/outside/door_option.h"

#include <filesystem>

namespace tecido::outside {

std::string shell_word(const std::string& s) {
  const bool plain = !s.empty() && s.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                       "0123456789_./=,:+-") == std::string::npos;
  if (plain) return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string plugin_option(const std::string& path) {
  return "--plugin " + shell_word(std::filesystem::absolute(path).lexically_normal().string());
}

std::string engine_cmd_option(const std::string& name, const std::string& command) {
  return "--engine-cmd " + shell_word(name + "=" + command);
}

}  // namespace tecido::outside
