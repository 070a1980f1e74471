#pragma once
/// The `tritri` suite's families of triangle pairs: uniform random pairs, and adversarial
/// families built to sit exactly on the cases floating-point tests get wrong (coplanar, touching
/// at a vertex or an edge, sharing a vertex, degenerate slivers, far from the origin).
///
/// Pair k of family f is a pure function of (seed, f, k): its generator draws from its own
/// substream, so any pair can be regenerated alone (a case, the disagreement file) and the
/// pairs do not depend on how they are split into cases.
#include "comparisons/io/tri_pairs.h"
#include "comparisons/suites/random.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::tritri {

/// Draws pair k of a family from its generator `r` (id left empty).
using PairGenerator = io::TriPair (*)(Rng& r, long k);

struct Family {
  std::string name;   ///< "random", "coplanar", ... (pair ids are "<name>/<k>")
  std::string about;  ///< one line: what the family claims about its pairs
  PairGenerator make;
  bool random = false;  ///< the uniform family: references are checked and speed is measured on it
};

/// Random pairs: six points uniform in the unit cube.
io::TriPair random_pair(Rng& r, long k);
/// b within 1e-16 .. 1e-6 of a's plane (per vertex, either side).
io::TriPair near_coplanar_pair(Rng& r, long k);
/// Exactly coplanar: integer combinations of two integer vectors from an integer origin.
io::TriPair coplanar_pair(Rng& r, long k);
/// A vertex of b exactly on a's closed face (a dyadic barycentric point of a lattice triangle).
io::TriPair touch_vertex_pair(Rng& r, long k);
/// An edge of b passes exactly through the midpoint of an edge of a.
io::TriPair touch_edge_pair(Rng& r, long k);
/// b's first vertex is one of a's vertices.
io::TriPair shared_vertex_pair(Rng& r, long k);
/// a nearly or exactly collinear; b a sliver too or a random triangle.
io::TriPair sliver_pair(Rng& r, long k);
/// Unit-size random pairs shifted 10^(3 + k mod 6) from the origin.
io::TriPair offset_pair(Rng& r, long k);

/// Every family in report order: random first, then the adversarial ones.
const std::vector<Family>& families();

/// Pair k of `family` (index `f` in its table) for `seed`, with id "<name>/<k>".
io::TriPair family_pair(std::uint64_t seed, std::size_t f, const Family& family, long k);

}  // namespace tecido::suites::tritri
