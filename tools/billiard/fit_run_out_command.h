// `billiard fit-run-out LOG`: the run-out model's two rates (planner/choice/rack_value.h) of one
// player, counted on a match's shot log (`billiard match --shots LOG`; planner/game/run_out_fit.h).
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddFitRunOutCommand(CLI::App& app);

}  // namespace billiard::cli
