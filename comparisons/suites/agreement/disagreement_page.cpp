#include "comparisons/suites/agreement/disagreement_page.h"

#include "comparisons/view/view_page.h"

#include <filesystem>

namespace tecido::suites::agreement {

std::vector<PageLink> write_disagreement_page(const std::string& out_dir, const std::string& file, const char* kind,
                                              const char* list, const io::Json& doc, const io::Json* page_doc) {
  const std::filesystem::path rel(file);
  const std::string folder = rel.parent_path().string();
  const std::string page = view::write_view_page(
      out_dir + "/" + folder, rel.stem().string(), std::string(kind) + " disagreements",
      {{"kind", kind}, {"file", rel.filename().string()}, {"doc", page_doc ? *page_doc : doc}});
  const std::string href = folder + "/" + page;
  const io::Json& entries = doc.at(list);
  std::vector<PageLink> links{
      {std::string(kind) + ": " + std::to_string(entries.size()) + " disagreements with the referee, in 3-D", href}};
  for (std::size_t k = 0; k < entries.size() && k < kLinkedEntries; ++k) {
    const io::Json& e = entries[k];
    links.push_back({e.value("id", std::string("?")) + " (" + e.value("engine", std::string("?")) + ")",
                     href + "#" + std::to_string(k)});
  }
  return links;
}

}  // namespace tecido::suites::agreement
