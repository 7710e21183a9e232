#include "sim/table/rack.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sim/table/seeded_uniform.h"

namespace billiard::table {

namespace {

using Eigen::Vector2d;

// WPBSA Official Rules of Snooker, section 1 (The Standard Table).
constexpr double kBaulkLine = 0.737;  // from the face of the bottom cushion [m]
constexpr double kDRadius = 0.292;    // the D's radius [m]
constexpr double kBlackSpot = 0.324;  // from the face of the top cushion [m]
// UMB: the starting spots' offset across the table from the bottom spot [m].
constexpr double kStartingSpotOffset = 0.182;

SceneBall AtRest(int id, const Vector2d& p) {
  return {id, physics::MakeBallState(p.x(), p.y(), 0, 0, 0, 0, 0)};
}

// The places of a rack whose rows have `row_sizes` balls, row 0 at `apex`, rows stepping along
// +x and centred on y = apex.y(), on the lattice of spacing 2R + kRackGap / 2, each moved by at
// most kRackGap / 4.
std::vector<Vector2d> RackPlaces(const std::vector<int>& row_sizes, const Vector2d& apex,
                                 double radius, SeededUniform* random) {
  const double spacing = 2 * radius + 0.5 * kRackGap;
  const double row_step = spacing * std::sqrt(3.0) / 2;
  std::vector<Vector2d> places;
  for (std::size_t row = 0; row < row_sizes.size(); ++row) {
    for (int j = 0; j < row_sizes[row]; ++j) {
      const Vector2d lattice(apex.x() + row * row_step,
                             apex.y() + (j - 0.5 * (row_sizes[row] - 1)) * spacing);
      places.push_back(lattice + random->InDisc(0.25 * kRackGap));
    }
  }
  return places;
}

const std::vector<int> kTriangleRows = {1, 2, 3, 4, 5};
const std::vector<int> kDiamondRows = {1, 2, 3, 2, 1};
constexpr std::size_t kRackMiddle = 4;  // the middle place of the third row, in both shapes

// Ids 1..n except those in `taken`.
std::vector<int> Remaining(int n, const std::vector<int>& taken) {
  std::vector<int> ids;
  for (int id = 1; id <= n; ++id) {
    if (std::find(taken.begin(), taken.end(), id) == taken.end()) ids.push_back(id);
  }
  return ids;
}

std::vector<SceneBall> EightBall(const TableGeometry& table, double radius, SeededUniform* random) {
  const std::vector<Vector2d> places =
      RackPlaces(kTriangleRows, Vector2d(0.75 * table.length, 0.5 * table.width), radius, random);
  constexpr std::size_t kBackLeft = 10, kBackRight = 14;
  std::vector<int> ids(places.size(), 0);
  ids[kRackMiddle] = 8;
  const int solid = 1 + static_cast<int>(random->Below(7));
  const int stripe = 9 + static_cast<int>(random->Below(7));
  const bool solid_left = random->Next() < 0.5;
  ids[kBackLeft] = solid_left ? solid : stripe;
  ids[kBackRight] = solid_left ? stripe : solid;
  std::vector<int> rest = Remaining(15, {8, solid, stripe});
  random->Shuffle(&rest);
  std::vector<SceneBall> balls;
  for (std::size_t i = 0, next = 0; i < places.size(); ++i) {
    balls.push_back(AtRest(ids[i] != 0 ? ids[i] : rest[next++], places[i]));
  }
  return balls;
}

std::vector<SceneBall> NineBall(const TableGeometry& table, double radius, SeededUniform* random) {
  const std::vector<Vector2d> places =
      RackPlaces(kDiamondRows, Vector2d(0.75 * table.length, 0.5 * table.width), radius, random);
  std::vector<int> rest = Remaining(8, {1});
  random->Shuffle(&rest);
  std::vector<SceneBall> balls;
  for (std::size_t i = 0, next = 0; i < places.size(); ++i) {
    const int id = i == 0 ? 1 : i == kRackMiddle ? 9 : rest[next++];
    balls.push_back(AtRest(id, places[i]));
  }
  return balls;
}

std::vector<SceneBall> Snooker(const TableGeometry& table, double radius, SeededUniform* random) {
  const double middle = 0.5 * table.width;
  const Vector2d pink(0.75 * table.length, middle);
  std::vector<SceneBall> balls = {
      AtRest(kSnookerYellow, Vector2d(kBaulkLine, middle - kDRadius)),
      AtRest(kSnookerGreen, Vector2d(kBaulkLine, middle + kDRadius)),
      AtRest(kSnookerBrown, Vector2d(kBaulkLine, middle)),
      AtRest(kSnookerBlue, Vector2d(0.5 * table.length, middle)),
      AtRest(kSnookerPink, pink),
      AtRest(kSnookerBlack, Vector2d(table.length - kBlackSpot, middle))};
  const Vector2d apex = pink + Vector2d(2 * radius + 0.5 * kRackGap, 0);
  const std::vector<Vector2d> reds = RackPlaces(kTriangleRows, apex, radius, random);
  for (std::size_t i = 0; i < reds.size(); ++i) balls.push_back(AtRest(1 + i, reds[i]));
  return balls;
}

// Where the cue ball goes before its jitter.
Vector2d CuePlace(RackKind kind, const TableGeometry& table, double radius) {
  const double middle = 0.5 * table.width;
  switch (kind) {
    case RackKind::kSnooker:
      // In the D, between the brown and the yellow, a radius behind the baulk line.
      return Vector2d(kBaulkLine - radius, middle - 0.5 * kDRadius);
    case RackKind::kThreeCushion:
      return Vector2d(0.25 * table.length, middle - kStartingSpotOffset);
    case RackKind::kEightBall:
    case RackKind::kNineBall:
      break;
  }
  return Vector2d(0.25 * table.length, middle);  // the head spot
}

void RequireFits(const std::vector<SceneBall>& balls, const TableGeometry& table, double radius) {
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const Vector2d p = balls[i].state.head<2>();
    if (!table.OnSurface(p, radius)) {
      throw std::invalid_argument("rack does not fit on table '" + table.name + "': ball " +
                                  std::to_string(balls[i].id) + " off the playing surface");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if ((p - balls[j].state.head<2>()).norm() < 2 * radius) {
        throw std::invalid_argument("rack does not fit on table '" + table.name + "': balls " +
                                    std::to_string(balls[j].id) + " and " +
                                    std::to_string(balls[i].id) + " overlap");
      }
    }
  }
}

}  // namespace

std::vector<SceneBall> Rack(RackKind kind, const TableGeometry& table, double ball_radius,
                            std::uint64_t seed) {
  if (!std::isfinite(ball_radius) || ball_radius <= 0) {
    throw std::invalid_argument("rack: ball radius must be positive");
  }
  SeededUniform random(seed);
  std::vector<SceneBall> balls = {
      AtRest(0, CuePlace(kind, table, ball_radius) + random.InDisc(kCueJitter))};
  std::vector<SceneBall> others;
  switch (kind) {
    case RackKind::kEightBall:
      others = EightBall(table, ball_radius, &random);
      break;
    case RackKind::kNineBall:
      others = NineBall(table, ball_radius, &random);
      break;
    case RackKind::kSnooker:
      others = Snooker(table, ball_radius, &random);
      break;
    case RackKind::kThreeCushion:
      others = {AtRest(1, Vector2d(0.25 * table.length, 0.5 * table.width)),
                AtRest(2, Vector2d(0.75 * table.length, 0.5 * table.width))};
      break;
  }
  balls.insert(balls.end(), others.begin(), others.end());
  RequireFits(balls, table, ball_radius);
  return balls;
}

RackKind ParseRackKind(const std::string& name) {
  const std::pair<const char*, RackKind> kinds[] = {{"eight-ball", RackKind::kEightBall},
                                                    {"nine-ball", RackKind::kNineBall},
                                                    {"snooker", RackKind::kSnooker},
                                                    {"three-cushion", RackKind::kThreeCushion}};
  for (const auto& [text, kind] : kinds) {
    if (name == text) return kind;
  }
  throw std::invalid_argument("unknown rack '" + name +
                              "' (eight-ball, nine-ball, snooker or three-cushion)");
}

bool FreePlace(const TableGeometry& table, double radius, const std::vector<SceneBall>& balls,
               const Eigen::Vector2d& p, double clearance) {
  if (!table.OnSurface(p, radius)) return false;
  return std::all_of(balls.begin(), balls.end(), [&](const SceneBall& b) {
    return (b.state.segment<2>(physics::kX) - p).norm() >= 2 * radius + clearance;
  });
}

Eigen::Vector2d FreeSpotFrom(const TableGeometry& table, double radius,
                             const std::vector<SceneBall>& balls, Eigen::Vector2d spot,
                             const Eigen::Vector2d& step, double clearance) {
  while (!FreePlace(table, radius, balls, spot, clearance) && table.OnSurface(spot + step, 0.0)) {
    spot += step;
  }
  return spot;
}

std::vector<SceneBall> WithBallAt(std::vector<SceneBall> balls, int id,
                                  const Eigen::Vector2d& place) {
  balls.erase(
      std::remove_if(balls.begin(), balls.end(), [id](const SceneBall& b) { return b.id == id; }),
      balls.end());
  SceneBall placed;
  placed.id = id;
  placed.state.segment<2>(physics::kX) = place;
  balls.insert(balls.begin(), placed);
  return balls;
}

std::vector<SceneBall> SeededNineBallLayout(const TableGeometry& table, double radius,
                                            std::uint64_t seed) {
  // Clear of the others by this beyond touching [m].
  constexpr double kClearance = 2e-3;
  SeededUniform uniform(seed);
  std::vector<SceneBall> balls;
  for (int id = 1; id <= 9; ++id) {
    for (;;) {
      const Eigen::Vector2d p(uniform.Between(0, table.length), uniform.Between(0, table.width));
      // A ball's width clear of the cushions: inside the surface shrunk by a diameter.
      if (!table.OnSurface(p, 3 * radius)) continue;
      if (!FreePlace(table, 2 * radius, balls, p, kClearance)) continue;
      SceneBall b;
      b.id = id;
      b.state.segment<2>(physics::kX) = p;
      balls.push_back(b);
      break;
    }
  }
  return balls;
}

}  // namespace billiard::table
