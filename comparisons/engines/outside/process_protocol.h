#pragma once
/// The JSON-lines protocol of process engines (`--engine-cmd NAME=COMMAND`), one request and one
/// reply per line, each a JSON object (docs/engines.md, "Validate your own engine"):
///   {"op":"hello","protocol":1}        -> {"protocol":1,"supports":["tri_tri","ccd","plane","dynamics",...],"order":p}
///     ("protocol" of the reply: the version the engine speaks; absent, 1; another, the engine fails)
///   {"op":"tri_tri","a":[[x,y,z]x3],"b":[[x,y,z]x3]}              -> {"hit":true|false|null}
///   {"op":"ccd","kind":"vertex-face"|"edge-edge","t0":[[x,y,z]x4],"t1":[[x,y,z]x4]} -> {"hit":bool|null,"toi":t|null}
///   {"op":"plane","plane":{"position","normal","forward","half_extents"},"from":[..],"to":[..]} -> {"hit":bool|null,"t":t|null}
///   {"op":"create","scene":{tecido's scene JSON},"features":[...]} -> {"ok":true} | {"error":"why"}
///   {"op":"step","dt":h,"steps":n}     -> {"x":[[x,y,z],...],"v":[[x,y,z],...]} (null: not finite)
/// Batched forms, used when hello's "supports" lists "<op>_batch": {"op":"<op>_batch","queries":[q,...]}
/// -> {"results":[r,...]}, each q the single request without "op", each r its single reply.
/// Any reply may be {"error":"..."}: a refusal for create, a failure of the engine otherwise.
/// These functions build requests and read replies; a reply that breaks the protocol throws
/// ProtocolError saying what is wrong.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/io/json_reader.h"

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace tecido::outside {

class ProtocolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr int kProtocolVersion = 1;

struct Hello {
  std::set<std::string> supports;  ///< ops the engine answers (unknown names are kept, unused)
  std::optional<double> order;     ///< the integration order it claims
};

io::Json hello_request();
Hello parse_hello(const io::Json& reply);

/// The single requests without "op" (a batch's queries); with_op() adds it.
io::Json tri_tri_query(const TriTriQuery& q);
io::Json ccd_query(const CcdQuery& q);
io::Json plane_query(const SegmentPlaneQuery& q);
io::Json with_op(io::Json query, const std::string& op);

std::optional<bool> parse_tri_tri(const io::Json& reply);
std::optional<CcdAnswer> parse_ccd(const io::Json& reply);
std::optional<SegmentPlaneHit> parse_plane(const io::Json& reply);
/// The replies of a batch of `n` queries: the "results" array, each checked to be an object.
std::vector<io::Json> parse_batch(const io::Json& reply, std::size_t n);

io::Json create_request(const Scene& scene);
/// The engine's refusal, or nullopt for {"ok":true}.
std::optional<std::string> parse_create(const io::Json& reply);

io::Json step_request(double dt, long long steps);
struct State {
  std::vector<Vec3> x, v;  ///< NaN where the engine wrote null
};
/// Positions and velocities of `n` particles.
State parse_step(const io::Json& reply, std::size_t n);

/// The "error" of a reply, or nullptr.
const std::string* reply_error(const io::Json& reply);

}  // namespace tecido::outside
