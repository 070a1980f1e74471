// tecido tritri --pairs FILE.json [--engines a,b] [--plugin PATH] [--engine-cmd NAME=CMD] --json
// Outside engines answer every pair in one batch through their door. Options, engine list and
// output rows are the query-command scaffold's (query_command.h): pairs with a "truth" (the tritri
// suite's disagreements) add it to their rows and get a line per engine on stderr, false positives
// and negatives; --of-engine NAME keeps the pairs whose id starts with "NAME:".
#include "comparisons/cli/query_command.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/engines/tri_tri_engines.h"
#include "comparisons/io/tri_pairs.h"

namespace tecido::cli {

namespace {

bool tritri_cell(bool hit) { return hit; }
outside::TriTriQuery tritri_query(const io::TriPair& p) { return {p.a, p.b}; }

Command add_tritri(CLI::App& app) {
  return add_query_command(app, {"tritri", "Triangle-triangle intersection per engine (closed triangles)", "--pairs",
                                 "Pairs file {\"pairs\":[{\"id\",\"a\":[[..]x3],\"b\":[[..]x3],\"truth\"?}]}",
                                 engine_names_of(tri_tri_engines()), ", and outside engines", &tri_tri_engine_names,
                                 answer_entries(&io::load_tri_pairs, &tritri_query, &tri_tri_answers, &tritri_cell, "tritri", "pairs")});
}

}  // namespace

TECIDO_REGISTER_COMMAND(tritri, add_tritri);

}  // namespace tecido::cli
