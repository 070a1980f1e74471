// libFuzzer target: bytes -> io::parse_json_text -> io::plane_cases_from_json (the cases file of
// `tecido plane`). Rejections must be io::InputError; accepted cases must have distinct ids and
// nesting within the limit, and must be finite, with a
// unit normal and forward and non-negative half extents, and must survive the writer's round
// trip (plane_cases_to_json -> plane_cases_from_json gives the same points and extents).
// make_bounded_plane keeps orthonormal input as given and orthogonalises twice otherwise, so the
// round trip must be exact (the bit-for-bit check below) and |normal . forward| at rounding
// level even for a forward 1e-9 rad off the normal (regress_* seeds: both were findings once).
#include "fuzz_common.h"

#include "comparisons/io/plane_cases.h"

#include <cmath>

namespace {

constexpr const char* kTarget = "fuzz_plane_cases";

bool same(const tecido::io::PlaneCase& a, const tecido::io::PlaneCase& b) {
  return a.id == b.id && a.from == b.from && a.to == b.to && a.plane.position == b.plane.position &&
         a.plane.normal == b.plane.normal && a.plane.forward == b.plane.forward &&
         a.plane.half_extents == b.plane.half_extents;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = tecido::fuzz::as_text(data, size);
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const auto doc = tecido::fuzz::parse_checked(kTarget, text);
    const auto cases = tecido::io::plane_cases_from_json(doc, "fuzz.json");
    tecido::fuzz::expect_unique_ids(kTarget, cases);
    for (const auto& c : cases) {
      const auto& p = c.plane;
      if (!c.from.allFinite() || !c.to.allFinite() || !p.position.allFinite() || !p.normal.allFinite() ||
          !p.forward.allFinite() || !p.half_extents.allFinite())
        tecido::fuzz::finding(kTarget, "accepted a non-finite case " + c.id);
      if (!(p.half_extents.x() >= 0.0 && p.half_extents.y() >= 0.0))
        tecido::fuzz::finding(kTarget, "accepted negative half extents, case " + c.id);
      if (std::abs(p.normal.norm() - 1.0) > 1e-12 || std::abs(p.forward.norm() - 1.0) > 1e-12 ||
          std::abs(p.normal.dot(p.forward)) > 1e-14)
        tecido::fuzz::finding(kTarget, "normal and forward not unit and orthogonal, case " + c.id);
    }
    // Round trip through the writer the suites use (numbers are printed to round-trip).
    const auto back = tecido::io::plane_cases_from_json(
        tecido::io::parse_json_text(tecido::io::plane_cases_to_json(cases).dump(), "roundtrip.json"), "roundtrip.json");
    if (back.size() != cases.size()) tecido::fuzz::finding(kTarget, "round trip changed the number of cases");
    for (std::size_t k = 0; k < cases.size(); ++k)
      if (!same(cases[k], back[k])) tecido::fuzz::finding(kTarget, "round trip changed case " + cases[k].id);
  });
  return 0;
}
