// `billiard bench-match --out DIR`: issue 48's match report. Ours against ours-no-safety and
// against easiest-looking at nine-ball and eight-ball under one noise (the computational pool's
// by default), the break alternating, seeded; DIR/match_report.md and DIR/match_report.json:
// win rates with Wilson (1927) 95 % intervals, eight-ball pots per attempt and one-visit clears
// after a legal break beside pix2pockets' (2025) 94.7 % and 30 %, safeties played and the share
// that worked, the breaks' rates, the decisions' median and 95th percentile.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddBenchMatchCommand(CLI::App& app);

}  // namespace billiard::cli
