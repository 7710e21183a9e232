// The table as geometry: the cushion noses, the rounded jaws of the pockets and the lines past
// which a ball drops, built from a table's specification (the numbers of the governing body:
// WPA for pool, WPBSA for snooker, UMB for carom; sim/params/tables/*.json cites them).
//
// What the event-based simulator needs of a table, and nothing more. A ball of radius R touches
//  - a cushion line (the nose of a rail or of a jaw face, a segment a -> b) when its centre is at
//    distance R on the normal side with its projection within [a, b];
//  - a cushion point (the rounded nose where a cushion face turns into a jaw face) when its
//    centre is at distance R + radius from the point's centre;
//  - a pocket when its centre crosses the pocket's capture line: then it drops.
// The boundary is closed: a ball leaves the playing surface only through a capture line.
//
// Construction of a pocket (the WPA equipment specifications' terms). The mouth is measured
// between the two noses, the sharp points where the cushion line turns into the jaw face ("from
// pointed lip to pointed lip"); a corner pocket's noses sit at mouth / sqrt(2) from the corner of
// the playing rectangle, a side pocket's at mouth / 2 either side of the long cushion's middle.
// The jaw angle is the angle of the rubber between the cushion face and the jaw face (WPA:
// 142 degrees corner, 104 side; 135 and 90 make the jaw faces parallel to the pocket's axis).
// The nose is rounded by a circle of jaw_radius tangent to both faces, so the cushion line ends
// and the jaw face begins where that circle touches them (the construction of pooltool's
// table layout, Kiefl 2020). The capture line is parallel to the mouth line, capture_depth into
// the pocket (the WPA "shelf": where the slate ends and the ball falls), and spans the rubber
// from jaw to jaw. Each jaw face runs past the capture line by half the mouth: any ball that
// fits through the mouth (R < mouth / 2) meets the face, not its end, before it drops.
//
// Coordinates: x along the long side, y across, origin at the lower-left corner of the playing
// surface (sim/physics/ball_state.h). Everything is ordered counter-clockwise around the table
// (pockets lower_left, lower_middle, lower_right, upper_right, upper_middle, upper_left; each
// line a -> b with the playing area on its left).
//
// Module: billiard::table. Eigen and the standard library alone.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace billiard::table {

// A table as its governing body specifies it (sim/params/tables/*.json): SI units, angles in
// degrees.
struct TableSpec {
  std::string name;           // "pool-9ft"
  std::string source;         // where every number comes from
  double length = 0;          // playing surface between the cushion noses [m]
  double width = 0;           // [m]
  double cushion_height = 0;  // nose above the cloth [m]
  struct PocketSpec {
    double mouth = 0;          // width between the two jaw noses [m]
    double jaw_angle = 0;      // angle of the rubber between cushion face and jaw face [deg]
    double jaw_radius = 0;     // rounding of the nose where the two faces meet [m]
    double capture_depth = 0;  // capture line inset from the mouth line, into the pocket [m]
  };
  std::optional<PocketSpec> corner, side;  // none for carom; side pockets need corner pockets
  // The wooden rail the cushion is glued to: its top's height above the cloth and its width from
  // the cushion's nose outward (the WPA's rail width, the cushion included) [m]. What a cue must
  // pass over (sim/cue/clearance.h); the balls never meet it. Optional, so that a table written
  // before rails were data still loads: without one the rail is taken as FastFiz takes it (a wall
  // at the nose line; here as high as the nose).
  struct RailSpec {
    double height = 0;  // >= cushion_height
    double width = 0;   // > 0
  };
  std::optional<RailSpec> rail;
};

// A nose line a -> b; `normal` is the unit normal pointing into the playing area (the left of
// a -> b). A ball touches when its centre is at distance R on the normal side with its
// projection within [a, b].
struct CushionLine {
  Eigen::Vector2d a, b;
  Eigen::Vector2d normal;
};

// A jaw's rounded nose: touched at |p - centre| = R + radius.
struct CushionPoint {
  Eigen::Vector2d centre;
  double radius;
};

// A pocket: `centre` is the middle of its mouth line (the point a shot aims at); a ball drops
// when its centre crosses the capture line a -> b, whose unit normal `inward` points into the
// pocket. Names: lower_left, lower_middle, lower_right, upper_left, upper_middle, upper_right
// (y = 0 lower, x = 0 left).
struct Pocket {
  std::string name;
  Eigen::Vector2d centre;
  Eigen::Vector2d capture_a, capture_b;
  Eigen::Vector2d inward;
};

struct TableGeometry {
  std::string name;
  double length = 0, width = 0, cushion_height = 0;
  // The rail along every side (TableSpec::RailSpec), beyond the nose lines x = 0, x = length,
  // y = 0, y = width; a spec without one gives the nose's height and no width.
  double rail_height = 0, rail_width = 0;
  std::vector<CushionLine> lines;    // the rails, then the jaw faces
  std::vector<CushionPoint> points;  // the rounded noses
  std::vector<Pocket> pockets;
  // The boundary polygon, counter-clockwise: the rails' and jaw faces' ends and the capture
  // lines (each rounded nose cut by its chord, which lies inside the nose's circle).
  std::vector<Eigen::Vector2d> outline;

  // Whether a ball of radius `radius` with centre p lies within the closed boundary, clear of
  // every cushion line and point (touching allowed, no overlap), and not beyond a capture line:
  // where a moving ball may be, its centre over a pocket's mouth on its way to drop included.
  bool InsideBoundary(const Eigen::Vector2d& p, double radius) const;
  // Whether a ball may be placed there: inside the boundary with its centre on the playing
  // surface, not beyond a pocket's mouth line (between the noses). A centre past the mouth
  // hangs over the pocket: a still ball there would never reach the capture line, and a real
  // one would drop.
  bool OnSurface(const Eigen::Vector2d& p, double radius) const;
  // The pocket whose mouth line (between its noses) the centre p lies past, or nullptr: where a
  // ball at rest hangs over that pocket and drops.
  const Pocket* PocketPastMouth(const Eigen::Vector2d& p) const;
  // The pocket called `name`, or nullptr.
  const Pocket* PocketNamed(const std::string& name) const;
};

// The geometry of `spec`: 6 rail cushions for pool and snooker (the long ones split by the side
// pockets), 4 for carom; two jaw faces and two rounded noses per pocket. Throws
// std::invalid_argument with a one-line reason on a spec that does not make a table (sizes not
// positive and finite, a jaw angle that opens the pocket or folds it shut, jaws that close
// before the capture line, pockets that overlap along a cushion, side pockets without corners,
// a rail lower than the cushion's nose or without width).
TableGeometry BuildTable(const TableSpec& spec);

}  // namespace billiard::table
