// `billiard plot`: a picture of a scene simulated, or of a plan, as PNG or SVG (plot/).
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddPlotCommand(CLI::App& app);

}  // namespace billiard::cli
