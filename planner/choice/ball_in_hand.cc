#include "planner/choice/ball_in_hand.h"

#include <chrono>
#include <optional>
#include <utility>

#include "planner/choice/placements.h"
#include "planner/choice/scene_balls.h"
#include "planner/choice/shot_choice.h"

namespace billiard::choice {

namespace {

// The places tried: the best-looking `placements`, or when none looks pottable the cue ball
// where it is, or at the head spot (x = 1/4 length) when it was lifted.
std::vector<Placement> PlacesToTry(const table::TableGeometry& table, double radius,
                                   const std::vector<table::SceneBall>& balls,
                                   const ChoiceOptions& options) {
  std::vector<Placement> places = CandidatePlacements(table, radius, balls, options);
  if (places.empty()) {
    const table::SceneBall* cue = FindBall(balls, 0);
    const Eigen::Vector2d place =
        cue ? Position(*cue) : Eigen::Vector2d(table.length / 4, table.width / 2);
    places.push_back({place, 0.0});
  }
  if (static_cast<int>(places.size()) > options.placements) places.resize(options.placements);
  return places;
}

}  // namespace

ChoiceResult ChooseWithBallInHand(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, batch::ThreadPool& pool) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<ChoiceResult> best;
  int simulations = 0;
  for (const Placement& p : PlacesToTry(table, params.ball.radius, balls, options)) {
    ChoiceResult r = ChooseUnconfirmed(table, params, WithCueBallAt(balls, p.place), options, pool);
    simulations += r.simulations;
    r.cue_placement = p.place;
    auto score = [](const ChoiceResult& c) {
      return c.chosen() ? c.chosen()->score : -1.0;
    };
    if (!best || score(r) > score(*best)) best = std::move(r);
  }
  best->simulations = simulations;
  // Only the placement played is confirmed: its probability, not the best of three, is reported.
  Confirm(table, params, WithCueBallAt(balls, *best->cue_placement), options, pool, &*best);
  best->decision_us = MicrosecondsSince(start);
  return *best;
}

}  // namespace billiard::choice
