#include "planner/pot/routes.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "planner/pot/pot_geometry.h"

namespace billiard::pot {

using table::SceneBall;

namespace {

// A pot's search simulates the balls within this distance of its routes' lines, beyond contact
// [m]: the drop window is a few degrees wide, 5 cm at a metre.
constexpr double kNearRoute = 0.15;
// Curves: the cue elevations [rad] and side offsets (fraction of the largest) tried, with draw.
// Low elevations: the hop limit (sim/cue/stroke_limits.h) allows a cue of 0.28 m/s / tan(elevation)
// along the heading, and the bend a curve gets within it (bench/curve_bend.py, docs/planning.md's
// "How much a curve bends") is largest from 7.5 to 15 degrees: 0.9-1.8 cm off a 1 m chord with
// draw, 1.1 cm without, 2 cm off 1.5 m at 7.5-10 degrees, 1.1-1.3 cm off 0.5 m at 12.5-15.
// Steeper, the slow cue's slide is spent within a few centimetres; lower, the bend of a fast cue's
// long slide is small.
constexpr double kCurveElevations[] = {7.5 * kDegree, 10.0 * kDegree, 12.5 * kDegree};
constexpr double kCurveSides[] = {0.7, -0.7};
// Draw lengthens the slide (the contact point's slip is the ball's speed plus its backspin's), over
// which the side spin about the travel bends the path: 0.7 of the largest offset below centre,
// with the side's 0.7 within the largest offset (0.99 of it).
constexpr double kCurveDraw = -0.7;

std::string BlockedWords(const std::string& what, const std::vector<int>& ids) {
  std::ostringstream s;
  s << what << " is blocked by ball";
  if (ids.size() > 1) s << "s";
  for (std::size_t i = 0; i < ids.size(); ++i) s << (i ? ", " : " ") << ids[i];
  return s.str();
}

// `route` with the balls across K's legs and the cue ball's (none for a curve's, whose path
// bends away from its line), in words.
Candidate WithBlockers(const SearchContext& search, const Route& route,
                       const std::vector<Eigen::Vector2d>& object_legs,
                       const std::vector<Eigen::Vector2d>& cue_legs) {
  const int object = search.object_id();
  const double clearance = 2.0 * search.radius();
  Candidate c{route, BallsAcrossLegs(search.balls(), object_legs, clearance, object), {}};
  if (!c.blockers.empty()) c.blocked = BlockedWords("ball " + std::to_string(object) + "'s line to the pocket", c.blockers);
  const std::vector<int> cue_blockers = BallsAcrossLegs(search.balls(), cue_legs, clearance, object);
  if (!cue_blockers.empty()) {
    if (!c.blocked.empty()) c.blocked += "; ";
    c.blocked += BlockedWords("the cue ball's line to the ghost ball", cue_blockers);
    c.blockers.insert(c.blockers.end(), cue_blockers.begin(), cue_blockers.end());
  }
  return c;
}

// Shortest first: the ball travels least, its errors grow least.
void SortShortestFirst(const SearchContext& search, std::vector<Candidate>* routes) {
  const double r = search.radius();
  const Eigen::Vector2d cue = search.cue_position(), k = search.object_ball().state.head<2>();
  const Eigen::Vector2d pocket = search.pocket().centre;
  const auto length = [&](const Candidate& c) {
    const Eigen::Vector2d ghost_of = GhostBall(k, (c.route.object_aim - k).normalized(), r);
    return (c.route.cue_aim - cue).norm() + (ghost_of - c.route.cue_aim).norm() +
           (c.route.object_aim - k).norm() + (pocket - c.route.object_aim).norm();
  };
  std::stable_sort(routes->begin(), routes->end(), [&](const Candidate& a, const Candidate& b) {
    return length(a) < length(b);
  });
}

}  // namespace

std::vector<int> BallsAcrossLegs(const std::vector<SceneBall>& balls, const std::vector<Eigen::Vector2d>& legs,
                                 double clearance, int object) {
  std::vector<int> ids;
  for (std::size_t i = 0; i + 1 < legs.size(); ++i) {
    for (int id : BallsAcross(balls, legs[i], legs[i + 1], clearance, {0, object})) ids.push_back(id);
  }
  return ids;
}

std::vector<Candidate> Routes(const SearchContext& search, ShotKind kind) {
  const table::TableGeometry& table = search.table();
  const double r = search.radius();
  const Eigen::Vector2d cue = search.cue_position(), k = search.object_ball().state.head<2>();
  const Eigen::Vector2d pocket = search.pocket().centre;
  std::vector<Candidate> out;
  const Eigen::Vector2d straight = (pocket - k).normalized();
  const Eigen::Vector2d ghost = GhostBall(k, straight, r);
  switch (kind) {
    case ShotKind::kDirect:
      out.push_back(WithBlockers(search, {ShotKind::kDirect, -1, pocket, ghost}, {k, pocket}, {cue, ghost}));
      break;
    case ShotKind::kBank:
      for (int rail = 0; rail < RailCount(table); ++rail) {
        const std::optional<Eigen::Vector2d> bounce = RailBounce(table, rail, k, pocket, r);
        // A rail the pocket lies on is no bank: the rebound would run along it.
        if (!bounce || (bounce->head<2>() - pocket).norm() < 4.0 * r) continue;
        const Eigen::Vector2d g = GhostBall(k, (*bounce - k).normalized(), r);
        out.push_back(WithBlockers(search, {ShotKind::kBank, rail, *bounce, g}, {k, *bounce, pocket}, {cue, g}));
      }
      break;
    case ShotKind::kKick:
      for (int rail = 0; rail < RailCount(table); ++rail) {
        const std::optional<Eigen::Vector2d> bounce = RailBounce(table, rail, cue, ghost, r);
        if (!bounce) continue;
        out.push_back(WithBlockers(search, {ShotKind::kKick, rail, pocket, *bounce}, {k, pocket}, {cue, *bounce, ghost}));
      }
      break;
    case ShotKind::kCurve:
      for (double elevation : kCurveElevations) {
        for (double side : kCurveSides) {
          Route route{ShotKind::kCurve, -1, pocket, ghost};
          route.elevation = elevation;
          route.tip_side = side * search.params().cue.max_tip_offset * r;
          route.tip_height = kCurveDraw * search.params().cue.max_tip_offset * r;
          out.push_back(WithBlockers(search, route, {k, pocket}, {}));
        }
      }
      break;
  }
  SortShortestFirst(search, &out);
  return out;
}

std::vector<SceneBall> NearRoute(const SearchContext& search, const Route& route) {
  const double r = search.radius();
  const Eigen::Vector2d k = search.object_ball().state.head<2>();
  const Eigen::Vector2d ghost = GhostBall(k, (route.object_aim - k).normalized(), r);
  std::vector<Eigen::Vector2d> cue_legs = {search.cue_position(), route.cue_aim};
  if (route.kind == ShotKind::kKick) cue_legs.push_back(ghost);
  std::vector<Eigen::Vector2d> object_legs = {k, route.object_aim};
  if (route.kind == ShotKind::kBank) object_legs.push_back(search.pocket().centre);
  std::vector<SceneBall> near = {search.cue_ball(), search.object_ball()};
  const double reach = 2.0 * r + kNearRoute;
  std::vector<int> ids = BallsAcrossLegs(search.balls(), cue_legs, reach, search.object_id());
  for (int id : BallsAcrossLegs(search.balls(), object_legs, reach, search.object_id())) ids.push_back(id);
  for (const SceneBall& b : search.balls()) {
    if (std::find(ids.begin(), ids.end(), b.id) != ids.end()) near.push_back(b);
  }
  return near;
}

}  // namespace billiard::pot
