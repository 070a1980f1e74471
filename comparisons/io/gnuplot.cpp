#include "comparisons/io/gnuplot.h"

#include "comparisons/io/atomic_file.h"

#include <cstdlib>

namespace tecido::io {

bool gnuplot_available() {
  static const bool found = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  return found;
}

bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script) {
  write_file_atomic(dir + "/" + name + ".gp", script);
  if (!gnuplot_available()) return false;
  const std::string cmd = "cd '" + dir + "' && gnuplot '" + name + ".gp' >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

}  // namespace tecido::io
