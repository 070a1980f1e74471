// tecido view (--pairs FILE | --cases FILE | --queries FILE) --out DIR
// A query file in 3-D: DIR/view.html (with view.data.js and the viewer's files) draws its entries
// one at a time, as the suites' disagreement pages do (a pairs file's two triangles, a cases file's
// segment and bounded plane, a queries file's motion over t in [0, 1]); the labels of a suite's
// disagreement file (engine, answer, referee) are shown beside. The file is read by the query
// command's reader: bad input is one line and exit 2, with nothing written. A run's frames have
// their page already: `tecido run SCENE --out DIR` writes DIR/index.html.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/view/file_view.h"
#include "comparisons/view/view_page.h"

#include <iostream>
#include <memory>

namespace tecido::cli {

namespace {

struct ViewOptions {
  std::string pairs, cases, queries, out;
};

int view(const ViewOptions& o) {
  const int given = !o.pairs.empty() + !o.cases.empty() + !o.queries.empty();
  if (given != 1) throw io::UsageError("view: give one of --pairs, --cases, --queries");
  const auto [kind, path] = !o.pairs.empty()   ? std::pair<std::string, std::string>{"tritri", o.pairs}
                            : !o.cases.empty() ? std::pair<std::string, std::string>{"plane", o.cases}
                                               : std::pair<std::string, std::string>{"ccd", o.queries};
  const io::Json data = view::file_view_data(kind, path);  // reads and checks before anything is written
  io::check_output_dir(o.out);
  const io::OutputDirLock lock(o.out);
  const std::string page = view::write_view_page(o.out, "view", "tecido view " + path, data);
  std::cout << "page " << o.out << "/" << page << "\n";
  return 0;
}

Command add_view(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* sub = app.add_subcommand("view", "Draw a pairs, cases or queries file in 3-D (an HTML page)");
  sub->add_option("--pairs", o->pairs, "Pairs file, as `tecido tritri --pairs` reads")->check(non_empty());
  sub->add_option("--cases", o->cases, "Cases file, as `tecido plane --cases` reads")->check(non_empty());
  sub->add_option("--queries", o->queries, "Queries file (JSON), as `tecido ccd --queries` reads")->check(non_empty());
  sub->add_option("--out", o->out, "Directory for view.html, view.data.js and the viewer's files")
      ->required()
      ->check(non_empty());
  return [o]() { return view(*o); };
}

}  // namespace

TECIDO_REGISTER_COMMAND(view, add_view);

}  // namespace tecido::cli
