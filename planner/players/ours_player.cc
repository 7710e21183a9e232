#include "planner/players/ours_player.h"

#include "planner/choice/ball_in_hand.h"
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
  if (lookahead_) return Choose(turn, options, pool);
  choice::ChoiceOptions without = options;
  without.lookahead = false;
  return Choose(turn, without, pool);
}

}  // namespace billiard::players
