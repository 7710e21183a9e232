#include "planner/choice/monte_carlo.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "planner/choice/lookahead.h"
#include "planner/choice/scene_balls.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/constants_uncertainty.h"
#include "sim/table/rail_contacts.h"

namespace billiard::choice {

namespace {

// The longest a stroke is simulated [s]: every pot rests well within it.
constexpr double kLongestStroke = 60.0;
// The constants' draws come from a stream of their own, apart from the noise's of the same
// sample: the two are independent, and a set without uncertainty draws the noise it always drew.
constexpr std::uint64_t kConstantsStream = 0x636f6e7374616e74ull;

// `balls` with the cue ball (id 0) struck by `stroke`; none when no cue gives the stroke.
std::optional<std::vector<table::SceneBall>> StruckStart(const physics::ModelParameters& params,
                                                         const std::vector<table::SceneBall>& balls,
                                                         const physics::CueStroke& stroke) {
  std::vector<table::SceneBall> start = balls;
  for (table::SceneBall& b : start) {
    if (b.id != 0) continue;
    try {
      b = table::Struck(b.id, stroke, Position(b), params);
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  }
  return start;
}

Execution Execute(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const std::vector<table::SceneBall>& balls, const pot::PotPlan& plan,
                  const ChoiceOptions& options, const Motion& motion, std::uint64_t sample,
                  bool value_next) {
  NormalStream normal(SampleSeed(options.seed, sample));
  const physics::CueStroke stroke = params::Perturbed(plan.stroke, options.noise,
                                                      params.ball.radius, [&] { return normal.Next(); });
  StrokeResult result =
      PlayToRest(table, DrawnConstants(params, options.sample_constants, options.seed, sample),
                 balls, stroke, motion);
  Execution e;
  e.potted = LegalPot(result, plan.ball, plan.pocket);
  if (e.potted && value_next) {
    e.next_value = BestNextShotValue(table, params.ball.radius, result.rest, options.rules,
                                     options.noise);
    e.rest = std::move(result.rest);
  }
  return e;
}

}  // namespace

std::uint64_t SampleSeed(std::uint64_t seed, std::uint64_t index) {
  // SplitMix64 (Steele, Lea and Flood 2014) over the seed, then over the index.
  auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  };
  return mix(mix(seed) ^ index);
}

physics::ModelParameters DrawnConstants(const physics::ModelParameters& params, bool draw,
                                        std::uint64_t seed, std::uint64_t index) {
  if (!draw || params.uncertainty.sd.empty()) return params;
  NormalStream normal(SampleSeed(seed ^ kConstantsStream, index));
  return params::SampledConstants(params, [&] { return normal.Next(); });
}

double NormalStream::Next() {
  if (spare_) {
    const double z = *spare_;
    spare_.reset();
    return z;
  }
  auto uniform = [&] { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; };
  const double r = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * M_PI * uniform();
  spare_ = r * std::sin(angle);
  return r * std::cos(angle);
}

StrokeResult PlayToRest(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls,
                        const physics::CueStroke& stroke, const Motion& motion,
                        std::vector<table::TableEvent>* events) {
  StrokeResult result;
  const std::optional<std::vector<table::SceneBall>> start = StruckStart(params, balls, stroke);
  if (!start) {
    result.rest = balls;
    return result;
  }
  result.struck = true;
  table::TableSimulationOptions sim_options;
  sim_options.five_dof = motion;
  table::TableSimulation sim(table, params, *start, sim_options);
  sim.Run(kLongestStroke);
  if (events) *events = sim.events();
  result.first_contact = table::FirstBallMet(sim.events(), 0);
  result.to_rail_after_contact = table::BallsToRailAfterFirstContact(sim.events(), 0);
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    if (sim.pocket(i)) {
      if (sim.id(i) == 0) {
        result.scratch = true;
      } else {
        result.pocketed.emplace_back(sim.id(i), *sim.pocket(i));
      }
      continue;
    }
    table::SceneBall b;
    b.id = sim.id(i);
    b.state.segment<2>(physics::kX) = sim.State(i).segment<2>(physics::kX);
    result.rest.push_back(b);
  }
  DropHangingBalls(table, &result);
  return result;
}

void DropHangingBalls(const table::TableGeometry& table, StrokeResult* result) {
  std::vector<table::SceneBall> rest;
  for (const table::SceneBall& b : result->rest) {
    const table::Pocket* pocket = table.PocketPastMouth(Position(b));
    if (!pocket) {
      rest.push_back(b);
    } else if (b.id == 0) {
      result->scratch = true;
    } else {
      result->pocketed.emplace_back(b.id, pocket->name);
    }
  }
  result->rest = std::move(rest);
}

int FirstContact(const table::TableGeometry& table, const physics::ModelParameters& params,
                 const std::vector<table::SceneBall>& balls, const physics::CueStroke& stroke) {
  const std::optional<std::vector<table::SceneBall>> start = StruckStart(params, balls, stroke);
  if (!start) return -1;
  table::TableSimulation sim(table, params, *start);
  sim.RunUntil([](const table::TableEvent& e) { return table::SettlesFirstBallMet(e, 0); },
               kLongestStroke);
  return table::FirstBallMet(sim.events(), 0);
}

bool LegalPot(const StrokeResult& result, int ball, const std::string& pocket) {
  if (!result.struck || result.scratch || result.first_contact != ball) return false;
  return std::any_of(result.pocketed.begin(), result.pocketed.end(),
                     [&](const auto& p) { return p.first == ball && p.second == pocket; });
}

PotProbability Binomial(int successes, int samples) {
  PotProbability p;
  p.samples = samples;
  p.successes = successes;
  if (samples > 0) {
    p.probability = static_cast<double>(successes) / samples;
    p.stderr_ = std::sqrt(p.probability * (1 - p.probability) / samples);
  }
  return p;
}

PotProbability PotRateOf(const std::vector<Execution>& executions) {
  int successes = 0;
  for (const Execution& e : executions) successes += e.potted;
  return Binomial(successes, static_cast<int>(executions.size()));
}

std::vector<Execution> ExecuteAll(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const std::vector<const pot::PotPlan*>& plans, int samples,
                                  const ChoiceOptions& options, const Motion& motion,
                                  bool value_next, batch::ThreadPool& pool) {
  return ExecuteRange(table, params, balls, plans, 0, samples, options, motion, value_next, pool);
}

std::vector<Execution> ExecuteRange(const table::TableGeometry& table,
                                    const physics::ModelParameters& params,
                                    const std::vector<table::SceneBall>& balls,
                                    const std::vector<const pot::PotPlan*>& plans, int first,
                                    int count, const ChoiceOptions& options, const Motion& motion,
                                    bool value_next, batch::ThreadPool& pool) {
  const std::size_t n = plans.size() * static_cast<std::size_t>(count);
  auto results = pool.Map(n, [&](std::size_t job) {
    return Execute(table, params, balls, *plans[job / count], options, motion,
                   first + job % count, value_next);
  });
  std::vector<Execution> executions(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (results[i].ok()) executions[i] = *results[i].value;  // a throw counts as a miss
  }
  return executions;
}

PotProbability EstimatePotProbability(const table::TableGeometry& table,
                                      const physics::ModelParameters& params,
                                      const std::vector<table::SceneBall>& balls,
                                      const pot::PotPlan& plan,
                                      const params::ExecutionNoise& noise, int samples,
                                      std::uint64_t seed, batch::ThreadPool& pool) {
  ChoiceOptions options;
  options.noise = noise;
  options.seed = seed;
  const std::vector<Execution> executions =
      ExecuteAll(table, params, balls, {&plan}, samples, options,
                 model_choice::TableMotion(params), false, pool);
  return PotRateOf(executions);
}

}  // namespace billiard::choice
