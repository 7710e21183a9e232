// The geometry a pot starts from: ghost balls, cut angles, rails as mirrors, and which balls lie
// across a line. These give the first guess of every route; the simulation has the last word
// (pot_planner.h).
//
// Centres move on a table of balls of radius r: a ball's centre bounces off a rail along the
// line r in front of the rail's nose (the "offset line"), so a one-rail route is the straight
// line to the target's mirror image in that offset line (the ideal reflection; the cushion
// model's rebound differs with speed and spin, which the simulation corrects).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::pot {

// Where the cue ball's centre must be, touching the object ball at `object`, for the line of
// centres to point along `direction` (unit): object - 2 r direction.
Eigen::Vector2d GhostBall(const Eigen::Vector2d& object, const Eigen::Vector2d& direction,
                          double radius);

// The cut angle [rad] between the cue ball's approach (unit) and the object ball's departure
// (unit): 0 full ball, pi/2 the thinnest possible.
double CutAngle(const Eigen::Vector2d& approach, const Eigen::Vector2d& departure);

// The rails of a table: TableGeometry::lines holds the rails first, then two jaw faces per
// pocket.
int RailCount(const table::TableGeometry& table);

// A one-rail route from `from` to `to` off rail `rail`: the point where the centre meets the
// rail's offset line, if the mirror line meets it within the rail and both ends lie in front of
// it.
std::optional<Eigen::Vector2d> RailBounce(const table::TableGeometry& table, int rail,
                                          const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                          double radius);

// The ids of the balls (other than those in `ignore`) ahead of a whose centres come closer than
// `clearance` to the segment a -> b: what a ball moving along it would touch (one beside or
// behind a, touching it perhaps, is left behind).
std::vector<int> BallsAcross(const std::vector<table::SceneBall>& balls, const Eigen::Vector2d& a,
                             const Eigen::Vector2d& b, double clearance,
                             const std::vector<int>& ignore);

}  // namespace billiard::pot
