#include "planner/game/run_out_fit.h"

namespace billiard::game {

namespace {

// A shot that weighed a safety against its best attempt, added to the side it played.
void CountWeighed(const nlohmann::json& shot, bool won, RunOutCounts* counts) {
  const double attempt = shot.at("attempt_win").get<double>();
  const double safety = shot.at("safety_win").get<double>();
  if (attempt < 0.0 || safety < 0.0) return;
  const bool safe = shot.at("safety").get<bool>();
  RunOutCounts::Weighed& side = safe ? counts->safeties : counts->attempts;
  ++side.count;
  side.estimated += safe ? safety : attempt;
  side.won += won;
}

}  // namespace

void CountRunOut(const nlohmann::json& rack, int player, RunOutCounts* counts) {
  const nlohmann::json& shots = rack.at("shots");
  const nlohmann::json& winner = rack.at("winner");
  const bool won = !winner.is_null() && winner.get<int>() == player;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    if (shots[i].at("player").get<int>() == player) CountWeighed(shots[i], won, counts);
  }
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
      kept = won;
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
