// A scene the table simulation accepts: the refusal of one it cannot run, with the ball named,
// and a camera's scene (touching balls measured a hair into each other or a cushion) made one.
#pragma once

#include <vector>

#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::table {

// Refuses, with a one-line reason naming the ball, a scene with a non-finite number, an id below
// 0 or repeated, a ball off the playing surface (TableGeometry::OnSurface) or two balls
// overlapping by more than a nanometre.
void ValidateScene(const TableGeometry& table, double radius, const std::vector<SceneBall>& balls);

// A scene as a camera sees it, made one ValidateScene accepts: balls that overlap each other by
// at most `max_overlap` [m] (touching balls, measured a fraction of a millimetre apart) are
// pushed apart along their line of centres, each by half, and a ball at most `max_overlap` into
// a cushion or over a pocket's mouth is moved toward the middle of the table until it is on the
// surface; velocities and spins are kept. Throws std::invalid_argument, as ValidateScene does,
// for a scene that needs more than that.
std::vector<SceneBall> SettledScene(const TableGeometry& table, double radius,
                                    std::vector<SceneBall> balls, double max_overlap);

}  // namespace billiard::table
