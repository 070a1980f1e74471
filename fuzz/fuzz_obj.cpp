// libFuzzer target: bytes -> io::parse_obj_text (the mesh reader of `tecido selfcollide`).
// Rejections must be io::InputError; an accepted mesh must have at least one triangle, finite
// vertices, and triangles of three different, valid vertex indices, each with its source line,
// and no more vertices and triangles than io::kMaxMeshVertices and io::kMaxMeshTriangles.
#include "fuzz_common.h"

#include "comparisons/io/obj_mesh.h"

namespace {
constexpr const char* kTarget = "fuzz_obj";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = tecido::fuzz::as_text(data, size);
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const tecido::io::ObjMesh m = tecido::io::parse_obj_text(text, "fuzz.obj");
    if (m.triangles.empty()) tecido::fuzz::finding(kTarget, "accepted a mesh without triangles");
    if (m.vertices.size() > tecido::io::kMaxMeshVertices || m.triangles.size() > tecido::io::kMaxMeshTriangles)
      tecido::fuzz::finding(kTarget, "accepted a mesh past the limits");
    if (m.triangle_line.size() != m.triangles.size()) tecido::fuzz::finding(kTarget, "triangle_line size differs");
    const auto nv = static_cast<long long>(m.vertices.size());
    for (const auto& v : m.vertices)
      if (!v.allFinite()) tecido::fuzz::finding(kTarget, "accepted a non-finite vertex");
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& tri = m.triangles[t];
      for (int k : tri)
        if (k < 0 || k >= nv) tecido::fuzz::finding(kTarget, "triangle " + std::to_string(t) + " has index out of range");
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
        tecido::fuzz::finding(kTarget, "triangle " + std::to_string(t) + " repeats a vertex");
      if (m.triangle_line[t] < 1) tecido::fuzz::finding(kTarget, "triangle line < 1");
    }
  });
  return 0;
}
