// The figures of a match that its players' tallies (match.h) do not hold, read from its racks'
// shots: how the breaks went, and how often a player cleared a rack in one visit.
//
// One-visit clears are the figure pix2pockets reports for its eight-ball baseline (2025: 30 % of
// racks cleared in one visit): of the racks whose break was legal and in which the player came
// to the table, those it won without leaving it: its first visit after the break (the breaker's
// continuing the break when it potted) ran to the rack's end. A break-and-run is one of them.
//
// Module: billiard::game.
#pragma once

#include <array>

#include "planner/game/match.h"

namespace billiard::game {

// The breaks of a match, the first shot of each rack.
struct MatchBreaks {
  int racks = 0;
  int legal = 0;      // judged legal
  int potted = 0;     // an object ball dropped, legal or not
  int kept = 0;       // legal and potted: the breaker stays at the table
  int scratches = 0;  // judged a foul for a scratch
};

MatchBreaks BreaksOf(const MatchRecord& match);

// One player's one-visit clears.
struct OneVisitClears {
  int chances = 0;  // racks with a legal break in which the player had a visit
  int clears = 0;   // of those, the ones it won in its first visit
};

// Each player's one-visit clears over `match`'s racks.
std::array<OneVisitClears, 2> OneVisitClearsOf(const MatchRecord& match);

}  // namespace billiard::game
