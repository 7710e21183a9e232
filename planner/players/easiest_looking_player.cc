#include "planner/players/easiest_looking_player.h"

#include "planner/choice/easiest_looking.h"

namespace billiard::players {

choice::ChoiceResult EasiestLooking::Decide(const Turn& turn,
                                            const choice::ChoiceOptions& options,
                                            batch::ThreadPool& /*pool*/) const {
  return choice::ChooseEasiestLooking(turn.table, turn.params, turn.balls, options,
                                      turn.constraints.ball_in_hand);
}

}  // namespace billiard::players
