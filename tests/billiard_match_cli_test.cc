// `billiard match` as a user runs it: the documented JSON, the racks and the interval adding up,
// the same figures whatever --threads, exit 2 for a bad command line; its shot log read back by
// `billiard fit-run-out`.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

const std::string kMatch =
    "match --players easiest-looking,easiest-looking --racks 2 --noise computational-pool --json";

nlohmann::json Match(const std::string& options) {
  const std::string args = kMatch + " " + options;
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 0) << args << ": " << r.out;
  return OneObject(r, args);
}

TEST(BilliardMatch, PrintsTheDocumentedSummary) {
  for (const char* game : {"nine-ball", "eight-ball"}) {
    const nlohmann::json j = Match(std::string("--game ") + game);
    EXPECT_EQ(j["game"], game);
    EXPECT_EQ(j["racks"], 2);
    ASSERT_EQ(j["players"].size(), 2u) << j;
    int won = 0;
    for (const nlohmann::json& p : j["players"]) {
      for (const char* key : {"name", "racks_won", "win_rate", "interval95", "break_and_runs",
                              "pots", "attempts", "safeties", "safeties_that_worked", "fouls"}) {
        EXPECT_TRUE(p.contains(key)) << key;
      }
      won += p["racks_won"].get<int>();
      EXPECT_DOUBLE_EQ(p["win_rate"].get<double>(), p["racks_won"].get<int>() / 2.0);
      EXPECT_LE(p["interval95"][0].get<double>(), p["win_rate"].get<double>());
      EXPECT_GE(p["interval95"][1].get<double>(), p["win_rate"].get<double>());
      EXPECT_LE(p["pots"].get<int>(), p["attempts"].get<int>());
      EXPECT_EQ(p["safeties"], 0);
    }
    EXPECT_EQ(won + j["undecided"].get<int>(), 2);
    EXPECT_LE(j["decision_us"]["median"].get<double>(), j["decision_us"]["p95"].get<double>());
  }
}

TEST(BilliardMatch, TheSameFiguresWhateverTheThreads) {
  nlohmann::json one = Match("--game nine-ball --threads 1");
  nlohmann::json two = Match("--game nine-ball --threads 2");
  one.erase("decision_us");
  two.erase("decision_us");
  for (nlohmann::json* j : {&one, &two}) {
    for (nlohmann::json& p : (*j)["players"]) p.erase("decision_us");
  }
  EXPECT_EQ(one, two);
}

TEST(BilliardMatch, ABadCommandLineExitsTwo) {
  for (const char* args : {"match --game snooker --players ours,ours",
                           "match --game nine-ball --players ours",
                           "match --game nine-ball --players ours,nobody",
                           "match --game nine-ball --players ours,ours --noise /no/such.json",
                           "match --game nine-ball --players ours,ours --racks 0"}) {
    EXPECT_EQ(Billiard(args).status, 2) << args;
  }
}

// The log holds a line a rack, each shot with its player, and fit-run-out reads it back (its
// counting is run_out_fit_test's).
TEST(BilliardMatch, TheShotLogIsARackALineAndFitRunOutReadsIt) {
  const std::string log = ::testing::TempDir() + "match_shots.jsonl";
  const nlohmann::json match = Match("--game nine-ball --shots " + log);
  std::ifstream in(log);
  std::string line;
  int racks = 0, shots = 0;
  while (std::getline(in, line)) {
    const nlohmann::json rack = nlohmann::json::parse(line);
    EXPECT_EQ(rack["rack"], racks++);
    for (const nlohmann::json& s : rack["shots"]) {
      ++shots;
      EXPECT_TRUE(s["player"] == 0 || s["player"] == 1) << s;
      EXPECT_EQ(s["attempt_win"], -1.0);  // easiest-looking weighs no safety
    }
  }
  EXPECT_EQ(racks, 2);
  EXPECT_GT(shots, 2);
  for (const char* player : {"0", "1"}) {
    const std::string args = std::string("fit-run-out ") + log + " --player " + player;
    const CommandResult r = Billiard(args);
    ASSERT_EQ(r.status, 0) << args;
    const nlohmann::json fit = OneObject(r, args);
    for (const char* rate : {"pot_rate", "arrival_chance"}) {
      EXPECT_LE(fit[rate]["count"].get<int>(), fit[rate]["of"].get<int>());
    }
    EXPECT_EQ(fit["calibration"]["safeties"]["won"]["of"], 0);
  }
  std::remove(log.c_str());
}

TEST(BilliardMatch, FitRunOutRefusesWhatIsNoShotLog) {
  const std::string bad = ::testing::TempDir() + "not_a_log.jsonl";
  std::ofstream(bad) << "{\"rack\": 0}\n";
  const CommandResult r = Billiard("fit-run-out " + bad, /*merge_stderr=*/true);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(":1: not a rack"), std::string::npos) << r.out;
  EXPECT_EQ(Billiard("fit-run-out /no/such/log.jsonl").status, 2);
  std::remove(bad.c_str());
}

}  // namespace
}  // namespace billiard::testing
