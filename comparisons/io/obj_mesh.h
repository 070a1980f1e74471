#pragma once
/// Reads a triangle mesh from a Wavefront OBJ file (the subset `tecido selfcollide` needs).
///  - `v x y z [w]`: a vertex (w, if present, is ignored); numbers must be finite.
///  - `f a b c ...`: a face; each corner is `i`, `i/t`, `i//n` or `i/t/n` (only the vertex index
///    i is used); i is 1-based, or negative to count back from the last vertex read so far
///    (-1 = the latest). A face names at least 3 vertices, all different. A face with n > 3
///    corners (a quad, a polygon) is split into the fan (c1, c_k, c_k+1), k = 2 .. n-1: a quad
///    `f a b c d` gives the triangles (a, b, c) and (a, c, d), in that order.
///  - Triangles are numbered 0, 1, 2, ... in the order they are produced (faces in file order,
///    a polygon's fan in order), which is the numbering of `selfcollide`'s output.
///  - Blank lines, `#` comments and every other record (vt, vn, o, g, s, l, usemtl, mtllib, ...)
///    are ignored. A positive index may refer to a vertex defined later in the file.
/// Errors are io::InputError(file, "line N", problem): a face naming a missing vertex (index 0
/// or beyond the vertex count), a repeated index in a face (degenerate face), fewer than three
/// corners, a malformed or non-finite number, a vertex with fewer than three coordinates.
/// A file with no face is an error too (there is nothing to test). At most io::kMaxMeshVertices
/// vertices and io::kMaxMeshTriangles triangles (comparisons/io/limits.h), rejected at the first
/// line past either; time and memory are linear in the text.
#include "core/geometry/types.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::io {

struct ObjMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  ///< 0-based vertex indices
  std::vector<int> triangle_line;             ///< the source line of each triangle (1-based)
};

/// Loads and validates an OBJ file; throws InputError.
ObjMesh load_obj_mesh(const std::string& path);
/// Parses OBJ text; `file` names it in messages.
ObjMesh parse_obj_text(const std::string& text, const std::string& file);

}  // namespace tecido::io
