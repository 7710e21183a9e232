#include "bench/constants_calibration.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "planner/choice/monte_carlo.h"
#include "planner/choice/shot_choice.h"
#include "sim/batch/thread_pool.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/rack.h"

namespace billiard::bench {

namespace {

// The executions' streams, apart from the choice's (its seed and its confirmation's) and from
// each other: the tables drawn, the robot's noise, and the exact estimate's samples.
constexpr std::uint64_t kTablesStream = 0x7461626c65732121ull;
constexpr std::uint64_t kNoiseStream = 0x6e6f697365212121ull;
constexpr std::uint64_t kExactStream = 0x6578616374212121ull;

// The world and what every choice shares.
struct Setup {
  physics::ModelParameters params;  // with its uncertainty
  physics::ModelParameters exact;   // the same without
  table::TableGeometry table;
  params::ExecutionNoise noise = params::LoadNoise(params::kDefaultNoise);
  choice::Motion motion;
};

Setup MakeSetup(const ConstantsCalibrationOptions& options) {
  Setup s;
  s.params = params::LoadParameters(options.params);
  s.table = table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  if (s.params.uncertainty.sd.empty()) {
    throw std::invalid_argument("bench-constants: " + params::ParameterSetLabel(s.params) +
                                " carries no uncertainty to draw");
  }
  s.exact = s.params;
  s.exact.uncertainty = {};
  s.motion = model_choice::TableMotion(s.params);
  return s;
}

choice::ChoiceOptions KindChoice(const ConstantsCalibrationOptions& options, pot::ShotKind kind,
                                 const params::ExecutionNoise& noise, std::uint64_t seed) {
  choice::ChoiceOptions c;
  c.rules = rules::Rules::kNineBall;
  c.noise = noise;
  c.kinds = {kind};
  c.lookahead = false;  // the probability is judged, not the position
  c.samples = options.samples;
  c.confirm_samples = options.confirm_samples;
  c.seed = seed;
  return c;
}

// `plan`'s stroke executed `tables` times, execution e on the table drawn for it and with its
// own noise: how many potted.
int PottedOnDrawnTables(const Setup& s, const std::vector<table::SceneBall>& balls,
                        const pot::PotPlan& plan, int tables, std::uint64_t seed,
                        batch::ThreadPool& pool) {
  auto executions = pool.Map(tables, [&](std::size_t e) {
    const physics::ModelParameters drawn =
        choice::DrawnConstants(s.params, true, seed + kTablesStream, e);
    choice::NormalStream normal(choice::SampleSeed(seed + kNoiseStream, e));
    const physics::CueStroke played = params::Perturbed(plan.stroke, s.noise, s.params.ball.radius,
                                                        [&] { return normal.Next(); });
    return choice::LegalPot(choice::PlayToRest(s.table, drawn, balls, played, s.motion), plan.ball,
                            plan.pocket);
  });
  int potted = 0;
  for (const auto& e : executions) potted += e.ok() && *e.value;  // a throw counts as a miss
  return potted;
}

// Layout `i`'s choice of `kind`, its two predictions and its executions, into `out` unless
// nothing of that kind plans.
void CalibrateLayout(const Setup& s, const ConstantsCalibrationOptions& options,
                     pot::ShotKind kind, int i, batch::ThreadPool& pool, KindCalibration* out) {
  const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(i);
  const double radius = s.params.ball.radius;
  const auto balls = WithSeededCueBall(
      s.table, radius, table::SeededNineBallLayout(s.table, radius, seed), seed);
  const choice::ChoiceResult r =
      choice::ChooseShot(s.table, s.params, balls, KindChoice(options, kind, s.noise, seed), pool);
  const choice::Candidate* chosen = r.chosen();
  if (r.status != choice::ChoiceStatus::kOk || !chosen || !chosen->finalist) return;
  CalibrationPoint sampled;
  sampled.predicted = chosen->reported().probability;
  sampled.selection = chosen->full.probability;
  sampled.executions = options.tables;
  sampled.potted = PottedOnDrawnTables(s, balls, chosen->plan, options.tables, seed, pool);
  CalibrationPoint exact = sampled;
  exact.predicted = choice::EstimatePotProbability(s.table, s.exact, balls, chosen->plan, s.noise,
                                                   options.confirm_samples, seed + kExactStream,
                                                   pool)
                        .probability;
  out->sampled.push_back(sampled);
  out->exact.push_back(exact);
}

}  // namespace

ConstantsCalibrationResult RunConstantsCalibration(const ConstantsCalibrationOptions& options) {
  const Setup s = MakeSetup(options);
  batch::ThreadPool pool(options.threads);
  ConstantsCalibrationResult result;
  result.options = options;
  for (pot::ShotKind kind : options.kinds) {
    KindCalibration k;
    k.kind = kind;
    for (int i = 0; i < options.layouts; ++i) {
      CalibrateLayout(s, options, kind, i, pool, &k);
      if ((i + 1) % 10 == 0 || i + 1 == options.layouts) {
        options.progress("bench-constants: " + std::string(pot::ShotKindName(kind)) + " " +
                         std::to_string(i + 1) + "/" + std::to_string(options.layouts) + ", " +
                         std::to_string(k.sampled.size()) + " chosen");
      }
    }
    result.kinds.push_back(std::move(k));
  }
  return result;
}

namespace {

// Executions, mean predictions, measured rate and deciles of `sampled` and `exact` (the same
// executions).
nlohmann::json PointsJson(const std::vector<CalibrationPoint>& sampled,
                          const std::vector<CalibrationPoint>& exact) {
  int executions = 0, potted = 0;
  double sampled_sum = 0.0, exact_sum = 0.0;
  for (std::size_t i = 0; i < sampled.size(); ++i) {
    executions += sampled[i].executions;
    potted += sampled[i].potted;
    sampled_sum += sampled[i].predicted * sampled[i].executions;
    exact_sum += exact[i].predicted * exact[i].executions;
  }
  auto rate = [&](double x) { return executions > 0 ? x / executions : 0.0; };
  bool sampled_calibrated = true, exact_calibrated = true;
  nlohmann::json j = {{"choices", static_cast<int>(sampled.size())},
                      {"executions", executions},
                      {"measured", rate(potted)},
                      {"mean_predicted_sampled", rate(sampled_sum)},
                      {"mean_predicted_exact", rate(exact_sum)}};
  j["deciles_sampled"] = DecilesJson(sampled, &sampled_calibrated);
  j["deciles_exact"] = DecilesJson(exact, &exact_calibrated);
  j["calibrated_sampled"] = sampled_calibrated;
  j["calibrated_exact"] = exact_calibrated;
  return j;
}

}  // namespace

nlohmann::json ConstantsCalibrationJson(const ConstantsCalibrationResult& result) {
  const ConstantsCalibrationOptions& o = result.options;
  nlohmann::json kinds = nlohmann::json::object();
  std::vector<CalibrationPoint> banks_kicks_sampled, banks_kicks_exact;
  for (const KindCalibration& k : result.kinds) {
    kinds[pot::ShotKindName(k.kind)] = PointsJson(k.sampled, k.exact);
    if (k.kind != pot::ShotKind::kBank && k.kind != pot::ShotKind::kKick) continue;
    banks_kicks_sampled.insert(banks_kicks_sampled.end(), k.sampled.begin(), k.sampled.end());
    banks_kicks_exact.insert(banks_kicks_exact.end(), k.exact.begin(), k.exact.end());
  }
  return {{"params", o.params},
          {"layouts", o.layouts},
          {"tables", o.tables},
          {"samples", o.samples},
          {"confirm_samples", o.confirm_samples},
          {"seed", o.seed},
          {"kinds", kinds},
          {"banks_and_kicks", PointsJson(banks_kicks_sampled, banks_kicks_exact)}};
}

namespace {

// The deciles of one prediction as a markdown table.
void WriteDecileTable(std::ostream& md, const nlohmann::json& deciles) {
  md << "| decile | executions | predicted | measured | judged | within 5 points |\n"
        "|---|---|---|---|---|---|\n";
  char line[160];
  for (const nlohmann::json& d : deciles) {
    if (d["count"].get<int>() == 0) continue;
    std::snprintf(line, sizeof line, "| %.1f-%.1f | %d | %.3f | %.3f +- %.3f | %s | %s |\n",
                  d["lo"].get<double>(), d["hi"].get<double>(), d["count"].get<int>(),
                  d["predicted"].get<double>(), d["measured"].get<double>(),
                  d["measured_stderr"].get<double>(), d["judged"].get<bool>() ? "yes" : "no",
                  d["within_5_points"].get<bool>() ? "yes" : "no");
    md << line;
  }
}

}  // namespace

void WriteConstantsReport(const ConstantsCalibrationResult& result, const std::string& dir) {
  const nlohmann::json j = ConstantsCalibrationJson(result);
  std::ofstream(dir + "/constants_results.json") << j.dump(2) << "\n";
  std::ofstream md(dir + "/constants_report.md");
  const ConstantsCalibrationOptions& o = result.options;
  md << "# The table's own uncertainty beside the robot's (issue 47)\n\n"
     << "`billiard bench-constants --params " << o.params << " --layouts " << o.layouts
     << " --tables " << o.tables << " --samples " << o.samples << " --confirm-samples "
     << o.confirm_samples << " --seed " << o.seed << "`\n\n"
     << "Seeded nine-ball layouts with a seeded cue ball, each chosen once per kind (the choice's "
        "candidates of that kind alone, the robot's noise, no lookahead) with the set's constants "
        "drawn within its uncertainty in every sample. Each chosen shot executed " << o.tables
     << " times, each on its own table drawn from the uncertainty with its own noise (seed "
        "streams apart from the choice's). *sampled*: the probability the choice reports; "
        "*exact*: the same shot's probability with the constants taken as exact (" << o.confirm_samples
     << " executions on the set's own values). A decile is judged where it holds at least "
     << kJudgedCount << " executions.\n\n"
     << "| kind | choices | executions | predicted, sampled | predicted, exact | measured | "
        "calibrated, sampled | calibrated, exact |\n|---|---|---|---|---|---|---|---|\n";
  auto row = [&](const std::string& name, const nlohmann::json& k) {
    char line[200];
    std::snprintf(line, sizeof line, "| %s | %d | %d | %.3f | %.3f | %.3f | %s | %s |\n",
                  name.c_str(), k["choices"].get<int>(), k["executions"].get<int>(),
                  k["mean_predicted_sampled"].get<double>(), k["mean_predicted_exact"].get<double>(),
                  k["measured"].get<double>(), k["calibrated_sampled"].get<bool>() ? "yes" : "no",
                  k["calibrated_exact"].get<bool>() ? "yes" : "no");
    md << line;
  };
  for (const auto& [name, k] : j["kinds"].items()) row(name, k);
  row("banks and kicks", j["banks_and_kicks"]);
  md << "\n## Banks and kicks, the constants drawn (the choice's prediction)\n\n";
  WriteDecileTable(md, j["banks_and_kicks"]["deciles_sampled"]);
  md << "\n## Banks and kicks, the constants taken as exact\n\n";
  WriteDecileTable(md, j["banks_and_kicks"]["deciles_exact"]);
}

}  // namespace billiard::bench
