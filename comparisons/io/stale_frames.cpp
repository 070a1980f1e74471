#include "comparisons/io/stale_frames.h"

#include "comparisons/io/output_error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>
#include <vector>

namespace tecido::io {

bool is_frame_file_name(const std::string& name) {
  const std::string head = "frame_";
  const auto dot = name.rfind('.');
  if (name.rfind(head, 0) != 0 || dot == std::string::npos) return false;
  const std::string ext = name.substr(dot);
  if (ext != ".obj" && ext != ".vtk") return false;
  const std::string digits = name.substr(head.size(), dot - head.size());
  return digits.size() >= 6 &&
         std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::size_t remove_stale_frames(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;  // frames/ may be a link to another disk: followed
  // Listed first, removed after: removing while iterating leaves the iterator's order unspecified.
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->symlink_status(ec).type() == fs::file_type::regular && is_frame_file_name(it->path().filename().string()))
      stale.push_back(it->path());
  if (ec) throw OutputError(dir, "cannot list the frames of an earlier run: " + ec.message());
  for (const fs::path& p : stale)
    if (!fs::remove(p, ec) && ec) throw OutputError(p.string(), "cannot remove this frame of an earlier run: " + ec.message());
  return stale.size();
}

}  // namespace tecido::io
