#pragma once
/// The ids of the entries of a query file (pairs of `tecido tritri`, cases of `tecido plane`,
/// CCD queries): an entry's "id" is a string, any other JSON value in its compact text, or the
/// entry's index when absent. Results are keyed by id, so two entries with one id are an error
/// naming the second entry's pointer and the first's.
#include "comparisons/io/json_reader.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace tecido::io {

/// Collects the ids of one list, rejecting the second use of any.
class UniqueIds {
 public:
  /// The id of `entry` (an object at `where`, index `index` of its list). Throws InputError at
  /// where/id (or where, for an id taken from the index) when an earlier entry has the same id.
  std::string read(const JsonReader& r, const Json& entry, const std::string& where, std::size_t index);

 private:
  std::unordered_map<std::string, std::string> first_;  ///< id -> pointer of its first entry
};

/// The shape every query file shares (`tritri` pairs, `plane` cases, CCD queries): the array
/// `doc[key]` of at most `limit` objects, each with a unique id (UniqueIds) and the fields that
/// `read(r, entry, where)` reads into an Entry (whose `id` this sets).
template <class Entry, class Read>
std::vector<Entry> read_entries(const Json& doc, const std::string& file, const char* key, std::size_t limit,
                                Read read) {
  JsonReader r(file);
  const std::string list = std::string("/") + key;
  const Json& items = r.require_array(r.require(doc, "", key), list);
  r.at_most(items.size(), list, limit, key);
  UniqueIds ids;
  std::vector<Entry> out;
  out.reserve(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::string w = child(list, k);
    const Json& e = r.require_object(items[k], w);
    std::string id = ids.read(r, e, w, k);
    Entry entry = read(r, e, w);
    entry.id = std::move(id);
    out.push_back(std::move(entry));
  }
  return out;
}

}  // namespace tecido::io
