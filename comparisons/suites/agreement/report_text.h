#pragma once
/// The pieces of an agreement suite's report that every such suite writes the same way: lists of
/// families where an engine's count is positive, the notes of families whose blocks failed, the
/// time per random case, and the paragraph on the disagreement file.
#include "comparisons/suites/agreement/table.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::agreement {

/// "- `name`: about\n" for each family (anything with a name and an about), in table order.
template <class FamilyT>
std::string family_list(const std::vector<FamilyT>& families) {
  std::string md;
  for (const FamilyT& f : families) md += "- `" + f.name + "`: " + f.about + "\n";
  return md;
}

/// How a suite samples its cases: counts, the seed, the sweep cases' size, and the words it uses.
struct Sample {
  long random = 0;      ///< cases of the random family
  long per_family = 0;  ///< cases of each adversarial family
  std::uint64_t seed = 0;
  long block = 0;       ///< cases per sweep case
  std::string unit;     ///< "pairs", "cases"
  std::string group;    ///< "family", "category"
};

/// "<random> random <unit> and <per_family> <unit> of each adversarial <group> (seed <seed>), in
/// sweep cases of at most <block> <unit> of one <group>".
std::string sample_sentence(const Sample& s);

/// The method's opening: "<random> <unit> ... of one <group>" (the sample), then `comparison` (what
/// each engine's answers are held against, ending with a lead-in to the list), then the families.
template <class FamilyT>
std::string method_opening(const Sample& s, const std::string& comparison, const std::vector<FamilyT>& families) {
  return sample_sentence(s) + comparison + family_list(families);
}

/// What one tally counts (a lambda without capture converts).
using Count = long (*)(const Tally& t);

/// "name (n of cases), ..." (`of_cases` false: "name (n)") over the families of `names` that did not
/// fail and where count(tally of engine e) is positive; "" when none.
std::string family_counts(const std::vector<std::string>& names, const AgreementTable& table, std::size_t e, Count count,
                          bool of_cases = true);

/// "\n<Word> `name` failed: <error>\n" for each family that failed (`word`: "Category", "Family").
std::string failed_notes(const std::vector<std::string>& names, const AgreementTable& table, const std::string& word);

/// Engine e's nanoseconds per random case, rounded ("" when none was timed).
std::string ns_text(const AgreementTable& table, std::size_t e);

/// "\n<kept> of the <found> disagreements with the referee are in `<file>` (ids `engine:<unit>/k`);
/// `<command> DIR/<file> --json`, DIR being this report's directory, reruns them with every engine.\n"
std::string disagreements_paragraph(std::size_t kept, long found, const std::string& file, const std::string& unit,
                                    const std::string& command);

}  // namespace tecido::suites::agreement
