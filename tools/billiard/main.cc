// billiard: simulate a ball, fit the contact model, plan a shot, find the balls in a frame.
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "lcmtypes/node/node_command_line.h"
#include "tools/billiard/bench_command.h"
#include "tools/billiard/bench_detect_command.h"
#include "tools/billiard/bench_estimator_command.h"
#include "tools/billiard/bench_planner_command.h"
#include "tools/billiard/bench_constants_command.h"
#include "tools/billiard/bench_match_command.h"
#include "tools/billiard/break_command.h"
#include "tools/billiard/burst_command.h"
#include "tools/billiard/calibrate_command.h"
#include "tools/billiard/choice_commands.h"
#include "tools/billiard/fit_run_out_command.h"
#include "tools/billiard/match_command.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/detect_command.h"
#include "tools/billiard/edge_report_command.h"
#include "tools/billiard/fit_contact_command.h"
#include "tools/billiard/fit_shots_command.h"
#include "tools/billiard/identify_noise_command.h"
#include "tools/billiard/learn_balls_command.h"
#include "tools/billiard/loop_command.h"
#include "tools/billiard/node_status_command.h"
#include "tools/billiard/plan_command.h"
#include "tools/billiard/plot_command.h"
#include "tools/billiard/pot_commands.h"
#include "tools/billiard/replay_command.h"
#include "tools/billiard/scene_commands.h"
#include "tools/billiard/simulate_command.h"
#include "tools/billiard/render_break_command.h"
#include "tools/billiard/tracks_command.h"
#include "tools/billiard/train_identity_command.h"

namespace {

// A command cut short by SIGINT or SIGTERM exits 130 whichever it was (docs/exit-codes.md),
// not as a process killed by the signal. `billiard loop` installs handlers of its own that end
// its session cleanly, with the same status.
void ExitStopped(int) { _exit(130); }

// A mistyped subcommand is suggested the nearest name this many edits away at most: a dropped,
// doubled or swapped letter or two, not a guess at an unrelated word.
constexpr std::size_t kNearEdits = 3;

// The first argument when it is no option and names no subcommand (CLI11 would say only that a
// subcommand is required), else "".
std::string UnknownSubcommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  const std::string word = argv[1];
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->check_name(word)) return "";
  }
  return word;
}

// The subcommands' names, for the nearest to a mistyped one.
std::vector<std::string> SubcommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  for (int signal_number : {SIGINT, SIGTERM}) std::signal(signal_number, ExitStopped);
  CLI::App app{"billiard: ball physics for a billiard-playing robot"};
  app.require_subcommand(1);
  // Parse errors in one line, like every other user error of the tool.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "billiard: " + std::string(e.what()) + " (see --help)\n";
  });
  billiard::nodes::VersionFlag(app, "billiard");
  billiard::cli::AddSimulateCommand(app);
  billiard::cli::AddFitContactCommand(app);
  billiard::cli::AddFitShotsCommand(app);
  billiard::cli::AddIdentifyCommand(app);
  billiard::cli::AddIdentifyNoiseCommand(app);
  billiard::cli::AddBenchShotFitCommand(app);
  billiard::cli::AddBenchCommand(app);
  billiard::cli::AddPlanCommand(app);
  billiard::cli::AddBenchPlannerCommand(app);
  billiard::cli::AddBenchEstimatorCommand(app);
  billiard::cli::AddReplayCommand(app);
  billiard::cli::AddLoopCommand(app);
  billiard::cli::AddBurstCommand(app);
  billiard::cli::AddNodeStatusCommand(app);
  billiard::cli::AddTracksCommand(app);
  billiard::cli::AddRenderBreakCommand(app);
  billiard::cli::AddEdgeReportCommand(app);
  billiard::cli::AddDetectCommand(app);
  billiard::cli::AddCalibrateCommand(app);
  billiard::cli::AddLearnBallsCommand(app);
  billiard::cli::AddTrainIdentityCommand(app);
  billiard::cli::AddBenchDetectCommand(app);
  billiard::cli::AddRackCommand(app);
  billiard::cli::AddBenchScenesCommand(app);
  billiard::cli::AddPlotCommand(app);
  billiard::cli::AddPlanPotCommand(app);
  billiard::cli::AddBenchPotCommand(app);
  billiard::cli::AddPotLayoutCommand(app);
  billiard::cli::AddChooseShotCommand(app);
  billiard::cli::AddPlayCommand(app);
  billiard::cli::AddBenchGameCommand(app);
  billiard::cli::AddMatchCommand(app);
  billiard::cli::AddFitRunOutCommand(app);
  billiard::cli::AddBenchBreakCommand(app);
  billiard::cli::AddBenchMatchCommand(app);
  billiard::cli::AddBenchConstantsCommand(app);
  if (const std::string word = UnknownSubcommand(app, argc, argv); !word.empty()) {
    const std::string nearest = billiard::cli::NearestName(word, SubcommandNames(app), kNearEdits);
    std::cerr << "billiard: unknown subcommand '" << word << "'"
              << (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") << " (see --help)"
              << std::endl;
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // A command line CLI11 rejects is a usage error like any other (--help is not one).
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const billiard::cli::UsageError& e) {
    std::cerr << "billiard: " << e.what() << std::endl;
    return 2;
  } catch (const billiard::cli::ExitStatus& e) {
    return e.status;
  } catch (const billiard::cli::Refused& e) {
    std::cerr << "billiard: " << e.what() << std::endl;
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "billiard: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
