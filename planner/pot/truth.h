// Step 5 of a pot, the truth: the search's plan played with the motion `billiard simulate --scene`
// runs by default (sim/model_choice/, `--model auto`: 5-DOF while a ball slides, so the cue ball
// meets K a little differently), re-aimed there, and refused unless it pots legally: K in P, the
// cue ball's first contact K, no scratch.
//
// A bank's drop window is found again on the truth, from the search's (K's state at the rail
// moves it), and the aim put at its middle; so is any route's where the search's jaws (Han
// 2005's impulse) let K rattle in and the truth's do not. Position play's truth aim is kept as it
// is: the rest point it was solved for moves with the smallest turn once the cue ball has met a
// cushion or two.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "planner/pot/aim.h"
#include "planner/pot/drop_window.h"
#include "planner/pot/pot_planner.h"
#include "planner/pot/routes.h"
#include "planner/pot/search_context.h"

namespace billiard::pot {

// The stroke the truth plays, to rest, and the aim and drop window it was found with.
struct TruthShot {
  Aimed aimed;  // the truth's aim: its heading, first contact and d departure / d heading
  Drop window;  // K's drop window the aim is at the middle of (the search's, unless found again)
  physics::CueStroke stroke;
  Played played;
};

// The search's plan for `route` (`shape` aimed by `aimed` at the middle of `drop`) on the truth;
// `placed`: position play's truth aim, kept as it is.
std::variant<TruthShot, Refusal> PlayOnTheTruth(SearchContext& search, const Route& route,
                                                const StrokeShape& shape, const Aimed& aimed,
                                                const Drop& drop, const std::optional<Aimed>& placed);

// Why a stroke's outcome is no legal pot, in words.
std::string Illegal(const SearchContext& search, const PotOutcome& o);

// The plan's parts the truth's shot gives: its stroke and launch, the cut, where K leaves and the
// cue ball rests, the events and every moving ball's path sampled every `sample_dt` [s] (and at
// its end: its rest, or where it dropped).
void DescribeShot(const TruthShot& shot, double sample_dt, PotPlan* plan);

}  // namespace billiard::pot
