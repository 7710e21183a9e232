// The table as obstacles to a cue: the cloth and the four rails, as boxes (rod_distance.h).
//
//  - The cloth: the playing surface between the cushion noses, reaching down without end from
//    z = 0.
//  - Each rail: a box along its whole side, from the nose line (x = 0, x = length, y = 0,
//    y = width of the TableGeometry) out by the rail's width, reaching down without end to the
//    rail's height (TableGeometry::rail_height, rail_width). The cushion between the nose and
//    the wood lies inside it: its cloth-covered top rises from the nose to the wooden cap, so
//    one box at the rail's height bounds both, over-cautious by at most rail_height -
//    cushion_height (3.7 mm on the built-in tables) over the cushion's 5 cm. The box runs across
//    the pockets too: their liners and the rail's corner castings stand about as high, and no
//    cue is played down through a pocket. A table without rail data gives a box of no width at
//    the nose's height: FastFiz's check (Archibald et al. 2010: the cue's line where it crosses
//    the nose line against a rail height), here with the cue's thickness.
// Beyond the rails' outer edges nothing is an obstacle: the floor is far below, the player (or
// the robot's body, body.h) above.
//
// Module: billiard::cue.
#pragma once

#include <string>
#include <vector>

#include "sim/cue/rod_distance.h"
#include "sim/table/table_geometry.h"

namespace billiard::cue {

struct TableObstacle {
  std::string name;  // "the cloth", "the lower rail" (y = 0), "the right rail" (x = length),
                     // "the upper rail" (y = width), "the left rail" (x = 0)
  Box box;
};

// The cloth, then the rails counter-clockwise from the lower one.
std::vector<TableObstacle> TableObstacles(const table::TableGeometry& table);

}  // namespace billiard::cue
