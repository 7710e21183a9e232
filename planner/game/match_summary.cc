#include "planner/game/match_summary.h"

#include <vector>

#include "planner/game/game_json.h"
#include "sim/batch/wilson.h"
#include "sim/rules/match_standing.h"

namespace billiard::game {

namespace {

constexpr double kMedian = 0.5;
constexpr double kP95 = 0.95;

void AddTally(const PlayerTally& rack, PlayerTally* total) {
  total->attempts += rack.attempts;
  total->pots += rack.pots;
  total->safeties += rack.safeties;
  total->safeties_that_worked += rack.safeties_that_worked;
  total->fouls += rack.fouls;
  for (const auto& [reason, count] : rack.foul_reasons) total->foul_reasons[reason] += count;
  total->decisions_us.insert(total->decisions_us.end(), rack.decisions_us.begin(),
                             rack.decisions_us.end());
}

nlohmann::json DecisionJson(const std::vector<double>& us) {
  return {{"median", Quantile(us, kMedian)}, {"p95", Quantile(us, kP95)}};
}

nlohmann::json PlayerJson(const PlayerTally& p, int racks) {
  nlohmann::json j = rules::MatchPlayerJson(
      p.name, {p.racks_won, p.break_and_runs, p.attempts, p.pots, p.safeties, p.fouls}, racks);
  j["safeties_that_worked"] = p.safeties_that_worked;
  j["foul_reasons"] = p.foul_reasons;
  j["decision_us"] = DecisionJson(p.decisions_us);
  return j;
}

}  // namespace

void AddRack(const RackFigures& rack, MatchRecord* match) {
  for (int p = 0; p < 2; ++p) AddTally(rack.players[p], &match->players[p]);
  if (rack.winner < 0) {
    ++match->undecided;
    return;
  }
  ++match->players[rack.winner].racks_won;
  match->players[rack.winner].break_and_runs += rack.break_and_run;
}

nlohmann::json MatchJson(const MatchRecord& match, const MatchLabels& labels) {
  const int racks = match.players[0].racks_won + match.players[1].racks_won + match.undecided;
  nlohmann::json j = {{"game", labels.game}, {"racks", racks}, {"seed", labels.seed},
                      {"noise", labels.noise}, {"undecided", match.undecided}};
  std::vector<double> every;
  for (const PlayerTally& p : match.players) {
    j["players"].push_back(PlayerJson(p, racks));
    every.insert(every.end(), p.decisions_us.begin(), p.decisions_us.end());
  }
  j["decision_us"] = DecisionJson(every);
  return j;
}

nlohmann::json RateJson(int count, int trials) {
  const batch::Interval i = batch::WilsonInterval(count, trials);
  return {{"count", count},
          {"of", trials},
          {"rate", trials ? static_cast<double>(count) / trials : 0.0},
          {"interval95", {i.lo, i.hi}}};
}

nlohmann::json RackJson(const RackResult& rack) {
  nlohmann::json shots = nlohmann::json::array();
  for (const ShotRecord& s : rack.shots) shots.push_back(ShotJson(s));
  return {{"rack", rack.rack},
          {"breaker", rack.breaker},
          {"winner", rack.winner < 0 ? nlohmann::json(nullptr) : nlohmann::json(rack.winner)},
          {"reason", rack.reason},
          {"break_and_run", rack.break_and_run},
          {"shots", shots}};
}

}  // namespace billiard::game
