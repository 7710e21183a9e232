// The robot's body against its own limits at a placed cue (robot.h says what each body is):
//  - a gantry: the carriage (the cue's axis at the bridge) and the butt (the axis at the cue's
//    end) inside the carriage's rectangle, the noses' rectangle grown by `overhang`; the
//    carriage at least `clearance` above the cloth;
//  - an arm: the gripper (the axis at the bridge) within `reach` of the base;
//  - a player: nothing.
// Each limit is a margin in metres, > 0 inside it (how far the point may still move before it
// meets the limit), < 0 beyond it: the body's part of the clearance (clearance.h). A gantry's
// margins grow with the elevation for a tip that moves little (the butt and the carriage come
// in and up); an arm's need not.
//
// Module: billiard::cue.
#pragma once

#include <string>

#include "sim/cue/placed_cue.h"
#include "sim/cue/robot.h"
#include "sim/table/table_geometry.h"

namespace billiard::cue {

struct BodyMargin {
  double distance = 0;  // [m], +infinity for a robot without a body
  std::string what;     // the limit nearest: "the carriage below its clearance", ...
  double along = 0;     // the point of the cue's axis it is checked at: the bridge or the butt [m]
};

// The least margin of `robot`'s body with its cue placed as `cue` over `table`.
BodyMargin BodyClearance(const table::TableGeometry& table, const PlacedCue& cue,
                         const Robot& robot);

}  // namespace billiard::cue
