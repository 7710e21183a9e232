#include "planner/players/easiest_looking_player.h"

#include "planner/choice/easiest_looking.h"

namespace billiard::players {

choice::ChoiceResult EasiestLooking::Decide(const table::TableGeometry& table,
                                            const physics::ModelParameters& params,
                                            const std::vector<table::SceneBall>& balls,
                                            const rules::Constraints& constraints,
                                            const choice::ChoiceOptions& options,
                                            batch::ThreadPool& /*pool*/) const {
  return choice::ChooseEasiestLooking(table, params, balls, options, constraints.ball_in_hand);
}

}  // namespace billiard::players
