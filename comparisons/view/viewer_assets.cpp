#include "comparisons/view/viewer_assets.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/text_file.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>

#ifndef TECIDO_VIEWER_DIR
#define TECIDO_VIEWER_DIR ""
#endif

namespace tecido::view {

namespace {

const char* const kAssets[] = {"tecido-viewer.js", "tecido.css"};

bool has_assets(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const char* a : kAssets)
    if (!std::filesystem::is_regular_file(dir / a, ec)) return false;
  return true;
}

}  // namespace

std::string viewer_dir() {
  const char* env = std::getenv("TECIDO_VIEWER_DIR");
  for (const std::filesystem::path& d : {std::filesystem::path(env ? env : ""), std::filesystem::path(TECIDO_VIEWER_DIR)})
    if (!d.empty() && has_assets(d)) return d.string();
  return "";
}

bool copy_viewer_assets(const std::string& dir) {
  const std::string from = viewer_dir();
  if (from.empty()) {
    static std::once_flag noted;
    std::call_once(noted, [] {
      std::cerr << "tecido: note: the 3-D viewer (tecido-viewer.js) was not built, so the pages show no 3-D view "
                   "(build the tecido-viewer target: node and npm, docs/viewer.md)\n";
    });
    return false;
  }
  for (const char* a : kAssets) {
    const std::string content = io::read_text_file(from + "/" + a);
    const std::string to = dir + "/" + a;
    std::error_code ec;
    if (std::filesystem::is_regular_file(to, ec) && io::read_text_file(to) == content) continue;
    io::write_file_atomic(to, content);
  }
  return true;
}

}  // namespace tecido::view
