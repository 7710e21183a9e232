// Step 1 of a pot, its routes: the first guesses of each kind and what geometry says blocks them.
//
// The object ball K's route is its line to the pocket's mouth (direct, kick, curve) or off one
// rail to the pocket's mirror image in the rail's offset line (bank; pot_geometry.h RailBounce);
// the cue ball's route is its line to the ghost ball (direct, bank), off one rail to the ghost
// ball's mirror image (kick), or bent by an elevated cue with side spin and draw (curve: 7.5, 10
// and 12.5 degrees of elevation, low enough for a pace that bends the path within the hop limit;
// 0.7 of the largest side offset either way, and 0.7 of it below centre). Geometry names the balls
// across each line, so that a blocked route is refused without a simulation; a curve bends away
// from its line, which names none on the cue ball's side.
//
// The headings the cue ball's and K's own paths give (a kick's, a curve's, a bank's line) are
// lone_path.h's.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "planner/pot/pot_planner.h"
#include "planner/pot/search_context.h"
#include "sim/table/scene.h"

namespace billiard::pot {

struct Route {
  ShotKind kind = ShotKind::kDirect;
  int rail = -1;
  Eigen::Vector2d object_aim = Eigen::Vector2d::Zero();  // where K is sent first
  Eigen::Vector2d cue_aim = Eigen::Vector2d::Zero();     // where the cue ball is sent first
  double elevation = 0.0, tip_side = 0.0, tip_height = 0.0;  // curve
};

// A route of a kind for K into P from where the balls are, with the balls geometry says lie
// across it.
struct Candidate {
  Route route;
  std::vector<int> blockers;  // on the object's line, then on the cue ball's
  std::string blocked;        // in words, when not clear
};

// The routes of `kind` for the search's K into its P, shortest first (the ball travels least,
// its errors grow least). A bank off the pocket's own rail (its rebound would run along it) and
// a kick whose bounce falls outside its rail are no routes.
std::vector<Candidate> Routes(const SearchContext& search, ShotKind kind);

// The ids of the balls (other than the cue ball and `object`) across the legs of a path (a
// polyline, pot_geometry.h BallsAcross on each leg in turn), within `clearance` of its lines.
std::vector<int> BallsAcrossLegs(const std::vector<table::SceneBall>& balls,
                                 const std::vector<Eigen::Vector2d>& legs, double clearance, int object);

// The balls a pot's search can meet before K drops: the cue ball, K, and those within 15 cm of
// the cue ball's route to the ghost ball or of K's route to the pocket (the drop window and the
// margin turn these lines by a few degrees at most). The rest cannot change which ball the cue
// ball meets first or whether K drops; the truth has them all.
std::vector<table::SceneBall> NearRoute(const SearchContext& search, const Route& route);

}  // namespace billiard::pot
