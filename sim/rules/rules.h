// The games by name: the rulesets a choice, a game and the table simulator are told to play.
// Each game is a file of its own (any.h, nine_ball.h); this is where a name finds it.
//
// Module: billiard::rules.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/rules/ruleset.h"

namespace billiard::rules {

// kAny: any object ball may be hit first and potted (any.h). kNineBall: the WPA Rules of Play's
// nine-ball, in the part judged (nine_ball.h).
enum class Rules { kAny, kNineBall };

// The ruleset of `rules` (one for the program's life).
const Ruleset& RulesetOf(Rules rules);

const char* RulesName(Rules rules);  // "any", "nine-ball"
// std::nullopt for an unknown name.
std::optional<Rules> ParseRules(const std::string& name);

// The object balls that may be hit first (and potted by a called shot) under `rules`: ids > 0
// on the table, ascending; under nine-ball the lowest alone.
std::vector<int> LegalTargets(Rules rules, const std::vector<table::SceneBall>& balls);

}  // namespace billiard::rules
