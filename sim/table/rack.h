// The balls of a game's opening position, at rest on a table.
//
// Where the rules put them:
//  - eight-ball: 15 balls in a triangle, its apex on the foot spot (the middle of the foot half,
//    x = 3/4 length), the 8 in the middle of the third row, a solid (1-7) in one back corner and
//    a stripe (9-15) in the other, the rest in any order (WPA / BCA World Standardized Rules,
//    eight-ball racking);
//  - nine-ball: balls 1-9 in a diamond, the 1 at the apex on the foot spot, the 9 in the middle
//    (WPA Rules of Play,
//    nine-ball racking);
//  - snooker: 15 reds in a triangle behind the pink, its apex red as near the pink as it can be
//    without touching; the colours on their spots (WPBSA Official Rules, section 1(d)-(f) and
//    section 2: baulk line 737 mm from the bottom cushion, the D of radius 292 mm, brown at the
//    middle of the baulk line, yellow at the D's right-hand corner and green at its left seen
//    from the baulk end, blue at the centre, pink midway between the centre and the top cushion,
//    black 324 mm from the top cushion); the cue ball in the D, between the brown and the yellow;
//  - three-cushion (UMB World Rules of Carom, article 3.3 Starting position): the red on the top
//    spot (x = 3/4 length), the opponent's ball (yellow) on the bottom spot (x = 1/4 length), the
//    player's cue ball on a starting spot beside it, 182 mm across on the starting line (pooltool
//    uses 182.5 mm, Kiefl, layouts.py).
// The cue ball of pool sits on the head spot (x = 1/4 length, the middle of the kitchen).
// The bottom (baulk, head) end is x = 0, the top (foot) end x = length.
//
// Real racks are not perfect: neighbouring balls sit a tiny gap apart. Here each ball of a rack
// lies on a lattice of spacing 2R + kRackGap / 2 and is moved by at most kRackGap / 4 in a seeded
// direction, so neighbours are 0 to kRackGap apart and none overlaps. The seed also shuffles
// the balls the rules leave free and moves the cue ball by at most kCueJitter. The seeded numbers
// come from std::mt19937_64 mapped to [0, 1) by hand (the standard distributions differ between
// standard libraries), so a seed gives the same rack everywhere.
//
// Ball ids: pool, the ball numbers (0 the cue ball, 1-15); snooker, 0 the cue ball, 1-15 the
// reds, 16 yellow, 17 green, 18 brown, 19 blue, 20 pink, 21 black; three-cushion, 0 the white
// cue ball, 1 yellow, 2 red.
//
// Module: billiard::table.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/physics/ball_state.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::table {

enum class RackKind { kEightBall, kNineBall, kSnooker, kThreeCushion };

// Largest gap between neighbouring balls of a rack [m] (0.1 mm).
inline constexpr double kRackGap = 1e-4;
// Largest seeded displacement of the cue ball from its place [m].
inline constexpr double kCueJitter = 2e-3;

// The snooker ids of the colours.
enum SnookerId : int {
  kSnookerYellow = 16,
  kSnookerGreen,
  kSnookerBrown,
  kSnookerBlue,
  kSnookerPink,
  kSnookerBlack
};

// The balls of the rack at rest on `table`, the cue ball first. Throws std::invalid_argument if
// the rack does not fit on the table (a pocketed game on a carom table is allowed if it fits).
std::vector<SceneBall> Rack(RackKind kind, const TableGeometry& table, double ball_radius,
                            std::uint64_t seed);

// "eight-ball" | "nine-ball" | "snooker" | "three-cushion"; throws std::invalid_argument
// otherwise.
RackKind ParseRackKind(const std::string& name);

// Whether a ball centred at `p` lies on `table`'s surface (TableGeometry::OnSurface with
// `radius`) and at least 2 radius + clearance from every ball of `balls`.
bool FreePlace(const TableGeometry& table, double radius, const std::vector<SceneBall>& balls,
               const Eigen::Vector2d& p, double clearance);

// `spot` when a ball of `radius` is free there (FreePlace), else the first free place from it in
// steps of `step` while on the table (the last tried when none is).
Eigen::Vector2d FreeSpotFrom(const TableGeometry& table, double radius,
                             const std::vector<SceneBall>& balls, Eigen::Vector2d spot,
                             const Eigen::Vector2d& step, double clearance);

// `balls` with ball `id` lifted, if there, and placed at rest at `place`, first.
std::vector<SceneBall> WithBallAt(std::vector<SceneBall> balls, int id,
                                  const Eigen::Vector2d& place);

// A nine-ball layout for a drill from ball in hand: balls 1-9 placed uniformly on the playing
// surface from `seed` (SeededUniform), each a ball's width clear of the others and of the
// cushions; no cue ball.
std::vector<SceneBall> SeededNineBallLayout(const TableGeometry& table, double radius,
                                            std::uint64_t seed);

}  // namespace billiard::table
