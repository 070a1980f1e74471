#include "comparisons/view/view_page.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/view/content_policy.h"
#include "comparisons/view/html_text.h"
#include "comparisons/view/viewer_assets.h"

namespace tecido::view {

std::string view_page_html(const std::string& name, const std::string& title) {
  return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n" + content_policy_meta(true) +
         "\n<title>" + html_text(title) +
         "</title>\n<link rel=\"stylesheet\" href=\"tecido.css\">\n</head>\n<body>\n<div class=\"view\">\n"
         "<div id=\"stage\"><p id=\"no-viewer\">The 3-D view needs tecido-viewer.js beside this page (built by the "
         "tecido-viewer target, docs/viewer.md).</p></div>\n<div id=\"panel\"><h1>" +
         html_text(title) + "</h1></div>\n</div>\n<script src=\"" + html_text(name) +
         ".data.js\"></script>\n<script src=\"tecido-viewer.js\"></script>\n</body>\n</html>\n";
}

std::string write_view_page(const std::string& dir, const std::string& name, const std::string& title,
                            const io::Json& data) {
  copy_viewer_assets(dir);
  const std::string js =
      "window.TECIDO_VIEW = " + data.dump(-1, ' ', true, io::Json::error_handler_t::replace) + ";\n";
  io::write_file_atomic(dir + "/" + name + ".data.js", js);
  io::write_file_atomic(dir + "/" + name + ".html", view_page_html(name, title));
  return name + ".html";
}

}  // namespace tecido::view
