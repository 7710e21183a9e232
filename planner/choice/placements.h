// Where a cue ball in hand may go for a pot: places behind each legal target on the line from
// each pocket (straight, cut 15 and 30 degrees either way, 0.15, 0.3 and 0.5 m back from the
// ghost ball), on the surface and clear of the balls, the best-looking of each target and
// pocket by EasyPotEstimate. The ball-in-hand choice chooses among them (ball_in_hand.h),
// position play sends the cue ball to the best (position_play.h), and the easiest-looking
// baseline places it at the best.
//
// Module: billiard::choice.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "planner/choice/choice_options.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// A ball-in-hand place and how easy its pot looks from there.
struct Placement {
  Eigen::Vector2d place;
  double estimate = 0.0;
};

// The best-looking place behind each legal target (under options.rules, the cue ball of
// `balls` lifted) for each pocket, best first (ties in target and pocket order); none whose
// pot looks impossible.
std::vector<Placement> CandidatePlacements(const table::TableGeometry& table, double radius,
                                           const std::vector<table::SceneBall>& balls,
                                           const ChoiceOptions& options);

}  // namespace billiard::choice
