#include "tools/billiard/bench_constants_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "bench/constants_calibration.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

void AddBenchConstantsCommand(CLI::App& app) {
  struct Args {
    bench::ConstantsCalibrationOptions options;
    std::string out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "bench-constants",
      "The choice's probability of direct pots, banks and kicks against executions on tables "
      "drawn from the parameter set's uncertainty, with the constants drawn and taken as exact "
      "(JSON summary on stdout)");
  bench::ConstantsCalibrationOptions& o = args->options;
  cmd->add_option("--params", o.params, "A parameter set with an \"uncertainty\" (name or file)")
      ->capture_default_str();
  cmd->add_option("--layouts", o.layouts, "Seeded layouts chosen on, per kind")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--tables", o.tables, "Executions of each chosen shot, each on its own drawn table")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--samples", o.samples, "The choice's full-model executions per finalist")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--confirm-samples", o.confirm_samples,
                  "Fresh executions of the chosen shot: its reported probability")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o.seed, "The first layout's seed")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", o.threads, "Threads")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--out", args->out, "Write constants_report.md and constants_results.json here");
  cmd->callback([args] {
    if (!args->out.empty()) RequireWritableDirectory(args->out, "--out");
    bench::ConstantsCalibrationOptions options = args->options;
    options.progress = [](const std::string& line) { std::cerr << line << std::endl; };
    bench::ConstantsCalibrationResult result;
    try {
      result = bench::RunConstantsCalibration(options);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--params: ") + e.what());
    }
    if (!args->out.empty()) {
      bench::WriteConstantsReport(result, args->out);
      std::cerr << "bench-constants: wrote " << args->out << "/constants_report.md\n";
    }
    std::cout << bench::ConstantsCalibrationJson(result).dump() << std::endl;
  });
}

}  // namespace billiard::cli
