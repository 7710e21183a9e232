// The report of a leave-one-source-out cross-validation (cross_validation.h): JSON, and
// cross_validation_report.md with cross_validation_results.json (every frame's scores too).
// Per source held out and pooled over the folds, overhead and oblique recall and precision and
// identity on the labelled classes, beside the same frames with the constants fitted on every
// source and with those set by hand; the constants each fold fitted; and the constants set from
// data that are fixed, not cross-validated.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "bench/cross_validation.h"

namespace billiard::bench {

// The detector's constants set from data that the protocol does not fit, by file: the figures
// do not cover them (docs/vision.md's table says what set each).
const std::vector<std::pair<std::string, std::string>>& FixedFromData();

// The figures and the fitted constants, without the frames' scores.
nlohmann::json CrossValidationJson(const CrossValidationResult& result);

// cross_validation_report.md and cross_validation_results.json into `dir`, created if missing.
void WriteCrossValidationReport(const CrossValidationResult& result, const std::string& dir);

}  // namespace billiard::bench
