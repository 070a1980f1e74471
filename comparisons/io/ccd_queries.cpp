#include "comparisons/io/ccd_queries.h"

#include "comparisons/io/entry_id.h"
#include "comparisons/io/text_file.h"

#include <limits>
#include <string_view>

namespace tecido::io {

namespace {

// ---- JSON ------------------------------------------------------------------------------------

/// "vertex-face" or "edge-edge" at `w`.
CcdKind read_kind(const JsonReader& r, const Json& j, const std::string& w) {
  const std::string name = r.string(j, w);
  if (name == ccd_kind_name(CcdKind::VertexFace)) return CcdKind::VertexFace;
  if (name == ccd_kind_name(CcdKind::EdgeEdge)) return CcdKind::EdgeEdge;
  r.fail(w, "unknown kind \"" + name + "\" (vertex-face, edge-edge)");
}

/// Exactly 4 points of 3 finite numbers.
std::array<Vec3, 4> read_points(const JsonReader& r, const Json& j, const std::string& w) {
  if (!j.is_array() || j.size() != 4) r.fail(w, "expected an array of 4 points");
  std::array<Vec3, 4> x;
  for (std::size_t k = 0; k < 4; ++k) x[k] = r.vec3(j[k], child(w, k), std::numeric_limits<double>::max());
  return x;
}

// ---- CSV -------------------------------------------------------------------------------------

constexpr int kColumns = 7;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

/// A row's fields, trimmed.
std::vector<std::string_view> split_row(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

const char* column_name(int c) {
  static const char* const names[kColumns] = {"x numerator", "x denominator", "y numerator", "y denominator",
                                              "z numerator", "z denominator", "truth"};
  return names[c];
}

/// Shortened copy of a field for a message.
std::string shown(std::string_view f) {
  return f.size() <= 40 ? std::string(f) : std::string(f.substr(0, 40)) + "...";
}

/// The problem with `f` as a decimal integer (optional sign, digits), or "" when it is one.
std::string integer_problem(std::string_view f) {
  const std::size_t start = (!f.empty() && (f[0] == '-' || f[0] == '+')) ? 1 : 0;
  if (f.size() == start) return "empty";
  for (std::size_t i = start; i < f.size(); ++i)
    if (f[i] < '0' || f[i] > '9') return "not an integer: \"" + shown(f) + "\"";
  if (f.size() - start > kMaxCcdIntegerDigits)
    return "integer of " + std::to_string(f.size() - start) + " digits (at most " +
           std::to_string(kMaxCcdIntegerDigits) + ")";
  return "";
}

bool all_zero_digits(std::string_view f) {
  for (char c : f)
    if (c != '0' && c != '-' && c != '+') return false;
  return true;
}

/// One row's three coordinates and truth; throws naming `line`.
struct CsvRow {
  std::array<reference::RationalCoord, 3> coord;
  bool truth = false;
};

CsvRow parse_row(std::string_view text, const std::string& file, const std::string& line) {
  const std::vector<std::string_view> f = split_row(text);
  if (f.size() != kColumns)
    throw InputError(file, line,
                     "expected 7 columns (x num, x den, y num, y den, z num, z den, truth), got " +
                         std::to_string(f.size()));
  for (int c = 0; c < kColumns; ++c) {
    const std::string problem = integer_problem(f[c]);
    if (!problem.empty()) throw InputError(file, line, std::string("column ") + std::to_string(c + 1) + " (" +
                                                           column_name(c) + "): " + problem);
  }
  CsvRow row;
  for (int a = 0; a < 3; ++a) {
    if (all_zero_digits(f[2 * a + 1]))
      throw InputError(file, line, std::string("column ") + std::to_string(2 * a + 2) + " (" + column_name(2 * a + 1) +
                                       "): zero denominator");
    row.coord[a] = {std::string(f[2 * a]), std::string(f[2 * a + 1])};
  }
  if (f[6] != "0" && f[6] != "1")
    throw InputError(file, line, "column 7 (truth): expected 0 or 1, got \"" + shown(f[6]) + "\"");
  row.truth = f[6] == "1";
  return row;
}

std::string line_name(std::size_t n) { return "line " + std::to_string(n); }

}  // namespace

std::vector<CcdQueryEntry> ccd_queries_from_json(const Json& doc, const std::string& file) {
  return read_entries<CcdQueryEntry>(doc, file, "queries", kMaxCcdQueries,
                                     [](const JsonReader& r, const Json& e, const std::string& w) {
    CcdQueryEntry q;
    q.query.kind = read_kind(r, r.require(e, w, "kind"), child(w, "kind"));
    q.query.x0 = read_points(r, r.require(e, w, "t0"), child(w, "t0"));
    q.query.x1 = read_points(r, r.require(e, w, "t1"), child(w, "t1"));
    if (e.contains("truth")) q.truth = r.boolean(e["truth"], child(w, "truth"));
    return q;
  });
}

std::vector<CcdQueryEntry> load_ccd_queries_json(const std::string& path) {
  return ccd_queries_from_json(read_json_file(path), path);
}

std::vector<CcdQueryEntry> parse_ccd_queries_csv(const std::string& text, const std::string& file, CcdKind kind) {
  std::vector<CcdQueryEntry> out;
  std::size_t rows = 0, line_no = 0, first_line = 0, last_line = 0;
  std::string_view rest(text);
  while (!rest.empty()) {
    const std::size_t nl = rest.find('\n');
    const std::string_view line = rest.substr(0, nl);
    rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
    ++line_no;
    if (trim(line).empty()) continue;
    const std::string where = line_name(line_no);
    if (rows == 8 * kMaxCcdQueries)
      throw InputError(file, where, "too many rows (at most " + std::to_string(kMaxCcdQueries) + " queries of 8)");
    const CsvRow row = parse_row(line, file, where);
    const std::size_t r = rows % 8;
    if (r == 0) {
      first_line = line_no;
      CcdQueryEntry e;
      e.id = std::to_string(out.size());
      e.query.kind = kind;
      e.rational = reference::RationalCcdQuery{};
      e.rational->kind = kind;
      e.truth = row.truth;
      out.push_back(std::move(e));
    } else if (row.truth != *out.back().truth) {
      throw InputError(file, where, std::string("truth ") + (row.truth ? "1" : "0") + " disagrees with the query's first row (" +
                                        line_name(first_line) + ": " + (row.truth ? "0" : "1") + ")");
    }
    (r < 4 ? out.back().rational->x0 : out.back().rational->x1)[r % 4] = row.coord;
    ++rows;
    last_line = line_no;
  }
  if (rows == 0) throw InputError(file, "", "no query rows (8 rows of 7 integers per query)");
  if (rows % 8 != 0)
    throw InputError(file, line_name(last_line),
                     std::to_string(rows) + " rows is not a multiple of 8: the query starting at " +
                         line_name(first_line) + " has " + std::to_string(rows % 8) + " rows");
  return out;
}

std::vector<CcdQueryEntry> load_ccd_queries_csv(const std::string& path, CcdKind kind) {
  return parse_ccd_queries_csv(read_text_file(path), path, kind);
}

Json ccd_queries_to_json(const std::vector<CcdQueryEntry>& entries) {
  auto points = [](const std::array<Vec3, 4>& x) {
    Json j = Json::array();
    for (const Vec3& p : x) j.push_back({p.x(), p.y(), p.z()});
    return j;
  };
  Json arr = Json::array();
  for (const CcdQueryEntry& e : entries) {
    Json q = {{"id", e.id}, {"kind", ccd_kind_name(e.query.kind)}, {"t0", points(e.query.x0)}, {"t1", points(e.query.x1)}};
    if (e.truth) q["truth"] = *e.truth;
    arr.push_back(std::move(q));
  }
  return Json{{"queries", arr}};
}

}  // namespace tecido::io
