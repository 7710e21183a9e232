#include "planner/players/players.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace billiard::players {
namespace {

TEST(PlayersTest, EachNameMakesThatPlayer) {
  const std::vector<std::string> names = PlayerNames();
  EXPECT_EQ(names, (std::vector<std::string>{"ours", "no-lookahead", "easiest-looking"}));
  for (const std::string& name : names) EXPECT_EQ(MakePlayer(name)->Name(), name);
  EXPECT_STREQ(MakePlayer(kOursNoSafety)->Name(), "ours-no-safety");
  EXPECT_STREQ(MakePlayer(kOursOneLevel)->Name(), "ours-one-level");
}

TEST(PlayersTest, EveryKnownNameMakesThatPlayer) {
  const std::vector<std::string> names = KnownPlayerNames();
  EXPECT_EQ(names.size(), PlayerNames().size() + 2);
  for (const std::string& name : names) EXPECT_EQ(MakePlayer(name)->Name(), name);
}

TEST(PlayersTest, AnUnknownNameIsRefusedWithTheKnownOnes) {
  try {
    MakePlayer("random");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown player 'random' (ours, no-lookahead, easiest-looking, ours-no-safety, "
                 "ours-one-level)");
  }
}

}  // namespace
}  // namespace billiard::players
