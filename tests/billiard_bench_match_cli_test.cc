// `billiard bench-match` as a user runs it: the report's files and their shape, the figures
// adding up, the same figures whatever --threads, exit 2 for a bad command line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

constexpr int kRacks = 2;

std::string Read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// bench-match on kRacks racks into a fresh directory (`more` added to its command line): its JSON
// file, checked to be what stdout printed.
nlohmann::json BenchMatch(const std::string& name, int threads, const std::string& more = "") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  const std::string args = "bench-match --racks " + std::to_string(kRacks) +
                           " --seed 3 --json --threads " + std::to_string(threads) + " --out " +
                           dir.string() + more;
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 0) << args << ": " << r.out;
  const nlohmann::json printed = OneObject(r, args);
  const nlohmann::json written = nlohmann::json::parse(Read(dir / "match_report.json"));
  EXPECT_EQ(printed, written);
  const std::string md = Read(dir / "match_report.md");
  for (const char* heading : {"# Match report", "## Racks won", "## Eight-ball: pots per attempt",
                              "## Safeties", "## Breaks", "## Decisions", "94.7 %"}) {
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
  }
  return written;
}

// Every duration removed: what is left depends on the seed alone.
nlohmann::json Figures(nlohmann::json j) {
  for (nlohmann::json& m : j["matches"]) {
    m.erase("decision_us");
    for (nlohmann::json& p : m["players"]) p.erase("decision_us");
  }
  return j;
}

TEST(BilliardBenchMatch, WritesTheReportAndTheSameFiguresWhateverTheThreads) {
  const nlohmann::json one = BenchMatch("bench_match_one", 1);
  ASSERT_EQ(one["matches"].size(), 4u) << one;
  for (const nlohmann::json& m : one["matches"]) {
    EXPECT_EQ(m["players"][0]["name"], "ours");
    EXPECT_EQ(m["racks"], kRacks);
    EXPECT_EQ(m["breaks"]["racks"], kRacks);
    int won = m["undecided"];
    for (const nlohmann::json& p : m["players"]) {
      won += p["racks_won"].get<int>();
      EXPECT_EQ(p["pots_per_attempt"]["count"], p["pots"]);
      EXPECT_EQ(p["pots_per_attempt"]["of"], p["attempts"]);
      EXPECT_LE(p["one_visit_clears"]["count"], p["one_visit_clears"]["of"]);
      EXPECT_LE(p["one_visit_clears"]["of"].get<int>(), kRacks);
      EXPECT_EQ(p["safeties_worked"]["of"], p["safeties"]);
    }
    EXPECT_EQ(won, kRacks);
    EXPECT_LE(m["breaks"]["legal_and_potted"]["count"], m["breaks"]["legal"]["count"]);
  }
  EXPECT_EQ(Figures(one), Figures(BenchMatch("bench_match_two", 2)));

  // One of the four matches played alone is the same match: its racks are seeded by the seed
  // and their index, whatever was played before.
  const nlohmann::json alone =
      BenchMatch("bench_match_alone", 2, " --games eight-ball --opponents easiest-looking");
  ASSERT_EQ(alone["matches"].size(), 1u) << alone;
  EXPECT_EQ(Figures(alone)["matches"][0], Figures(one)["matches"][3]);
}

TEST(BilliardBenchMatch, ABadCommandLineExitsTwo) {
  for (const char* args :
       {"bench-match", "bench-match --out /tmp/x --racks 0",
        "bench-match --out /tmp/x --noise /no/such.json",
        "bench-match --out /tmp/x --games snooker", "bench-match --out /tmp/x --opponents ours",
        "bench-match --out /proc/no/such/dir"}) {
    EXPECT_EQ(Billiard(args).status, 2) << args;
  }
}

}  // namespace
}  // namespace billiard::testing
