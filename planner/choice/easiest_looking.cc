#include "planner/choice/easiest_looking.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <utility>

#include "planner/choice/lookahead.h"
#include "planner/choice/placements.h"
#include "planner/choice/scene_balls.h"
#include "planner/pot/pot_geometry.h"
#include "sim/cue/clearance.h"

namespace billiard::choice {

namespace {

// A legal target and pocket, and how easy its pot looks.
struct Look {
  int ball;
  const table::Pocket* pocket;
  double estimate;
};

// The cue ball in hand at the easiest-looking place, or at the head spot (x = 1/4 length) when
// nothing looks pottable.
Eigen::Vector2d EasiestPlace(const table::TableGeometry& table, double radius,
                             const std::vector<table::SceneBall>& balls,
                             const ChoiceOptions& options) {
  const std::vector<Placement> places = CandidatePlacements(table, radius, balls, options);
  if (!places.empty()) return places.front().place;
  return Eigen::Vector2d(table.length / 4, table.width / 2);
}

// Every legal target and pocket, the easiest-looking first (ties in target and pocket order).
std::vector<Look> Looks(const table::TableGeometry& table, double radius,
                        const std::vector<table::SceneBall>& scene, const ChoiceOptions& options) {
  std::vector<Look> looks;
  for (int ball : rules::LegalTargets(options.rules, scene)) {
    for (const table::Pocket& pocket : table.pockets) {
      looks.push_back({ball, &pocket, EasyPotEstimate(radius, scene, ball, pocket, options.noise)});
    }
  }
  std::stable_sort(looks.begin(), looks.end(),
                   [](const Look& a, const Look& b) { return a.estimate > b.estimate; });
  return looks;
}

// The first of `looks` whose direct pot plans, aimed through the ghost ball; none when none
// plans. Counts the simulations into `result`.
std::optional<Candidate> EasiestThatPlans(const table::TableGeometry& table,
                                          const physics::ModelParameters& params,
                                          const std::vector<table::SceneBall>& scene,
                                          const std::vector<Look>& looks,
                                          const ChoiceOptions& options, ChoiceResult* result) {
  for (const Look& look : looks) {
    pot::PotRequest request;
    request.ball = look.ball;
    request.pocket = look.pocket->name;
    request.kind = pot::ShotKind::kDirect;
    pot::PotPlan plan = pot::PlanPot(table, params, scene, request, options.pot);
    result->simulations += plan.simulations;
    if (plan.status != pot::PotStatus::kOk) continue;
    if (const auto heading = pot::GhostBallHeading(table, params, scene, plan, options.pot)) {
      plan.stroke.heading = *heading;
    }
    if (options.pot.robot) {
      plan.clearance = cue::Clearance(table, params.ball.radius, scene, 0, plan.stroke, *options.pot.robot);
      if (!plan.clearance->clears) continue;  // the ghost ball's heading turned into the cue's way
    }
    Candidate c;
    c.plan = std::move(plan);
    c.screen_probability = look.estimate;
    c.score = look.estimate;
    return c;
  }
  return std::nullopt;
}

}  // namespace

ChoiceResult ChooseEasiestLooking(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, bool ball_in_hand) {
  const auto start = std::chrono::steady_clock::now();
  const double radius = params.ball.radius;
  std::vector<table::SceneBall> scene = balls;
  std::optional<Eigen::Vector2d> placement;
  if (ball_in_hand) {
    placement = EasiestPlace(table, radius, balls, options);
    scene = WithCueBallAt(balls, *placement);
  }
  if (auto refusal = Unplayable(table, params, scene, options.rules)) return *refusal;
  ChoiceResult result;
  result.cue_placement = placement;
  const std::vector<Look> looks = Looks(table, radius, scene, options);
  if (auto chosen = EasiestThatPlans(table, params, scene, looks, options, &result)) {
    result.candidates.push_back(std::move(*chosen));
    result.status = ChoiceStatus::kOk;
    result.likely = result.candidates.front().score >= options.likely;
  } else {
    NoPlan(table, params.ball.radius, scene, options.rules, options.pot.robot, "no direct pot of a legal ball plans",
           &result);
  }
  result.decision_us = MicrosecondsSince(start);
  return result;
}

}  // namespace billiard::choice
