#include "bench/cross_validation_report.h"

#include <filesystem>
#include <fstream>
#include <map>

#include "bench/detection_report.h"
#include "bench/format.h"

namespace billiard::bench {

namespace {

// The three sets of constants each held-out frame is scored with, in the report's order.
struct Protocol {
  const char* key;    // in the JSON
  const char* title;  // in the report
  std::vector<FrameScore> FoldResult::*scores;
};
const Protocol kProtocols[] = {
    {"leave_one_source_out", "left out", &FoldResult::held_out},
    {"fitted_on_all_sources", "fitted on all", &FoldResult::fitted_on_all},
    {"set_by_hand", "set by hand", &FoldResult::by_hand}};

const char* const kViews[] = {"overhead", "oblique", "all"};

nlohmann::json ViewsJson(const std::vector<FrameScore>& frames) {
  nlohmann::json views = nlohmann::json::object();
  for (const auto& [view, group] : ByView(frames)) views[view] = FiguresJson(Total(group));
  return views;
}

nlohmann::json ConstantsJson(const FittedConstants& c) {
  const estimator::IdentityFit& fit = c.identity;
  const estimator::IdentityParameters& p = fit.parameters;
  return {{"min_score", c.min_score},
          {"cue_white", p.cue_white},
          {"cue_white_fitted", fit.cue_white},
          {"cue_colour", p.cue_colour},
          {"cue_colour_fitted", fit.cue_colour},
          {"black_share", p.black_share},
          {"black_share_fitted", fit.black_share},
          {"stripe_plain", p.stripe_plain},
          {"stripe_plain_fitted", fit.stripe_plain},
          {"colour_classes_fitted", fit.classes_fitted},
          {"colour_classes_kept", fit.classes_kept}};
}

nlohmann::json ColoursJson(const estimator::IdentityParameters& p) {
  static const std::map<estimator::BallSet, const char*> kTables = {
      {estimator::BallSet::kPool, "pool"},
      {estimator::BallSet::kSnooker, "snooker"},
      {estimator::BallSet::kCarom, "carom"}};
  nlohmann::json colours = nlohmann::json::array();
  for (const estimator::ColourPrototype& c : p.colours) {
    colours.push_back({{"table", kTables.at(c.table)},
                       {"class", estimator::BallClassName(c.ball_class)},
                       {"lab", {c.lab[0], c.lab[1], c.lab[2]}}});
  }
  return colours;
}

// Every fold's held-out frames scored with `protocol`'s constants.
std::vector<FrameScore> Pooled(const CrossValidationResult& result, const Protocol& protocol) {
  std::vector<FrameScore> frames;
  for (const FoldResult& fold : result.folds) {
    const auto& scores = fold.*protocol.scores;
    frames.insert(frames.end(), scores.begin(), scores.end());
  }
  return frames;
}

int FrameCount(const CrossValidationResult& result) {
  int frames = 0;
  for (const FoldResult& fold : result.folds) frames += static_cast<int>(fold.held_out.size());
  return frames;
}

std::string Percent(double share) { return Fixed(100 * share, 1) + " %"; }

std::string Identity(const Totals& t) {
  return t.classed ? std::to_string(t.classed_right) + " / " + std::to_string(t.classed) : "-";
}

// "recall / precision | identity" of a group, or dashes for none.
std::string Cells(const std::vector<const FrameScore*>& group) {
  if (group.empty()) return "- | -";
  const Totals t = Total(group);
  return Percent(t.recall) + " / " + Percent(t.precision) + " | " + Identity(t);
}

std::string Threshold(double value, bool fitted) {
  return Fixed(value, 3) + (fitted ? "" : " (kept)");
}

void WriteProtocol(const CrossValidationResult& result, std::ostream& md) {
  std::string sets;
  for (const std::string& set : result.sets) sets += " --set " + set;
  md << "# The detector's fitted constants, left out one source at a time\n\n"
     << "`billiard bench-detect --cross-validate" << sets << "`: " << FrameCount(result)
     << " frames from " << result.folds.size()
     << " sources (a source is the repository a frame came from). Each source's frames are held "
        "out in turn; the constants fitted from data are fitted by code on the other sources' "
        "labelled frames and the detector with them is scored on the frames held out "
        "(\"left out\": the headline figures). Beside them, the same frames with the constants "
        "fitted on every source, their own among them (\"fitted on all\"), and with the "
        "constants set by hand (\"set by hand\", `bench-detect`'s own figures).\n\n"
     << "Fitted: `min_score`, the score a detection is reported from, the one of";
  for (const double s : result.min_scores) md << " " << Fixed(s, 2);
  md << " whose detections on the training frames have the highest F1 of recall and precision "
        "(the middle of those that tie; the detector runs at each on every frame); the identity's "
        "share thresholds `cue_white`, `cue_colour`, `black_share`, `stripe_plain` (decision "
        "stumps of maximum margin over the training frames' detections that match a labelled "
        "class, at the fitted `min_score`; \"(kept)\" where a side had fewer than "
     << estimator::kMinBallsPerSide
     << " balls and the hand-set value stayed) and each class's colours (one per training "
        "source that shows the class: its balls' median colour; a class no training ball shows "
        "keeps the hand-set colours). `estimator/identity_fit.h` says how. A detection matches a "
        "label within max(8 px, 0.6 R); identity counts the matched balls whose class is "
        "labelled.\n\n";
}

void WritePooled(const CrossValidationResult& result, std::ostream& md) {
  md << "## Pooled over the folds\n\n| view | frames | labels |";
  for (const Protocol& p : kProtocols) md << " " << p.title << ": recall / precision | identity |";
  md << "\n|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::map<std::string, std::vector<const FrameScore*>>> groups;
  std::vector<std::vector<FrameScore>> pooled;
  for (const Protocol& p : kProtocols) pooled.push_back(Pooled(result, p));
  for (const auto& frames : pooled) groups.push_back(ByView(frames));
  for (const char* view : kViews) {
    const Totals t = Total(groups[0][view]);
    md << "| " << view << " | " << t.frames << " | " << t.labels << " |";
    for (auto& g : groups) md << " " << Cells(g[view]) << " |";
    md << "\n";
  }
}

void WritePerSource(const CrossValidationResult& result, std::ostream& md) {
  md << "\n## Per source held out\n\n| source | frames | labels |";
  for (const Protocol& p : kProtocols) md << " " << p.title << ": recall / precision | identity |";
  md << "\n|---|---|---|---|---|---|---|---|---|\n";
  for (const FoldResult& fold : result.folds) {
    const Totals t = Total(ByView(fold.held_out)["all"]);
    md << "| " << fold.fold.source << " | " << t.frames << " | " << t.labels << " |";
    for (const Protocol& p : kProtocols) md << " " << Cells(ByView(fold.*p.scores)["all"]) << " |";
    md << "\n";
  }
}

void WriteConstantsRow(const std::string& name, const FittedConstants& c, std::ostream& md) {
  const auto& fit = c.identity;
  const auto& p = fit.parameters;
  md << "| " << name << " | " << Fixed(c.min_score, 2) << " | "
     << Threshold(p.cue_white, fit.cue_white) << " | " << Threshold(p.cue_colour, fit.cue_colour)
     << " | " << Threshold(p.black_share, fit.black_share) << " | "
     << Threshold(p.stripe_plain, fit.stripe_plain) << " | " << fit.classes_fitted << " / "
     << fit.classes_kept << " |\n";
}

void WriteConstants(const CrossValidationResult& result, std::ostream& md) {
  md << "\n## The constants fitted\n\n| fitted without | min_score | cue_white | cue_colour | "
        "black_share | stripe_plain | colour classes fitted / kept |\n"
        "|---|---|---|---|---|---|---|\n";
  for (const FoldResult& fold : result.folds) WriteConstantsRow(fold.fold.source, fold.fitted, md);
  WriteConstantsRow("(none: every source)", result.fitted_on_all, md);
  const estimator::IdentityParameters& hand = estimator::HandSetIdentity();
  md << "| (set by hand) | " << Fixed(estimator::DetectorOptions().min_score, 2) << " | "
     << Fixed(hand.cue_white, 3) << " | " << Fixed(hand.cue_colour, 3) << " | "
     << Fixed(hand.black_share, 3) << " | " << Fixed(hand.stripe_plain, 3) << " | 0 / all |\n";
  md << "\n## Fixed, set from data: not cross-validated\n\nThese constants were set by looking "
        "at frames (docs/vision.md's table says which) and every fold keeps them: the figures "
        "above do not measure how they transfer.\n\n";
  for (const auto& [file, names] : FixedFromData()) md << "- `" << file << "`: " << names << "\n";
}

void WriteFrames(const CrossValidationResult& result, std::ostream& md) {
  md << "\n## Per frame\n\n| frame | source | view | labels | left out: found / false | "
        "identity | set by hand: found / false | identity | note |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  for (const FoldResult& fold : result.folds) {
    for (std::size_t i = 0; i < fold.held_out.size(); ++i) {
      const FrameScore& f = fold.held_out[i];
      const FrameScore& h = fold.by_hand[i];
      const auto identity = [](const FrameScore& s) {
        return s.classed ? std::to_string(s.classed_right) + " / " + std::to_string(s.classed)
                         : std::string("-");
      };
      md << "| " << f.file << " | " << fold.fold.source << " | " << f.view << " | " << f.labels
         << " | " << f.found << " / " << f.false_detections << " | " << identity(f) << " | "
         << h.found << " / " << h.false_detections << " | " << identity(h) << " | " << f.failure
         << " |\n";
    }
  }
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& FixedFromData() {
  static const std::vector<std::pair<std::string, std::string>> kFixed = {
      {"estimator/table_cloth.cc",
       "kChromaSpreads, kMinChromaTolerance, kMinBrightness, kMaxBrightness, "
       "kMaxRelativeGradient"},
      {"estimator/table_finder.cc",
       "kMinClothFraction, kOtherStretchNose, kFocalAgreement, kOverheadAspectTolerance, "
       "kMaxClothLightness, kMinClothChroma"},
      {"estimator/outline_stretches.cc",
       "kSideBand, kSideEnd, kMaxStretches, kMinStretch, kMaxStretchTurn"},
      {"estimator/table_edges.cc",
       "kEdgeFrom, kEdgeMiddle, kMinEdge, kEdgeNoises, kMinPlaces, kNoseOfBest, kFaintEdges, "
       "kMinFaintEdge, kFaintRidge, kFaintClearancePx, kFaintMaxTilt"},
      {"estimator/cloth_model.cc", "kEdgeNoises, kMinEdge"},
      {"estimator/ball_scale.cc", "kMaxBlobAspect, kMinBlobFill, kMinScaleSupport"},
      {"estimator/ball_detector.cc",
       "kMinVoteSupport, kSettlingScore, kSettledScaleChange, kLargerScales, kSureGain, "
       "kOverlapRadii, kNoisyEdges, kNoiseSmoothingPx"},
      {"estimator/ball_placement.cc",
       "kPocketRadii, kOffSurfaceRadii, kOffClothRadii, kMaxForeignSurround, kMinSurroundSeen"},
      {"estimator/ball_score.h", "kSureScore"},
      {"estimator/ball_outline.cc",
       "kEdgeOfRayMax, kCandidateReach, kMaxShiftRadii, kMaxRadiusChange, kSupportPx, "
       "kSupportRadii"},
      {"estimator/ball_score.cc",
       "kOutlineFrom, kOutlineWidth, kSizeTolerance, kVotesFrom, kVotesWidth, kNotClothFrom, "
       "kNotClothWidth, kShineFrom, kShineWidth, kShinePercentile, kSphereRimToCore, "
       "kSphereWidth"},
      {"estimator/circle_votes.cc", "kMinEdgeNoises, kFullEdgeNoises, kMinFullEdge"},
      {"estimator/local_cloth.h",
       "kDarkStart, kDarkRamp, kBrightStart, kBrightRamp, kAcrossNoise, kMinAcross"},
      {"estimator/not_cloth.h",
       "kIntruderBallAreas, kIntruderOpeningRadii, kIntruderFaintContrast"},
      {"estimator/ball_scale.h", "kScaleAgreement"},
      {"estimator/ball_pixels.h", "kGreyChroma, kWhiteLightness, kBlackLightness, kPlainSaturation"},
      {"estimator/ball_identity.cc",
       "kLimbRadii, kBrightBalls, kMaxCueChroma, kChromaWeight, kLightnessWeight, kShareMargin, "
       "kColourUnit, kNoColourCost, kUnknownCost, kCostFloor, kBandRadii, kClothRing, kBandShare"}};
  return kFixed;
}

nlohmann::json CrossValidationJson(const CrossValidationResult& result) {
  nlohmann::json pooled = nlohmann::json::object();
  for (const Protocol& p : kProtocols) pooled[p.key] = ViewsJson(Pooled(result, p));
  nlohmann::json folds = nlohmann::json::array();
  for (const FoldResult& fold : result.folds) {
    nlohmann::json f = {{"held_out", fold.fold.source},
                        {"frames", fold.held_out.size()},
                        {"constants", ConstantsJson(fold.fitted)}};
    for (const Protocol& p : kProtocols) f[p.key] = ViewsJson(fold.*p.scores);
    folds.push_back(f);
  }
  nlohmann::json fixed = nlohmann::json::object();
  for (const auto& [file, names] : FixedFromData()) fixed[file] = names;
  return {{"sets", result.sets},
          {"frames", FrameCount(result)},
          {"sources", result.folds.size()},
          {"min_scores_tried", result.min_scores},
          {"fitted",
           {"min_score", "colours", "cue_white", "cue_colour", "black_share", "stripe_plain"}},
          {"pooled", pooled},
          {"constants_fitted_on_all_sources", ConstantsJson(result.fitted_on_all)},
          {"folds", folds},
          {"fixed_from_data_not_cross_validated", fixed},
          {"wall_s", result.wall_s}};
}

void WriteCrossValidationReport(const CrossValidationResult& result, const std::string& dir) {
  std::filesystem::create_directories(dir);
  nlohmann::json all = CrossValidationJson(result);
  all["colours_fitted_on_all_sources"] = ColoursJson(result.fitted_on_all.identity.parameters);
  for (std::size_t i = 0; i < result.folds.size(); ++i) {
    const FoldResult& fold = result.folds[i];
    all["folds"][i]["colours"] = ColoursJson(fold.fitted.identity.parameters);
    nlohmann::json frames = nlohmann::json::array();
    for (const FrameScore& f : fold.held_out) {
      frames.push_back({{"file", f.file},
                        {"view", f.view},
                        {"labels", f.labels},
                        {"found", f.found},
                        {"false", f.false_detections},
                        {"classed", f.classed},
                        {"classed_right", f.classed_right},
                        {"failure", f.failure}});
    }
    all["folds"][i]["held_out_frames"] = frames;
  }
  OpenForWriting(dir + "/cross_validation_results.json") << all.dump(1) << "\n";
  std::ofstream md = OpenForWriting(dir + "/cross_validation_report.md");
  WriteProtocol(result, md);
  WritePooled(result, md);
  WritePerSource(result, md);
  WriteConstants(result, md);
  WriteFrames(result, md);
  if (!md) throw std::runtime_error("writing the cross-validation report failed");
}

}  // namespace billiard::bench
