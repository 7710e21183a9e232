// Issue 47's "the table's own uncertainty beside the robot's", measured: is the shot choice's
// probability of a bank or a kick calibrated on a table whose constants are known only within
// the parameter set's uncertainty (sim/params/constants_uncertainty.h)?
//
// Seeded layouts (a nine-ball layout and a seeded cue ball, as bench-game's), each chosen once
// per kind (direct, bank, kick: the choice's candidates of that kind alone, nine-ball rules, the
// robot's noise, no lookahead: the probability is what is judged) with the constants' draws on.
// The chosen shot is then executed `tables` times, execution e on its own table drawn from the
// uncertainty and with its own noise, both from seed streams apart from the choice's: the
// world the robot meets. Its reported probability is judged against those executions by decile
// (calibration.h); beside it, the same shot's probability with the constants taken as exact
// (confirm_samples executions on the set's own values): the overconfidence the draws remove.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/calibration.h"
#include "planner/pot/pot_planner.h"

namespace billiard::bench {

struct ConstantsCalibrationOptions {
  std::string params = "pool";  // a set with an uncertainty
  int layouts = 120;            // choices per kind
  int tables = 16;              // executions of each chosen shot, each on its own drawn table
  int samples = 32;             // the choice's full-model executions per finalist
  int confirm_samples = 256;    // its fresh executions of the chosen shot: the prediction
  std::uint64_t seed = 4700;
  int threads = 2;
  std::vector<pot::ShotKind> kinds = {pot::ShotKind::kDirect, pot::ShotKind::kBank,
                                      pot::ShotKind::kKick};
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

// One kind's choices: each chosen shot's probability with the constants drawn (`sampled`) and
// taken as exact (`exact`), against the same executions on drawn tables.
struct KindCalibration {
  pot::ShotKind kind = pot::ShotKind::kDirect;
  std::vector<CalibrationPoint> sampled, exact;
};

struct ConstantsCalibrationResult {
  ConstantsCalibrationOptions options;
  std::vector<KindCalibration> kinds;
};

// Throws std::invalid_argument when options.params names no set or a set without uncertainty.
ConstantsCalibrationResult RunConstantsCalibration(const ConstantsCalibrationOptions& options);

// Per kind and for banks and kicks together: executions, mean predictions (sampled, exact),
// the measured rate, the deciles of each prediction and whether the sampled one is calibrated.
nlohmann::json ConstantsCalibrationJson(const ConstantsCalibrationResult& result);

// Writes constants_report.md (how it was measured, the kinds, the deciles of banks and kicks with
// the constants drawn and taken as exact) and constants_results.json into `dir`.
void WriteConstantsReport(const ConstantsCalibrationResult& result, const std::string& dir);

}  // namespace billiard::bench
