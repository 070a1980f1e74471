#pragma once
/// Counters of the paths core's continuous collision test (ccd/ccd.h) takes, per thread: a
/// diagnostic for benchmarks and tests (which path decided), never an input to a decision.

namespace tecido {

struct CcdStats {
  unsigned long long queries = 0;            ///< calls of ccd / ccd_vertex_face / ccd_edge_edge
  unsigned long long non_finite = 0;         ///< answered hit at t = 0 because an input was NaN or infinite
  unsigned long long box_rejections = 0;     ///< decided by disjoint swept boxes
  unsigned long long cubic_rejections = 0;   ///< decided by the coplanarity cubic on [0, 1]
  unsigned long long time_search_nodes = 0;  ///< intervals the time search visited
  unsigned long long time_search_hits = 0;   ///< hits decided by the time search's rules
  unsigned long long inclusion_calls = 0;    ///< intervals handed to the inclusion search
  unsigned long long inclusion_boxes = 0;    ///< boxes the inclusion search evaluated
  unsigned long long inclusion_caps = 0;     ///< inclusion searches stopped by the box cap
};

/// This thread's counters (reset them by assigning CcdStats{}).
CcdStats& ccd_stats();

}  // namespace tecido
