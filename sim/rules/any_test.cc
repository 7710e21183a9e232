#include "sim/rules/any.h"

#include <gtest/gtest.h>

#include "sim/params/table_specs.h"

namespace billiard::rules {
namespace {

class AnyBallTest : public ::testing::Test {
 protected:
  AnyBallTest() : table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {}
  // A shot played with every object ball of `on_table` legal, first meeting `first`.
  static Shot Played(std::vector<int> on_table, int first, std::vector<int> potted, int left) {
    Shot s;
    s.constraints.legal_targets = std::move(on_table);
    s.first_contact = first;
    s.potted = std::move(potted);
    s.object_balls_left = left;
    return s;
  }
  table::TableGeometry table_;
  AnyBall rules_;
};

TEST_F(AnyBallTest, EveryObjectBallIsATarget) {
  table::SceneBall cue, three, one;
  three.id = 3;
  one.id = 1;
  EXPECT_EQ(rules_.LegalTargets({three, cue, one}), (std::vector<int>{1, 3}));
  EXPECT_FALSE(rules_.RackOver({three, cue}));
  EXPECT_TRUE(rules_.RackOver({cue}));
}

// Any first contact is legal: the highest ball first, potting another, keeps the visit.
TEST_F(AnyBallTest, AnyFirstContactIsLegal) {
  const Judgement j = rules_.Judge(table_, Played({1, 2, 3}, 3, {1}, 2));
  EXPECT_TRUE(j.legal());
  EXPECT_EQ(j.foul_reason, "");
  EXPECT_FALSE(j.turn_over);
  EXPECT_FALSE(j.ball_in_hand);
  EXPECT_FALSE(j.rack_over);
}

TEST_F(AnyBallTest, TheFoulsOfThePocketGames) {
  Shot scratch = Played({1, 2}, 1, {1}, 1);
  scratch.scratch = true;
  const Judgement j = rules_.Judge(table_, scratch);
  EXPECT_EQ(j.foul_reason, "scratch");
  EXPECT_TRUE(j.ball_in_hand);
  EXPECT_TRUE(j.turn_over);
  EXPECT_TRUE(j.respots.empty());  // the potted 1 stays down
  EXPECT_EQ(rules_.Judge(table_, Played({1, 2}, -1, {}, 2)).foul_reason, "no contact");
  Shot miscue = Played({1, 2}, -1, {}, 2);
  miscue.struck = false;
  EXPECT_EQ(rules_.Judge(table_, miscue).foul_reason, "miscue");
}

// The rack is over when the last object ball drops, on a foul too: nothing comes back.
TEST_F(AnyBallTest, RackOverWithTheLastBall) {
  EXPECT_TRUE(rules_.Judge(table_, Played({4}, 4, {4}, 0)).rack_over);
  Shot scratched = Played({4}, 4, {4}, 0);
  scratched.scratch = true;
  const Judgement j = rules_.Judge(table_, scratched);
  EXPECT_TRUE(j.foul);
  EXPECT_TRUE(j.rack_over);
}

}  // namespace
}  // namespace billiard::rules
