#include "comparisons/engines/outside/process_engine.h"

#include "comparisons/engines/outside/engine_error.h"
#include "comparisons/engines/outside/process_simulation.h"
#include "comparisons/io/escaped_text.h"

#include <algorithm>

namespace tecido::outside {

using io::Json;

namespace {
thread_local double door_seconds = 0.0;  ///< see door_seconds_on_this_thread()
}  // namespace

double door_seconds_on_this_thread() { return door_seconds; }

ProcessEngine::ProcessEngine(const std::string& name, const std::string& command, std::chrono::duration<double> timeout)
    : name_(name), process_(command, timeout) {}

std::shared_ptr<ProcessEngine> ProcessEngine::start(const std::string& name, const std::string& command,
                                                    std::chrono::duration<double> timeout) {
  std::shared_ptr<ProcessEngine> e;
  try {
    e = std::make_shared<ProcessEngine>(name, command, timeout);
  } catch (const ProcessFailure& f) {
    throw EngineError("engine " + name + " (`" + command + "`)", "start", f.what());
  }
  const Json reply = e->request(hello_request(), "hello");
  try {
    e->hello_ = parse_hello(reply);
  } catch (const ProtocolError& p) {
    e->fail("hello", p.what());
  }
  const Capabilities c = e->capabilities();
  if (!c.tri_tri && !c.segment_plane && !c.ccd_vertex_face && !c.dynamics)
    e->fail("hello", "\"supports\" lists none of tri_tri, plane, ccd, dynamics");
  return e;
}

Capabilities ProcessEngine::capabilities() const {
  const auto has = [&](const char* op) { return hello_.supports.count(op) != 0; };
  Capabilities c;
  c.tri_tri = has("tri_tri");
  c.segment_plane = has("plane");
  c.ccd_vertex_face = c.ccd_edge_edge = has("ccd");
  c.dynamics = has("dynamics");
  return c;
}

void ProcessEngine::fail(const std::string& op, const std::string& problem, const std::string& tail) {
  std::lock_guard<std::mutex> lock(failure_mutex_);
  if (failure_.empty()) {
    failed_op_ = op;
    failure_ = problem + (tail.empty() ? "" : "; its stderr ends: " + tail);
  }
  throw EngineError("engine " + name_ + " (`" + process_.command() + "`)", "op " + failed_op_, failure_);
}

Json ProcessEngine::request(const Json& req, const std::string& op, bool error_ok) {
  {
    std::lock_guard<std::mutex> lock(failure_mutex_);
    if (!failure_.empty())
      throw EngineError("engine " + name_ + " (`" + process_.command() + "`)", "op " + failed_op_, failure_);
  }
  std::string line;
  try {
    double seconds = 0.0;
    line = process_.round_trip(req.dump(), &seconds);
    door_seconds += seconds;
  } catch (const ProcessFailure& f) {
    fail(op, f.what(), f.stderr_tail());
  }
  Json reply;
  try {
    reply = Json::parse(line);
  } catch (const Json::exception& e) {
    // parse_error: not JSON; out_of_range (406): a number past the range of doubles, e.g. 1e400.
    const std::string shown = io::escaped_text(line.substr(0, 120)) + (line.size() > 120 ? "..." : "");
    const bool overflow = dynamic_cast<const Json::out_of_range*>(&e) != nullptr;
    fail(op, std::string(overflow ? "a number in the reply is out of the range of doubles: \"" : "malformed JSON reply: \"") +
                 shown + "\"");
  }
  if (!reply.is_object()) fail(op, "the reply is not a JSON object: " + io::escaped_text(line.substr(0, 120)));
  if (!error_ok)
    if (const std::string* e = reply_error(reply)) fail(op, "the engine answered an error: " + io::escaped_text(*e));
  return reply;
}

std::vector<Json> ProcessEngine::answer_all(const std::string& op, const std::vector<Json>& queries) {
  std::vector<Json> out;
  out.reserve(queries.size());
  if (hello_.supports.count(op + "_batch") == 0) {
    for (const Json& q : queries) out.push_back(request(with_op(q, op), op));
    return out;
  }
  for (std::size_t begin = 0; begin < queries.size(); begin += kBatchChunk) {
    const std::size_t end = std::min(queries.size(), begin + kBatchChunk);
    Json batch = Json::array();
    for (std::size_t k = begin; k < end; ++k) batch.push_back(queries[k]);
    const Json chunk{{"op", op + "_batch"}, {"queries", std::move(batch)}};
    const Json reply = request(chunk, op + "_batch");
    try {
      for (Json& r : parse_batch(reply, end - begin)) out.push_back(std::move(r));
    } catch (const ProtocolError& p) {
      fail(op + "_batch", p.what());
    }
  }
  return out;
}

std::vector<std::optional<bool>> ProcessEngine::tri_tri(const std::vector<TriTriQuery>& queries) {
  std::vector<Json> qs;
  for (const TriTriQuery& q : queries) qs.push_back(tri_tri_query(q));
  std::vector<std::optional<bool>> out;
  for (const Json& r : answer_all("tri_tri", qs)) {
    if (const std::string* e = reply_error(r)) fail("tri_tri", "the engine answered an error: " + io::escaped_text(*e));
    try {
      out.push_back(parse_tri_tri(r));
    } catch (const ProtocolError& p) {
      fail("tri_tri", p.what());
    }
  }
  return out;
}

std::vector<std::optional<SegmentPlaneHit>> ProcessEngine::segment_plane(const std::vector<SegmentPlaneQuery>& queries) {
  std::vector<Json> qs;
  for (const SegmentPlaneQuery& q : queries) qs.push_back(plane_query(q));
  std::vector<std::optional<SegmentPlaneHit>> out;
  for (const Json& r : answer_all("plane", qs)) {
    if (const std::string* e = reply_error(r)) fail("plane", "the engine answered an error: " + io::escaped_text(*e));
    try {
      out.push_back(parse_plane(r));
    } catch (const ProtocolError& p) {
      fail("plane", p.what());
    }
  }
  return out;
}

std::vector<std::optional<CcdAnswer>> ProcessEngine::ccd(const std::vector<CcdQuery>& queries) {
  std::vector<Json> qs;
  for (const CcdQuery& q : queries) qs.push_back(ccd_query(q));
  std::vector<std::optional<CcdAnswer>> out;
  for (const Json& r : answer_all("ccd", qs)) {
    if (const std::string* e = reply_error(r)) fail("ccd", "the engine answered an error: " + io::escaped_text(*e));
    try {
      out.push_back(parse_ccd(r));
    } catch (const ProtocolError& p) {
      fail("ccd", p.what());
    }
  }
  return out;
}

void ProcessEngine::release_scene() { scene_.release(); }

Creation ProcessEngine::create(const Scene& scene) {
  scene_.take("engine " + name_ + " (`" + process_.command() + "`)", "the process");
  Creation c;
  try {
    const std::optional<std::string> refusal = [&] {
      const Json reply = request(create_request(scene), "create", /*error_ok=*/true);
      try {
        return parse_create(reply);
      } catch (const ProtocolError& p) {
        fail("create", p.what());
      }
    }();
    if (refusal) {
      release_scene();
      c.refusal = refusal->empty() ? "refused the scene without a reason" : *refusal;
      return c;
    }
    c.simulation = std::make_unique<ProcessSimulation>(shared_from_this(), scene);
  } catch (...) {
    release_scene();
    throw;
  }
  return c;
}

}  // namespace tecido::outside
