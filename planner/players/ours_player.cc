#include "planner/players/ours_player.h"

#include <chrono>

#include "planner/choice/ball_in_hand.h"
#include "planner/choice/safety.h"
#include "planner/choice/shot_choice.h"

namespace billiard::players {

namespace {

choice::ChoiceResult Choose(const Turn& turn, const choice::ChoiceOptions& options,
                            batch::ThreadPool& pool) {
  if (turn.constraints.ball_in_hand) {
    return choice::ChooseWithBallInHand(turn.table, turn.params, turn.balls, options, pool);
  }
  return choice::ChooseShot(turn.table, turn.params, turn.balls, options, pool);
}

}  // namespace

choice::ChoiceResult Ours::Decide(const Turn& turn, const choice::ChoiceOptions& options,
                                  batch::ThreadPool& pool) const {
  const auto start = std::chrono::steady_clock::now();
  choice::ChoiceOptions played = options;
  played.lookahead = lookahead_ && options.lookahead;
  played.second_level = two_level_ && options.second_level;
  choice::ChoiceResult result = Choose(turn, played, pool);
  if (safeties_ && !turn.alone && !turn.constraints.ball_in_hand) {
    choice::ConsiderSafety(turn.table, turn.params, turn.balls, played, pool, &result);
    result.decision_us = choice::MicrosecondsSince(start);
  }
  return result;
}

}  // namespace billiard::players
