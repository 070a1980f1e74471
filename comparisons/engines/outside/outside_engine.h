#pragma once
/// An engine from outside tecido's tree, reached through one of two doors: a C plug-in
/// (include/tecido/plugin.h, plugin_engine.h) or a process speaking JSON lines (process_engine.h).
/// Commands and suites see it through this one interface: batches of queries in, answers out in
/// the same order, and dynamics simulations behind engines::DynamicsEngine.
///
/// Batches: every query method takes a whole batch, so that a process door answers many queries
/// per round trip (a plug-in loops). Answers are a function of the query alone, so the order in
/// which threads call an engine never changes a result.
#include "comparisons/engines/dynamics_engine.h"
#include "core/geometry/ccd/query.h"
#include "core/geometry/segment_plane.h"
#include "core/geometry/types.h"
#include "core/scene/scene.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tecido::outside {

/// What an outside engine answers.
struct Capabilities {
  bool tri_tri = false;
  bool segment_plane = false;
  bool ccd_vertex_face = false;
  bool ccd_edge_edge = false;
  bool dynamics = false;
};

struct TriTriQuery {
  Triangle a, b;
};

struct SegmentPlaneQuery {
  BoundedPlane plane;
  Vec3 from, to;
};

/// A dynamics simulation created by an outside engine, or the engine's reason for refusing the
/// scene ("not modelled by <engine>: <reason>" in reports).
struct Creation {
  std::unique_ptr<engines::DynamicsEngine> simulation;  ///< null when refused
  std::string refusal;                                    ///< the engine's reason, when refused
};

class OutsideEngine {
 public:
  virtual ~OutsideEngine() = default;
  /// The engine's name on the command line (--engines NAME).
  virtual const std::string& name() const = 0;
  /// How it was reached, for reports: "plug-in /abs/path.so (ABI 1)" or "process `python3 e.py`".
  virtual std::string door() const = 0;
  /// The option that loads it again (door_option.h: "--plugin /abs/lib.so" or "--engine-cmd
  /// 'NAME=COMMAND'"), for the replay commands of reports; "" when it has no door of the command
  /// line (an engine made in a test).
  virtual std::string door_option() const { return ""; }
  /// Whether each answer costs a round trip through a pipe (reports say costs include it).
  virtual bool is_process() const = 0;
  virtual Capabilities capabilities() const = 0;
  /// The integration order the engine claims (the order suite checks it), if it claims one.
  virtual std::optional<double> claimed_order() const = 0;

  /// Answers in query order; nullopt where the engine cannot say. Throws EngineError when the
  /// door fails. Callers only ask what capabilities() lists.
  virtual std::vector<std::optional<bool>> tri_tri(const std::vector<TriTriQuery>& queries) = 0;
  virtual std::vector<std::optional<SegmentPlaneHit>> segment_plane(const std::vector<SegmentPlaneQuery>& queries) = 0;
  /// Vertex-face and edge-edge queries, in any mix.
  virtual std::vector<std::optional<CcdAnswer>> ccd(const std::vector<CcdQuery>& queries) = 0;

  /// A simulation of `scene` stepped at scene.dt, or the engine's refusal.
  virtual Creation create(const Scene& scene) = 0;
};

using OutsideEnginePtr = std::shared_ptr<OutsideEngine>;

/// Wall time this thread has spent in round trips of process engines, waiting for a turn excluded
/// [s]: the cost of a process door, which the thread's CPU time does not see.
double door_seconds_on_this_thread();

/// "not modelled by NAME: REASON", the line reports print for a refused scene.
inline std::string not_modelled_line(const std::string& engine, const std::string& reason) {
  return "not modelled by " + engine + ": " + reason;
}

}  // namespace tecido::outside
