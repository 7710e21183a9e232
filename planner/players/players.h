// The players by name: `billiard play --policy`, `bench-game`'s drills, the game's options.
//
// Module: billiard::players.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "planner/players/player.h"

namespace billiard::players {

// "ours", "no-lookahead", "easiest-looking", in that order.
std::vector<std::string> PlayerNames();

// The player named `name`; throws std::invalid_argument naming it and the known ones otherwise.
std::unique_ptr<Player> MakePlayer(const std::string& name);

}  // namespace billiard::players
