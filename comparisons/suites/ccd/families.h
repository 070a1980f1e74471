#pragma once
/// The ccd suite's families: the kinds of case the handcrafted set of the CCD benchmark (Wang,
/// Ferguson, Schneider, Jiang, Attene and Panozzo, ACM TOG 2021, after Erleben's "spikes",
/// "wedges" and sliding scenes) is made of, plus random motion, for vertex-face and edge-edge.
/// One generator function per family, listed in a table by index (the suite's case k is family k).
/// Every family but `random` constructs its answers (constructions.h), which the exact referee
/// must reproduce; `random` has only the referee's.
#include "comparisons/suites/ccd/constructions.h"
#include "comparisons/suites/ccd/settings.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// Appends `count` queries of the family to `out`, drawn from `r`.
using FamilyFn = void (*)(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);

struct Family {
  const char* name;  ///< "random", "crossing", ...
  CcdKind kind;
  FamilyFn generate;
  const char* about;  ///< one line for the report
  /// Whether the answers are constructed (every query's `known` is 0 or 1).
  bool constructed = true;
  /// Whether the floating-point references (FCL, Bullet) are checked here: only on random motion,
  /// where their documented tolerances are far below the features of the queries.
  bool checks_references = false;
};

/// "vertex-face/random", the family's full name in checks and ids.
std::string family_name(const Family& f);

/// Every family, vertex-face first, in a fixed order.
const std::vector<Family>& families();

/// The family's queries for the suite's seed: `settings.per_family` of them (random families:
/// `random_per_family`) from substream(seed, index), each relabelled at random.
std::vector<KnownQuery> family_queries(std::size_t index, const Settings& s, std::uint64_t seed);

// The generators (vertex_face_families.cpp, edge_edge_families.cpp).
void vf_random(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_crossing(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_spike(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_sliding(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_parallel(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_degenerate(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_endpoints(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_near_miss(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void vf_scale(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_random(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_crossing(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_crack(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_sliding(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_wedge(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_coplanar(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_parallel(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_degenerate(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_endpoints(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_near_miss(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);
void ee_scale(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out);

}  // namespace tecido::suites::ccd
