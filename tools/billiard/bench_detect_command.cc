#include "tools/billiard/bench_detect_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>
#include <vector>

#include "bench/detection_benchmark.h"
#include "bench/detection_suite.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/image_files.h"

namespace billiard::cli {

namespace {

struct BenchDetectArgs {
  std::string set, out, corners, params = params::kDefaultParameterSet;
  bool synthetic = false, no_overlays = false;
  std::uint32_t seed = 2026;
};

void Run(const BenchDetectArgs& args) {
  if (args.set.empty() == !args.synthetic) {
    throw UsageError("give one of --set DIR (a labelled set) and --synthetic (the rendered suite)");
  }
  RequireWritableDirectory(args.out, "--out");
  std::vector<bench::LabelledFrame> frames;
  std::string set = args.set;
  if (args.synthetic) {
    set = args.out + "/synthetic";
    std::cerr << "bench-detect: rendering the synthetic suite into " << set << std::endl;
    frames = bench::RenderDetectionSuite(LoadParametersOption(args.params), args.seed);
    bench::WriteLabelledSet(frames, set);
  } else {
    try {
      frames = bench::LoadLabelledSet(args.set);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--set: ") + e.what());
    }
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
  if (!args.no_overlays) options.overlay_dir = args.out + "/overlays";
  options.progress = [](const std::string& line) {
    std::cerr << "bench-detect: " << line << std::endl;
  };
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
  cmd->add_option("--set", args->set, "Directory with labels.json and its images");
  cmd->add_flag("--synthetic", args->synthetic,
                "Render the synthetic suite (overhead and oblique cameras, racks, five cloths) "
                "into OUT/synthetic and run on it instead");
  cmd->add_option("--corners", args->corners,
                  "The playing surface's corners of the set's frames (JSON, as "
                  "estimator/testing/real_table_corners.json): whether each table was found");
  cmd->add_option("--params", args->params, "The balls and table of --synthetic")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of --synthetic")->capture_default_str();
  cmd->add_option("--out", args->out,
                  "Directory for detection_report.md, detection_results.json and overlays/")
      ->required();
  cmd->add_flag("--no-overlays", args->no_overlays, "Do not draw an overlay per frame");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
