// The games by name: the rulesets a choice, a game and the table simulator are told to play.
// Each game is a file of its own (any.h, nine_ball.h, eight_ball.h); this is where a name finds
// it.
//
// Module: billiard::rules.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/rules/ruleset.h"

namespace billiard::rules {

// kAny: any object ball may be hit first and potted (any.h). kNineBall: the WPA Rules of Play's
// nine-ball (nine_ball.h). kEightBall: the computational pool's eight-ball on an open table;
// kEightBallSolids, kEightBallStripes: the same for a player whose group is taken
// (eight_ball.h).
enum class Rules { kAny, kNineBall, kEightBall, kEightBallSolids, kEightBallStripes };

// The ruleset of `rules` (one for the program's life).
const Ruleset& RulesetOf(Rules rules);

// Whether `rules` is eight-ball's, on an open table or with a group taken.
bool IsEightBall(Rules rules);

// "any", "nine-ball", "eight-ball", "eight-ball-solids", "eight-ball-stripes".
const char* RulesName(Rules rules);
// std::nullopt for an unknown name.
std::optional<Rules> ParseRules(const std::string& name);

// The object balls that may be hit first (and potted by a called shot) under `rules`: ids > 0
// on the table, ascending; under nine-ball the lowest alone; under eight-ball the group's.
std::vector<int> LegalTargets(Rules rules, const std::vector<table::SceneBall>& balls);

}  // namespace billiard::rules
