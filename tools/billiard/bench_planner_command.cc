#include "tools/billiard/bench_planner_command.h"

#include <iostream>
#include <memory>

#include "bench/planner_benchmark.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct BenchPlannerArgs {
  std::string out;
  std::string params = params::kDefaultParameterSet;
  bench::PlannerBenchmarkOptions options;
};

void Run(const BenchPlannerArgs& args) {
  if (args.options.requests < 1) throw UsageError("--requests must be >= 1");
  const physics::ModelParameters params = LoadParametersOption(args.params);
  RequireWritableDirectory(args.out, "--out");
  bench::PlannerBenchmarkOptions options = args.options;
  options.progress = [](const std::string& line) {
    std::cerr << "bench-planner: " << line << std::endl;
  };
  const bench::PlannerBenchmarkResult result = bench::RunPlannerBenchmark(params, options);
  bench::WritePlannerReport(result, args.out);
  std::cerr << "bench-planner: wrote " << args.out << "/planner_report.md, planner_results.csv ("
            << result.wall_s << " s)" << std::endl;
  std::cout << bench::PlannerSummaryJson(result).dump() << std::endl;
}

}  // namespace

void AddBenchPlannerCommand(CLI::App& app) {
  auto args = std::make_shared<BenchPlannerArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench-planner",
      "Plan seeded random requests three ways (closed form, refined with sensitivities, refined "
      "with central differences) and re-simulate every plan");
  cmd->add_option("--out", args->out, "Directory for planner_report.md and planner_results.csv")
      ->required();
  cmd->add_option("--requests", args->options.requests, "Number of requests")
      ->capture_default_str();
  cmd->add_option("--seed", args->options.seed, "Seed of the requests")->capture_default_str();
  cmd->add_option("--params", args->params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
