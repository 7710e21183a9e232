#include "planner/game/match.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "planner/players/players.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::game {
namespace {

// A player that only ever nudges the cue ball toward the head rail: it meets no ball, a foul
// every shot ("no contact").
class AlwaysFouls final : public players::Player {
 public:
  const char* Name() const override { return "always-fouls"; }
  choice::ChoiceResult Decide(const players::Turn&, const choice::ChoiceOptions&,
                              batch::ThreadPool&) const override {
    choice::ChoiceResult r;
    r.status = choice::ChoiceStatus::kNoPlan;
    physics::CueStroke nudge;
    nudge.speed = 0.05;
    nudge.heading = M_PI;  // away from the rack at the foot
    r.fallback = nudge;
    return r;
  }
};

class MatchTest : public ::testing::Test {
 protected:
  MatchTest()
      : params_(params::LoadParameters("pool")),
        table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {
    options_.choice.samples = 8;
    options_.choice.screen_samples = 4;
    options_.choice.finalists = 2;
    options_.choice.confirm_samples = 0;
    options_.choice.placements = 2;
    options_.choice.position_plans = 1;
    options_.choice.kinds = {pot::ShotKind::kDirect};
    options_.execution = params::LoadNoise("computational-pool");
    options_.shot_limit = 40;
  }
  physics::ModelParameters params_;
  table::TableGeometry table_;
  MatchOptions options_;
};

// Two players who foul every shot: after the break the one who fouls three times in a row first
// loses, and that is the player who shot right after the break (the breaker when it potted).
TEST_F(MatchTest, ThreeFoulsInARowLoseTheRack) {
  options_.players = {std::make_shared<AlwaysFouls>(), std::make_shared<AlwaysFouls>()};
  options_.racks = 2;
  batch::ThreadPool pool(1);
  const MatchRecord match = PlayMatch(table_, params_, options_, pool);
  for (const RackResult& r : match.racks) {
    EXPECT_EQ(r.breaker, r.rack % 2);
    EXPECT_EQ(r.shots.front().player, r.breaker);
    EXPECT_TRUE(r.shots.front().break_shot);
    EXPECT_EQ(r.reason, "3 fouls in a row");
    ASSERT_EQ(r.shots.size(), 6u);  // the break, then five fouls alternating
    const int first = r.shots[1].player;
    for (std::size_t i = 1; i < r.shots.size(); ++i) {
      EXPECT_EQ(r.shots[i].foul_reason, "no contact");
      EXPECT_EQ(r.shots[i].player, (first + static_cast<int>(i) - 1) % 2);
    }
    EXPECT_EQ(r.winner, 1 - first);
  }
  const int break_fouls = match.racks[0].shots[0].foul + match.racks[1].shots[0].foul;
  EXPECT_EQ(match.players[0].fouls + match.players[1].fouls, 10 + break_fouls);
  EXPECT_EQ(match.players[0].foul_reasons.at("no contact") +
                match.players[1].foul_reasons.at("no contact"),
            10);
}

// The table changes hands exactly when the rules end the visit: after a foul or a shot that
// pots nothing (nine-ball); the tallies add up to the shots played.
TEST_F(MatchTest, VisitsAlternateAsTheRulesSay) {
  options_.players = {players::MakePlayer("easiest-looking"),
                      players::MakePlayer("easiest-looking")};
  options_.racks = 2;
  batch::ThreadPool pool(2);
  const MatchRecord match = PlayMatch(table_, params_, options_, pool);
  int attempts = 0, pots = 0, fouls = 0;
  for (const RackResult& r : match.racks) {
    for (std::size_t i = 0; i + 1 < r.shots.size(); ++i) {
      const ShotRecord& s = r.shots[i];
      const bool turn_over = s.foul || s.potted.empty();
      EXPECT_EQ(r.shots[i + 1].player != s.player, turn_over) << "rack " << r.rack << " shot " << i;
    }
    for (const ShotRecord& s : r.shots) {
      attempts += !s.break_shot && s.ball >= 0;
      pots += s.called_potted;
      fouls += s.foul;
    }
  }
  EXPECT_EQ(match.players[0].attempts + match.players[1].attempts, attempts);
  EXPECT_EQ(match.players[0].pots + match.players[1].pots, pots);
  EXPECT_EQ(match.players[0].fouls + match.players[1].fouls, fouls);
  EXPECT_EQ(match.players[0].racks_won + match.players[1].racks_won + match.undecided, 2);
}

// Eight-ball: every shot after the break calls a ball and pocket, and once a player's group is
// taken its calls are of that group (or the 8 after it).
TEST_F(MatchTest, EightBallCallsAndKeepsToTheGroup) {
  options_.game = rules::Rules::kEightBall;
  options_.players = {players::MakePlayer("easiest-looking"),
                      players::MakePlayer("easiest-looking")};
  options_.racks = 1;
  batch::ThreadPool pool(2);
  const RackResult r = PlayMatch(table_, params_, options_, pool).racks.front();
  std::array<int, 2> group = {0, 0};  // 1 solids, 2 stripes, by the first call potted
  for (const ShotRecord& s : r.shots) {
    if (s.break_shot || s.status != "ok") continue;
    EXPECT_GE(s.ball, 1);
    EXPECT_FALSE(s.pocket.empty());
    const int g = s.ball < 8 ? 1 : (s.ball > 8 ? 2 : 0);
    if (group[s.player] != 0 && g != 0) EXPECT_EQ(g, group[s.player]) << s.number;
    if (group[s.player] == 0 && s.called_potted && g != 0) {
      group[s.player] = g;
      group[1 - s.player] = 3 - g;
    }
  }
}

// The same seed plays the same match on one thread or two, shot for shot.
TEST_F(MatchTest, IdenticalWhateverTheThreads) {
  options_.players = {players::MakePlayer("ours"), players::MakePlayer("easiest-looking")};
  options_.racks = 1;
  options_.shot_limit = 6;
  batch::ThreadPool one(1), two(2);
  const MatchRecord a = PlayMatch(table_, params_, options_, one);
  const MatchRecord b = PlayMatch(table_, params_, options_, two);
  ASSERT_EQ(a.racks[0].shots.size(), b.racks[0].shots.size());
  for (std::size_t i = 0; i < a.racks[0].shots.size(); ++i) {
    const ShotRecord &x = a.racks[0].shots[i], &y = b.racks[0].shots[i];
    EXPECT_EQ(x.player, y.player);
    EXPECT_EQ(x.ball, y.ball);
    EXPECT_EQ(x.pocket, y.pocket);
    EXPECT_EQ(x.potted, y.potted);
    EXPECT_EQ(x.predicted, y.predicted);
    EXPECT_EQ(x.safety, y.safety);
    EXPECT_EQ(x.cue_placement.has_value(), y.cue_placement.has_value());
  }
  EXPECT_EQ(a.racks[0].winner, b.racks[0].winner);
}

// A shot of `player`: a safety, a foul, an attempt of probability `predicted` (-1: no call).
ShotRecord Shot(int player, bool safety, bool foul, double predicted) {
  ShotRecord s;
  s.player = player;
  s.safety = safety;
  s.foul = foul;
  s.predicted = predicted;
  s.ball = predicted < 0 ? -1 : 1;
  return s;
}

// A safety worked when the opponent's next shot fouled or attempted nothing above 50 %, the
// shooter's own shots after it (a pot on the safety kept the table) passed over.
TEST(SafetyWorkedTest, JudgedOnTheOpponentsNextShot) {
  RackResult rack;
  rack.winner = 1;
  rack.shots = {Shot(0, true, false, -1), Shot(1, false, false, 0.8),   // an easy shot left
                Shot(1, true, false, -1), Shot(0, false, false, 0.4),   // a hard one left
                Shot(0, true, false, -1), Shot(1, false, true, 0.9),    // they fouled
                Shot(1, true, false, -1), Shot(1, false, false, 0.9),   // kept the table ...
                Shot(0, false, false, 0.5),                             // ... then 50 %
                Shot(0, true, false, -1)};                              // the rack's last shot
  EXPECT_FALSE(SafetyWorked(rack, 0));
  EXPECT_TRUE(SafetyWorked(rack, 2));
  EXPECT_TRUE(SafetyWorked(rack, 4));
  EXPECT_TRUE(SafetyWorked(rack, 6));
  EXPECT_FALSE(SafetyWorked(rack, 9));  // no reply, and player 0 lost the rack
}

// A match by name: the table's noise is the one the players assume, and a bad name is refused
// with the field at fault first.
TEST(OptionsOfTest, NamesTheFieldAtFault) {
  const MatchOptions options =
      OptionsOf({"eight-ball", {"ours", "easiest-looking"}, "computational-pool", 9, 12, 30});
  EXPECT_EQ(options.game, rules::Rules::kEightBall);
  EXPECT_STREQ(options.players[1]->Name(), "easiest-looking");
  EXPECT_EQ(options.execution.name, "computational-pool");
  EXPECT_EQ(options.execution.heading, params::LoadNoise("computational-pool").heading);
  EXPECT_EQ(options.choice.noise.name, options.execution.name);
  EXPECT_EQ(options.choice.noise.heading, options.execution.heading);
  EXPECT_EQ(options.seed, 9u);
  EXPECT_EQ(options.racks, 12);
  EXPECT_EQ(options.shot_limit, 30);
  const auto refusal = [](const MatchNames& names) {
    try {
      OptionsOf(names);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).substr(0, std::string(e.what()).find(':'));
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal({"snooker", {"ours", "ours"}, "robot"}), "game");
  EXPECT_EQ(refusal({"any", {"ours", "ours"}, "robot"}), "game");
  EXPECT_EQ(refusal({"nine-ball", {"ours", "nobody"}, "robot"}), "players");
  EXPECT_EQ(refusal({"nine-ball", {"ours", "ours"}, "/no/such.json"}), "noise");
}

TEST(QuantileTest, NearestRank) {
  EXPECT_EQ(Quantile({}, 0.5), 0.0);
  EXPECT_EQ(Quantile({5, 1, 3, 2, 4}, 0.5), 3.0);
  EXPECT_EQ(Quantile({5, 1, 3, 2, 4}, 0.95), 5.0);
  EXPECT_EQ(Quantile({5, 1, 3, 2, 4}, 0.0), 1.0);
}

}  // namespace
}  // namespace billiard::game
