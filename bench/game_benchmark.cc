#include "bench/game_benchmark.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "bench/format.h"
#include "planner/choice/monte_carlo.h"
#include "planner/players/players.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/noise_file.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/rules/rules.h"
#include "plot/reliability.h"

namespace billiard::bench {

namespace {

constexpr char kTournamentNoise[] = "computational-pool";
// The replays' noise stream, apart from the choice's and the games'.
constexpr std::uint64_t kReplayStream = 0x7265706c61792121ull;

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * v.size()))];
}

choice::ChoiceOptions BaseChoice(const GameBenchmarkOptions& options,
                                 const params::ExecutionNoise& noise) {
  choice::ChoiceOptions c;
  c.rules = rules::Rules::kNineBall;
  c.noise = noise;
  c.samples = options.samples;
  c.confirm_samples = options.confirm_samples;
  c.pot.robot = options.robot;
  // Every shot here plays on the set's own constants: known exactly, not drawn (bench-constants
  // measures the choice on tables drawn from the set's uncertainty).
  c.sample_constants = false;
  return c;
}

bool SameChoice(const choice::ChoiceResult& a, const choice::ChoiceResult& b) {
  if (a.candidates.size() != b.candidates.size()) return false;
  for (std::size_t k = 0; k < a.candidates.size(); ++k) {
    const choice::Candidate &x = a.candidates[k], &y = b.candidates[k];
    if (x.plan.ball != y.plan.ball || x.plan.pocket != y.plan.pocket || x.score != y.score ||
        x.confirmed.successes != y.confirmed.successes) {
      return false;
    }
  }
  return true;
}

// The noise the calibration's replays execute with.
std::string PlantNoise(const GameBenchmarkOptions& options) {
  return options.plant_noise.empty() ? options.noise : options.plant_noise;
}

// The chosen shot of each seeded choice played `executions` times more with fresh noise (the
// plant's, on the table's own model), against the probability the choice reported.
void Calibrate(const table::TableGeometry& table, const physics::ModelParameters& params,
               const GameBenchmarkOptions& options, batch::ThreadPool& pool,
               GameBenchmarkResult* result) {
  const params::ExecutionNoise noise = params::LoadNoise(options.noise);
  const params::ExecutionNoise plant = params::LoadNoise(PlantNoise(options));
  const auto motion = model_choice::TableMotion(params);
  const std::unique_ptr<players::Player> ours = players::MakePlayer("ours");
  for (int i = 0; i < options.calibration_layouts; ++i) {
    const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(i);
    const auto balls = WithSeededCueBall(
        table, params.ball.radius, game::SeededNineBallLayout(table, params.ball.radius, seed),
        seed);
    choice::ChoiceOptions c = BaseChoice(options, noise);
    c.seed = seed;
    const players::Turn turn{table, params, balls, {false, rules::LegalTargets(c.rules, balls)}};
    const choice::ChoiceResult r = ours->Decide(turn, c, pool);
    result->choice_us.push_back(r.decision_us);
    if (i == 0) {
      batch::ThreadPool one(1);
      result->thread_count_independent =
          SameChoice(r, ours->Decide(turn, c, one));
    }
    const choice::Candidate* chosen = r.chosen();
    if (chosen && chosen->finalist) {
      CalibrationPoint point;
      point.predicted = chosen->reported().probability;
      point.selection = chosen->full.probability;
      auto replays = pool.Map(options.executions, [&](std::size_t e) {
        choice::NormalStream normal(choice::SampleSeed(seed + kReplayStream, e));
        const physics::CueStroke played = params::Perturbed(
            chosen->plan.stroke, plant, params.ball.radius, [&] { return normal.Next(); });
        return choice::LegalPot(choice::PlayToRest(table, params, balls, played, motion),
                                chosen->plan.ball, chosen->plan.pocket);
      });
      for (const auto& replay : replays) {
        ++point.executions;
        point.potted += replay.ok() && *replay.value;
      }
      result->calibration.push_back(point);
    }
    if ((i + 1) % 10 == 0 || i + 1 == options.calibration_layouts) {
      options.progress("bench-game: calibration " + std::to_string(i + 1) + "/" +
                       std::to_string(options.calibration_layouts) + ", median choice " +
                       Fixed(Median(result->choice_us) / 1000, 0) + " ms");
    }
  }
}

// The six drills of a layout: each noise x each player, in that order.
struct Drill {
  const char* noise;
  std::string player;
};

std::vector<Drill> Drills() {
  std::vector<Drill> drills;
  for (const char* noise : {params::kDefaultNoise, kTournamentNoise}) {
    for (const std::string& player : players::PlayerNames()) drills.push_back({noise, player});
  }
  return drills;
}

void Tally(const game::GameRecord& game, PolicyResult* pr) {
  ++pr->games;
  pr->attempts += game.summary.attempts;
  pr->pots += game.summary.pots;
  pr->fouls += game.summary.fouls;
  pr->run_outs += game.summary.run_out;
  pr->balls += game.summary.balls_potted;
  for (const game::ShotRecord& s : game.shots) {
    pr->decision_us.push_back(s.decision_us);
    if (s.ball >= 0 && s.likely) {
      ++pr->likely_attempts;
      pr->likely_pots += s.called_potted;
    }
  }
}

void PlayDrills(const table::TableGeometry& table, const physics::ModelParameters& params,
                const GameBenchmarkOptions& options, batch::ThreadPool& pool,
                const std::function<void(const GameBenchmarkResult&)>& checkpoint,
                GameBenchmarkResult* result) {
  const std::vector<Drill> drills = Drills();
  std::vector<params::ExecutionNoise> noises;
  std::vector<std::shared_ptr<const players::Player>> drill_players;
  for (const Drill& d : drills) {
    noises.push_back(params::LoadNoise(d.noise));
    drill_players.push_back(players::MakePlayer(d.player));
    PolicyResult pr;
    pr.noise = d.noise;
    pr.policy = d.player;
    result->policies.push_back(pr);
  }
  const auto start = std::chrono::steady_clock::now();
  for (int first = 0; first < options.layouts; first += options.chunk) {
    const int count = std::min(options.chunk, options.layouts - first);
    // One thread per drill, the drills side by side: a drill's choices are mostly short
    // batches that two threads share poorly.
    auto games = pool.Map(count * drills.size(), [&](std::size_t job) {
      const std::uint64_t seed =
          options.seed + 100000 + static_cast<std::uint64_t>(first + job / drills.size());
      const std::size_t d = job % drills.size();
      game::GameOptions g;
      g.choice = BaseChoice(options, noises[d]);
      g.choice.seed = seed;
      g.player = drill_players[d];
      g.execution = noises[d];
      g.seed = seed;
      g.ball_in_hand = true;
      g.single_visit = true;
      g.shot_limit = options.shot_limit;
      batch::ThreadPool one(1);
      return game::PlayGame(table, params,
                            game::SeededNineBallLayout(table, params.ball.radius, seed), g, one);
    });
    for (std::size_t job = 0; job < games.size(); ++job) {
      if (!games[job].ok()) throw std::runtime_error("bench-game: a drill failed: " + games[job].error);
      Tally(*games[job].value, &result->policies[job % drills.size()]);
    }
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int done = first + count;
    std::ostringstream line;
    line << "bench-game: drills " << done << "/" << options.layouts << " layouts, "
         << Fixed(elapsed / 60, 1) << " min, about "
         << Fixed(elapsed / done * (options.layouts - done) / 60, 1) << " min to go;";
    for (const PolicyResult& pr : result->policies) {
      line << " " << pr.noise << "/" << pr.policy << " " << pr.pots << "/" << pr.attempts;
    }
    options.progress(line.str());
    if (checkpoint) checkpoint(*result);
  }
}

double Rate(int a, int b) { return b > 0 ? static_cast<double>(a) / b : 0.0; }

}  // namespace

GameBenchmarkResult RunGameBenchmark(
    const GameBenchmarkOptions& options,
    const std::function<void(const GameBenchmarkResult&)>& checkpoint) {
  GameBenchmarkResult result;
  result.options = options;
  const physics::ModelParameters params = params::LoadParameters(params::kDefaultParameterSet);
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  batch::ThreadPool pool(options.threads);
  Calibrate(table, params, options, pool, &result);
  if (checkpoint) checkpoint(result);
  PlayDrills(table, params, options, pool, checkpoint, &result);
  return result;
}

namespace {

// The robot the choices plan for, in words.
std::string RobotName(const GameBenchmarkOptions& options) {
  return options.robot ? options.robot->name : "none (level cue, unchecked)";
}

// A noise as its file gives it (the source left out: it is long), and where it came from.
nlohmann::json NoiseSummary(const std::string& name_or_file) {
  nlohmann::json j = nlohmann::json::parse(params::FormatNoise(params::LoadNoise(name_or_file)));
  j.erase("source");
  j["from"] = name_or_file;
  return j;
}

}  // namespace

nlohmann::json GameSummaryJson(const GameBenchmarkResult& r) {
  nlohmann::json j;
  int executions = 0, potted = 0;
  double predicted_sum = 0.0, selection_sum = 0.0;
  for (const CalibrationPoint& p : r.calibration) {
    executions += p.executions;
    potted += p.potted;
    predicted_sum += p.predicted * p.executions;
    selection_sum += p.selection * p.executions;
  }
  bool calibrated = true;
  const nlohmann::json deciles = DecilesJson(r.calibration, &calibrated);
  j["calibration"] = {{"executions", executions},
                      {"choices", static_cast<int>(r.calibration.size())},
                      {"confirm_samples", r.options.confirm_samples},
                      {"mean_predicted", executions ? predicted_sum / executions : 0.0},
                      {"mean_selection_estimate", executions ? selection_sum / executions : 0.0},
                      {"measured", Rate(potted, executions)},
                      {"noise", NoiseSummary(r.options.noise)},
                      {"plant_noise", NoiseSummary(PlantNoise(r.options))},
                      {"deciles", deciles},
                      {"calibrated", calibrated}};
  j["decision"] = {{"median_us", Median(r.choice_us)},
                   {"p90_us", Percentile(r.choice_us, 0.9)},
                   {"threads", r.options.threads},
                   {"thread_count_independent", r.thread_count_independent}};
  nlohmann::json policies = nlohmann::json::array();
  for (const PolicyResult& p : r.policies) {
    policies.push_back({{"noise", p.noise},
                        {"policy", p.policy},
                        {"games", p.games},
                        {"attempts", p.attempts},
                        {"pots", p.pots},
                        {"pots_per_attempt", Rate(p.pots, p.attempts)},
                        {"likely_attempts", p.likely_attempts},
                        {"likely_pots", p.likely_pots},
                        {"pots_per_likely_attempt", Rate(p.likely_pots, p.likely_attempts)},
                        {"run_outs", p.run_outs},
                        {"run_out_rate", Rate(p.run_outs, p.games)},
                        {"fouls", p.fouls},
                        {"balls_per_visit", Rate(p.balls, p.games)},
                        {"median_decision_us", Median(p.decision_us)}});
  }
  j["drills"] = policies;
  j["layouts"] = r.policies.empty() ? 0 : r.policies.front().games;
  j["layouts_requested"] = r.options.layouts;
  j["seed"] = r.options.seed;
  j["robot"] = RobotName(r.options);
  return j;
}

void WriteGameReport(const GameBenchmarkResult& r, const std::string& dir) {
  const nlohmann::json s = GameSummaryJson(r);
  OpenForWriting(dir + "/game_results.json") << s.dump(2) << "\n";
  plot::DrawReliability(Deciles(r.calibration),
                        "Shot choice calibration: " +
                            std::to_string(s["calibration"]["executions"].get<int>()) +
                            " executions (told " +
                            s["calibration"]["noise"]["name"].get<std::string>() + ", played " +
                            s["calibration"]["plant_noise"]["name"].get<std::string>() + ")",
                        kJudgedCount, dir + "/game_reliability.png");
  std::ofstream out = OpenForWriting(dir + "/game_report.md");
  const int layouts = s["layouts"].get<int>();
  const auto& cal = s["calibration"];
  out << "# Shot choice: calibration, baselines, decision time\n\n"
      << "From `nice billiard bench-game --out docs/benchmarks --layouts " << r.options.layouts
      << " --calibration-layouts " << r.options.calibration_layouts << " --executions "
      << r.options.executions << " --confirm-samples " << r.options.confirm_samples << " --seed "
      << r.options.seed << " --threads " << r.options.threads << " --robot "
      << (r.options.robot ? r.options.robot->name : "none") << " --noise " << r.options.noise
      << " --plant-noise " << PlantNoise(r.options) << "` (seeded nine-ball layouts on "
      << params::kDefaultTable << ", bench/game_benchmark.h). The numbers are this "
      << "run's, on a 2-core machine shared with other work. Robot: " << RobotName(r.options)
      << " (every stroke at the elevation its cue needs, planner/pot/cue_elevation.h).";
  if (layouts < r.options.layouts) {
    out << " **The run was stopped after " << layouts << " of the " << r.options.layouts
        << " layouts asked for** (each chunk of " << r.options.chunk
        << " layouts is written as it ends, every policy on the same layouts).";
  }
  out << "\n\n## Calibration\n\n"
      << cal["choices"].get<int>() << " seeded choices (a seeded cue ball, nine-ball rules, "
      << "planning for the noise " << r.options.noise << ", " << r.options.samples << " full-model executions of each of the finalists, "
      << "then " << r.options.confirm_samples << " fresh ones of the chosen shot on a seed stream "
      << "of their own: its reported probability), the chosen shot of each replayed "
      << r.options.executions << " times with fresh noise of the plant's, "
      << PlantNoise(r.options) << ", on the table's own model: "
      << cal["executions"].get<int>() << " executions. Over all of them the mean reported "
      << "probability is " << Fixed(cal["mean_predicted"].get<double>(), 3) << ", the measured rate "
      << Fixed(cal["measured"].get<double>(), 3) << "; the finalists' own estimate that chose the "
      << "shot would have said " << Fixed(cal["mean_selection_estimate"].get<double>(), 3)
      << " (the maximum of the finalists' noisy estimates is biased up, a winner's curse; "
      << "the gap to the measured rate is what the confirmation removes, however small). "
      << "A decile holding " << kJudgedCount
      << " or more executions is judged against 5 points; the measured rate's binomial standard "
      << "error is given (replays of one choice share its true probability, so the error across "
      << "choices is larger where a decile holds few choices).\n\n"
      << "![reliability diagram](game_reliability.png)\n\n"
      << "| predicted | choices | executions | mean predicted | measured | judged | within 5 points |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const auto& d : cal["deciles"]) {
    out << "| " << Fixed(d["lo"].get<double>(), 1) << "-" << Fixed(d["hi"].get<double>(), 1)
        << " | " << d["choices"].get<int>() << " | " << d["count"].get<int>() << " | "
        << Fixed(d["predicted"].get<double>(), 3) << " | "
        << Fixed(d["measured"].get<double>(), 3) << " +- "
        << Fixed(d["measured_stderr"].get<double>(), 3) << " | "
        << (d["judged"].get<bool>() ? "yes" : "no") << " | "
        << (d["within_5_points"].get<bool>() ? "yes" : "**no**") << " |\n";
  }
  out << "\nCalibrated (every judged decile within 5 points): "
      << (cal["calibrated"].get<bool>() ? "yes" : "**no**") << ".\n\n"
      << "## Drills from ball in hand\n\n"
      << layouts << " seeded nine-ball layouts, each one visit from ball in hand "
      << "(until a shot pots nothing or fouls, at most " << r.options.shot_limit
      << " shots), the choice assuming the noise the table executes with; every policy plays "
      << "the same layouts and the same execution noise.\n\n"
      << "**Attempt**: every shot that called a ball and pocket is an attempt, whatever its "
      << "probability (the choice plays no safeties: a shot called unlikely is still played as "
      << "a pot, and counts). A pot is the called ball in the called pocket, legally (first "
      << "contact the lowest ball, no scratch). The last column counts only the attempts the "
      << "choice called likely (reported probability >= 0.5; the easiest-looking baseline's by "
      << "its closed-form estimate), for information: it is not the headline figure.\n\n"
      << "| noise | policy | pots / attempts | run-outs | fouls | balls per visit | median decision | pots / likely attempts |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : s["drills"]) {
    out << "| " << p["noise"].get<std::string>() << " | " << p["policy"].get<std::string>()
        << " | " << p["pots"].get<int>() << " / " << p["attempts"].get<int>() << " = "
        << Fixed(p["pots_per_attempt"].get<double>(), 3) << " | " << p["run_outs"].get<int>()
        << " / " << p["games"].get<int>() << " | " << p["fouls"].get<int>() << " | "
        << Fixed(p["balls_per_visit"].get<double>(), 2) << " | "
        << Fixed(p["median_decision_us"].get<double>() / 1000, 0) << " ms | "
        << p["likely_pots"].get<int>() << " / " << p["likely_attempts"].get<int>() << " = "
        << Fixed(p["pots_per_likely_attempt"].get<double>(), 3) << " |\n";
  }
  out << "\nThe drills' decision times are on one thread each, two drills at once.\n\n"
      << "## Decision time\n\n"
      << "`ChooseShot` on the calibration layouts (nine-ball rules, no ball in hand, the "
      << "confirmation included) on " << r.options.threads << " threads: median "
      << Fixed(s["decision"]["median_us"].get<double>() / 1000, 0) << " ms, p90 "
      << Fixed(s["decision"]["p90_us"].get<double>() / 1000, 0)
      << " ms. One thread and " << r.options.threads << " give the same choice: "
      << (r.thread_count_independent ? "yes" : "**no**") << ".\n";
}

}  // namespace billiard::bench
