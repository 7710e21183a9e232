#include "planner/players/no_lookahead_player.h"

namespace billiard::players {

choice::ChoiceResult NoLookahead::Decide(const table::TableGeometry& table,
                                         const physics::ModelParameters& params,
                                         const std::vector<table::SceneBall>& balls,
                                         const rules::Constraints& constraints,
                                         const choice::ChoiceOptions& options,
                                         batch::ThreadPool& pool) const {
  choice::ChoiceOptions without = options;
  without.lookahead = false;
  return Ours::Decide(table, params, balls, constraints, without, pool);
}

}  // namespace billiard::players
