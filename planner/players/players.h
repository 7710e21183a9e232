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

// "ours" as round 3 chose, without safeties and with the next shot valued in closed form
// (issue 48's baseline: the player it asks the new one to beat): MakePlayer makes it;
// PlayerNames lists the three kinds of player.
inline constexpr char kOursNoSafety[] = "ours-no-safety";
// "ours" with the one-level lookahead (the next shot in closed form): the two levels' baseline.
inline constexpr char kOursOneLevel[] = "ours-one-level";

// Every name MakePlayer knows: PlayerNames, then kOursNoSafety and kOursOneLevel (what a
// command's --player or --players accepts).
std::vector<std::string> KnownPlayerNames();

// KnownPlayerNames joined by ", " (a command's help, an error naming the known ones).
std::string KnownPlayerList();

// The player named `name` (one of KnownPlayerNames); throws std::invalid_argument naming it and
// the known ones otherwise.
std::unique_ptr<Player> MakePlayer(const std::string& name);

}  // namespace billiard::players
