#include "tools/billiard/bench_detect_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>
#include <vector>

#include "bench/cross_validation.h"
#include "bench/cross_validation_report.h"
#include "bench/detection_benchmark.h"
#include "bench/detection_report.h"
#include "bench/detection_suite.h"
#include "bench/hard_suite_report.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/detect_options.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/image_files.h"

namespace billiard::cli {

namespace {

struct BenchDetectArgs {
  std::vector<std::string> sets;
  std::string out, corners, params = params::kDefaultParameterSet;
  std::string identity = "rules", identity_model, hard_case;
  bool synthetic = false, hard_suite = false, no_overlays = false, cross_validate = false;
  std::uint32_t seed = 2026;
};

void Progress(const std::string& line) { std::cerr << "bench-detect: " << line << std::endl; }

// The labelled sets of --set; UsageError naming the option when one is missing or malformed.
std::vector<bench::LabelledSet> LoadSets(const std::vector<std::string>& directories) {
  std::vector<bench::LabelledSet> sets;
  for (const std::string& directory : directories) {
    try {
      sets.push_back({directory, bench::LoadLabelledSet(directory)});
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--set: ") + e.what());
    }
  }
  return sets;
}

// --cross-validate: the constants fitted from data, left out one source at a time
// (bench/cross_validation.h).
void CrossValidate(const BenchDetectArgs& args) {
  if (args.sets.empty()) throw UsageError("--cross-validate needs --set DIR (one or more)");
  if (args.synthetic || !args.corners.empty()) {
    throw UsageError("--cross-validate takes labelled sets alone: no --synthetic, no --corners");
  }
  const std::vector<bench::LabelledSet> sets = LoadSets(args.sets);
  std::vector<bench::LabelledFrame> frames;
  for (const auto& set : sets) frames.insert(frames.end(), set.frames.begin(), set.frames.end());
  try {
    bench::LeaveOneSourceOut(frames);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--cross-validate: ") + e.what());
  }
  RequireWritableDirectory(args.out, "--out");
  bench::CrossValidationOptions options;
  options.read_image = ReadImage;
  options.progress = Progress;
  options.classifier = IdentityOption(args.identity, args.identity_model);
  const bench::CrossValidationResult result = bench::RunCrossValidation(sets, options);
  bench::WriteCrossValidationReport(result, args.out);
  Progress("wrote " + args.out + "/cross_validation_report.md (" + std::to_string(result.wall_s) +
           " s)");
  std::cout << bench::CrossValidationJson(result).dump() << std::endl;
}

// --hard-suite: the rendered hard cases with their truth (bench/hard_suite.h).
void HardSuite(const BenchDetectArgs& args) {
  if (!args.sets.empty() || args.synthetic || !args.corners.empty()) {
    throw UsageError("--hard-suite renders its own frames: no --set, --synthetic or --corners");
  }
  RequireWritableDirectory(args.out, "--out");
  const std::string set = args.out + "/hard";
  Progress("rendering the hard suite into " + set);
  const std::vector<bench::HardFrame> frames =
      bench::RenderHardSuite(LoadParametersOption(args.params), args.seed, args.hard_case);
  if (frames.empty()) throw UsageError("--case " + args.hard_case + ": no case of the hard suite");
  std::vector<bench::LabelledFrame> labelled;
  for (const auto& f : frames) labelled.push_back(f.frame);
  bench::WriteLabelledSet(labelled, set);
  bench::DetectionBenchmarkOptions options;
  options.read_image = ReadImage;
  if (!args.no_overlays) options.overlay_dir = args.out + "/overlays";
  options.progress = Progress;
  const bench::HardSuiteResult result = bench::RunHardSuite(frames, options);
  bench::WriteHardSuiteReport(result, args.out);
  Progress("wrote " + args.out + "/hard_suite_report.md");
  std::cout << bench::HardSuiteJson(result).dump() << std::endl;
}

void Run(const BenchDetectArgs& args) {
  if (args.cross_validate) return CrossValidate(args);
  if (args.hard_suite) return HardSuite(args);
  if (!args.hard_case.empty()) throw UsageError("--case picks cases of --hard-suite only");
  if (args.sets.size() > 1) throw UsageError("give one --set DIR (several with --cross-validate)");
  if (args.sets.empty() == !args.synthetic) {
    throw UsageError("give one of --set DIR (a labelled set) and --synthetic (the rendered suite)");
  }
  RequireWritableDirectory(args.out, "--out");
  std::vector<bench::LabelledFrame> frames;
  const std::string set = args.synthetic ? args.out + "/synthetic" : args.sets.front();
  if (args.synthetic) {
    std::cerr << "bench-detect: rendering the synthetic suite into " << set << std::endl;
    frames = bench::RenderDetectionSuite(LoadParametersOption(args.params), args.seed);
    bench::WriteLabelledSet(frames, set);
  } else {
    frames = LoadSets(args.sets).front().frames;
    if (!args.corners.empty()) {
      try {
        bench::LoadTableCorners(args.corners, &frames);
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--corners: ") + e.what());
      }
    }
  }
  bench::DetectionBenchmarkOptions options;
  options.read_image = ReadImage;
  options.classifier = IdentityOption(args.identity, args.identity_model);
  if (!args.no_overlays) options.overlay_dir = args.out + "/overlays";
  options.progress = Progress;
  const bench::DetectionBenchmarkResult result = bench::RunDetectionBenchmark(set, frames, options);
  bench::WriteDetectionReport(result, args.out);
  std::cerr << "bench-detect: wrote " << args.out << "/detection_report.md (" << result.wall_s
            << " s)" << std::endl;
  std::cout << bench::DetectionSummaryJson(result).dump() << std::endl;
}

}  // namespace

void AddBenchDetectCommand(CLI::App& app) {
  auto args = std::make_shared<BenchDetectArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench-detect",
      "Run the detector on a labelled set of frames (DIR/labels.json): recall, precision and "
      "centre error per frame and per view");
  cmd->add_option("--set", args->sets,
                  "Directory with labels.json and its images (repeatable with --cross-validate)");
  cmd->add_flag("--cross-validate", args->cross_validate,
                "Fit the constants set from data on all sources but one and score the one left "
                "out, for each source: OUT/cross_validation_report.md, JSON on stdout");
  cmd->add_flag("--synthetic", args->synthetic,
                "Render the synthetic suite (overhead and oblique cameras, racks, five cloths) "
                "into OUT/synthetic and run on it instead");
  cmd->add_flag("--hard-suite", args->hard_suite,
                "Render the hard suite (an arm, a player, a third out of frame, barrel lens "
                "k1 = -0.3, elevations 15-45 degrees) into OUT/hard and score each side of the "
                "table against its truth: OUT/hard_suite_report.md");
  cmd->add_option("--case", args->hard_case,
                  "With --hard-suite, only the cases whose name begins with this (\"lens\", "
                  "\"arm\", \"elevation 30\", ...)");
  cmd->add_option("--corners", args->corners,
                  "The playing surface's corners of the set's frames (JSON, as "
                  "estimator/testing/real_table_corners.json): whether each table was found");
  cmd->add_option("--params", args->params, "The balls and table of --synthetic and --hard-suite")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of --synthetic and --hard-suite")->capture_default_str();
  cmd->add_option("--out", args->out,
                  "Directory for detection_report.md, detection_results.json and overlays/")
      ->required();
  cmd->add_flag("--no-overlays", args->no_overlays, "Do not draw an overlay per frame");
  AddIdentityOptions(cmd, &args->identity, &args->identity_model);
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
