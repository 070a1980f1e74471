// libFuzzer target: the replies of a process engine (`--engine-cmd`, the JSON-lines door of
// comparisons/engines/outside/process_engine.h). The door reads replies from a child process's
// pipe (json_lines_process.h) and cannot take a stream, so the target runs a fake engine: a
// /bin/sh loop that answers each request line with the next line of a file holding the fuzzer's
// bytes. The door then does what `tecido` does: start (hello), then one batch of queries of the
// kind byte 0 picks (tri_tri, ccd vertex-face, ccd edge-edge, plane; 1 to 3 queries, batched
// when hello lists "<op>_batch"). A reply that breaks the protocol, a dead or silent engine,
// must come out as EngineError (an io::InputError); anything else is a finding (another
// exception, a crash, a leak, UBSan). Accepted answers must be one per query, a CCD toi and a
// plane t finite, and a claimed order in (0, 100].
// A reply holding a number past the range of doubles ({"hit":true,"toi":1e400}: regress_toi_overflow,
// regress_order_overflow) was found to escape as json::out_of_range; the door now reports it as
// its EngineError (ProcessEngine::request).
// Input: byte 0 the op (b % 4), byte 1 the number of queries (1 + b % 3), then the reply lines.
#include "fuzz_common.h"

#include "comparisons/engines/outside/process_engine.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <unistd.h>

namespace {

constexpr const char* kTarget = "fuzz_engine_replies";

/// The file the fake engine answers from (one per fuzzing process) and its command.
const std::string& replies_file() {
  static const std::string path = "/tmp/tecido_fuzz_engine_replies." + std::to_string(::getpid());
  return path;
}

std::string fake_engine_command() {
  return "exec 3<'" + replies_file() +
         "'; while IFS= read -r q; do IFS= read -r l <&3 || exit 0; printf '%s\\n' \"$l\"; done";
}

void ask(tecido::outside::ProcessEngine& e, int op, std::size_t n) {
  using tecido::fuzz::finding;
  tecido::Triangle t{tecido::Vec3(0, 0, 0), tecido::Vec3(1, 0, 0), tecido::Vec3(0, 1, 0)};
  if (op == 0) {
    const auto r = e.tri_tri(std::vector<tecido::outside::TriTriQuery>(n, {t, t}));
    if (r.size() != n) finding(kTarget, "tri_tri: " + std::to_string(r.size()) + " answers to " + std::to_string(n));
  } else if (op == 1 || op == 2) {
    tecido::CcdQuery q;
    q.kind = op == 1 ? tecido::CcdKind::VertexFace : tecido::CcdKind::EdgeEdge;
    const auto r = e.ccd(std::vector<tecido::CcdQuery>(n, q));
    if (r.size() != n) finding(kTarget, "ccd: " + std::to_string(r.size()) + " answers to " + std::to_string(n));
    for (const auto& a : r)
      if (a && a->hit && !std::isfinite(a->toi)) finding(kTarget, "ccd: accepted a non-finite toi");
  } else {
    const auto r = e.segment_plane(std::vector<tecido::outside::SegmentPlaneQuery>(n, {tecido::BoundedPlane{}, tecido::Vec3(0, 0, 1), tecido::Vec3(0, 0, -1)}));
    if (r.size() != n) finding(kTarget, "plane: " + std::to_string(r.size()) + " answers to " + std::to_string(n));
    for (const auto& a : r)
      if (a && a->hit && !std::isfinite(a->t)) finding(kTarget, "plane: accepted a non-finite t");
  }
}

/// Starts the fake engine (hello), checks its claimed order, asks one batch.
void ask_all(int op, std::size_t n) {
  const auto engine = tecido::outside::ProcessEngine::start("fuzz", fake_engine_command(), std::chrono::seconds(2));
  if (const auto order = engine->claimed_order())
    if (!(*order > 0.0 && *order <= 100.0)) tecido::fuzz::finding(kTarget, "accepted order " + std::to_string(*order));
  ask(*engine, op, n);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int op = data[0] % 4;
  const std::size_t n = 1 + data[1] % 3;
  {
    std::ofstream f(replies_file(), std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data + 2), static_cast<std::streamsize>(size - 2));
  }
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    ask_all(op, n);
  });
  return 0;
}
