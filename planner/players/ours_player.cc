#include "planner/players/ours_player.h"

#include "planner/choice/ball_in_hand.h"
#include "planner/choice/shot_choice.h"

namespace billiard::players {

choice::ChoiceResult Ours::Decide(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const rules::Constraints& constraints,
                                  const choice::ChoiceOptions& options,
                                  batch::ThreadPool& pool) const {
  if (constraints.ball_in_hand) {
    return choice::ChooseWithBallInHand(table, params, balls, options, pool);
  }
  return choice::ChooseShot(table, params, balls, options, pool);
}

}  // namespace billiard::players
