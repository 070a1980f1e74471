#pragma once
/// An engine behind a JSON-lines process (`--engine-cmd NAME=COMMAND`; the protocol is in
/// process_protocol.h). The process is started once, when the engine is loaded, and greeted with
/// hello; every query batch is sent in chunks of up to kBatchChunk queries per line when the
/// engine lists "<op>_batch", one query per line otherwise.
///
/// Threads: one process, one request at a time (JsonLinesProcess holds a mutex), and answers
/// depend only on the query, so results do not depend on the thread count. The process holds one
/// scene at a time: a simulation leases the process from create() until it is destroyed, so
/// dynamics runs of one process engine run one after another (a thread that asks for a second
/// simulation while holding one gets an error instead of a deadlock). Queries may interleave.
///
/// Any failure of the door (death, timeout, malformed JSON, an {"error"} reply to a query or a
/// step) is an EngineError naming the engine, its command, the request and its stderr tail.
#include "comparisons/engines/outside/door_option.h"
#include "comparisons/engines/outside/json_lines_process.h"
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/engines/outside/process_protocol.h"
#include "comparisons/engines/outside/scene_lease.h"

#include <chrono>
#include <memory>
#include <mutex>

namespace tecido::outside {

class ProcessEngine final : public OutsideEngine, public std::enable_shared_from_this<ProcessEngine> {
 public:
  static constexpr std::size_t kBatchChunk = 4096;

  /// Starts `command` and sends hello; throws EngineError when it cannot.
  static std::shared_ptr<ProcessEngine> start(const std::string& name, const std::string& command,
                                              std::chrono::duration<double> timeout);

  const std::string& name() const override { return name_; }
  std::string door() const override { return "process `" + process_.command() + "`"; }
  std::string door_option() const override { return engine_cmd_option(name_, process_.command()); }
  bool is_process() const override { return true; }
  Capabilities capabilities() const override;
  std::optional<double> claimed_order() const override { return hello_.order; }

  std::vector<std::optional<bool>> tri_tri(const std::vector<TriTriQuery>& queries) override;
  std::vector<std::optional<SegmentPlaneHit>> segment_plane(const std::vector<SegmentPlaneQuery>& queries) override;
  std::vector<std::optional<CcdAnswer>> ccd(const std::vector<CcdQuery>& queries) override;
  Creation create(const Scene& scene) override;

  /// One request, one reply (parsed, an object); `op` names it in errors. An {"error"} reply is an
  /// EngineError unless `error_ok`.
  io::Json request(const io::Json& req, const std::string& op, bool error_ok = false);
  /// Round trips so far.
  long long round_trips() const { return process_.round_trips(); }
  /// Ends the lease of a simulation (ProcessSimulation's destructor).
  void release_scene();
  /// Throws the EngineError of request `op`: "engine NAME (`COMMAND`): op OP: problem; its stderr ends: tail".
  /// The engine is broken from then on: every later request throws this first error again, so
  /// whichever thread reports it, the message names what failed first.
  [[noreturn]] void fail(const std::string& op, const std::string& problem, const std::string& tail = {});

  ProcessEngine(const std::string& name, const std::string& command, std::chrono::duration<double> timeout);

 private:
  /// Answers `queries` of one op through the batched form when supported.
  std::vector<io::Json> answer_all(const std::string& op, const std::vector<io::Json>& queries);

  std::string name_;
  JsonLinesProcess process_;
  Hello hello_;
  SceneLease scene_;
  std::mutex failure_mutex_;
  std::string failed_op_, failure_;  ///< the first failure (empty while the engine works)
};

}  // namespace tecido::outside
