// libFuzzer target: bytes -> io::parse_ccd_queries_csv (the benchmark's CSV read by `tecido ccd`
// and the ccd suite), then the nearest doubles of each accepted entry
// (reference::nearest_double_query, through GMP: what the engines' layer hands a floating-point
// engine). Byte 0 picks the kind (vertex-face or edge-edge); the rest is the file. Rejections
// must be io::InputError. Accepted entries must keep the reader's promises: at most
// io::kMaxCcdQueries, ids "0", "1", ... in order, a truth on each, rational coordinates whose
// numerators and denominators are decimal integers (optional sign) of at most
// io::kMaxCcdIntegerDigits digits with a nonzero denominator, and rounding them must not throw
// (a rational past the range of doubles rounds to an infinity, which is allowed).
#include "fuzz_common.h"

#include "comparisons/io/ccd_queries.h"
#include "reference/exact_ccd.h"

namespace {

constexpr const char* kTarget = "fuzz_ccd_queries_csv";

bool valid_integer(const std::string& s, bool nonzero) {
  const std::size_t start = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
  if (s.size() == start || s.size() - start > tecido::io::kMaxCcdIntegerDigits) return false;
  bool zero = true;
  for (std::size_t i = start; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    zero = zero && s[i] == '0';
  }
  return !(nonzero && zero);
}

void check_entry(const tecido::io::CcdQueryEntry& e, std::size_t k, tecido::CcdKind kind) {
  using tecido::fuzz::finding;
  if (e.id != std::to_string(k)) finding(kTarget, "entry " + std::to_string(k) + " has id " + e.id);
  if (!e.rational || !e.truth) finding(kTarget, "entry " + e.id + " lacks its rationals or its truth");
  if (e.query.kind != kind || e.rational->kind != kind) finding(kTarget, "entry " + e.id + " has another kind");
  for (const auto* x : {&e.rational->x0, &e.rational->x1})
    for (const auto& p : *x)
      for (const auto& c : p)
        if (!valid_integer(c.num, false) || !valid_integer(c.den, true))
          finding(kTarget, "entry " + e.id + " accepted the coordinate " + c.num.substr(0, 40) + "/" + c.den.substr(0, 40));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto kind = (data[0] & 1) ? tecido::CcdKind::EdgeEdge : tecido::CcdKind::VertexFace;
  const std::string text = tecido::fuzz::as_text(data + 1, size - 1);
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    auto entries = tecido::io::parse_ccd_queries_csv(text, "fuzz.csv", kind);
    if (entries.size() > tecido::io::kMaxCcdQueries) tecido::fuzz::finding(kTarget, "accepted more than kMaxCcdQueries");
    for (std::size_t k = 0; k < entries.size(); ++k) {
      check_entry(entries[k], k, kind);
      try {
        entries[k].query = tecido::reference::nearest_double_query(*entries[k].rational);
      } catch (const std::exception& e) {
        tecido::fuzz::finding(kTarget, std::string("rounding accepted entry ") + entries[k].id + " threw: " + e.what());
      }
    }
  });
  return 0;
}
