// The selfcollision suite's disagreement file (comparisons/suites/selfcollision/frame_disagreements.*)
// on hand-made frames: what is kept within the caps, the case result's round trip, the file's
// document and the page's compact form, and the page written for a hand-made disagreement.
#include "comparisons/suites/selfcollision/frame_disagreements.h"

#include "comparisons/suites/agreement/disagreement_page.h"
#include "comparisons/suites/selfcollision/frame_sources.h"
#include "comparisons/view/base64.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

namespace tecido::suites::selfcollision {
namespace {

using Pairs = std::vector<std::array<int, 2>>;

/// Two frames of a 4-triangle mesh (the positions are only carried, never tested for contact).
FrameSet hand_frames() {
  FrameSet set;
  set.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
  for (int f = 0; f < 2; ++f) {
    Frame fr;
    fr.time = 0.5 * (f + 1);
    for (int v = 0; v < 12; ++v) fr.x.push_back(Vec3(v + 0.1 * f, 1.0 / 3.0, -v - 0.25));
    set.frames.push_back(fr);
  }
  return set;
}

TEST(FrameDisagreements, KeptWithinTheCapsWithTheirFramesOnce) {
  Settings s;
  s.max_entries_per_source = 2;
  s.max_pairs_per_list = 1;
  const FrameSet set = hand_frames();
  KeptDisagreements k;
  k.note(s, "good", set, 0, {{0, 2}}, {{0, 2}});                // agrees: not a disagreement
  k.note(s, "liar", set, 0, {{0, 3}, {1, 2}}, {{0, 2}});        // misses (0,2), invents (0,3) and (1,2)
  k.note(s, "blind", set, 0, {}, {{0, 2}, {1, 3}});             // misses both
  k.note(s, "blind", set, 1, {}, {{2, 3}});                     // over the cap: counted, not kept
  EXPECT_EQ(k.found, 3);
  ASSERT_EQ(k.kept.size(), 2u);
  EXPECT_EQ(k.kept[0].engine, "liar");
  EXPECT_EQ(k.kept[0].pairs.missed, (Pairs{{0, 2}}));
  EXPECT_EQ(k.kept[0].pairs.extra, (Pairs{{0, 3}}));  // the first of 2
  EXPECT_EQ(k.kept[0].missed, 1);
  EXPECT_EQ(k.kept[0].extra, 2);
  EXPECT_EQ(k.kept[1].pairs.missed, (Pairs{{0, 2}}));
  EXPECT_EQ(k.kept[1].missed, 2);
  ASSERT_EQ(k.frames.size(), 1u);  // both kept entries are of frame 0
  EXPECT_EQ(k.frames[0].first, 0);
  EXPECT_EQ(k.frames[0].second.x, set.frames[0].x);
  EXPECT_EQ(k.triangles, set.triangles);

  const KeptDisagreements back = kept_from_json(io::Json::parse(kept_json(k).dump()));
  EXPECT_EQ(kept_json(back), kept_json(k));
  EXPECT_EQ(back.frames[0].second.x, set.frames[0].x);  // doubles round-trip exactly

  const FrameSource src{"hand", "hand-made", nullptr};
  const io::Json doc = disagreements_json({src}, {k}, "exact", s);
  ASSERT_EQ(doc["entries"].size(), 2u);
  EXPECT_EQ(doc["entries"][0]["id"], "liar:hand/0");
  EXPECT_EQ(doc["entries"][1]["extra"], io::Json::array());
  EXPECT_EQ(doc["sources"][0]["entries_found"], 3);
  EXPECT_EQ(doc["sources"][0]["frames"][0]["time"], 0.5);
  EXPECT_EQ(doc["max_pairs_per_list"], 1);

  const io::Json page = disagreements_page_doc(doc);
  std::vector<float> x;
  for (const Vec3& p : set.frames[0].x)
    for (int c = 0; c < 3; ++c) x.push_back(static_cast<float>(p[c]));
  EXPECT_EQ(page["sources"][0]["frames"][0]["x"], view::float32_base64(x));
  EXPECT_EQ(page["sources"][0]["triangles"], view::uint32_base64({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(page["entries"], doc["entries"]);
}

TEST(FrameDisagreements, PageOfAHandMadeDisagreementLinksItsEntries) {
  Settings s;
  const FrameSet set = hand_frames();
  KeptDisagreements k;
  k.note(s, "liar", set, 1, {{0, 3}}, {{1, 2}});
  const io::Json doc = disagreements_json({FrameSource{"<b>hand</b>", "", nullptr}}, {k}, "exact", s);
  const auto dir = testing::temp_dir("selfcollision-page");
  const io::Json page = disagreements_page_doc(doc);
  const auto links = agreement::write_disagreement_page(dir.string(), "selfcollision/disagreements.json",
                                                        "selfcollision", "entries", doc, &page);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_EQ(links[0].href, "selfcollision/disagreements.html");
  EXPECT_EQ(links[1].href, "selfcollision/disagreements.html#0");
  EXPECT_EQ(links[1].text, "liar:<b>hand</b>/1 (liar)");  // report.html escapes it where it lands
  const std::string js = testing::slurp(dir / "selfcollision" / "disagreements.data.js");
  EXPECT_EQ(js.rfind("window.TECIDO_VIEW = ", 0), 0u);
  const io::Json data = io::Json::parse(js.substr(21, js.size() - 21 - 2));
  EXPECT_EQ(data["kind"], "selfcollision");
  EXPECT_EQ(data["doc"], page);
  EXPECT_NE(testing::slurp(dir / "selfcollision" / "disagreements.html").find("disagreements.data.js"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites::selfcollision
