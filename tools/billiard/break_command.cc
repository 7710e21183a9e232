#include "tools/billiard/break_command.h"

#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "planner/game/break_scratches.h"
#include "planner/game/break_search.h"
#include "sim/batch/thread_pool.h"
#include "sim/batch/wilson.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/match_command.h"
#include "tools/billiard/scene_commands.h"

namespace billiard::cli {

namespace {

// The search's racks are seeded apart from the measured ones, so that the figures are held out.
constexpr std::uint64_t kSearchSeedOffset = 1000003;

struct BenchBreakArgs {
  std::string game;
  std::string noise = "computational-pool";
  std::string robot = params::kDefaultRobot;
  int samples = 400;
  std::uint64_t seed = 1;
  int threads = batch::DefaultThreadCount();
  std::vector<double> given;  // --break: offset, aim, speed, tip[, behind]
  bool search = false;
  int search_samples = 200;
  int rounds = 2;
  int refinements = 0;
  double max_behind = 0.0;
  double max_scratch = 0.05;
  double scratch_z = 1.0;
  bool scratches = false;  // --scratches: the optimised break's scratches by pocket and path
  bool json = false;
};

nlohmann::json RateJson(int count, int samples) {
  const batch::Interval i = batch::WilsonInterval(count, samples);
  return {{"count", count},
          {"rate", samples ? static_cast<double>(count) / samples : 0.0},
          {"interval95", {i.lo, i.hi}}};
}

nlohmann::json BreakJson(const game::Break& b, const game::BreakRates& r) {
  return {{"cue_offset_m", b.cue_offset},
          {"aim_radii", b.aim},
          {"speed_mps", b.speed},
          {"tip_height_radii", b.tip_height},
          {"behind_m", b.behind},
          {"samples", r.samples},
          {"legal", RateJson(r.legal, r.samples)},
          {"potted", RateJson(r.potted, r.samples)},
          {"legal_and_potted", RateJson(r.kept, r.samples)},
          {"scratch", RateJson(r.scratches, r.samples)},
          {"failed", r.failed},
          {"first_failure", r.first_failure}};
}

// `t` as JSON: each (pocket, path) and its count, and each path's count and mean balls met.
nlohmann::json ScratchTallyJson(const game::ScratchTally& t) {
  nlohmann::json rows = nlohmann::json::array(), paths = nlohmann::json::object();
  for (const auto& [key, count] : t.by_pocket_and_path) {
    rows.push_back({{"pocket", key.first}, {"path", key.second}, {"count", count}});
  }
  for (const auto& [path, count] : t.by_path) {
    paths[path] = {{"count", count},
                   {"mean_balls_met", static_cast<double>(t.balls_met.at(path)) / count}};
  }
  return {
      {"samples", t.samples}, {"scratches", t.scratches}, {"by_pocket", rows}, {"by_path", paths}};
}

// The scratch tally on stderr, a line per pocket and path.
void ReportScratches(const nlohmann::json& j) {
  std::cerr << "scratches by pocket and path (" << j["scratches"].get<int>() << " of "
            << j["samples"].get<int>() << " racks):" << std::endl;
  for (const nlohmann::json& row : j["by_pocket"]) {
    const std::string pocket = row["pocket"].get<std::string>();
    std::cerr << "  " << (pocket.empty() ? "(past a mouth)" : pocket) << ", "
              << row["path"].get<std::string>() << ": " << row["count"].get<int>() << std::endl;
  }
}

// One line on stderr: the break and its rates.
void Report(const std::string& name, const nlohmann::json& j) {
  const auto rate = [&](const char* key) { return j[key]["rate"].get<double>(); };
  const nlohmann::json& kept = j["legal_and_potted"]["interval95"];
  std::cerr << std::setprecision(3) << name << ": cue ball " << j["cue_offset_m"].get<double>()
            << " m off the axis, aim " << j["aim_radii"].get<double>() << " R, "
            << j["speed_mps"].get<double>() << " m/s, tip " << j["tip_height_radii"].get<double>()
            << " R, " << j["behind_m"].get<double>()
            << " m behind the head string: legal and potted " << rate("legal_and_potted")
            << " (95 % " << kept[0].get<double>() << " to " << kept[1].get<double>() << "), legal "
            << rate("legal") << ", potted " << rate("potted") << ", scratch " << rate("scratch")
            << " of " << j["samples"].get<int>() << " racks" << std::endl;
  if (const int failed = j["failed"].get<int>()) {
    std::cerr << name << ": " << failed << " racks could not be played ("
              << j["first_failure"].get<std::string>() << ")" << std::endl;
  }
}

// --break's four or five numbers as a break.
game::Break BreakOf(const std::vector<double>& v) {
  if (v.size() != 4 && v.size() != 5) throw UsageError("--break: 4 or 5 numbers");
  for (double x : v) RequireFinite(x, "--break");
  const double behind = v.size() == 5 ? v[4] : 0.0;
  if (behind < 0) throw UsageError("--break: the place behind the head string must be >= 0");
  return {v[0], v[1], v[2], v[3], behind};
}

void Run(const BenchBreakArgs& args) {
  const rules::Rules game = GameOf(args.game);
  params::ExecutionNoise noise;
  cue::Robot robot;
  try {
    noise = params::LoadNoise(args.noise);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--noise: ") + e.what());
  }
  try {
    robot = params::LoadRobot(args.robot);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--robot: ") + e.what());
  }
  const physics::ModelParameters params = LoadParametersOption(params::kDefaultParameterSet);
  const table::TableGeometry table = LoadTableOption(params::kDefaultTable);
  const game::BreakSetting setting{table, params, game, noise, model_choice::TableMotion(params),
                                   &robot};
  batch::ThreadPool pool(args.threads);
  game::Break optimised = game::StoredBreak(game);
  if (!args.given.empty()) optimised = BreakOf(args.given);
  nlohmann::json j = {
      {"game", args.game}, {"noise", args.noise}, {"robot", robot.name}, {"seed", args.seed}};
  if (args.search) {
    game::BreakSearchOptions options;
    options.ranges = {robot.speed.max, robot.max_tip_offset, args.max_behind};
    options.samples = args.search_samples;
    options.rounds = args.rounds;
    options.refinements = args.refinements;
    options.seed = args.seed + kSearchSeedOffset;
    options.max_scratch = args.max_scratch;
    options.scratch_z = args.scratch_z;
    const game::BreakSearchResult found =
        game::SearchBreak(setting, args.given.empty() ? game::Break{} : optimised, options, pool);
    optimised = found.best;
    j["search"] = {{"candidates", found.candidates},
                   {"samples", options.samples},
                   {"seed", options.seed},
                   {"rounds", options.rounds},
                   {"refinements", options.refinements},
                   {"max_scratch", options.max_scratch},
                   {"scratch_z", options.scratch_z},
                   {"kept", found.rates.kept},
                   {"scratches", found.rates.scratches},
                   {"scratch_bound", game::ScratchBound(found.rates, options.scratch_z)},
                   {"feasible", game::Feasible(found.rates, options)}};
  }
  const std::vector<game::BreakRates> rates =
      game::EvaluateBreaks(setting, {game::Break{}, optimised}, args.samples, args.seed, pool);
  j["today"] = BreakJson(game::Break{}, rates[0]);
  j["optimised"] = BreakJson(optimised, rates[1]);
  Report("today's break", j["today"]);
  Report(args.search          ? "searched break"
         : args.given.empty() ? "stored break"
                              : "given break",
         j["optimised"]);
  if (args.scratches) {
    j["optimised"]["scratch_paths"] = ScratchTallyJson(
        game::TallyBreakScratches(setting, optimised, args.samples, args.seed, pool));
    ReportScratches(j["optimised"]["scratch_paths"]);
  }
  if (args.json) std::cout << j.dump() << std::endl;
}

}  // namespace

void AddBenchBreakCommand(CLI::App& app) {
  auto args = std::make_shared<BenchBreakArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench-break",
      "The break on seeded racks with the table's noise: legal, potted and scratch rates (Wilson "
      "95 % intervals) of today's break and the optimised one (--search: search it again)");
  cmd->add_option("--game", args->game, "nine-ball | eight-ball")->required();
  cmd->add_option("--noise", args->noise,
                  "The execution noise: robot | computational-pool | a JSON file")
      ->capture_default_str();
  cmd->add_option("--robot", args->robot, "The robot whose ranges bound the search")
      ->capture_default_str();
  cmd->add_option("--samples", args->samples, "Racks each break is measured on")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", args->seed, "Seed of the measured racks and noise")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", args->threads, "Threads (the results do not depend on them)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--break", args->given,
                  "A break to measure instead of the stored one (with --search, the search's "
                  "start): the cue ball's offset from the long axis [m], the aim [ball "
                  "radii], the speed [m/s], the tip height [ball radii], optionally the place "
                  "behind the head string [m] (0)")
      ->delimiter(',')
      ->expected(4, 5);
  cmd->add_flag("--search", args->search,
                "Search the break again (on racks seeded apart from the measured ones)");
  cmd->add_option("--search-samples", args->search_samples, "Racks each candidate is played on")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--rounds", args->rounds, "The search's passes over the parameters")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--refinements", args->refinements,
                  "The search: passes after the rounds, each on half the last's steps about the "
                  "best")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-behind", args->max_behind,
                  "The search: how far behind the head string it places the cue ball [m] (0: "
                  "on it); the cue raised as the robot's needs to clear the head rail")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-scratch", args->max_scratch,
                  "The search: the scratch rate's upper bound a break must keep within")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--scratch-z", args->scratch_z,
                  "The search: the normal quantile of that one-sided Wilson bound (1: 84 %)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--scratches", args->scratches,
                "Also count the measured break's scratches by pocket and by the cue ball's path "
                "after its last ball contact (direct, off rails, hanging, no ball)");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
