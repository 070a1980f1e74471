#pragma once
/// The ids of the entries of a query file (pairs of `tecido tritri`, cases of `tecido plane`,
/// CCD queries): an entry's "id" is a string, any other JSON value in its compact text, or the
/// entry's index when absent. Results are keyed by id, so two entries with one id are an error
/// naming the second entry's pointer and the first's.
#include "comparisons/io/json_reader.h"

#include <string>
#include <unordered_map>

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

}  // namespace tecido::io
