#include "tools/billiard/bench_estimator_command.h"

#include <iostream>
#include <memory>

#include "bench/estimator_benchmark.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct BenchEstimatorArgs {
  std::string out;
  std::string params = params::kDefaultParameterSet;
  bench::EstimatorBenchmarkOptions options;
};

void Run(const BenchEstimatorArgs& args) {
  if (args.options.scenes < 1) throw UsageError("--scenes must be >= 1");
  if (args.options.balls < 1 || args.options.balls > 16) throw UsageError("--balls must be 1-16");
  if (args.options.struck < 0 || args.options.struck > args.options.balls) {
    throw UsageError("--struck must be between 0 and --balls");
  }
  const physics::ModelParameters params = LoadParametersOption(args.params);
  RequireWritableDirectory(args.out, "--out");
  bench::EstimatorBenchmarkOptions options = args.options;
  options.progress = [](const std::string& line) {
    std::cerr << "bench-estimator: " << line << std::endl;
  };
  const bench::EstimatorBenchmarkResult result = bench::RunEstimatorBenchmark(params, options);
  bench::WriteEstimatorReport(result, args.out);
  std::cerr << "bench-estimator: wrote " << args.out << "/estimator_report.md (" << result.wall_s
            << " s)" << std::endl;
  std::cout << bench::EstimatorSummaryJson(result).dump() << std::endl;
}

}  // namespace

void AddBenchEstimatorCommand(CLI::App& app) {
  auto args = std::make_shared<BenchEstimatorArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench-estimator",
      "Render seeded shots at 1280x720, 120 Hz, estimate them, compare with the truth");
  cmd->add_option("--out", args->out, "Directory for estimator_report.md")->required();
  cmd->add_option("--scenes", args->options.scenes, "Number of scenes")->capture_default_str();
  cmd->add_option("--balls", args->options.balls, "Balls per scene (1-16)")->capture_default_str();
  cmd->add_option("--struck", args->options.struck, "Balls struck per scene")
      ->capture_default_str();
  cmd->add_option("--seed", args->options.seed, "Seed of the scenes")->capture_default_str();
  cmd->add_option("--params", args->params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
