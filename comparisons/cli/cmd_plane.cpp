// tecido plane --cases FILE.json [--engines a,b] [--plugin PATH] [--engine-cmd NAME=CMD] --json
// Outside engines answer every case in one batch through their door. Options, engine list and
// output rows are the query-command scaffold's (query_command.h): cases with a "truth" (the plane
// suite's disagreements) add it to their rows and get a line per engine on stderr, false positives
// and negatives; --of-engine NAME keeps the cases whose id starts with "NAME:".
#include "comparisons/cli/query_command.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/engines/segment_plane_engines.h"
#include "comparisons/io/plane_cases.h"

namespace tecido::cli {

namespace {

io::Json plane_cell(const SegmentPlaneHit& h) { return {{"hit", h.hit}, {"t", h.hit ? io::Json(h.t) : io::Json(nullptr)}}; }
outside::SegmentPlaneQuery plane_query(const io::PlaneCase& c) { return {c.plane, c.from, c.to}; }

Command add_plane(CLI::App& app) {
  return add_query_command(app, {"plane", "Segment vs bounded plane: hit and crossing fraction per engine", "--cases",
                                 "Cases file {\"cases\":[{\"id\",\"plane\",\"from\",\"to\",\"truth\"?}]}",
                                 engine_names_of(segment_plane_engines()), ", and outside engines",
                                 &segment_plane_engine_names,
                                 answer_entries(&io::load_plane_cases, &plane_query, &segment_plane_answers, &plane_cell, "plane", "cases")});
}

}  // namespace

TECIDO_REGISTER_COMMAND(plane, add_plane);

}  // namespace tecido::cli
