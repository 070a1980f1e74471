#include "comparisons/io/obj_mesh.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/text_file.h"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <unordered_set>

namespace tecido::io {

namespace {

/// OBJ's token separators (what isspace() says in the C locale, but the newline that ends a line).
inline bool separator(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/// The whitespace-separated tokens of one line, one at a time (nothing is copied; a plain loop
/// over the characters: string_view::find_first_of calls memchr on the separator set once per
/// character, which was a tenth of a large mesh's `selfcollide`).
class Tokens {
 public:
  explicit Tokens(std::string_view line) : p_(line.data()), end_(line.data() + line.size()) {}
  bool next(std::string_view& tok) {
    while (p_ != end_ && separator(*p_)) ++p_;
    if (p_ == end_) return false;
    const char* b = p_;
    while (p_ != end_ && !separator(*p_)) ++p_;
    tok = std::string_view(b, static_cast<std::size_t>(p_ - b));
    return true;
  }

 private:
  const char* p_;
  const char* end_;
};

[[noreturn]] void fail(const std::string& file, int line_no, const std::string& problem) {
  throw InputError(file, "line " + std::to_string(line_no), problem);
}

/// A token as a NUL-terminated string for strtod / strtoll: in a buffer on the stack when it
/// fits (every number of a real mesh), so that a large file's parse allocates nothing per token.
class TokenText {
 public:
  explicit TokenText(std::string_view tok) {
    if (tok.size() < sizeof(small_)) {
      tok.copy(small_, tok.size());
      small_[tok.size()] = '\0';
    } else {
      large_.assign(tok);
    }
  }
  const char* c_str() const { return large_.empty() ? small_ : large_.c_str(); }

 private:
  char small_[64];
  std::string large_;
};

/// A token std::from_chars does not take whole (a sign '+', hex, inf/nan, out of range, or not a
/// number): strtod's reading, as before from_chars read the plain ones (both round correctly,
/// so a number gets the same double either way).
double parse_number_slowly(std::string_view tok, const std::string& file, int line_no) {
  const TokenText text(tok);
  const char* s = text.c_str();
  char* end = nullptr;
  const double d = std::strtod(s, &end);
  if (end == s || *end != '\0') fail(file, line_no, "\"" + std::string(s) + "\" is not a number");
  return d;
}

/// The rest of a `v x y z [w]` line.
Vec3 parse_vertex(Tokens& tokens, const std::string& file, int line_no) {
  Vec3 p = Vec3::Zero();
  std::string_view tok;
  int k = 0;
  for (; tokens.next(tok); ++k) {
    if (k == 4) fail(file, line_no, "a vertex has at most four numbers (v x y z [w])");
    double d = 0;
    const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), d);
    if (ec != std::errc() || ptr != tok.data() + tok.size()) d = parse_number_slowly(tok, file, line_no);
    if (!std::isfinite(d))
      fail(file, line_no, std::string(k < 3 ? "coordinate" : "weight") + " \"" + std::string(tok) + "\" is not finite");
    if (k < 3) p[k] = d;
  }
  if (k < 3) fail(file, line_no, "a vertex needs three coordinates (v x y z)");
  return p;
}

/// One corner of a face (`i`, `i/t`, `i//n`, `i/t/n`): the 1-based index, a negative one
/// resolved against the `vertices` read so far (positive ones may name later vertices).
long long parse_corner(std::string_view tok, std::size_t vertices, const std::string& file, int line_no) {
  const std::string_view index = tok.substr(0, tok.find('/'));
  long long i = 0;
  const auto [ptr, ec] = std::from_chars(index.data(), index.data() + index.size(), i);
  if (index.empty() || ec != std::errc() || ptr != index.data() + index.size()) {  // '+', or not an index: strtoll's reading
    const TokenText text(index);
    const char* s = text.c_str();
    char* end = nullptr;
    errno = 0;
    i = std::strtoll(s, &end, 10);
    if (index.empty() || end == s || *end != '\0' || errno == ERANGE)
      fail(file, line_no, "\"" + std::string(tok) + "\" is not a vertex index");
  }
  if (i == 0) fail(file, line_no, "vertex index 0 (OBJ indices start at 1)");
  if (i > 0) return i;
  const long long resolved = static_cast<long long>(vertices) + 1 + i;
  if (resolved < 1)
    fail(file, line_no, "vertex " + std::string(index) + " names a missing vertex (only " + std::to_string(vertices) + " defined so far)");
  return resolved;
}

/// Faces as read: every corner in one array, each face a range of it (the memory of the text).
struct Faces {
  std::vector<long long> corners;
  std::vector<std::size_t> begin{0};
  std::vector<int> line;
  std::size_t triangles = 0;
};

/// The rest of an `f a b c ...` line, appended to `faces`; stops at the first corner past
/// kMaxMeshTriangles. Linear in the corners (a repeated one is a degenerate face).
void parse_face(Tokens& tokens, std::size_t vertices, Faces& faces, const std::string& file, int line_no) {
  const auto start = static_cast<std::ptrdiff_t>(faces.begin.back());
  std::unordered_set<long long> seen;  // past a few corners, where a linear search would make it quadratic
  std::string_view tok;
  std::size_t n = 0;
  while (tokens.next(tok)) {
    const long long c = parse_corner(tok, vertices, file, line_no);
    const auto first = faces.corners.begin() + start, last = faces.corners.end();
    if (n == 8) seen.insert(first, last);
    const bool repeated = n < 8 ? std::find(first, last, c) != last : !seen.insert(c).second;
    if (repeated) fail(file, line_no, "degenerate face: vertex " + std::to_string(c) + " is repeated");
    if (++n >= 3 && ++faces.triangles > kMaxMeshTriangles)
      fail(file, line_no, "more than " + std::to_string(kMaxMeshTriangles) + " triangles (the limit; a face of n corners is n - 2)");
    faces.corners.push_back(c);
  }
  if (n < 3) fail(file, line_no, "a face needs at least three vertices");
  faces.begin.push_back(faces.corners.size());
  faces.line.push_back(line_no);
}

/// The faces' fans, once every vertex is known.
void build_triangles(const Faces& faces, ObjMesh& mesh, const std::string& file) {
  const long long nv = static_cast<long long>(mesh.vertices.size());
  mesh.triangles.reserve(faces.triangles);
  mesh.triangle_line.reserve(faces.triangles);
  for (std::size_t f = 0; f + 1 < faces.begin.size(); ++f) {
    const long long* c = faces.corners.data() + faces.begin[f];
    const std::size_t n = faces.begin[f + 1] - faces.begin[f];
    for (std::size_t k = 0; k < n; ++k)
      if (c[k] > nv)
        fail(file, faces.line[f], "face names missing vertex " + std::to_string(c[k]) + " (the file has " + std::to_string(nv) + " vertices)");
    for (std::size_t k = 1; k + 1 < n; ++k) {
      mesh.triangles.push_back({static_cast<int>(c[0] - 1), static_cast<int>(c[k] - 1), static_cast<int>(c[k + 1] - 1)});
      mesh.triangle_line.push_back(faces.line[f]);
    }
  }
}

}  // namespace

ObjMesh parse_obj_text(const std::string& text, const std::string& file) {
  ObjMesh mesh;
  Faces faces;
  int line_no = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t eol = std::min(text.find('\n', pos), text.size());
    std::string_view line(text.data() + pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    line = line.substr(0, line.find('#'));
    Tokens tokens(line);
    std::string_view record;
    if (!tokens.next(record)) continue;
    if (record == "v") {
      if (mesh.vertices.size() == kMaxMeshVertices)
        fail(file, line_no, "more than " + std::to_string(kMaxMeshVertices) + " vertices (the limit)");
      mesh.vertices.push_back(parse_vertex(tokens, file, line_no));
    } else if (record == "f") {
      parse_face(tokens, mesh.vertices.size(), faces, file, line_no);
    }
  }
  build_triangles(faces, mesh, file);
  if (mesh.triangles.empty()) fail(file, line_no > 0 ? line_no : 1, "the file has no face");
  return mesh;
}

ObjMesh load_obj_mesh(const std::string& path) { return parse_obj_text(read_text_file(path), path); }

}  // namespace tecido::io
