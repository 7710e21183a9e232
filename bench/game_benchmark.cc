#include "bench/game_benchmark.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "bench/format.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/seeded_uniform.h"
#include "tools/plot/reliability.h"

namespace billiard::bench {

namespace {

constexpr char kTable[] = "pool-9ft";
constexpr char kTournamentNoise[] = "computational-pool";
// Deciles that hold at least this many executions are judged (the acceptance's rule).
constexpr int kJudgedCount = 30;
constexpr double kCalibrationTolerance = 0.05;
// The replays' noise stream, apart from the choice's and the games'.
constexpr std::uint64_t kReplayStream = 0x7265706c61792121ull;
constexpr int kDeciles = 10;

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

// A layout with a cue ball placed at a seeded free place (a choice without ball in hand).
std::vector<table::SceneBall> WithSeededCueBall(const table::TableGeometry& table, double radius,
                                                std::vector<table::SceneBall> balls,
                                                std::uint64_t seed) {
  table::SeededUniform uniform(seed);
  for (;;) {
    const Eigen::Vector2d p(uniform.Between(0, table.length), uniform.Between(0, table.width));
    if (!table.OnSurface(p, 3 * radius)) continue;
    const bool clear = std::all_of(balls.begin(), balls.end(), [&](const auto& b) {
      return (b.state.template segment<2>(physics::kX) - p).norm() >= 4 * radius;
    });
    if (clear) return choice::WithCueBallAt(std::move(balls), p);
  }
}

std::vector<plot::ReliabilityBin> Deciles(const std::vector<CalibrationPoint>& points) {
  std::vector<plot::ReliabilityBin> bins(kDeciles);
  std::vector<double> predicted_sum(kDeciles, 0.0);
  std::vector<int> potted(kDeciles, 0);
  for (int i = 0; i < kDeciles; ++i) {
    bins[i].lo = i / double(kDeciles);
    bins[i].hi = (i + 1) / double(kDeciles);
  }
  for (const CalibrationPoint& p : points) {
    const int i = std::min(kDeciles - 1, static_cast<int>(p.predicted * kDeciles));
    bins[i].count += p.executions;
    predicted_sum[i] += p.predicted * p.executions;
    potted[i] += p.potted;
  }
  for (int i = 0; i < kDeciles; ++i) {
    if (bins[i].count == 0) continue;
    bins[i].predicted = predicted_sum[i] / bins[i].count;
    bins[i].measured = static_cast<double>(potted[i]) / bins[i].count;
  }
  return bins;
}

choice::ChoiceOptions BaseChoice(const GameBenchmarkOptions& options,
                                 const params::ExecutionNoise& noise) {
  choice::ChoiceOptions c;
  c.rules = choice::Rules::kNineBall;
  c.noise = noise;
  c.samples = options.samples;
  return c;
}

void Calibrate(const table::TableGeometry& table, const physics::ModelParameters& params,
               const GameBenchmarkOptions& options, batch::ThreadPool& pool,
               GameBenchmarkResult* result) {
  const params::ExecutionNoise noise = params::LoadNoise(params::kDefaultNoise);
  const auto motion = model_choice::TableMotion(params);
  for (int i = 0; i < options.calibration_layouts; ++i) {
    const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(i);
    const auto balls = WithSeededCueBall(
        table, params.ball.radius, choice::SeededNineBallLayout(table, params.ball.radius, seed),
        seed);
    choice::ChoiceOptions c = BaseChoice(options, noise);
    c.seed = seed;
    const choice::ChoiceResult r = choice::ChooseShot(table, params, balls, c, pool);
    result->choice_us.push_back(r.decision_us);
    if (i == 0) {
      batch::ThreadPool one(1);
      const choice::ChoiceResult again = choice::ChooseShot(table, params, balls, c, one);
      result->thread_count_independent = again.candidates.size() == r.candidates.size();
      for (std::size_t k = 0; k < r.candidates.size() && result->thread_count_independent; ++k) {
        result->thread_count_independent =
            again.candidates[k].plan.ball == r.candidates[k].plan.ball &&
            again.candidates[k].plan.pocket == r.candidates[k].plan.pocket &&
            again.candidates[k].score == r.candidates[k].score;
      }
    }
    for (const choice::Candidate& cand : r.candidates) {
      if (!cand.finalist) continue;
      CalibrationPoint point;
      point.predicted = cand.full.probability;
      auto replays = pool.Map(options.executions, [&](std::size_t e) {
        choice::NormalStream normal(
            choice::SampleSeed(seed + kReplayStream, e + 1000 * static_cast<std::uint64_t>(i)));
        const physics::CueStroke played = params::Perturbed(
            cand.plan.stroke, noise, params.ball.radius, [&] { return normal.Next(); });
        return choice::LegalPot(choice::PlayToRest(table, params, balls, played, motion),
                                cand.plan.ball, cand.plan.pocket);
      });
      for (const auto& replay : replays) {
        ++point.executions;
        point.potted += replay.ok() && *replay.value;
      }
      result->calibration.push_back(point);
    }
    options.progress("bench-game: calibration " + std::to_string(i + 1) + "/" +
                     std::to_string(options.calibration_layouts));
  }
}

void PlayDrills(const table::TableGeometry& table, const physics::ModelParameters& params,
                const GameBenchmarkOptions& options, batch::ThreadPool& pool,
                GameBenchmarkResult* result) {
  for (const std::string noise_name : {params::kDefaultNoise, kTournamentNoise}) {
    const params::ExecutionNoise noise = params::LoadNoise(noise_name);
    for (choice::Policy policy : {choice::Policy::kOurs, choice::Policy::kNoLookahead,
                                  choice::Policy::kEasiestLooking}) {
      PolicyResult pr;
      pr.noise = noise_name;
      pr.policy = choice::PolicyName(policy);
      for (int i = 0; i < options.layouts; ++i) {
        const std::uint64_t seed = options.seed + 100000 + static_cast<std::uint64_t>(i);
        choice::GameOptions g;
        g.choice = BaseChoice(options, noise);
        g.choice.seed = seed;
        g.policy = policy;
        g.execution = noise;
        g.seed = seed;
        g.ball_in_hand = true;
        g.single_visit = true;
        g.shot_limit = options.shot_limit;
        const choice::GameRecord game = choice::PlayGame(
            table, params, choice::SeededNineBallLayout(table, params.ball.radius, seed), g, pool);
        ++pr.games;
        pr.attempts += game.summary.attempts;
        pr.pots += game.summary.pots;
        pr.fouls += game.summary.fouls;
        pr.run_outs += game.summary.run_out;
        pr.balls += game.summary.balls_potted;
        for (const choice::ShotRecord& s : game.shots) pr.decision_us.push_back(s.decision_us);
      }
      options.progress("bench-game: " + pr.noise + " noise, " + pr.policy + ": " +
                       std::to_string(pr.run_outs) + " run-outs of " + std::to_string(pr.games) +
                       ", " + std::to_string(pr.pots) + " pots of " + std::to_string(pr.attempts) +
                       " attempts");
      result->policies.push_back(pr);
    }
  }
}

double Rate(int a, int b) { return b > 0 ? static_cast<double>(a) / b : 0.0; }

}  // namespace

GameBenchmarkResult RunGameBenchmark(const GameBenchmarkOptions& options) {
  GameBenchmarkResult result;
  result.options = options;
  const physics::ModelParameters params = params::LoadParameters(params::kDefaultParameterSet);
  const table::TableGeometry table = table::BuildTable(params::LoadTableSpec(kTable));
  batch::ThreadPool pool(options.threads);
  Calibrate(table, params, options, pool, &result);
  PlayDrills(table, params, options, pool, &result);
  return result;
}

nlohmann::json GameSummaryJson(const GameBenchmarkResult& r) {
  nlohmann::json j;
  int executions = 0;
  for (const CalibrationPoint& p : r.calibration) executions += p.executions;
  nlohmann::json deciles = nlohmann::json::array();
  bool calibrated = true;
  for (const plot::ReliabilityBin& b : Deciles(r.calibration)) {
    const bool judged = b.count >= kJudgedCount;
    const bool within = std::abs(b.measured - b.predicted) <= kCalibrationTolerance;
    if (judged && !within) calibrated = false;
    deciles.push_back({{"lo", b.lo}, {"hi", b.hi}, {"count", b.count},
                       {"predicted", b.predicted}, {"measured", b.measured}, {"judged", judged},
                       {"within_5_points", within}});
  }
  j["calibration"] = {{"executions", executions}, {"choices", r.options.calibration_layouts},
                      {"deciles", deciles}, {"calibrated", calibrated}};
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
                        {"run_outs", p.run_outs},
                        {"run_out_rate", Rate(p.run_outs, p.games)},
                        {"fouls", p.fouls},
                        {"balls_per_visit", Rate(p.balls, p.games)},
                        {"median_decision_us", Median(p.decision_us)}});
  }
  j["drills"] = policies;
  j["layouts"] = r.options.layouts;
  j["seed"] = r.options.seed;
  return j;
}

void WriteGameReport(const GameBenchmarkResult& r, const std::string& dir) {
  const nlohmann::json s = GameSummaryJson(r);
  OpenForWriting(dir + "/game_results.json") << s.dump(2) << "\n";
  plot::DrawReliability(Deciles(r.calibration),
                        "Shot choice calibration: " +
                            std::to_string(s["calibration"]["executions"].get<int>()) +
                            " noisy executions (robot noise)",
                        kJudgedCount, dir + "/game_reliability.png");
  std::ofstream out = OpenForWriting(dir + "/game_report.md");
  out << "# Shot choice: calibration, baselines, decision time\n\n"
      << "From `billiard bench-game --out docs/benchmarks --layouts " << r.options.layouts
      << " --calibration-layouts " << r.options.calibration_layouts << " --executions "
      << r.options.executions << " --seed " << r.options.seed << " --threads "
      << r.options.threads << "` (seeded nine-ball layouts on pool-9ft, bench/game_benchmark.h). "
      << "The numbers are this run's, on a 2-core machine shared with other work.\n\n"
      << "## Calibration\n\n"
      << "The finalists of " << r.options.calibration_layouts
      << " seeded choices (a seeded cue ball, nine-ball rules, the robot's noise, "
      << r.options.samples << " full-model executions each), each replayed " << r.options.executions
      << " times with fresh noise: " << s["calibration"]["executions"].get<int>()
      << " executions. A decile holding " << kJudgedCount
      << " or more is judged against 5 points.\n\n"
      << "![reliability diagram](game_reliability.png)\n\n"
      << "| predicted | executions | mean predicted | measured | judged | within 5 points |\n"
      << "|---|---|---|---|---|---|\n";
  for (const auto& d : s["calibration"]["deciles"]) {
    out << "| " << Fixed(d["lo"].get<double>(), 1) << "-" << Fixed(d["hi"].get<double>(), 1)
        << " | " << d["count"].get<int>() << " | " << Fixed(d["predicted"].get<double>(), 3)
        << " | " << Fixed(d["measured"].get<double>(), 3) << " | "
        << (d["judged"].get<bool>() ? "yes" : "no") << " | "
        << (d["within_5_points"].get<bool>() ? "yes" : "**no**") << " |\n";
  }
  out << "\nCalibrated (every judged decile within 5 points): "
      << (s["calibration"]["calibrated"].get<bool>() ? "yes" : "**no**") << ".\n\n"
      << "## Drills from ball in hand\n\n"
      << r.options.layouts << " seeded nine-ball layouts, each one visit from ball in hand "
      << "(until a shot pots nothing or fouls, at most " << r.options.shot_limit
      << " shots), the choice assuming the noise the table executes with.\n\n"
      << "| noise | policy | pots / attempts | run-outs | fouls | balls per visit | median decision |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const auto& p : s["drills"]) {
    out << "| " << p["noise"].get<std::string>() << " | " << p["policy"].get<std::string>()
        << " | " << p["pots"].get<int>() << " / " << p["attempts"].get<int>() << " = "
        << Fixed(p["pots_per_attempt"].get<double>(), 3) << " | " << p["run_outs"].get<int>()
        << " / " << p["games"].get<int>() << " | " << p["fouls"].get<int>() << " | "
        << Fixed(p["balls_per_visit"].get<double>(), 2) << " | "
        << Fixed(p["median_decision_us"].get<double>() / 1000, 0) << " ms |\n";
  }
  out << "\n## Decision time\n\n"
      << "`ChooseShot` on the calibration layouts (nine-ball rules, no ball in hand) on "
      << r.options.threads << " threads: median "
      << Fixed(s["decision"]["median_us"].get<double>() / 1000, 0) << " ms, p90 "
      << Fixed(s["decision"]["p90_us"].get<double>() / 1000, 0)
      << " ms. One thread and " << r.options.threads << " give the same choice: "
      << (r.thread_count_independent ? "yes" : "**no**") << ".\n";
}

}  // namespace billiard::bench
