// What a stroke's legality turns on besides its first contact (FirstBallMet): the balls driven
// to a rail after it. The pocket games' "No Rail after Contact" (WPA Rules of Play, Standard
// Fouls: after the cue ball meets the legal ball, a ball must be pocketed or the cue ball or a
// numbered ball must contact a rail) and their legal break (nine-ball: four numbered balls to
// the rail, or a ball pocketed) count these.
//
// A rail contact is an impact on a cushion's nose line or on a jaw's rounded nose (both are the
// cushion rubber); a ball dropping into a pocket is not one.
//
// Module: billiard::table.
#pragma once

#include <vector>

#include "sim/table/table_simulation.h"

namespace billiard::table {

// Whether an event of `type` is a rail contact (a cushion's nose or a jaw's).
bool IsRailContact(EventType type);

// The ids of the balls that meet a cushion or a jaw in `events` after ball `id` first meets a
// ball, each once, ascending; none when it meets no ball.
std::vector<int> BallsToRailAfterFirstContact(const std::vector<TableEvent>& events, int id);

}  // namespace billiard::table
