// `billiard plot`: a picture of a scene simulated, or of a plan, as PNG or SVG (plot/), with the
// robot's cue of its stroke seen from above (plot/cue_outline.h): the cue placed as the planner
// places it (sim/cue/), where it comes nearest what it clears, its elevation.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddPlotCommand(CLI::App& app);

}  // namespace billiard::cli
