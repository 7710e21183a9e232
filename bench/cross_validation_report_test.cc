// The cross-validation's report on a result made by hand: the pooled figures are the folds'
// summed, per view and over all; each fold's constants say which were kept; the constants not
// cross-validated are listed; the markdown and the results file are written.
#include "bench/cross_validation_report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace billiard::bench {
namespace {

FrameScore Score(const std::string& view, int labels, int found, int false_ones, int classed,
                 int right) {
  FrameScore s;
  s.file = view + ".png";
  s.view = view;
  s.labels = labels;
  s.found = found;
  s.false_detections = false_ones;
  s.classed = classed;
  s.classed_right = right;
  return s;
}

CrossValidationResult TwoFolds() {
  CrossValidationResult result;
  result.sets = {"dev", "dev2"};
  result.min_scores = {0.4, 0.5};
  result.fitted_on_all.min_score = 0.5;
  result.fitted_on_all.identity.parameters = estimator::HandSetIdentity();
  FoldResult a;
  a.fold.source = "a/one";
  a.fitted.min_score = 0.4;
  a.fitted.identity.parameters = estimator::HandSetIdentity();
  a.fitted.identity.cue_white = true;
  a.held_out = {Score("overhead", 10, 9, 1, 8, 6), Score("oblique", 4, 4, 0, 0, 0)};
  a.fitted_on_all = a.by_hand = a.held_out;
  FoldResult b;
  b.fold.source = "b/two";
  b.fitted = a.fitted;
  b.held_out = {Score("overhead", 6, 3, 3, 3, 3)};
  b.fitted_on_all = b.by_hand = {Score("overhead", 6, 6, 0, 6, 6)};
  result.folds = {a, b};
  return result;
}

TEST(CrossValidationReport, ThePooledFiguresAreTheFoldsSummed) {
  const nlohmann::json j = CrossValidationJson(TwoFolds());
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["sources"], 2);
  const auto& left_out = j["pooled"]["leave_one_source_out"];
  EXPECT_EQ(left_out["overhead"]["labels"], 16);
  EXPECT_EQ(left_out["overhead"]["found"], 12);
  EXPECT_DOUBLE_EQ(left_out["overhead"]["recall"].get<double>(), 12.0 / 16);
  EXPECT_DOUBLE_EQ(left_out["overhead"]["precision"].get<double>(), 12.0 / 16);
  EXPECT_DOUBLE_EQ(left_out["all"]["recall"].get<double>(), 16.0 / 20);
  EXPECT_DOUBLE_EQ(left_out["all"]["identity"].get<double>(), 9.0 / 11);
  EXPECT_DOUBLE_EQ(j["pooled"]["set_by_hand"]["overhead"]["recall"].get<double>(), 15.0 / 16);
  EXPECT_EQ(j["folds"][1]["held_out"], "b/two");
  EXPECT_EQ(j["folds"][1]["leave_one_source_out"]["all"]["found"], 3);
  EXPECT_EQ(j["folds"][0]["constants"]["min_score"], 0.4);
  EXPECT_EQ(j["folds"][0]["constants"]["cue_white_fitted"], true);
  EXPECT_EQ(j["folds"][0]["constants"]["stripe_plain_fitted"], false);
  EXPECT_EQ(j["fixed_from_data_not_cross_validated"].size(), FixedFromData().size());
}

// The list says where each constant is: every name is defined in the file given for it (the
// constants moved with a split, and the list went stale once).
TEST(CrossValidationReport, EveryConstantNotCrossValidatedIsInTheFileListedForIt) {
  for (const auto& [file, names] : FixedFromData()) {
    std::ifstream in(std::string(BILLIARD_SOURCE_DIR) + "/" + file);
    ASSERT_TRUE(in) << file;
    std::stringstream text;
    text << in.rdbuf();
    std::stringstream list(names);
    for (std::string name; std::getline(list >> std::ws, name, ',');) {
      const std::regex defined("constexpr[^;]*\\b" + name + "\\b(\\[\\w*\\])?\\s*=");
      EXPECT_TRUE(std::regex_search(text.str(), defined)) << name << " is not defined in " << file;
    }
  }
}

TEST(CrossValidationReport, WritesTheReportAndTheResults) {
  const std::string dir = ::testing::TempDir() + "/cross_validation_report";
  std::filesystem::remove_all(dir);
  WriteCrossValidationReport(TwoFolds(), dir);
  std::ifstream md(dir + "/cross_validation_report.md");
  std::stringstream text;
  text << md.rdbuf();
  const std::string report = text.str();
  EXPECT_NE(report.find("--cross-validate --set dev --set dev2"), std::string::npos);
  EXPECT_NE(report.find("| overhead | 2 | 16 | 75.0 % / 75.0 % | 9 / 11 |"), std::string::npos)
      << report;
  EXPECT_NE(report.find("| a/one | 0.40 | 0.600 | 0.200 (kept) |"), std::string::npos) << report;
  EXPECT_NE(report.find("kMaxForeignSurround"), std::string::npos);
  nlohmann::json results;
  std::ifstream(dir + "/cross_validation_results.json") >> results;
  EXPECT_EQ(results["folds"][0]["held_out_frames"].size(), 2u);
  EXPECT_FALSE(results["folds"][0]["colours"].empty());
}

}  // namespace
}  // namespace billiard::bench
