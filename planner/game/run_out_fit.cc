#include "planner/game/run_out_fit.h"

namespace billiard::game {

void CountRunOut(const nlohmann::json& rack, int player, RunOutCounts* counts) {
  const nlohmann::json& shots = rack.at("shots");
  const nlohmann::json& winner = rack.at("winner");
  for (std::size_t i = 1; i < shots.size(); ++i) {
    const nlohmann::json& shot = shots[i];
    const nlohmann::json& before = shots[i - 1];
    if (shot.at("player").get<int>() != player) continue;
    bool kept = false;
    if (i + 1 < shots.size()) {
      kept = shots[i + 1].at("player").get<int>() == player;
    } else if (winner.is_null()) {
      continue;
    } else {
      kept = winner.get<int>() == player;
    }
    if (before.at("player").get<int>() == player) {
      if (before.at("break").get<bool>()) continue;
      ++counts->continuing;
      counts->continuing_kept += kept;
    } else if (!before.at("foul").get<bool>()) {
      ++counts->arriving;
      counts->arriving_kept += kept;
    }
  }
}

}  // namespace billiard::game
