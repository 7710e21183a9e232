#include "sim/table/table_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace billiard::table {

namespace {

using Eigen::Vector2d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
// The jaw angles at which a pocket's jaw faces run parallel to its axis: a corner pocket's axis
// is the diagonal (45 degrees to both cushions), a side pocket's is square to its cushion.
constexpr double kCornerParallelJaw = 135.0;
constexpr double kSideParallelJaw = 90.0;
constexpr double kStraightAngle = 180.0;
// Capture lines closer than this to a cushion line lie on it [m].
constexpr double kOnLine = 1e-12;

Vector2d LeftNormal(const Vector2d& v) { return Vector2d(-v.y(), v.x()).normalized(); }
Vector2d RightNormal(const Vector2d& v) { return Vector2d(v.y(), -v.x()).normalized(); }

Vector2d Rotate(const Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vector2d(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

double DistanceToSegment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d ab = b - a;
  const double along = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + along * ab)).norm();
}

// Crossing-number test (Franklin's PNPOLY): whether p lies inside the polygon.
bool InsidePolygon(const std::vector<Vector2d>& polygon, const Vector2d& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vector2d& u = polygon[i];
    const Vector2d& v = polygon[j];
    if ((u.y() > p.y()) != (v.y() > p.y()) &&
        p.x() < (v.x() - u.x()) * (p.y() - u.y()) / (v.y() - u.y()) + u.x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Where a pocket is cut: the rectangle's corner (or a long cushion's middle) `corner`, the
// directions of the cushions arriving at it and leaving it counter-clockwise, and how far from
// `corner` along each cushion the noses sit.
struct PocketSite {
  const char* name;
  Vector2d corner;
  Vector2d arriving, leaving;
  double nose_offset;
  const TableSpec::PocketSpec* spec;
  double parallel_jaw;  // the jaw angle whose faces run parallel to the pocket's axis [deg]
};

// One side of a pocket: the rounded nose and the jaw face behind it.
struct Jaw {
  Vector2d rail_end;    // where the cushion line ends: the rounding's tangent point on it
  Vector2d face_start;  // where the jaw face begins: the rounding's tangent point on it
  Vector2d face_end;
  Vector2d capture;  // the capture line's end on this jaw
  bool capture_on_face;
  CushionPoint nose;
};

// The pocket's frame: the mouth's middle and the unit axis into the pocket.
struct Mouth {
  Vector2d middle, axis, across;  // across: unit, from the arriving nose to the leaving one
  double width;
  double Depth(const Vector2d& p) const { return (p - middle).dot(axis); }
};

// A jaw at nose `nose`; `along` points from the nose back along its cushion, `turn` is +1 for
// the jaw met first counter-clockwise (the face turns counter-clockwise from `along` through the
// rubber) and -1 for the second.
Jaw BuildJaw(const Vector2d& nose, const Vector2d& along, double turn,
             const TableSpec::PocketSpec& spec, const Mouth& mouth) {
  const double half_angle = 0.5 * spec.jaw_angle * kDegree;
  const Vector2d face = Rotate(along, turn * spec.jaw_angle * kDegree);
  const double tangent = spec.jaw_radius / std::tan(half_angle);
  Jaw jaw;
  jaw.rail_end = nose + tangent * along;
  jaw.face_start = nose + tangent * face;
  jaw.nose = {nose + (along + face).normalized() * (spec.jaw_radius / std::sin(half_angle)),
              spec.jaw_radius};
  const double face_depth_rate = face.dot(mouth.axis);  // depth gained per metre of face
  const double start_depth = mouth.Depth(jaw.face_start);
  jaw.capture_on_face = spec.capture_depth >= start_depth;
  if (spec.capture_depth <= mouth.Depth(jaw.rail_end) + kOnLine) {
    // On the cushion line of a side pocket (where the rounding's depth is stationary, so the
    // crossing below is ill-conditioned): the capture line starts where the cushion line ends.
    jaw.capture = jaw.rail_end;
  } else if (jaw.capture_on_face) {
    jaw.capture = nose + (spec.capture_depth / face_depth_rate) * face;
  } else {
    // The capture line meets the rounding: of its two crossings with the circle, the one on the
    // exposed arc is the nearer to the pocket's axis.
    const Vector2d on_axis = mouth.middle + spec.capture_depth * mouth.axis;
    const Vector2d offset = on_axis - jaw.nose.centre;
    const double b = offset.dot(mouth.across);
    const double root =
        std::sqrt(std::max(0.0, b * b - offset.squaredNorm() + spec.jaw_radius * spec.jaw_radius));
    const double w = std::abs(-b - root) < std::abs(-b + root) ? -b - root : -b + root;
    jaw.capture = on_axis + w * mouth.across;
  }
  const double end_depth = std::max(spec.capture_depth, start_depth) + 0.5 * mouth.width;
  jaw.face_end = nose + (end_depth / face_depth_rate) * face;
  return jaw;
}

void Require(bool ok, const std::string& table, const std::string& reason) {
  if (!ok) throw std::invalid_argument("table '" + table + "': " + reason);
}

bool PositiveFinite(double x) { return std::isfinite(x) && x > 0; }

// The length of cushion a pocket takes from each cushion it cuts: the nose's offset from the
// corner plus the rounding's tangent length.
double CushionTaken(const TableSpec::PocketSpec& p, double nose_offset) {
  return nose_offset + p.jaw_radius / std::tan(0.5 * p.jaw_angle * kDegree);
}

void ValidatePocket(const TableSpec::PocketSpec& p, const std::string& table, const char* which,
                    double parallel_jaw) {
  const std::string what = std::string(which) + " pocket ";
  Require(PositiveFinite(p.mouth), table, what + "mouth must be positive");
  Require(std::isfinite(p.jaw_radius) && p.jaw_radius >= 0, table,
          what + "jaw_radius must be >= 0");
  Require(std::isfinite(p.capture_depth) && p.capture_depth >= 0, table,
          what + "capture_depth must be >= 0");
  Require(std::isfinite(p.jaw_angle) && p.jaw_angle >= parallel_jaw && p.jaw_angle < kStraightAngle,
          table,
          what + "jaw_angle must be in [" + std::to_string(static_cast<int>(parallel_jaw)) +
              ", 180) degrees (jaw faces parallel to the pocket's axis up to a cushion without a "
              "pocket)");
  // The jaw faces converge by (jaw_angle - parallel) each; they must stay apart down to the
  // faces' ends, half a mouth past the capture line (or past the rounding, if deeper).
  const double half_angle = 0.5 * p.jaw_angle * kDegree;
  const double convergence = (p.jaw_angle - parallel_jaw) * kDegree;
  const double rounding_depth = p.jaw_radius / std::tan(half_angle) * std::cos(convergence);
  const double end_depth = std::max(p.capture_depth, rounding_depth) + 0.5 * p.mouth;
  Require(0.5 * p.mouth - end_depth * std::tan(convergence) > 0, table,
          what + "jaws close before the capture line (jaw_angle too large for the mouth)");
}

}  // namespace

const Pocket* TableGeometry::PocketNamed(const std::string& name) const {
  for (const Pocket& pocket : pockets) {
    if (pocket.name == name) return &pocket;
  }
  return nullptr;
}

bool TableGeometry::OnSurface(const Vector2d& p, double radius) const {
  return InsideBoundary(p, radius) && !PocketPastMouth(p);
}

const Pocket* TableGeometry::PocketPastMouth(const Vector2d& p) const {
  for (const Pocket& pocket : pockets) {
    if ((p - pocket.centre).dot(pocket.inward) > 0.0) return &pocket;
  }
  return nullptr;
}

bool TableGeometry::InsideBoundary(const Vector2d& p, double radius) const {
  if (!InsidePolygon(outline, p)) return false;
  for (const CushionLine& line : lines) {
    if (DistanceToSegment(p, line.a, line.b) < radius) return false;
  }
  for (const CushionPoint& point : points) {
    if ((p - point.centre).norm() < radius + point.radius) return false;
  }
  return true;
}

namespace {

// A rail no lower than the cushion's nose, of some width.
void ValidateRail(const TableSpec& spec) {
  Require(std::isfinite(spec.rail->height) && spec.rail->height >= spec.cushion_height, spec.name,
          "rail.height must be at least cushion_height");
  Require(PositiveFinite(spec.rail->width), spec.name, "rail.width must be positive");
}

}  // namespace

TableGeometry BuildTable(const TableSpec& spec) {
  const std::string& name = spec.name;
  Require(PositiveFinite(spec.length) && PositiveFinite(spec.width), name,
          "length and width must be positive");
  Require(spec.length >= spec.width, name, "length must be at least the width");
  Require(PositiveFinite(spec.cushion_height), name, "cushion_height must be positive");
  Require(spec.corner.has_value() || !spec.side.has_value(), name,
          "side pockets without corner pockets");
  if (spec.rail) ValidateRail(spec);

  TableGeometry table;
  table.name = spec.name;
  table.length = spec.length;
  table.width = spec.width;
  table.cushion_height = spec.cushion_height;
  table.rail_height = spec.rail ? spec.rail->height : spec.cushion_height;
  table.rail_width = spec.rail ? spec.rail->width : 0.0;
  const double L = spec.length, W = spec.width;
  const Vector2d east(1, 0), north(0, 1), west(-1, 0), south(0, -1);

  if (!spec.corner) {
    const std::array<Vector2d, 4> corners = {Vector2d(0, 0), Vector2d(L, 0), Vector2d(L, W),
                                             Vector2d(0, W)};
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Vector2d& a = corners[i];
      const Vector2d& b = corners[(i + 1) % corners.size()];
      table.lines.push_back({a, b, LeftNormal(b - a)});
      table.outline.push_back(a);
    }
    return table;
  }

  const TableSpec::PocketSpec& corner = *spec.corner;
  ValidatePocket(corner, name, "corner", kCornerParallelJaw);
  const double corner_offset = corner.mouth / std::sqrt(2.0);
  Require(2 * CushionTaken(corner, corner_offset) < W, name,
          "the corner pockets overlap along the short cushions");
  std::vector<PocketSite> sites;
  if (spec.side) {
    ValidatePocket(*spec.side, name, "side", kSideParallelJaw);
    Require(CushionTaken(corner, corner_offset) + CushionTaken(*spec.side, 0.5 * spec.side->mouth) <
                0.5 * L,
            name, "the corner and side pockets overlap along the long cushions");
  } else {
    Require(2 * CushionTaken(corner, corner_offset) < L, name,
            "the corner pockets overlap along the long cushions");
  }
  const auto add_corner = [&](const char* pocket, const Vector2d& at, const Vector2d& arriving,
                              const Vector2d& leaving) {
    sites.push_back({pocket, at, arriving, leaving, corner_offset, &corner, kCornerParallelJaw});
  };
  const auto add_side = [&](const char* pocket, const Vector2d& at, const Vector2d& direction) {
    if (spec.side) {
      sites.push_back({pocket, at, direction, direction, 0.5 * spec.side->mouth, &*spec.side,
                       kSideParallelJaw});
    }
  };
  add_corner("lower_left", Vector2d(0, 0), south, east);
  add_side("lower_middle", Vector2d(0.5 * L, 0), east);
  add_corner("lower_right", Vector2d(L, 0), east, north);
  add_corner("upper_right", Vector2d(L, W), north, west);
  add_side("upper_middle", Vector2d(0.5 * L, W), west);
  add_corner("upper_left", Vector2d(0, W), west, south);

  std::vector<std::pair<Jaw, Jaw>> jaws;
  for (const PocketSite& site : sites) {
    const Vector2d arriving_nose = site.corner - site.nose_offset * site.arriving;
    const Vector2d leaving_nose = site.corner + site.nose_offset * site.leaving;
    Mouth mouth;
    mouth.middle = 0.5 * (arriving_nose + leaving_nose);
    mouth.width = (leaving_nose - arriving_nose).norm();
    mouth.across = (leaving_nose - arriving_nose) / mouth.width;
    mouth.axis = RightNormal(mouth.across);
    const Jaw first = BuildJaw(arriving_nose, -site.arriving, +1, *site.spec, mouth);
    const Jaw second = BuildJaw(leaving_nose, site.leaving, -1, *site.spec, mouth);
    jaws.emplace_back(first, second);
    table.pockets.push_back({site.name, mouth.middle, first.capture, second.capture, mouth.axis});
  }

  for (std::size_t i = 0; i < jaws.size(); ++i) {
    const Vector2d& a = jaws[i].second.rail_end;
    const Vector2d& b = jaws[(i + 1) % jaws.size()].first.rail_end;
    table.lines.push_back({a, b, LeftNormal(b - a)});
  }
  for (const auto& [first, second] : jaws) {
    table.lines.push_back(
        {first.face_start, first.face_end, LeftNormal(first.face_end - first.face_start)});
    table.lines.push_back(
        {second.face_end, second.face_start, LeftNormal(second.face_start - second.face_end)});
    table.points.push_back(first.nose);
    table.points.push_back(second.nose);
    table.outline.push_back(first.rail_end);
    if (first.capture_on_face) table.outline.push_back(first.face_start);
    table.outline.push_back(first.capture);
    table.outline.push_back(second.capture);
    if (second.capture_on_face) table.outline.push_back(second.face_start);
    table.outline.push_back(second.rail_end);
  }
  return table;
}

}  // namespace billiard::table
