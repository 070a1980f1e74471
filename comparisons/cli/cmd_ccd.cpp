// tecido ccd --queries FILE.json [--engines core,exact,fcl,bullet] --json
// tecido ccd --queries FILE.csv --csv-kind vertex-face|edge-edge [--engines ...] --json
// Outside engines (--plugin PATH, --engine-cmd NAME=CMD) answer every query in one batch through
// their door, on the nearest doubles of rational queries (counted apart like fcl's), and null on a
// kind they do not model.
// Prints {"results":[{"id","<engine>":{"hit":bool,"toi":t|null}|null, ...}]} (null: the engine
// cannot answer this query), engines in the order named. When the queries carry a truth (the CSV's
// ground-truth column, or "truth" in a JSON file such as the ccd suite's disagreements), each
// result adds "truth" and stderr gets one summary line per engine: false positives and negatives.
// --of-engine NAME keeps the queries whose id starts with "NAME:" (one engine's disagreements in
// the suite's file, the other keys of whose entries, "engine", "answer", "referee", are labels):
// with --engines NAME and that engine's door, the replay the suite prints for it.
// CSV queries add "rounded": whether some rational coordinate is not a double; the exact engine
// answers on the rationals, the others on the nearest doubles, and their errors on rounded queries
// are counted apart (they answered a slightly different query). Formats: comparisons/io/ccd_queries.h.
// The options (input, --engines, --json, outside engines) are the query-command scaffold's
// (query_command.h).
#include "comparisons/cli/query_command.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/engines/ccd_engines.h"
#include "comparisons/io/ccd_queries.h"
#include "comparisons/io/input_error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace tecido::cli {

namespace {

using OJson = nlohmann::ordered_json;

/// One engine's tally against the truth: exact-double queries, and rounded ones apart.
struct Tally {
  long queries = 0, fp = 0, fn = 0, rounded = 0, rounded_fp = 0, rounded_fn = 0, no_answer = 0;
};

void count(Tally& t, const std::optional<CcdAnswer>& a, bool truth, bool apart) {
  if (!a) {
    ++t.no_answer;
    return;
  }
  const bool fp = a->hit && !truth, fn = !a->hit && truth;
  if (apart) {
    ++t.rounded, t.rounded_fp += fp, t.rounded_fn += fn;
  } else {
    ++t.queries, t.fp += fp, t.fn += fn;
  }
}

std::string summary(const std::string& name, const Tally& t) {
  std::string s = fmt::format("tecido ccd: {}: {} false positives, {} false negatives of {} queries", name, t.fp, t.fn,
                              t.queries);
  if (t.rounded) s += fmt::format("; rounded queries apart: {} false positives, {} false negatives of {}",
                                  t.rounded_fp, t.rounded_fn, t.rounded);
  if (t.no_answer) s += fmt::format("; no answer on {}", t.no_answer);
  return s;
}

CcdKind parse_csv_kind(const std::string& s) {
  if (s == "vertex-face") return CcdKind::VertexFace;
  if (s == "edge-edge") return CcdKind::EdgeEdge;
  throw io::UsageError("--csv-kind: expected vertex-face or edge-edge, got \"" + s + "\"");
}

std::vector<io::CcdQueryEntry> load(const std::string& path, const std::string& csv_kind) {
  if (!csv_kind.empty()) return io::load_ccd_queries_csv(path, parse_csv_kind(csv_kind));
  if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0)
    throw io::UsageError("--queries " + path + ": a CSV file needs --csv-kind vertex-face|edge-edge");
  return io::load_ccd_queries_json(path);
}

OJson answer_json(const std::optional<CcdAnswer>& a) {
  if (!a) return nullptr;
  return OJson{{"hit", a->hit}, {"toi", a->hit ? OJson(a->toi) : OJson(nullptr)}};
}

/// One engine of the run: built-in (answers entry by entry, on the rationals where it can) or
/// outside (answers the whole file in one batch through its door).
struct Answerer {
  std::string name;
  const CcdEngine* builtin = nullptr;
  outside::OutsideEnginePtr outside;
  bool on_rationals() const { return builtin && builtin->test_rational; }
};

std::vector<Answerer> answerers(const std::vector<std::string>& names, const outside::OutsideEngines& outside) {
  std::vector<Answerer> out;
  for (const auto& n : names) {
    Answerer a{n, find_ccd_engine(n), nullptr};
    if (!a.builtin) a.outside = outside.find(n);
    out.push_back(std::move(a));
  }
  return out;
}

/// Every answer of engine `a` to the prepared entries, in order.
std::vector<std::optional<CcdAnswer>> answer_all(const Answerer& a, const std::vector<io::CcdQueryEntry>& entries) {
  if (a.builtin) {
    std::vector<std::optional<CcdAnswer>> out;
    out.reserve(entries.size());
    for (const auto& e : entries) out.push_back(answer_ccd_entry(*a.builtin, e));
    return out;
  }
  std::vector<CcdQuery> queries;
  queries.reserve(entries.size());
  for (const auto& e : entries) queries.push_back(e.query);
  return a.outside->ccd(queries);
}

int run_ccd(const QueryRequest& request, const std::string& csv_kind) {
  const std::vector<Answerer> engines = answerers(request.engines, *request.outside);
  std::vector<io::CcdQueryEntry> entries = entries_of_engine(load(request.input, csv_kind), request.of_engine);
  bool all_truth = true;
  std::vector<char> rounded(entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    all_truth = all_truth && entries[i].truth.has_value();
    rounded[i] = prepare_ccd_entry(entries[i]);
  }
  std::vector<std::vector<std::optional<CcdAnswer>>> answers;
  for (const Answerer& a : engines) answers.push_back(answer_all(a, entries));
  std::vector<Tally> tally(engines.size());
  OJson results = OJson::array();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const io::CcdQueryEntry& e = entries[i];
    OJson row{{"id", e.id}};
    if (e.truth) row["truth"] = *e.truth;
    if (e.rational) row["rounded"] = static_cast<bool>(rounded[i]);
    for (std::size_t k = 0; k < engines.size(); ++k) {
      row[engines[k].name] = answer_json(answers[k][i]);
      if (all_truth) count(tally[k], answers[k][i], *e.truth, rounded[i] && !engines[k].on_rationals());
    }
    results.push_back(std::move(row));
  }
  std::cout << OJson{{"results", results}}.dump() << "\n";
  // A replay (--of-engine) of an engine without disagreements still says so: 0 and 0 of 0.
  if (all_truth && (!entries.empty() || !request.of_engine.empty()))
    for (std::size_t k = 0; k < engines.size(); ++k) std::cerr << summary(engines[k].name, tally[k]) << "\n";
  return 0;
}

Command add_ccd(CLI::App& app) {
  auto csv_kind = std::make_shared<std::string>();
  QueryCommand c;
  c.name = "ccd";
  c.summary = "Continuous collision (vertex-face, edge-edge over one time step) per engine, against a truth when given";
  c.input_option = "--queries";
  c.input_help =
      "Queries file: JSON {\"queries\":[{\"id\",\"kind\":\"vertex-face\"|\"edge-edge\",\"t0\":[[x,y,z]x4],"
      "\"t1\":[[x,y,z]x4]}]} (vertex-face: vertex, then the triangle's corners; edge-edge: a0, a1, b0, b1), "
      "or the CCD benchmark's CSV with --csv-kind";
  c.input_non_empty = false;
  c.options = [csv_kind](CLI::App& sub) {
    sub.add_option("--csv-kind", *csv_kind,
                   "Read --queries as the CCD benchmark's CSV of this kind (vertex-face|edge-edge): 8 rows per query "
                   "(t0 rows, then t1 rows), columns x num, x den, y num, y den, z num, z den, truth (0/1); ids are "
                   "the 0-based query index");
  };
  c.builtin = engine_names_of(ccd_engines());
  c.engines_note = "; bullet answers vertex-face only; and outside engines answering ccd";
  c.known = &ccd_engine_names;
  c.footer =
      "Output: {\"results\":[{\"id\",\"truth\"?,\"rounded\"?,\"<engine>\":{\"hit\":bool,\"toi\":t|null}|null}]}. "
      "With a truth (CSV, or \"truth\" in JSON), stderr gets one line per engine: false positives and negatives; "
      "CSV queries whose rationals are not doubles (\"rounded\": true) are answered by exact on the rationals and "
      "by the others on the nearest doubles, and counted apart for the others.";
  c.run = [csv_kind](const QueryRequest& request) { return run_ccd(request, *csv_kind); };
  return add_query_command(app, std::move(c));
}

}  // namespace

TECIDO_REGISTER_COMMAND(ccd, add_ccd);

}  // namespace tecido::cli
