#pragma once
/// The input of `tecido ccd` (docs/design.md section 3, "Contracts added in the second milestone"):
///
/// JSON: {"queries":[{"id":"..","kind":"vertex-face"|"edge-edge","t0":[[x,y,z]x4],"t1":[[x,y,z]x4]}]}
///   (core/geometry/ccd/query.h: vertex-face is the vertex, then the triangle's corners; edge-edge
///   is a0, a1, b0, b1). Every number finite; exactly 4 points of 3 numbers; ids unique (an absent
///   id is the entry's index, a non-string id its JSON text); an optional boolean "truth" (the
///   suite's disagreement files carry the exact answer there); other keys are labels, ignored.
///
/// CSV (the CCD benchmark of Wang, Ferguson, Schneider, Jiang, Attene and Panozzo, ACM TOG 2021):
///   8 rows per query, the JSON order above (t0 rows, then t1 rows), each row 7 integer columns:
///   x numerator, x denominator, y num, y den, z num, z den, ground truth (0/1, the same on the 8
///   rows). Integers are decimal with an optional sign, of any length up to kMaxCcdIntegerDigits
///   digits, kept as text (a coordinate is the exact rational num/den, den != 0). Blank lines are
///   skipped; a trailing '\r' is dropped; fields may carry spaces around them. Ids are the 0-based
///   query index as a string.
///
/// Errors are io::InputError: the file and the JSON pointer (JSON) or "line N" (CSV).
#include "comparisons/io/json_reader.h"
#include "comparisons/io/limits.h"  // kMaxCcdQueries: queries in one file (JSON entries, CSV rows / 8)
#include "core/geometry/ccd/query.h"
#include "reference/exact_ccd.h"  // RationalCcdQuery: a plain struct (no GMP; usable without the reference build)

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tecido::io {

/// Longest integer of a CSV coordinate, in digits (a double as a fraction in lowest terms has at
/// most 324 digits above or below; the benchmark's integers have about 20).
constexpr std::size_t kMaxCcdIntegerDigits = 1100;

/// One query of a queries file.
struct CcdQueryEntry {
  std::string id;
  /// The doubles. JSON: as read. CSV: left zero by the reader; the engines' layer fills in the
  /// nearest doubles (comparisons/engines/ccd_engines.h, prepare_ccd_entry).
  CcdQuery query;
  /// CSV only: the exact rational coordinates.
  std::optional<reference::RationalCcdQuery> rational;
  /// CSV: the ground-truth column; JSON: the optional "truth" key.
  std::optional<bool> truth;
};

/// Reads a JSON queries file; throws InputError.
std::vector<CcdQueryEntry> load_ccd_queries_json(const std::string& path);
std::vector<CcdQueryEntry> ccd_queries_from_json(const Json& doc, const std::string& file);

/// Reads the benchmark's CSV, every query of `kind`; throws InputError naming the line.
std::vector<CcdQueryEntry> load_ccd_queries_csv(const std::string& path, CcdKind kind);
std::vector<CcdQueryEntry> parse_ccd_queries_csv(const std::string& text, const std::string& file, CcdKind kind);

/// A queries JSON document of the entries' doubles (and "truth" where set), which
/// ccd_queries_from_json reads back bit for bit (nlohmann::json writes each double in its
/// shortest round-trip form, -0.0 included).
Json ccd_queries_to_json(const std::vector<CcdQueryEntry>& entries);

}  // namespace tecido::io
