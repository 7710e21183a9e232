#include "planner/game/match_summary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "sim/batch/wilson.h"
#include "planner/players/players.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::game {
namespace {

// A tally of `attempts` shots, `pots` of them potted, fouls by reason, decision times.
PlayerTally Tally(int attempts, int pots, std::map<std::string, int> fouls,
                  std::vector<double> decisions_us) {
  PlayerTally t;
  t.attempts = attempts;
  t.pots = pots;
  for (const auto& [reason, count] : fouls) t.fouls += count;
  t.foul_reasons = std::move(fouls);
  t.decisions_us = std::move(decisions_us);
  return t;
}

// Three racks by hand: player 0 wins one by break-and-run, player 1 one, one is undecided;
// every count is the sum of the racks', the decision times in the order the racks came.
TEST(AddRackTest, SumsTheRacksFigures) {
  MatchRecord match;
  AddRack({0, true, {Tally(5, 5, {}, {1, 2}), Tally(0, 0, {}, {})}}, &match);
  AddRack({1, false, {Tally(3, 1, {{"scratch", 1}}, {3}), Tally(4, 3, {{"scratch", 2}}, {4})}},
          &match);
  AddRack({-1, false, {Tally(2, 0, {{"no contact", 1}}, {5}), Tally(1, 1, {}, {6})}}, &match);
  EXPECT_EQ(match.players[0].racks_won, 1);
  EXPECT_EQ(match.players[0].break_and_runs, 1);
  EXPECT_EQ(match.players[1].racks_won, 1);
  EXPECT_EQ(match.players[1].break_and_runs, 0);
  EXPECT_EQ(match.undecided, 1);
  EXPECT_EQ(match.players[0].attempts, 10);
  EXPECT_EQ(match.players[0].pots, 6);
  EXPECT_EQ(match.players[0].fouls, 2);
  EXPECT_EQ(match.players[0].foul_reasons, (std::map<std::string, int>{{"no contact", 1}, {"scratch", 1}}));
  EXPECT_EQ(match.players[1].foul_reasons.at("scratch"), 2);
  EXPECT_EQ(match.players[0].decisions_us, (std::vector<double>{1, 2, 3, 5}));
  EXPECT_EQ(match.players[1].decisions_us, (std::vector<double>{4, 6}));
}

// The JSON's racks are the racks won and undecided; the win rates and intervals Wilson's of
// them; the decision times' median and 95th percentile by nearest rank over 1..100 us.
TEST(MatchJsonTest, RatesIntervalsAndDecisionTimes) {
  MatchRecord match;
  match.players[0].name = "ours";
  match.players[1].name = "easiest-looking";
  std::vector<double> us(100);
  std::iota(us.begin(), us.end(), 1.0);
  match.players[0].decisions_us.assign(us.begin(), us.begin() + 60);
  match.players[1].decisions_us.assign(us.begin() + 60, us.end());
  match.players[0].racks_won = 7;
  match.players[1].racks_won = 2;
  match.undecided = 1;
  const nlohmann::json j = MatchJson(match, {"nine-ball", "computational-pool", 5});
  EXPECT_EQ(j["game"], "nine-ball");
  EXPECT_EQ(j["noise"], "computational-pool");
  EXPECT_EQ(j["seed"], 5);
  EXPECT_EQ(j["racks"], 10);
  EXPECT_EQ(j["undecided"], 1);
  EXPECT_EQ(j["players"][0]["name"], "ours");
  EXPECT_DOUBLE_EQ(j["players"][0]["win_rate"].get<double>(), 0.7);
  const batch::Interval wilson = batch::WilsonInterval(7, 10);
  EXPECT_DOUBLE_EQ(j["players"][0]["interval95"][0].get<double>(), wilson.lo);
  EXPECT_DOUBLE_EQ(j["players"][0]["interval95"][1].get<double>(), wilson.hi);
  EXPECT_DOUBLE_EQ(j["decision_us"]["median"].get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(j["decision_us"]["p95"].get<double>(), 95.0);
  EXPECT_DOUBLE_EQ(j["players"][1]["decision_us"]["median"].get<double>(), 80.0);
}

// The figures that do not depend on the clock: everything but the decision times.
nlohmann::json WithoutTimes(nlohmann::json j) {
  j.erase("decision_us");
  for (nlohmann::json& p : j["players"]) p.erase("decision_us");
  return j;
}

// Racks played apart, last first, each on a pool of its own, sum to the match one process
// plays in order: a rack's figures depend on the seed and its index alone.
TEST(AddRackTest, RacksPlayedApartSumToTheMatch) {
  const physics::ModelParameters params = params::LoadParameters("pool");
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  MatchOptions options;
  options.players = {players::MakePlayer("easiest-looking"),
                     players::MakePlayer("easiest-looking")};
  options.execution = params::LoadNoise("computational-pool");
  options.choice.noise = options.execution;
  options.seed = 3;
  options.racks = 4;
  batch::ThreadPool two(2);
  MatchRecord apart;
  for (int p = 0; p < 2; ++p) apart.players[p].name = options.players[p]->Name();
  for (int rack = options.racks - 1; rack >= 0; --rack) {
    batch::ThreadPool one(1);
    RackFigures figures;
    const RackResult r = PlayRack(table, params, rack, options, one, &figures.players);
    figures.winner = r.winner;
    figures.break_and_run = r.break_and_run;
    AddRack(figures, &apart);
  }
  const MatchLabels labels{"nine-ball", "computational-pool", options.seed};
  const nlohmann::json together = MatchJson(PlayMatch(table, params, options, two), labels);
  EXPECT_EQ(WithoutTimes(MatchJson(apart, labels)), WithoutTimes(together));
  EXPECT_EQ(together["racks"], options.racks);
  EXPECT_GT(together["players"][0]["attempts"].get<int>() +
                together["players"][1]["attempts"].get<int>(),
            0);
}

}  // namespace
}  // namespace billiard::game
