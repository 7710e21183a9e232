// The players by name: `billiard play --policy`, `bench-game`'s drills, the game's options.
//
// Module: billiard::players.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "planner/players/player.h"

namespace billiard::players {

// "ours", "no-lookahead", "easiest-looking", in that order: the players, each once.
std::vector<std::string> PlayerNames();

// The name "ours" also goes by in a match against a player with safeties: the same player until
// ours plays safeties (issue 48). MakePlayer makes it; PlayerNames does not list it twice.
inline constexpr char kOursNoSafety[] = "ours-no-safety";

// The player named `name` (one of PlayerNames, or kOursNoSafety); throws std::invalid_argument naming it and the known ones otherwise.
std::unique_ptr<Player> MakePlayer(const std::string& name);

}  // namespace billiard::players
