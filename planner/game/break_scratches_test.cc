// The scratch classes read from events built by hand (the truth by construction), from a cue
// ball struck alone into a corner pocket, and counted over racks as the break's rates count
// them.
#include "planner/game/break_scratches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "planner/choice/monte_carlo.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/testing/events.h"

namespace billiard::game {
namespace {

using table::EventType;
using table::TableEvent;
using table::testing::Event;

TableEvent Drop(int ball, const std::string& pocket) {
  TableEvent e = Event(EventType::kBallPocket, ball);
  e.pocket = pocket;
  return e;
}

// `r` is a scratch in `pocket` by `path`, after `balls` ball contacts and `rails` rails.
void ExpectScratch(const std::optional<ScratchRecord>& r, const std::string& pocket,
                   ScratchPath path, int balls, int rails) {
  ASSERT_TRUE(r);
  EXPECT_EQ(r->pocket, pocket);
  EXPECT_EQ(r->path, path);
  EXPECT_EQ(r->balls_met, balls);
  EXPECT_EQ(r->rails, rails);
}

TEST(CueBallScratchTest, RailsCountFromTheLastBallContact) {
  const std::vector<TableEvent> events = {
      Event(EventType::kBallBall, 0, 1),
      Event(EventType::kBallCushion, 0),
      Event(EventType::kBallCushion, 5),  // another ball's rail: not the cue ball's
      Event(EventType::kBallBall, 2, 0),  // the cue ball as the pair's other ball
      Event(EventType::kBallCushion, 0),
      Event(EventType::kBallJaw, 0),
      Drop(0, "upper_left")};
  ExpectScratch(CueBallScratch(events, true), "upper_left", ScratchPath::kOffRails, 2, 2);
}

TEST(CueBallScratchTest, ADropStraightFromABallIsDirect) {
  const std::vector<TableEvent> events = {Event(EventType::kBallCushion, 0),
                                          Event(EventType::kBallBall, 0, 1), Drop(1, "lower_right"),
                                          Drop(0, "lower_middle")};
  ExpectScratch(CueBallScratch(events, true), "lower_middle", ScratchPath::kDirect, 1, 0);
}

TEST(CueBallScratchTest, NoDropIsNoScratchUnlessTheBallHangsPastAMouth) {
  const std::vector<TableEvent> events = {Event(EventType::kBallBall, 0, 1),
                                          Drop(1, "lower_right")};
  EXPECT_FALSE(CueBallScratch(events, false));
  ExpectScratch(CueBallScratch(events, true), "", ScratchPath::kHanging, 1, 0);
  EXPECT_STREQ(ScratchPathName(ScratchPath::kHanging), "hanging");
}

// The cue ball alone struck along the diagonal at the corner pocket at the origin: it drops
// there having met no ball.
TEST(CueBallScratchTest, ACueBallStruckAloneIntoACornerMetNoBall) {
  const physics::ModelParameters params = params::LoadParameters("pool");
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  table::SceneBall cue;
  cue.id = 0;
  cue.state.segment<2>(physics::kX) = Eigen::Vector2d(0.4, 0.4);
  physics::CueStroke stroke;
  stroke.speed = 2.0;
  stroke.heading = -0.75 * M_PI;  // toward the origin
  std::vector<TableEvent> events;
  const choice::StrokeResult result = choice::PlayToRest(table, params, {cue}, stroke, {}, &events);
  ASSERT_TRUE(result.scratch);
  ExpectScratch(CueBallScratch(events, result.scratch), "lower_left", ScratchPath::kNoBall, 0, 0);
}

// The tally replays the break's samples: its scratches are the rates' on the same racks, and
// its classes sum to them.
TEST(BreakScratchTallyTest, CountsTheScratchesTheRatesCount) {
  const physics::ModelParameters params = params::LoadParameters("pool");
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const BreakSetting setting{table, params, rules::Rules::kNineBall,
                             params::LoadNoise("computational-pool"),
                             model_choice::TableMotion(params)};
  batch::ThreadPool pool(2);
  constexpr int kRacks = 120;
  constexpr std::uint64_t kSeed = 2027;
  const Break side = StoredBreak(rules::Rules::kNineBall);
  const BreakRates rates = EvaluateBreaks(setting, {side}, kRacks, kSeed, pool)[0];
  const ScratchTally tally = TallyBreakScratches(setting, side, kRacks, kSeed, pool);
  EXPECT_EQ(tally.samples, kRacks);
  EXPECT_EQ(tally.scratches, rates.scratches);
  EXPECT_GT(tally.scratches, 0);  // the side break at 8 m/s scratches some racks of 120
  int by_pocket = 0, by_path = 0;
  for (const auto& [key, n] : tally.by_pocket_and_path) by_pocket += n;
  for (const auto& [path, n] : tally.by_path) by_path += n;
  EXPECT_EQ(by_pocket, tally.scratches);
  EXPECT_EQ(by_path, tally.scratches);
}

}  // namespace
}  // namespace billiard::game
