#include "plot/table_picture.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "plot/ball_look.h"
#include "plot/canvas.h"
#include "plot/labels.h"

namespace billiard::plot {

namespace {

using Eigen::Vector2d;

void Source(cairo_t* cr, const Rgb& c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

// Fills the current path in `fill` and outlines it in `line`, `width` px wide.
void FillAndOutline(cairo_t* cr, const Rgb& fill, const Rgb& line, double width) {
  Source(cr, fill);
  cairo_fill_preserve(cr);
  Source(cr, line);
  cairo_set_line_width(cr, width);
  cairo_stroke(cr);
}

// Whether the ball moved: its path drawn, its start outlined, its key in the legend.
bool Moved(const PictureBall& ball) {
  return ball.path.size() >= 2 && (ball.path.back() - ball.path.front()).norm() > 0.0;
}

// The colour of an event's mark, and its name for the legend.
struct MarkStyle {
  Rgb colour;
  const char* name;
};
MarkStyle Mark(table::EventType type) {
  switch (type) {
    case table::EventType::kBallBall:
      return {{0.90, 0.10, 0.10}, "ball-ball"};
    case table::EventType::kBallCushion:
    case table::EventType::kBallJaw:
      return {{1.00, 0.85, 0.10}, "cushion, jaw"};
    case table::EventType::kBallPocket:
      return {{0.10, 0.10, 0.10}, "pocket"};
    case table::EventType::kBallPush:
      return {{1.00, 0.40, 0.80}, "push"};
    case table::EventType::kTransition:
      break;
  }
  return {{0.70, 0.95, 1.00}, "transition"};
}

void Arrow(cairo_t* cr, const Vector2d& from, const Vector2d& to, double head) {
  cairo_move_to(cr, from.x(), from.y());
  cairo_line_to(cr, to.x(), to.y());
  cairo_stroke(cr);
  const Vector2d d = (to - from).normalized();
  const Vector2d n(-d.y(), d.x());
  const Vector2d a = to - head * d + 0.5 * head * n, b = to - head * d - 0.5 * head * n;
  cairo_move_to(cr, to.x(), to.y());
  cairo_line_to(cr, a.x(), a.y());
  cairo_line_to(cr, b.x(), b.y());
  cairo_close_path(cr);
  cairo_fill(cr);
}

void Polygon(cairo_t* cr, const std::vector<Vector2d>& points) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    k == 0 ? cairo_move_to(cr, points[k].x(), points[k].y())
           : cairo_line_to(cr, points[k].x(), points[k].y());
  }
  cairo_close_path(cr);
}

// The launch and the spin of a ball that starts moving: the velocity as a black arrow from its
// centre; the spin about the horizontal as the velocity a ball rolling with it would have,
// (r wy, -r wx), a blue arrow (along the velocity: follow; against it: draw); the side spin wz
// as a green arc round the ball, counterclockwise for wz > 0 (right english), its length
// growing with |wz| up to three quarters of a turn at 100 rad/s.
void DrawLaunch(cairo_t* cr, const TablePicture& pic, const PictureBall& ball) {
  const physics::BallState& s = ball.start;
  const Vector2d c = TablePixel(pic, s.head<2>());
  const double r = pic.ball_radius * kPixelsPerMetre;
  const Vector2d v(s[physics::kVx], s[physics::kVy]);
  // Picture y points down: a table direction (dx, dy) is (dx, -dy) in pixels.
  const auto pixels = [](const Vector2d& d) { return Vector2d(d.x(), -d.y()); };
  cairo_set_line_width(cr, 2.0);
  if (v.norm() > 0.0) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    Arrow(cr, c, c + pixels(v.normalized()) * (r + 25.0 * std::min(v.norm(), 8.0)), 8.0);
  }
  const Vector2d roll(pic.ball_radius * s[physics::kWy], -pic.ball_radius * s[physics::kWx]);
  if (roll.norm() > 1e-9) {
    cairo_set_source_rgb(cr, 0.1, 0.3, 1.0);
    Arrow(cr, c, c + pixels(roll.normalized()) * (r + 40.0 * std::min(roll.norm(), 4.0)), 7.0);
  }
  const double wz = s[physics::kWz];
  if (std::abs(wz) > 1e-9) {
    const double sweep = 1.5 * M_PI * std::min(std::abs(wz) / 100.0, 1.0);
    const double radius = r + 5.0;
    cairo_set_source_rgb(cr, 0.0, 0.6, 0.2);
    // Counterclockwise on the table is clockwise in the picture (its y points down).
    const double start = -0.5 * M_PI;
    const double end = wz > 0 ? start - sweep : start + sweep;
    wz > 0 ? cairo_arc_negative(cr, c.x(), c.y(), radius, start, end)
           : cairo_arc(cr, c.x(), c.y(), radius, start, end);
    cairo_stroke(cr);
    const Vector2d tip = c + radius * Vector2d(std::cos(end), std::sin(end));
    const Vector2d along = wz > 0 ? Vector2d(std::sin(end), -std::cos(end))
                                  : Vector2d(-std::sin(end), std::cos(end));
    Arrow(cr, tip - 6.0 * along, tip, 7.0);
  }
}

// The cue behind ball 0, along its heading and offset sideways by the tip's side offset.
void DrawCue(cairo_t* cr, const TablePicture& pic, const physics::CueStroke& cue,
             const Vector2d& ball) {
  const Vector2d heading(std::cos(cue.heading), std::sin(cue.heading));
  const Vector2d right(heading.y(), -heading.x());
  const Vector2d tip = ball - (pic.ball_radius + 0.01) * heading + cue.tip_side * right;
  const Vector2d butt = tip - 0.6 * heading;
  const Vector2d a = TablePixel(pic, tip), b = TablePixel(pic, butt);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_source_rgb(cr, 0.55, 0.35, 0.15);
  cairo_set_line_width(cr, 7.0);
  cairo_move_to(cr, b.x(), b.y());
  cairo_line_to(cr, a.x(), a.y());
  cairo_stroke(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
}

// A robot's cue from above (cue_outline.h): its tapered outline, a ring where it comes nearest
// what it clears (a dashed line on to a ball's centre), and its label by the butt.
void DrawRobotCue(cairo_t* cr, const TablePicture& pic, const CueOutline& cue, double width) {
  constexpr double kRingPx = 6.0, kLabelPx = 12.0, kLabelGapPx = 10.0;
  std::vector<Vector2d> corners;
  for (const Vector2d& c : OutlineCorners(cue)) corners.push_back(TablePixel(pic, c));
  Polygon(cr, corners);
  FillAndOutline(cr, kCueRgb, {0.25, 0.15, 0.05}, 1.0);
  if (cue.nearest) {
    const Vector2d at = TablePixel(pic, *cue.nearest);
    cairo_set_source_rgb(cr, cue.distance > 0.0 ? 1.0 : 0.9, cue.distance > 0.0 ? 0.5 : 0.0, 0.0);
    cairo_set_line_width(cr, 2.0);
    if (cue.obstacle) {
      const Vector2d to = TablePixel(pic, *cue.obstacle);
      const double dash = 3.0;
      cairo_set_dash(cr, &dash, 1, 0.0);
      cairo_move_to(cr, at.x(), at.y());
      cairo_line_to(cr, to.x(), to.y());
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0.0);
    }
    cairo_arc(cr, at.x(), at.y(), kRingPx, 0, 2 * M_PI);
    cairo_stroke(cr);
  }
  // The label centred over the butt, on the side away from the cue (above it, or below a butt
  // that lies below its tip), kept on the picture.
  const std::string label = CueLabel(cue);
  const Vector2d tip = TablePixel(pic, cue.tip), butt = TablePixel(pic, cue.butt);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kLabelPx);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, label.c_str(), &extents);
  const double x = std::clamp(butt.x() - 0.5 * extents.x_advance, 2.0, width - extents.x_advance - 2.0);
  const double y = butt.y() > tip.y() + kLabelGapPx ? butt.y() + kLabelGapPx + kLabelPx : butt.y() - kLabelGapPx;
  cairo_set_source_rgb(cr, 1, 1, 1);
  Text(cr, x, y, label, kLabelPx);
}

// A ball as a player sees it from above: its body, a stripe's band across the middle (half the
// ball's height), a thin black rim.
void DrawBall(cairo_t* cr, const Vector2d& c, double r, const BallLook& look) {
  cairo_arc(cr, c.x(), c.y(), r, 0, 2 * M_PI);
  Source(cr, look.body);
  cairo_fill_preserve(cr);
  if (look.band) {
    cairo_save(cr);
    cairo_clip(cr);
    cairo_rectangle(cr, c.x() - r, c.y() - 0.5 * r, 2 * r, r);
    Source(cr, *look.band);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_arc(cr, c.x(), c.y(), r, 0, 2 * M_PI);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
}

// A path's stroke: its ball's path colour, dashed for a stripe.
void PathStroke(cairo_t* cr, int id) {
  static const double kDash[] = {7.0, 4.0};
  Source(cr, PathColour(id), 0.9);
  cairo_set_line_width(cr, 2.0);
  cairo_set_dash(cr, kDash, DashedPath(id) ? 2 : 0, 0.0);
}

constexpr double kLabelFontPx = 11.0;
constexpr double kLeaderFromPx = 4.0;  // beyond the first ring's 2 px gap

// The number of every ball left on the table, placed apart (PlaceLabels), white on the cloth.
void DrawLabels(cairo_t* cr, const TablePicture& pic, double r) {
  std::vector<LabelRequest> requests;
  std::vector<std::string> texts;
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kLabelFontPx);
  for (const PictureBall& ball : pic.balls) {
    if (ball.pocket || ball.path.empty()) continue;
    texts.push_back(std::to_string(ball.id));
    cairo_text_extents_t e;
    cairo_text_extents(cr, texts.back().c_str(), &e);
    requests.push_back({TablePixel(pic, ball.path.back()), Vector2d(e.x_advance, kLabelFontPx)});
  }
  const std::vector<LabelBox> boxes = PlaceLabels(requests, r);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_set_line_width(cr, 0.8);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    // A number pushed out of the first ring gets a line to its ball.
    const Vector2d c = requests[i].centre;
    const Vector2d nearest = c.cwiseMax(boxes[i].min).cwiseMin(boxes[i].max);
    if ((nearest - c).norm() > r + kLeaderFromPx) {
      const Vector2d from = c + r * (nearest - c).normalized();
      cairo_move_to(cr, from.x(), from.y());
      cairo_line_to(cr, nearest.x(), nearest.y());
      cairo_stroke(cr);
    }
    // The box's bottom is the text's baseline: digits have no descent.
    Text(cr, boxes[i].min.x(), boxes[i].max.y(), texts[i], kLabelFontPx);
  }
}

// The key of the paths, down the right rail: a stroke of each moving ball's path style beside
// its ball, drawn as on the table, and its number.
void DrawPathLegend(cairo_t* cr, const TablePicture& pic, double width, double height) {
  const std::vector<int> ids = PathLegendIds(pic);
  if (ids.empty()) return;
  constexpr double kRowPx = 22.0, kBallPx = 6.0;
  const double x = width - kMarginPx + 8.0;
  const double top = kMarginPx + 50.0;  // below the corner pocket
  const double row = std::min(kRowPx, (height - 2 * kMarginPx - 100.0) / ids.size());
  cairo_set_source_rgb(cr, 1, 1, 1);
  Text(cr, x, top - 12.0, "paths", 11.0);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const double y = top + k * row;
    PathStroke(cr, ids[k]);
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x + 16.0, y);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    DrawBall(cr, Vector2d(x + 16.0 + kBallPx, y), kBallPx, LookOf(ids[k]));
    cairo_set_source_rgb(cr, 1, 1, 1);
    Text(cr, x + 16.0 + 2 * kBallPx + 3.0, y + 4.0, std::to_string(ids[k]), 11.0);
  }
}

}  // namespace

std::vector<int> PathLegendIds(const TablePicture& picture) {
  std::vector<int> ids;
  for (const PictureBall& ball : picture.balls) {
    if (Moved(ball)) ids.push_back(ball.id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

Vector2d TablePixel(const TablePicture& picture, const Vector2d& p) {
  return {kMarginPx + kPixelsPerMetre * p.x(),
          kMarginPx + kPixelsPerMetre * (picture.table.width - p.y())};
}

std::vector<Vector2d> SampledPath(double t_end, double dt, const std::vector<double>& at,
                                  const std::function<Vector2d(double)>& position) {
  std::vector<double> times;
  for (double t = 0.0; t < t_end; t += dt) times.push_back(t);
  times.insert(times.end(), at.begin(), at.end());
  times.push_back(t_end);
  std::sort(times.begin(), times.end());
  std::vector<Vector2d> path;
  for (double t : times) {
    if (t <= t_end) path.push_back(position(t));
  }
  return path;
}

void AddSimulation(const table::TableSimulation& sim, double dt, TablePicture* picture) {
  std::map<int, std::size_t> index;
  for (std::size_t i = 0; i < sim.ball_count(); ++i) index[sim.id(i)] = i;
  std::map<int, std::vector<double>> event_times;
  std::map<int, double> dropped;
  for (const table::TableEvent& e : sim.events()) {
    const Vector2d a = sim.StateAt(index[e.ball], e.time).head<2>();
    Vector2d at = a;
    if (e.type == table::EventType::kBallBall) {
      at = 0.5 * (a + sim.StateAt(index[e.other], e.time).head<2>());
      event_times[e.other].push_back(e.time);
    }
    if (e.type == table::EventType::kBallPocket) dropped[e.ball] = e.time;
    event_times[e.ball].push_back(e.time);
    picture->events.push_back({e.type, at});
  }
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    PictureBall ball;
    ball.id = sim.id(i);
    ball.start = sim.StateAt(i, 0.0);
    ball.pocket = sim.pocket(i);
    const double end = dropped.count(ball.id) ? dropped[ball.id] : sim.time();
    ball.path = SampledPath(end, dt, event_times[ball.id],
                            [&](double t) -> Vector2d { return sim.StateAt(i, t).head<2>(); });
    picture->balls.push_back(ball);
  }
}

void DrawTable(const TablePicture& pic, const std::string& path) {
  const int width = static_cast<int>(std::ceil(2 * kMarginPx + kPixelsPerMetre * pic.table.length));
  const int height = static_cast<int>(std::ceil(2 * kMarginPx + kPixelsPerMetre * pic.table.width));
  Canvas canvas(path, width, height);
  cairo_t* cr = canvas.cr();
  const double r = pic.ball_radius * kPixelsPerMetre;

  // The rails, then the cloth inside the boundary (cushion noses, jaws, capture lines).
  cairo_set_source_rgb(cr, 0.40, 0.22, 0.10);
  cairo_rectangle(cr, 0, 0, width, height);
  cairo_fill(cr);
  std::vector<Vector2d> outline;
  for (const Vector2d& p : pic.table.outline) outline.push_back(TablePixel(pic, p));
  cairo_set_source_rgb(cr, 0.05, 0.45, 0.25);
  Polygon(cr, outline);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.02, 0.30, 0.15);
  cairo_set_line_width(cr, 2.0);
  for (const table::CushionLine& line : pic.table.lines) {
    const Vector2d a = TablePixel(pic, line.a), b = TablePixel(pic, line.b);
    cairo_move_to(cr, a.x(), a.y());
    cairo_line_to(cr, b.x(), b.y());
    cairo_stroke(cr);
  }
  for (const table::Pocket& pocket : pic.table.pockets) {
    const Vector2d a = TablePixel(pic, pocket.capture_a), b = TablePixel(pic, pocket.capture_b);
    const Vector2d mid = 0.5 * (a + b);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_arc(cr, mid.x(), mid.y(), 0.5 * (a - b).norm(), 0, 2 * M_PI);
    cairo_fill(cr);
  }

  // Paths under everything else, each in its ball's colour (the cue ball's grey on the cloth).
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const PictureBall& ball : pic.balls) {
    if (ball.path.size() < 2) continue;
    PathStroke(cr, ball.id);
    for (std::size_t k = 0; k < ball.path.size(); ++k) {
      const Vector2d p = TablePixel(pic, ball.path[k]);
      k == 0 ? cairo_move_to(cr, p.x(), p.y()) : cairo_line_to(cr, p.x(), p.y());
    }
    cairo_stroke(cr);
  }
  cairo_set_dash(cr, nullptr, 0, 0.0);
  constexpr double kDotPx = 2.2;
  for (const TrackedDots& dots : pic.tracked) {
    for (const Vector2d& sample : dots.samples) {
      const Vector2d p = TablePixel(pic, sample);
      cairo_arc(cr, p.x(), p.y(), kDotPx, 0, 2 * M_PI);
      FillAndOutline(cr, LookOf(dots.id).colour(), {0, 0, 0}, 0.6);
    }
  }
  if (pic.target) {
    const Vector2d t = TablePixel(pic, *pic.target);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, 2.0);
    cairo_arc(cr, t.x(), t.y(), r, 0, 2 * M_PI);
    cairo_stroke(cr);
    cairo_move_to(cr, t.x() - 1.5 * r, t.y());
    cairo_line_to(cr, t.x() + 1.5 * r, t.y());
    cairo_move_to(cr, t.x(), t.y() - 1.5 * r);
    cairo_line_to(cr, t.x(), t.y() + 1.5 * r);
    cairo_stroke(cr);
  }
  // Where each ball started: an outline, when it moved.
  for (const PictureBall& ball : pic.balls) {
    if (!Moved(ball)) continue;
    const Vector2d p = TablePixel(pic, ball.path.front());
    Source(cr, LookOf(ball.id).colour());
    cairo_set_line_width(cr, 1.5);
    cairo_arc(cr, p.x(), p.y(), r, 0, 2 * M_PI);
    cairo_stroke(cr);
  }
  for (const PictureEvent& e : pic.events) {
    const Vector2d p = TablePixel(pic, e.at);
    Source(cr, Mark(e.type).colour);
    cairo_arc(cr, p.x(), p.y(), 3.0, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  // Where each ball ended, as it looks, with its number beside it, apart from the others'.
  for (const PictureBall& ball : pic.balls) {
    if (ball.pocket || ball.path.empty()) continue;
    DrawBall(cr, TablePixel(pic, ball.path.back()), r, LookOf(ball.id));
  }
  DrawLabels(cr, pic, r);
  if (pic.robot_cue) {
    DrawRobotCue(cr, pic, *pic.robot_cue, width);
  } else if (pic.cue && !pic.balls.empty()) {
    DrawCue(cr, pic, *pic.cue, pic.balls.front().start.head<2>());
  }
  for (const PictureBall& ball : pic.balls) {
    if (ball.start.tail<5>().norm() > 0.0) DrawLaunch(cr, pic, ball);
  }

  // The title on the top rail; the legend of the marks on the bottom one.
  cairo_set_source_rgb(cr, 1, 1, 1);
  Text(cr, kMarginPx, 0.5 * kMarginPx, pic.title, 14.0);
  double x = kMarginPx;
  const double y = height - 0.5 * kMarginPx + 4.0;
  for (const table::EventType type :
       {table::EventType::kBallBall, table::EventType::kBallCushion,
        table::EventType::kBallPocket, table::EventType::kTransition,
        table::EventType::kBallPush}) {
    Source(cr, Mark(type).colour);
    cairo_arc(cr, x, y - 4.0, 4.0, 0, 2 * M_PI);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    Text(cr, x + 8.0, y, Mark(type).name, 12.0);
    x += 120.0;
  }
  DrawPathLegend(cr, pic, width, height);
  cairo_set_source_rgb(cr, 1, 1, 1);
  Text(cr, width - kMarginPx, 0.5 * kMarginPx,
       "black: launch; blue: roll of the spin (follow along, draw against); green: side spin", 12.0,
       1.0);
  canvas.Finish();
}

}  // namespace billiard::plot
