#include "comparisons/io/obj_mesh.h"

#include "comparisons/io/text_file.h"

#include "comparisons/io/input_error.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tecido::io {

namespace {

std::vector<std::string> split_ws(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream ss(line);
  std::string tok;
  while (ss >> tok) out.push_back(tok);
  return out;
}

}  // namespace

ObjMesh parse_obj_text(const std::string& text, const std::string& file) {
  ObjMesh mesh;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  std::vector<std::vector<long long>> faces;  // resolved 1-based indices (may exceed count so far)
  std::vector<int> face_line;
  auto fail = [&](int ln, const std::string& problem) -> void {
    throw InputError(file, "line " + std::to_string(ln), problem);
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const auto tok = split_ws(line);
    if (tok.empty()) continue;
    if (tok[0] == "v") {
      if (tok.size() < 4) fail(line_no, "a vertex needs three coordinates (v x y z)");
      if (tok.size() > 5) fail(line_no, "a vertex has at most four numbers (v x y z [w])");
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        const std::string& s = tok[1 + k];
        char* end = nullptr;
        errno = 0;
        const double d = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0') fail(line_no, "\"" + s + "\" is not a number");
        if (!std::isfinite(d)) fail(line_no, "coordinate \"" + s + "\" is not finite");
        p[k] = d;
      }
      if (tok.size() == 5) {
        char* end = nullptr;
        const double w = std::strtod(tok[4].c_str(), &end);
        if (end == tok[4].c_str() || *end != '\0') fail(line_no, "\"" + tok[4] + "\" is not a number");
        if (!std::isfinite(w)) fail(line_no, "weight \"" + tok[4] + "\" is not finite");
      }
      mesh.vertices.push_back(p);
    } else if (tok[0] == "f") {
      if (tok.size() < 4) fail(line_no, "a face needs at least three vertices");
      std::vector<long long> idx;
      for (std::size_t k = 1; k < tok.size(); ++k) {
        const std::string s = tok[k].substr(0, tok[k].find('/'));
        char* end = nullptr;
        errno = 0;
        const long long i = std::strtoll(s.c_str(), &end, 10);
        if (s.empty() || end == s.c_str() || *end != '\0' || errno == ERANGE)
          fail(line_no, "\"" + tok[k] + "\" is not a vertex index");
        if (i == 0) fail(line_no, "vertex index 0 (OBJ indices start at 1)");
        long long resolved = i;
        if (i < 0) {
          resolved = static_cast<long long>(mesh.vertices.size()) + 1 + i;
          if (resolved < 1)
            fail(line_no, "vertex " + s + " names a missing vertex (only " + std::to_string(mesh.vertices.size()) +
                              " defined so far)");
        }
        for (long long prev : idx)
          if (prev == resolved) fail(line_no, "degenerate face: vertex " + std::to_string(resolved) + " is repeated");
        idx.push_back(resolved);
      }
      faces.push_back(std::move(idx));
      face_line.push_back(line_no);
    }
  }
  const long long nv = static_cast<long long>(mesh.vertices.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (long long i : faces[f])
      if (i > nv)
        fail(face_line[f], "face names missing vertex " + std::to_string(i) + " (the file has " + std::to_string(nv) +
                               " vertices)");
    for (std::size_t k = 1; k + 1 < faces[f].size(); ++k) {
      mesh.triangles.push_back({static_cast<int>(faces[f][0] - 1), static_cast<int>(faces[f][k] - 1),
                                static_cast<int>(faces[f][k + 1] - 1)});
      mesh.triangle_line.push_back(face_line[f]);
    }
  }
  if (mesh.triangles.empty()) throw InputError(file, "line " + std::to_string(line_no > 0 ? line_no : 1), "the file has no face");
  if (nv > 2000000000LL) throw InputError(file, "", "too many vertices");
  return mesh;
}

ObjMesh load_obj_mesh(const std::string& path) { return parse_obj_text(read_text_file(path), path); }

}  // namespace tecido::io
