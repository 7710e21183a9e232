#include "sim/table/table_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "sim/params/table_specs.h"

namespace billiard::table {
namespace {

using Eigen::Vector2d;

constexpr double kInch = 0.0254;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// Ball radii of the games' rules: WPA 2.25 in, WPBSA 52.5 mm, UMB 61.5 mm.
constexpr double kPoolRadius = 0.5 * 2.25 * kInch;
constexpr double kSnookerRadius = 0.5 * 0.0525;
constexpr double kCaromRadius = 0.5 * 0.0615;

TableGeometry Built(const std::string& name) { return BuildTable(params::LoadTableSpec(name)); }

// [0, 1) from the raw 64-bit draws, as the racks do: the same numbers on every platform.
double Uniform(std::mt19937_64* engine) {
  return static_cast<double>((*engine)() >> 11) * 0x1.0p-53;
}

double Cross(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The first time at which a ball of radius R moving from p along the unit direction v touches a
// cushion line, a cushion point or crosses a capture line (infinity if none); `captured` says
// whether it was a capture line.
double FirstHit(const TableGeometry& table, const Vector2d& p, const Vector2d& v, double R,
                bool* captured) {
  double first = kInfinity;
  *captured = false;
  for (const CushionLine& line : table.lines) {
    const double approach = -v.dot(line.normal);
    if (approach <= 0) continue;
    const double t = ((p - line.a).dot(line.normal) - R) / approach;
    if (t < 0) continue;
    const Vector2d ab = line.b - line.a;
    const double along = (p + t * v - line.a).dot(ab) / ab.squaredNorm();
    if (along >= 0 && along <= 1 && t < first) first = t;
  }
  for (const CushionPoint& point : table.points) {
    const Vector2d d = p - point.centre;
    const double b = d.dot(v);
    const double c = d.squaredNorm() - std::pow(R + point.radius, 2);
    const double discriminant = b * b - c;
    if (b >= 0 || discriminant < 0) continue;
    const double t = -b - std::sqrt(discriminant);
    if (t >= 0 && t < first) first = t;
  }
  for (const Pocket& pocket : table.pockets) {
    const double approach = v.dot(pocket.inward);
    if (approach <= 0) continue;
    const double t = -(p - pocket.capture_a).dot(pocket.inward) / approach;
    const Vector2d ab = pocket.capture_b - pocket.capture_a;
    const double along = (p + t * v - pocket.capture_a).dot(ab) / ab.squaredNorm();
    if (t >= 0 && along >= 0 && along <= 1 && t < first) {
      first = t;
      *captured = true;
    }
  }
  return first;
}

struct ClosureCase {
  const char* table;
  double radius;
};

void PrintTo(const ClosureCase& c, std::ostream* os) { *os << c.table; }

class ClosureTest : public ::testing::TestWithParam<ClosureCase> {};

// The boundary is closed: from 10,000 seeded places on the surface, a straight line in a seeded
// direction stays on the surface until it first meets a cushion line or point at distance R or a
// capture line, and is off the surface just after. A gap in the boundary would let a ray run off
// the surface with no hit (or with a hit only past the gap).
TEST_P(ClosureTest, EveryRayMeetsACushionOrACaptureLine) {
  const TableGeometry table = Built(GetParam().table);
  const double R = GetParam().radius;
  std::mt19937_64 engine(20260101);
  constexpr int kRays = 10000;
  constexpr double kStep = 1e-6;  // [m]
  int captured_rays = 0;
  for (int ray = 0; ray < kRays; ++ray) {
    Vector2d p;
    do {
      p = Vector2d(table.length * Uniform(&engine), table.width * Uniform(&engine));
    } while (!table.OnSurface(p, R));
    const double angle = 2 * kPi * Uniform(&engine);
    const Vector2d v(std::cos(angle), std::sin(angle));
    bool captured = false;
    const double t = FirstHit(table, p, v, R, &captured);
    ASSERT_TRUE(std::isfinite(t)) << "ray " << ray << " from " << p.transpose() << " along "
                                  << v.transpose() << " meets nothing";
    for (int k = 0; k < 8; ++k) {
      ASSERT_TRUE(table.InsideBoundary(p + (k / 8.0) * t * v, R))
          << "ray " << ray << " leaves the surface before its first hit at t = " << t;
    }
    if (t > kStep) {
      ASSERT_TRUE(table.InsideBoundary(p + (t - kStep) * v, R)) << "ray " << ray;
    }
    ASSERT_FALSE(table.InsideBoundary(p + (t + kStep) * v, R))
        << "ray " << ray << " still on the surface past its hit at t = " << t;
    captured_rays += captured;
  }
  const bool pockets = !table.pockets.empty();
  EXPECT_EQ(captured_rays > 0, pockets) << captured_rays << " of " << kRays << " rays dropped";
  RecordProperty("captured_rays", captured_rays);
}

INSTANTIATE_TEST_SUITE_P(BuiltInTables, ClosureTest,
                         ::testing::Values(ClosureCase{"pool-7ft", kPoolRadius},
                                           ClosureCase{"pool-8ft", kPoolRadius},
                                           ClosureCase{"pool-9ft", kPoolRadius},
                                           ClosureCase{"snooker-12ft", kSnookerRadius},
                                           ClosureCase{"carom-10ft", kCaromRadius}),
                         [](const auto& info) {
                           std::string name = info.param.table;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

TEST(TableGeometryTest, CountsOfAPocketTableAndACaromTable) {
  const TableGeometry pool = Built("pool-9ft");
  EXPECT_EQ(pool.lines.size(), 6u + 12u);  // six rails, two jaw faces per pocket
  EXPECT_EQ(pool.points.size(), 12u);
  EXPECT_EQ(pool.pockets.size(), 6u);
  const TableGeometry carom = Built("carom-10ft");
  EXPECT_EQ(carom.lines.size(), 4u);
  EXPECT_TRUE(carom.points.empty());
  EXPECT_TRUE(carom.pockets.empty());
}

// The sharp nose of a rounded jaw, found from the built geometry alone: the two lines that end
// tangent to the nose's circle, extended until they meet. `angle` is the angle between them at
// the nose, through the rubber (from the nose towards each line's far end).
struct Nose {
  Vector2d at;
  double angle_degrees;
};

Nose NoseOf(const TableGeometry& table, const CushionPoint& point) {
  std::vector<std::pair<Vector2d, Vector2d>> tangent;  // (tangent end, far end)
  for (const CushionLine& line : table.lines) {
    for (const auto& [end, far] : {std::pair(line.a, line.b), std::pair(line.b, line.a)}) {
      const bool on_circle = std::abs((end - point.centre).norm() - point.radius) < 1e-12;
      const bool square = std::abs((end - point.centre).dot(far - end)) < 1e-12;
      if (on_circle && square) tangent.emplace_back(end, far);
    }
  }
  EXPECT_EQ(tangent.size(), 2u);
  const auto& [p, p_far] = tangent[0];
  const auto& [q, q_far] = tangent[1];
  const Vector2d u = (p_far - p).normalized(), w = (q_far - q).normalized();
  const double s = Cross(q - p, w) / Cross(u, w);
  const Vector2d at = p + s * u;
  return {at, std::acos((p_far - at).normalized().dot((q_far - at).normalized())) * 180 / kPi};
}

class WpaPocketTest : public ::testing::TestWithParam<const char*> {};

// The pockets as built against the WPA Equipment Specifications (Pocket Openings): mouth between
// the noses 4.5-4.625 in corner, 5-5.125 in side; cut angle 142 +-1 deg corner, 104 +-1 deg
// side. The corner pockets' mouths sit square across the diagonal, the side pockets' at the long
// cushions' middles; the capture line lies the shelf depth (BCA Pocket Specifications: corner
// 1.625-1.875 in, side 0-0.375 in) into the pocket, from jaw face to jaw face.
TEST_P(WpaPocketTest, MouthsAnglesAndPlacesAsBuilt) {
  const TableGeometry table = Built(GetParam());
  const double L = table.length, W = table.width;
  std::vector<Nose> noses;
  for (const CushionPoint& point : table.points) noses.push_back(NoseOf(table, point));
  ASSERT_EQ(noses.size(), 12u);
  for (const Pocket& pocket : table.pockets) {
    SCOPED_TRACE(pocket.name);
    const bool side = pocket.name.find("middle") != std::string::npos;
    std::vector<Nose> mine;
    for (const Nose& nose : noses) {
      if ((nose.at - pocket.centre).norm() < 4 * kInch) mine.push_back(nose);
    }
    ASSERT_EQ(mine.size(), 2u);
    const double mouth = (mine[0].at - mine[1].at).norm();
    EXPECT_GE(mouth, (side ? 5.0 : 4.5) * kInch - 1e-12);
    EXPECT_LE(mouth, (side ? 5.125 : 4.625) * kInch + 1e-12);
    for (const Nose& nose : mine) EXPECT_NEAR(nose.angle_degrees, side ? 104 : 142, 1.0);
    EXPECT_LT((0.5 * (mine[0].at + mine[1].at) - pocket.centre).norm(), 1e-12);

    const Vector2d corner(pocket.centre.x() < 0.5 * L ? 0 : L, pocket.centre.y() < 0.5 * W ? 0 : W);
    if (side) {
      EXPECT_NEAR(pocket.centre.x(), 0.5 * L, 1e-12);
      EXPECT_NEAR(pocket.centre.y(), corner.y(), 1e-12);
    } else {
      // The mouth cuts a right isosceles triangle off the corner: its height is half the mouth.
      EXPECT_NEAR((pocket.centre - corner).norm(), 0.5 * mouth, 1e-12);
      EXPECT_NEAR(std::abs(pocket.centre.x() - corner.x()),
                  std::abs(pocket.centre.y() - corner.y()), 1e-12);
    }
    const double depth = (pocket.capture_a - pocket.centre).dot(pocket.inward);
    EXPECT_NEAR((pocket.capture_b - pocket.centre).dot(pocket.inward), depth, 1e-12);
    EXPECT_GE(depth, (side ? 0.0 : 1.625) * kInch - 1e-12);
    EXPECT_LE(depth, (side ? 0.375 : 1.875) * kInch + 1e-12);
    EXPECT_GT(pocket.inward.dot(pocket.centre - Vector2d(0.5 * L, 0.5 * W)), 0)
        << "inward must point away from the table";
    for (const Vector2d& end : {pocket.capture_a, pocket.capture_b}) {
      int faces_through = 0;
      for (const CushionLine& line : table.lines) {
        const Vector2d ab = line.b - line.a;
        const double along = (end - line.a).dot(ab) / ab.squaredNorm();
        faces_through +=
            std::abs(Cross(ab.normalized(), end - line.a)) < 1e-12 && along > 0 && along < 1;
      }
      EXPECT_EQ(faces_through, 1) << "capture line must end on a jaw face";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(WpaTables, WpaPocketTest,
                         ::testing::Values("pool-7ft", "pool-8ft", "pool-9ft"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

Vector2d MirrorX(const TableGeometry& t, const Vector2d& p) { return {t.length - p.x(), p.y()}; }
Vector2d MirrorY(const TableGeometry& t, const Vector2d& p) { return {p.x(), t.width - p.y()}; }

// Mirror images of the built table across its two middle lines are the table itself: every line
// (reversed, since a mirror turns counter-clockwise into clockwise), point and pocket has its
// image among the others.
TEST(TableGeometryTest, MirrorSymmetry) {
  for (const char* name : {"pool-9ft", "snooker-12ft", "carom-10ft"}) {
    SCOPED_TRACE(name);
    const TableGeometry table = Built(name);
    for (const auto mirror : {MirrorX, MirrorY}) {
      for (const CushionLine& line : table.lines) {
        const Vector2d a = mirror(table, line.b), b = mirror(table, line.a);
        const Vector2d normal = mirror(table, line.normal) - mirror(table, Vector2d::Zero());
        int images = 0;
        for (const CushionLine& other : table.lines) {
          images += (other.a - a).norm() < 1e-12 && (other.b - b).norm() < 1e-12 &&
                    (other.normal - normal).norm() < 1e-12;
        }
        EXPECT_EQ(images, 1) << line.a.transpose() << " -> " << line.b.transpose();
      }
      for (const CushionPoint& point : table.points) {
        int images = 0;
        for (const CushionPoint& other : table.points) {
          images += (other.centre - mirror(table, point.centre)).norm() < 1e-12 &&
                    other.radius == point.radius;
        }
        EXPECT_EQ(images, 1);
      }
      for (const Pocket& pocket : table.pockets) {
        int images = 0;
        for (const Pocket& other : table.pockets) {
          images += (other.centre - mirror(table, pocket.centre)).norm() < 1e-12 &&
                    (other.capture_a - mirror(table, pocket.capture_b)).norm() < 1e-12 &&
                    (other.capture_b - mirror(table, pocket.capture_a)).norm() < 1e-12;
        }
        EXPECT_EQ(images, 1) << pocket.name;
      }
    }
  }
}

// OnSurface at places whose answer is plain: the carom table's interior is the rectangle inset
// by R; a ball past a pocket's capture line is gone, and one past its mouth line (between the
// noses) hangs over the pocket: inside the boundary a moving ball keeps to, but no place to put
// a ball.
TEST(TableGeometryTest, OnSurfaceAtPlainPlaces) {
  const TableGeometry carom = Built("carom-10ft");
  const double R = kCaromRadius;
  EXPECT_TRUE(carom.OnSurface({R, R}, R));
  EXPECT_TRUE(carom.OnSurface({carom.length - R - 1e-9, carom.width - R - 1e-9}, R));
  EXPECT_FALSE(carom.OnSurface({R - 1e-9, 0.5 * carom.width}, R));
  EXPECT_FALSE(carom.OnSurface({0.5 * carom.length, carom.width - R + 1e-9}, R));
  EXPECT_FALSE(carom.OnSurface({-1, 0.5 * carom.width}, R));

  const TableGeometry pool = Built("pool-9ft");
  for (const Pocket& pocket : pool.pockets) {
    const Vector2d middle = 0.5 * (pocket.capture_a + pocket.capture_b);
    EXPECT_TRUE(pool.InsideBoundary(middle - 1e-6 * pocket.inward, 0.01)) << pocket.name;
    EXPECT_FALSE(pool.InsideBoundary(middle + 1e-6 * pocket.inward, 0.01)) << pocket.name;
    EXPECT_FALSE(pool.OnSurface(middle - 1e-6 * pocket.inward, 0.01)) << pocket.name;
    EXPECT_TRUE(pool.OnSurface(pocket.centre - 1e-6 * pocket.inward, 0.01)) << pocket.name;
    EXPECT_FALSE(pool.OnSurface(pocket.centre + 1e-6 * pocket.inward, 0.01)) << pocket.name;
    EXPECT_EQ(pool.PocketPastMouth(pocket.centre - 1e-6 * pocket.inward), nullptr) << pocket.name;
    EXPECT_EQ(pool.PocketPastMouth(pocket.centre + 1e-6 * pocket.inward), &pocket) << pocket.name;
  }
  EXPECT_EQ(pool.PocketPastMouth({0.5 * pool.length, 0.5 * pool.width}), nullptr);
  // The corner pocket's mouth runs from nose to nose, mouth / sqrt(2) from the corner along each
  // cushion (x + y = 0.0819 m at the lower left): a ball at (0.01, 0.01) is 4.4 cm past it,
  // over the pocket, though inside the playing rectangle and short of the capture line.
  EXPECT_TRUE(pool.InsideBoundary({0.01, 0.01}, kPoolRadius));
  EXPECT_FALSE(pool.OnSurface({0.01, 0.01}, kPoolRadius));
}

TableSpec PoolSpec() { return params::LoadTableSpec(params::kDefaultTable); }

void ExpectRefused(const TableSpec& spec, const std::string& reason) {
  try {
    BuildTable(spec);
    ADD_FAILURE() << "accepted; expected: " << reason;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
  }
}

TEST(TableGeometryTest, RefusesSpecsThatMakeNoTable) {
  TableSpec spec = PoolSpec();
  spec.length = -1;
  ExpectRefused(spec, "length and width must be positive");
  spec = PoolSpec();
  spec.cushion_height = std::nan("");
  ExpectRefused(spec, "cushion_height must be positive");
  spec = PoolSpec();
  spec.corner.reset();
  ExpectRefused(spec, "side pockets without corner pockets");
  spec = PoolSpec();
  spec.corner->jaw_angle = 130;  // the jaws would open outwards
  ExpectRefused(spec, "corner pocket jaw_angle must be in [135, 180)");
  spec = PoolSpec();
  spec.side->jaw_angle = 179;  // the jaws would meet right behind the mouth
  ExpectRefused(spec, "side pocket jaws close before the capture line");
  spec = PoolSpec();
  spec.corner->mouth = 0.9;
  ExpectRefused(spec, "the corner pockets overlap along the short cushions");
  spec = PoolSpec();
  spec.side->mouth = 2.4;
  ExpectRefused(spec, "the corner and side pockets overlap along the long cushions");
  spec = PoolSpec();
  spec.side->capture_depth = -0.01;
  ExpectRefused(spec, "side pocket capture_depth must be >= 0");
  spec = PoolSpec();
  spec.rail->height = 0.9 * spec.cushion_height;  // the nose would stand above the wood
  ExpectRefused(spec, "rail.height must be at least cushion_height");
  spec = PoolSpec();
  spec.rail->width = 0;
  ExpectRefused(spec, "rail.width must be positive");
}

// The rail as given, and without one (a spec written before rails were data) a wall at the nose
// line as high as the nose: FastFiz's rail, at our nose's height.
TEST(TableGeometryTest, RailAsGivenOrAtTheNose) {
  TableSpec spec = PoolSpec();
  ASSERT_TRUE(spec.rail.has_value());
  const TableGeometry pool = BuildTable(spec);
  EXPECT_EQ(pool.rail_height, spec.rail->height);
  EXPECT_EQ(pool.rail_width, spec.rail->width);
  spec.rail.reset();
  const TableGeometry bare = BuildTable(spec);
  EXPECT_EQ(bare.rail_height, spec.cushion_height);
  EXPECT_EQ(bare.rail_width, 0.0);
}

}  // namespace
}  // namespace billiard::table
