#include "tools/billiard/bench_command.h"

#include <iostream>
#include <memory>

#include "bench/report.h"
#include "bench/speed_error.h"
#include "sim/physics/parameters.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct BenchArgs {
  bool quick = false;
  std::string out;
  // The scene suite holds the states of the paper's Figs. 6-10, which belong to its 20 mm ball.
  std::string params = "paper";
  bench::BenchmarkOptions options;
};

void Run(BenchArgs args) {
  if (args.options.random_shots < 0) throw UsageError("--shots must be >= 0");
  if (args.options.threads < 1) throw UsageError("--threads must be >= 1");
  const physics::ModelParameters params = LoadParametersOption(args.params);
  RequireWritableDirectory(args.out, "--out");
  args.options.quick = args.quick;
  args.options.progress = [](const std::string& line) {
    std::cerr << "bench: " << line << std::endl;
  };
  const bench::BenchmarkResult result = bench::RunBenchmark(params, args.options);
  bench::WriteReport(result, args.out);
  std::cerr << "bench: wrote " << args.out << "/report.md, results.csv, speed_vs_error.png, "
            << "model_choice.json (" << result.wall_s << " s)" << std::endl;
  std::cout << bench::SummaryJson(result, args.out).dump() << std::endl;
}

}  // namespace

void AddBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Speed against error of every model and integrator over a seeded scene suite, and our "
      "default against Odeint, CVODE and the floor on Figs. 6-10");
  cmd->add_flag("--quick", args->quick,
                "Fewer methods and 20 random shots (under a minute; the test suite runs it)");
  cmd->add_option("--out", args->out, "Directory for report.md, results.csv, speed_vs_error.png")
      ->required();
  cmd->add_option("--params", args->params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  cmd->add_option("--shots", args->options.random_shots,
                  "Random cue shots (default 200, quick 20)");
  cmd->add_option("--seed", args->options.seed, "Seed of the random shots")->capture_default_str();
  cmd->add_option("--threads", args->options.threads,
                  "Threads for the converged references, and the most the batch scaling "
                  "measures (1, 2, 4, ... up to it, at least 2; other timing always uses one)")
      ->capture_default_str();
  cmd->callback([args, cmd] {
    BenchArgs a = *args;
    if (a.quick && cmd->count("--shots") == 0) a.options.random_shots = 20;
    Run(a);
  });
}

}  // namespace billiard::cli
