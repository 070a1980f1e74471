// libFuzzer target: bytes -> io::parse_json_text -> io::ccd_queries_from_json (the JSON queries
// file of `tecido ccd`). Rejections must be io::InputError. Accepted queries must keep the
// reader's promises: at most io::kMaxCcdQueries, ids distinct, nesting within the limit, every
// coordinate finite, and the writer's round trip (ccd_queries_to_json, what the suite's
// disagreement files hold) must give back the same ids, kinds, doubles (bit for bit, -0.0
// included) and truths.
#include "fuzz_common.h"

#include "comparisons/io/ccd_queries.h"

#include <cstring>

namespace {

constexpr const char* kTarget = "fuzz_ccd_queries_json";

bool same_bits(const std::array<tecido::Vec3, 4>& a, const std::array<tecido::Vec3, 4>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 12) == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = tecido::fuzz::as_text(data, size);
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const auto doc = tecido::fuzz::parse_checked(kTarget, text);
    const auto entries = tecido::io::ccd_queries_from_json(doc, "fuzz.json");
    if (entries.size() > tecido::io::kMaxCcdQueries) tecido::fuzz::finding(kTarget, "accepted more than kMaxCcdQueries");
    tecido::fuzz::expect_unique_ids(kTarget, entries);
    for (const auto& e : entries) {
      if (e.rational) tecido::fuzz::finding(kTarget, "a JSON entry with rational coordinates, " + e.id);
      for (const auto* x : {&e.query.x0, &e.query.x1})
        for (const auto& p : *x)
          if (!p.allFinite()) tecido::fuzz::finding(kTarget, "accepted a non-finite coordinate, query " + e.id);
    }
    const auto back = tecido::io::ccd_queries_from_json(
        tecido::io::parse_json_text(tecido::io::ccd_queries_to_json(entries).dump(), "roundtrip.json"), "roundtrip.json");
    if (back.size() != entries.size()) tecido::fuzz::finding(kTarget, "round trip changed the number of queries");
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const auto &a = entries[k], &b = back[k];
      if (a.id != b.id || a.query.kind != b.query.kind || !same_bits(a.query.x0, b.query.x0) ||
          !same_bits(a.query.x1, b.query.x1) || a.truth != b.truth)
        tecido::fuzz::finding(kTarget, "round trip changed query " + a.id);
    }
  });
  return 0;
}
