// `billiard bench-break`: the break of nine-ball or eight-ball played on many seeded racks with
// the table's noise (planner/game/break_search.h): the legal, potted, kept (legal and potted)
// and scratch rates with Wilson intervals, of today's break (the head spot, full at the apex at
// 5 m/s) beside the stored optimised one, or with --search the one a new search finds.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddBenchBreakCommand(CLI::App& app);

}  // namespace billiard::cli
