#include "planner/node/planner_node_command.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "planner/players/players.h"

namespace billiard::planner_node {
namespace {

// Parses `args` (after the program's name) as planner_node's command line.
PlannerNodeCommandLine Parse(std::vector<std::string> args) {
  CLI::App app;
  PlannerNodeCommandLine line;
  AddPlannerNodeOptions(app, &line);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a vector backwards
  app.parse(reversed);
  return line;
}

TEST(PlannerNodeCommand, EveryPlayerAMatchCanNameIsANodesPlayer) {
  EXPECT_EQ(Parse({}).options.player, "ours");
  for (const std::string& name : players::KnownPlayerNames()) {
    EXPECT_EQ(Parse({"--player", name}).options.player, name);
  }
}

TEST(PlannerNodeCommand, AnUnknownPlayerIsRefused) {
  EXPECT_THROW(Parse({"--player", "nobody"}), CLI::ValidationError);
}

}  // namespace
}  // namespace billiard::planner_node
