#include "tools/billiard/bench_detect_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>

#include "bench/detection_benchmark.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/image_files.h"

namespace billiard::cli {

namespace {

struct BenchDetectArgs {
  std::string set, out;
  bool no_overlays = false;
};

void Run(const BenchDetectArgs& args) {
  RequireWritableDirectory(args.out, "--out");
  bench::DetectionBenchmarkOptions options;
  options.read_image = ReadImage;
  if (!args.no_overlays) options.overlay_dir = args.out + "/overlays";
  options.progress = [](const std::string& line) {
    std::cerr << "bench-detect: " << line << std::endl;
  };
  bench::DetectionBenchmarkResult result;
  try {
    result = bench::RunDetectionBenchmark(args.set, options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--set: ") + e.what());
  }
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
  cmd->add_option("--set", args->set, "Directory with labels.json and its images")->required();
  cmd->add_option("--out", args->out,
                  "Directory for detection_report.md, detection_results.json and overlays/")
      ->required();
  cmd->add_flag("--no-overlays", args->no_overlays, "Do not draw an overlay per frame");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
