#include "comparisons/io/entry_id.h"

namespace tecido::io {

std::string UniqueIds::read(const JsonReader& r, const Json& entry, const std::string& where, std::size_t index) {
  const auto it = entry.find("id");
  const bool given = it != entry.end();
  std::string id = !given ? std::to_string(index) : it->is_string() ? it->get<std::string>() : it->dump();
  const std::string at = given ? child(where, "id") : where;
  const auto [prev, inserted] = first_.emplace(id, at);
  if (!inserted) {
    const std::string how = given ? "" : " (an entry without \"id\" is known by its index)";
    r.fail(at, "duplicate id \"" + id + "\" (first at " + prev->second + ")" + how);
  }
  return id;
}

}  // namespace tecido::io
