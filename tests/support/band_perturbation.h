#pragma once
// A suite run twice, once with data/tolerances.json and once with one band made impossible: the
// set of checks must not change (bands decide pass or fail, never what runs), every check whose
// band came from the perturbed entry must fail, and every other check must keep its verdict.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/tolerances.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace tecido::testing {

/// `pointer` is a JSON pointer into the tolerance file ("/ccd/core_random_max_toi_error"); it is
/// set to `impossible` (a value no measurement can meet for that band).
inline void expect_band_decides_only_pass_or_fail(
    const std::function<suites::SuiteResult(const suites::SuiteContext&)>& run, const std::string& pointer,
    double impossible) {
  const auto file = suites::Tolerances::load(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json");
  io::Json doc = file.doc();
  ASSERT_TRUE(doc.contains(io::Json::json_pointer(pointer))) << pointer;
  doc[io::Json::json_pointer(pointer)] = impossible;
  const suites::Tolerances perturbed(doc, "perturbed.json");
  suites::SuiteContext ctx;
  ctx.quick = true;
  ctx.seed = 7;
  ctx.threads = 2;
  ctx.tolerances = &file;
  ctx.out_dir = temp_dir("bands-base").string();
  const suites::SuiteResult base = run(ctx);
  ctx.tolerances = &perturbed;
  ctx.out_dir = temp_dir("bands-perturbed").string();
  const suites::SuiteResult moved = run(ctx);
  ASSERT_EQ(base.checks.size(), moved.checks.size());
  int hit = 0;
  for (std::size_t k = 0; k < base.checks.size(); ++k) {
    const auto& a = base.checks[k];
    const auto& b = moved.checks[k];
    ASSERT_EQ(a.name, b.name);
    if (a.tolerance == pointer) {
      ++hit;
      EXPECT_FALSE(b.pass) << b.name << " passed with " << pointer << " = " << impossible;
    } else {
      EXPECT_EQ(a.pass, b.pass) << b.name << " changed its verdict though its band did not change";
    }
  }
  EXPECT_GE(hit, 1) << "no check takes its band from " << pointer;
}

}  // namespace tecido::testing
