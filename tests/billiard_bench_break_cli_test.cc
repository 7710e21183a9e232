// `billiard bench-break` as a user runs it: the documented JSON, the counts nesting and the
// rates matching them, the same figures whatever --threads, exit 2 for a bad command line.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

const std::string kBench = "bench-break --samples 12 --json";

nlohmann::json Bench(const std::string& options) {
  const std::string args = kBench + " " + options;
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 0) << args << ": " << r.out;
  return OneObject(r, args);
}

TEST(BilliardBenchBreak, PrintsTheDocumentedRates) {
  for (const char* game : {"nine-ball", "eight-ball"}) {
    const nlohmann::json j = Bench(std::string("--game ") + game);
    EXPECT_EQ(j["game"], game);
    EXPECT_EQ(j["noise"], "computational-pool");
    for (const char* which : {"today", "optimised"}) {
      const nlohmann::json& b = j[which];
      ASSERT_EQ(b["samples"], 12) << b;
      for (const char* key : {"legal", "potted", "legal_and_potted", "scratch"}) {
        const nlohmann::json& rate = b[key];
        EXPECT_DOUBLE_EQ(rate["rate"].get<double>(), rate["count"].get<int>() / 12.0) << key;
        EXPECT_LE(rate["interval95"][0].get<double>(), rate["rate"].get<double>()) << key;
        EXPECT_GE(rate["interval95"][1].get<double>(), rate["rate"].get<double>()) << key;
      }
      EXPECT_LE(b["legal_and_potted"]["count"], b["legal"]["count"]);
      EXPECT_LE(b["legal_and_potted"]["count"], b["potted"]["count"]);
    }
    EXPECT_EQ(j["today"]["speed_mps"], 5.0);  // the head spot's roll at 5 m/s
  }
}

// A given break is measured as given: the stored break's own numbers give its figures, and a
// roll at 1 m/s keeps the table on none of the racks.
TEST(BilliardBenchBreak, AGivenBreakIsMeasuredAsGiven) {
  const nlohmann::json stored = Bench("--game eight-ball")["optimised"];
  const std::string numbers = stored["cue_offset_m"].dump() + "," + stored["aim_radii"].dump() +
                              "," + stored["speed_mps"].dump() + "," +
                              stored["tip_height_radii"].dump();
  EXPECT_EQ(Bench("--game eight-ball --break=" + numbers)["optimised"], stored);
  const nlohmann::json soft =
      Bench("--game eight-ball --break=" + stored["cue_offset_m"].dump() + ",0,1,0")["optimised"];
  EXPECT_EQ(soft["speed_mps"], 1.0);
  EXPECT_EQ(soft["legal_and_potted"]["count"], 0);
}

// --search reports the documented keys; --refinements adds candidates, at most two a parameter
// a pass.
TEST(BilliardBenchBreak, RefinementsAddCandidatesToTheSearch) {
  const std::string search = "--game nine-ball --search --search-samples 4 --rounds 1";
  const nlohmann::json coarse = Bench(search)["search"];
  const nlohmann::json refined = Bench(search + " --refinements 1")["search"];
  for (const char* key : {"candidates", "samples", "seed", "rounds", "refinements", "max_scratch",
                          "scratch_z", "kept", "scratches", "scratch_bound", "feasible"}) {
    EXPECT_TRUE(refined.contains(key)) << key;
  }
  EXPECT_EQ(coarse["refinements"], 0);
  EXPECT_EQ(refined["refinements"], 1);
  constexpr int kParameters = 4;
  EXPECT_GT(refined["candidates"].get<int>(), coarse["candidates"].get<int>());
  EXPECT_LE(refined["candidates"].get<int>(), coarse["candidates"].get<int>() + 2 * kParameters);
}

// --scratches classes every scratch the rates count, by pocket and by path; a fifth --break
// number places the cue ball behind the head string.
TEST(BilliardBenchBreak, ScratchesAreClassedAndTheKitchenIsReached) {
  const std::string args = "bench-break --game nine-ball --samples 60 --scratches --json";
  const nlohmann::json b = OneObject(Billiard(args), args)["optimised"];
  ASSERT_GT(b["scratch"]["count"].get<int>(), 0);  // the stored side break scratches some of 60
  const nlohmann::json& paths = b["scratch_paths"];
  EXPECT_EQ(paths["samples"], 60);
  EXPECT_EQ(paths["scratches"], b["scratch"]["count"]);
  int by_pocket = 0;
  for (const nlohmann::json& row : paths["by_pocket"]) by_pocket += row["count"].get<int>();
  EXPECT_EQ(by_pocket, paths["scratches"].get<int>());
  const nlohmann::json behind = Bench("--game nine-ball --break=-0.3,0,8,0,0.2")["optimised"];
  EXPECT_EQ(behind["behind_m"], 0.2);
  EXPECT_EQ(Bench("--game nine-ball")["optimised"]["behind_m"], 0.0);
  EXPECT_EQ(behind["failed"], 0);
}

// A break from the head cushion's nose (0.635 m behind the head string of the 9-ft table) cannot
// be played: every rack counted as failed, with the reason, and none kept.
TEST(BilliardBenchBreak, ABreakThatCannotBePlayedSaysSo) {
  const nlohmann::json b = Bench("--game nine-ball --break=0,0,8,0,0.635")["optimised"];
  EXPECT_EQ(b["failed"], b["samples"]);
  EXPECT_EQ(b["legal_and_potted"]["count"], 0);
  EXPECT_NE(b["first_failure"].get<std::string>().find("off the kitchen"), std::string::npos);
}

TEST(BilliardBenchBreak, TheSameFiguresWhateverTheThreads) {
  EXPECT_EQ(Bench("--game nine-ball --threads 1"), Bench("--game nine-ball --threads 2"));
}

TEST(BilliardBenchBreak, ABadCommandLineExitsTwo) {
  for (const char* args :
       {"bench-break --game snooker", "bench-break",
        "bench-break --game nine-ball --noise /no/such.json",
        "bench-break --game nine-ball --robot nobody", "bench-break --game nine-ball --samples 0",
        "bench-break --game nine-ball --break=1,2",
        "bench-break --game nine-ball --break=0,0,8,0,-0.1",
        "bench-break --game nine-ball --break=0,0,8,0,0.1,2",
        "bench-break --game nine-ball --max-behind -1",
        "bench-break --game nine-ball --search --refinements -1"}) {
    EXPECT_EQ(Billiard(args).status, 2) << args;
  }
}

}  // namespace
}  // namespace billiard::testing
