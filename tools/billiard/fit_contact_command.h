#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard fit-contact`: fits the approximate friction model to the integral one.
void AddFitContactCommand(CLI::App& app);

}  // namespace billiard::cli
