// libFuzzer target: bytes -> io::parse_json_text -> io::tri_pairs_from_json (the pairs file of
// `tecido tritri`). Rejections must be io::InputError; accepted coordinates must be finite and
// within the documented |x| <= 1e15, ids distinct, nesting within the limit, and the writer's
// round trip must give the same doubles.
#include "fuzz_common.h"

#include "comparisons/io/tri_pairs.h"

#include <cmath>

namespace {
constexpr const char* kTarget = "fuzz_tri_pairs";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = tecido::fuzz::as_text(data, size);
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const auto doc = tecido::fuzz::parse_checked(kTarget, text);
    const auto pairs = tecido::io::tri_pairs_from_json(doc, "fuzz.json");
    tecido::fuzz::expect_unique_ids(kTarget, pairs);
    for (const auto& p : pairs)
      for (const auto* t : {&p.a, &p.b})
        for (const auto& v : *t)
          if (!v.allFinite() || v.cwiseAbs().maxCoeff() > 1e15)
            tecido::fuzz::finding(kTarget, "accepted a coordinate outside |x| <= 1e15, pair " + p.id);
    const auto back = tecido::io::tri_pairs_from_json(
        tecido::io::parse_json_text(tecido::io::tri_pairs_to_json(pairs).dump(), "roundtrip.json"), "roundtrip.json");
    if (back.size() != pairs.size()) tecido::fuzz::finding(kTarget, "round trip changed the number of pairs");
    for (std::size_t k = 0; k < pairs.size(); ++k)
      if (back[k].id != pairs[k].id || back[k].a != pairs[k].a || back[k].b != pairs[k].b)
        tecido::fuzz::finding(kTarget, "round trip changed pair " + pairs[k].id);
  });
  return 0;
}
