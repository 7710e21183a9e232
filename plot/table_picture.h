// A picture of the table: the cloth and its cushions and pockets, every ball's path, where it
// started (an outline) and where it ended (filled, or gone into a pocket), the events marked,
// the launch and spin of each ball that starts moving, and, for a plan, the cue and the target.
//
// The picture's frame, fixed so that a reader (and a test) can find a table point in it: 400 px
// a metre, x to the right and y up, the playing surface's corner (0, 0) at (kMarginPx,
// kMarginPx + 400 W) px from the top left, a rail kMarginPx wide all round; a width of
// 2 kMarginPx + 400 L px, a height of 2 kMarginPx + 400 W px.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plot/ball_look.h"
#include "plot/cue_outline.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::plot {

inline constexpr double kPixelsPerMetre = 400.0;
inline constexpr double kMarginPx = 60.0;

struct PictureBall {
  int id = 0;                         // 0 the cue ball; pool's look by number (ball_look.h)
  std::vector<Eigen::Vector2d> path;  // the centre in time order: front where it starts
  physics::BallState start = physics::BallState::Zero();  // its launch and spin are drawn
  std::optional<std::string> pocket;  // dropped into it: no ball at the path's end
};

// Where a camera saw a ball: dots in its colour over the paths (a tracked shot against its
// simulation).
struct TrackedDots {
  int id = 0;
  std::vector<Eigen::Vector2d> samples;
};

struct PictureEvent {
  table::EventType type;
  Eigen::Vector2d at;  // a ball-ball contact's point, else the ball's centre
};

struct TablePicture {
  table::TableGeometry table;
  double ball_radius = 0.0;
  std::string title;
  std::vector<PictureBall> balls;
  std::vector<PictureEvent> events;
  std::vector<TrackedDots> tracked;
  std::optional<physics::CueStroke> cue;  // the stroke at ball 0's start, drawn as a plain cue
  // A robot's cue (cue_outline.h), drawn instead of the plain one: its outline, where it comes
  // nearest what it clears, its elevation and clearance labelled by its butt.
  std::optional<CueOutline> robot_cue;
  std::optional<Eigen::Vector2d> target;  // a plan's target
};

// The pixel of a table point in the picture's frame (above).
Eigen::Vector2d TablePixel(const TablePicture& picture, const Eigen::Vector2d& p);

// Fine enough that a path's polyline bends smoothly at 400 px a metre: 5 ms is 3.5 cm at 7 m/s.
inline constexpr double kPathSampleDt = 5e-3;

// position(t) at t = 0, dt, ... below t_end, at each time of `at` up to t_end (every event's
// position a vertex) and at t_end.
std::vector<Eigen::Vector2d> SampledPath(double t_end, double dt, const std::vector<double>& at,
                                         const std::function<Eigen::Vector2d(double)>& position);

// Adds what `sim` ran to `picture`: each ball (its id, its launch, its path sampled every `dt`
// up to the end or its drop) and each event's mark.
void AddSimulation(const table::TableSimulation& sim, double dt, TablePicture* picture);

// The balls whose paths the picture's key lists, down the right rail: every ball that moved,
// by number (each drawn as it looks, beside a stroke of its path: a stripe's dashed).
std::vector<int> PathLegendIds(const TablePicture& picture);

// The colour a robot's cue is filled with: pale maple, apart from the cloth, the rails and the
// balls, so that a reader (and a test) finds it.
inline constexpr Rgb kCueRgb{0.93, 0.80, 0.55};

// Draws `picture` into `path` (.png or .svg). The balls look as plot/ball_look.h says (stripes
// as stripes), their numbers placed apart (plot/labels.h). Throws std::invalid_argument for another
// extension, std::runtime_error when the file cannot be written.
void DrawTable(const TablePicture& picture, const std::string& path);

}  // namespace billiard::plot
