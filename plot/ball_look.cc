#include "plot/ball_look.h"

#include <array>

namespace billiard::plot {

namespace {

constexpr Rgb kWhite{1.00, 1.00, 1.00};
constexpr Rgb kCuePath{0.85, 0.85, 0.85};
constexpr int kSolids = 8;  // 1-8; 9-15 their stripes; the set repeats after 15

// The solids' colours, 1 to 8.
Rgb SolidColour(int number) {
  static const std::array<Rgb, kSolids> kColours = {{{1.00, 0.80, 0.00},
                                                     {0.00, 0.25, 0.75},
                                                     {0.85, 0.05, 0.05},
                                                     {0.45, 0.10, 0.60},
                                                     {1.00, 0.45, 0.00},
                                                     {0.00, 0.50, 0.20},
                                                     {0.50, 0.05, 0.10},
                                                     {0.05, 0.05, 0.05}}};
  return kColours[number - 1];
}

// The ball's place in the set of 15 object balls, 1 to 15.
int NumberInSet(int id) { return (id - 1) % 15 + 1; }

}  // namespace

BallLook SnookerLookOf(SnookerBall ball) {
  // Red, yellow, green, brown, blue, pink, black: the colours' order in SnookerBall.
  static const std::array<Rgb, 7> kColours = {{{0.85, 0.00, 0.00},
                                               {1.00, 0.85, 0.10},
                                               {0.00, 0.55, 0.25},
                                               {0.45, 0.25, 0.08},
                                               {0.05, 0.30, 0.85},
                                               {1.00, 0.55, 0.70},
                                               {0.05, 0.05, 0.05}}};
  return {kColours[static_cast<std::size_t>(ball)], std::nullopt};
}

BallLook LookOf(int id) {
  if (id <= 0) return {kWhite, std::nullopt};
  const int number = NumberInSet(id);
  if (number <= kSolids) return {SolidColour(number), std::nullopt};
  return {kWhite, SolidColour(number - kSolids)};
}

Rgb PathColour(int id) { return id <= 0 ? kCuePath : LookOf(id).colour(); }

bool DashedPath(int id) { return LookOf(id).band.has_value(); }

}  // namespace billiard::plot
