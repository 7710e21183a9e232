// How a ball looks in a picture, by its number as a pool player knows the set: the cue ball
// white, 1-8 solids (yellow, blue, red, purple, orange, green, maroon, black), 9-15 stripes, a
// white ball with a band of the colour of the solid eight below it (9 yellow, 10 blue, ...), so
// that the 1 and the 9 are told apart at a glance. A stripe's path is drawn dashed in its band's
// colour, so the two paths are told apart too. Snooker's balls are plain balls of their
// colours (SnookerLookOf).
#pragma once

#include <optional>

namespace billiard::plot {

struct Rgb {
  double r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

struct BallLook {
  Rgb body;                 // the ball's ground: white for the cue ball and the stripes
  std::optional<Rgb> band;  // a stripe's band round the middle
  Rgb colour() const { return band ? *band : body; }  // what names the ball: marks, outlines
};

// The look of ball `id` (ids past 15 repeat the solids' and stripes' colours, 16 as 1).
BallLook LookOf(int id);

// Snooker's balls, told by colour alone (the 15 reds alike; the colours' values 2 to 7 follow
// in this order), as the World Snooker rules name them.
enum class SnookerBall { kRed, kYellow, kGreen, kBrown, kBlue, kPink, kBlack };

// A snooker ball's look: a plain ball of its colour (the cue ball is LookOf(0)). Its path is
// drawn solid in that colour.
BallLook SnookerLookOf(SnookerBall ball);

// The colour of ball `id`'s path on the cloth (the cue ball's a light grey: white would glare),
// and whether it is dashed (a stripe's).
Rgb PathColour(int id);
bool DashedPath(int id);

}  // namespace billiard::plot
