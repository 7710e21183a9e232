// `billiard loop`: the closed loop in one process, the estimator, planner and table simulator
// nodes on LCM's in-memory provider (memq://), for machines where the nodes cannot talk over UDP
// multicast (launch_scripts/run_loop.sh falls back to it). The options and the JSON summary are
// table_sim_node's.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddLoopCommand(CLI::App& app);

}  // namespace billiard::cli
