#pragma once
/// The data of a page for a user's query file (`tecido view`): a pairs file (tritri), a cases file
/// (plane) or a queries file (ccd, JSON), read and checked by the query command's own reader (bad
/// input: io::InputError), written back canonically (the readers' *_to_json) with the labels a
/// suite's disagreement file adds (agreement/replay.h) kept where they have their types: "engine"
/// a string, "answer" and "referee" objects of a boolean "hit" and a number or null time ("t" for
/// plane, "toi" for ccd). Anything else in the file is not carried to the page.
#include "comparisons/io/json_reader.h"

#include <string>

namespace tecido::view {

/// {"kind": kind, "file": the file's name, "doc": the canonical document}; kind is "tritri",
/// "plane" or "ccd".
io::Json file_view_data(const std::string& kind, const std::string& path);

}  // namespace tecido::view
