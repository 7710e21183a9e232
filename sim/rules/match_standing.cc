#include "sim/rules/match_standing.h"

#include "sim/batch/wilson.h"

namespace billiard::rules {

nlohmann::json MatchPlayerJson(const std::string& name, const MatchPlayerCounts& counts,
                               int racks) {
  const batch::Interval interval = batch::WilsonInterval(counts.racks_won, racks);
  return {{"name", name},
          {"racks_won", counts.racks_won},
          {"win_rate", racks ? static_cast<double>(counts.racks_won) / racks : 0.0},
          {"interval95", {interval.lo, interval.hi}},
          {"break_and_runs", counts.break_and_runs},
          {"pots", counts.pots},
          {"attempts", counts.attempts},
          {"safeties", counts.safeties},
          {"fouls", counts.fouls}};
}

}  // namespace billiard::rules
