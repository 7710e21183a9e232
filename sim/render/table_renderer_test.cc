// The renderer against the camera model: where balls appear, how big, how they blur, and noise
// that is reproducible.
#include "sim/render/table_renderer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <iostream>

#include <opencv2/imgproc.hpp>

#include "sim/params/parameter_sets.h"
#include "sim/physics/simulator.h"

namespace billiard::render {
namespace {

const std::array<double, 5> kLens{-0.12, 0.03, 4e-4, -3e-4, 0.0};
const cv::Vec3b kWhite{255, 255, 255};

physics::ModelParameters Pool() { return params::LoadParameters("pool"); }

camera::CameraModel Straight(int width = 1280, int height = 720) {
  return camera::CameraModel::Overhead(Pool().table, width, height);
}

// Lens distortion and a camera a little off the vertical, as mounted in practice.
camera::CameraModel DistortedAndTilted() {
  camera::CameraModel c = camera::CameraModel::Overhead(Pool().table, 1280, 720, 2.5, 0.92, kLens);
  const Eigen::Vector3d centre = c.Centre();
  c.rotation = Eigen::AngleAxisd(0.03, Eigen::Vector3d::UnitX()).toRotationMatrix() *
               Eigen::AngleAxisd(-0.02, Eigen::Vector3d::UnitY()).toRotationMatrix() * c.rotation;
  c.translation = -c.rotation * centre;
  return c;
}

// Flat white balls without shadow, vignetting, noise or blur: a pixel's value then tells how much
// of it the ball covers.
RenderOptions Flat() {
  RenderOptions o;
  o.ambient = 1.0;
  o.specular = 0.0;
  o.vignetting = 0.0;
  o.shadow = 0.0;
  o.noise_sigma = 0.0;
  o.exposure_s = 0.0;
  return o;
}

// The fraction of each pixel a ball of `colour` covers, from a frame and the empty table.
cv::Mat Coverage(const cv::Mat& frame, const cv::Mat& background, const cv::Vec3b& colour) {
  cv::Mat coverage(frame.size(), CV_64F);
  for (int v = 0; v < frame.rows; ++v) {
    for (int u = 0; u < frame.cols; ++u) {
      const cv::Vec3d f = frame.at<cv::Vec3b>(v, u), b = background.at<cv::Vec3b>(v, u);
      const cv::Vec3d contrast = cv::Vec3d(colour) - b;
      coverage.at<double>(v, u) = (f - b).dot(contrast) / contrast.dot(contrast);
    }
  }
  return coverage;
}

struct Blob {
  double area = 0;  // [px^2]
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
};

Blob Measure(const cv::Mat& coverage) {
  Blob b;
  for (int v = 0; v < coverage.rows; ++v) {
    for (int u = 0; u < coverage.cols; ++u) {
      const double w = coverage.at<double>(v, u);
      b.area += w;
      b.centroid += w * Eigen::Vector2d(u, v);
    }
  }
  b.centroid /= b.area;
  return b;
}

// The exact image of the sphere: the camera's projection of the circle where the rays from the
// camera's centre touch it, as a polygon.
std::vector<Eigen::Vector2d> SilhouettePolygon(const camera::CameraModel& camera,
                                               const Eigen::Vector3d& centre, double r) {
  const Eigen::Vector3d eye = camera.Centre();
  const double distance = (centre - eye).norm();
  const Eigen::Vector3d axis = (centre - eye) / distance;
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  const double alpha = std::asin(r / distance);
  std::vector<Eigen::Vector2d> polygon;
  for (int i = 0; i < 720; ++i) {
    const double phi = 2 * M_PI * i / 720;
    const Eigen::Vector3d ray =
        std::cos(alpha) * axis + std::sin(alpha) * (std::cos(phi) * e1 + std::sin(phi) * e2);
    polygon.push_back(camera.Project(eye + distance * std::cos(alpha) * ray));
  }
  return polygon;
}

// A polygon's area and centroid.
Blob PolygonBlob(const std::vector<Eigen::Vector2d>& polygon) {
  Blob b;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& p = polygon[i];
    const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
    const double cross = p.x() * q.y() - q.x() * p.y();
    b.area += 0.5 * cross;
    b.centroid += (p + q) * cross / 6.0;
  }
  b.centroid /= b.area;
  b.area = std::abs(b.area);
  return b;
}

Blob Silhouette(const camera::CameraModel& camera, const Eigen::Vector3d& centre, double r) {
  return PolygonBlob(SilhouettePolygon(camera, centre, r));
}

// The part of a convex polygon on the side of the line through a and b where `kept` lies
// (Sutherland and Hodgman 1974, one edge).
std::vector<Eigen::Vector2d> Clipped(const std::vector<Eigen::Vector2d>& polygon,
                                     const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                     const Eigen::Vector2d& kept) {
  const auto side = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d d = b - a, e = p - a;
    return d.x() * e.y() - d.y() * e.x();
  };
  const double sign = side(kept) > 0 ? 1.0 : -1.0;
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& p = polygon[i];
    const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
    const double sp = sign * side(p), sq = sign * side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) out.push_back(p + sp / (sp - sq) * (q - p));
  }
  return out;
}

double EquivalentRadius(const Blob& b) { return std::sqrt(b.area / M_PI); }

TEST(TableRenderer, BallAppearsWhereAndAsLargeAsTheCameraProjectsIt) {
  const physics::ModelParameters p = Pool();
  const double r = p.ball.radius;
  for (const camera::CameraModel& camera : {Straight(), DistortedAndTilted()}) {
    const TableRenderer renderer(camera, p, Flat());
    for (const Eigen::Vector2d& xy :
         {Eigen::Vector2d(1.27, 0.635), Eigen::Vector2d(0.05, 0.05), Eigen::Vector2d(2.49, 1.22),
          Eigen::Vector2d(0.8137, 0.3311), Eigen::Vector2d(2.1003, 0.9871)}) {
      const Eigen::Vector3d centre(xy.x(), xy.y(), r);
      const cv::Mat frame = renderer.Render({RenderBall::AtRest(0, kWhite, xy)}, 0.0);
      const Blob blob = Measure(Coverage(frame, renderer.background(), kWhite));
      const Blob truth = Silhouette(camera, centre, r);
      SCOPED_TRACE(testing::Message()
                   << "ball at " << xy.transpose() << ", distortion " << camera.distortion[0]);
      EXPECT_LT((blob.centroid - camera.Project(centre)).norm(), 0.1);
      EXPECT_LT((blob.centroid - truth.centroid).norm(), 0.03);
      EXPECT_NEAR(EquivalentRadius(blob), EquivalentRadius(truth), 0.1);
    }
  }
  // Straight below the camera the image is a circle of radius f tan(asin(r / D)), 13.4 px here.
  // (Off the axis it grows: at the corners the silhouette's area is that of a 14.3 px circle.)
  const camera::CameraModel camera = Straight();
  const TableRenderer renderer(camera, p, Flat());
  const Eigen::Vector2d below(camera.Centre().head<2>());
  const double distance = camera.Centre().z() - r;
  const Blob blob = Measure(Coverage(renderer.Render({RenderBall::AtRest(0, kWhite, below)}, 0.0),
                                     renderer.background(), kWhite));
  EXPECT_NEAR(EquivalentRadius(blob), camera.fx * r / std::sqrt(distance * distance - r * r), 0.05);
}

TEST(TableRenderer, FollowsASimulatedTrajectory) {
  const physics::ModelParameters p = Pool();
  const camera::CameraModel camera = Straight();
  const TableRenderer renderer(camera, p, Flat());
  physics::SimulationOptions closed_form;
  closed_form.model = physics::Model::kClosedForm;
  const auto trajectory =
      physics::Simulate(p, physics::MakeBallState(0.3, 0.4, 1.2, 0.5, 0, 0, 0), 3.0, closed_form)
          .trajectory;
  for (const double t : {0.0, 0.4, 1.3}) {
    const physics::BallState s = trajectory->At(t);
    const cv::Mat frame = renderer.Render({RenderBall::Following(0, kWhite, trajectory)}, t);
    const Blob blob = Measure(Coverage(frame, renderer.background(), kWhite));
    EXPECT_LT(
        (blob.centroid - camera.Project({s[physics::kX], s[physics::kY], p.ball.radius})).norm(),
        0.1)
        << t;
  }
}

TEST(TableRenderer, EmptyTableShowsClothInsideThePlayingSurfaceAndBordersOutside) {
  const physics::ModelParameters p = Pool();
  RenderOptions o = Flat();
  o.ambient = 0.35;  // the light straight down still lights the cloth fully
  for (const camera::CameraModel& camera : {Straight(), DistortedAndTilted()}) {
    const TableRenderer renderer(camera, p, o);
    const cv::Mat frame = renderer.Render({}, 0.0);
    const double margin = 2 * camera.MetresPerPixel({1.27, 0.635, 0.0});
    int inside = 0, border = 0;
    for (int v = 0; v < frame.rows; ++v) {
      for (int u = 0; u < frame.cols; ++u) {
        const Eigen::Vector3d cloth = camera.Unproject({u, v}, 0.0);
        const Eigen::Vector3d top = camera.Unproject({u, v}, o.cushion_height);
        const bool on_cloth = cloth.x() > margin && cloth.x() < p.table.length - margin &&
                              cloth.y() > margin && cloth.y() < p.table.width - margin;
        const bool on_border = top.x() < -margin || top.x() > p.table.length + margin ||
                               top.y() < -margin || top.y() > p.table.width + margin;
        if (on_cloth) {
          ++inside;
          ASSERT_EQ(frame.at<cv::Vec3b>(v, u), o.cloth) << u << ", " << v;
        } else if (on_border) {
          ++border;
          EXPECT_NE(frame.at<cv::Vec3b>(v, u), o.cloth) << u << ", " << v;
        }
      }
    }
    EXPECT_GT(inside, frame.total() / 2);
    EXPECT_GT(border, frame.total() / 50);
  }
}

TEST(TableRenderer, GrayFramesAreTheLumaOfColourFrames) {
  const physics::ModelParameters p = Pool();
  RenderOptions o;
  o.noise_sigma = 0;
  // No highlight: in colour it saturates (a channel clips at 255), in gray it need not.
  o.specular = 0;
  const TableRenderer colour(Straight(640, 360), p, o);
  o.gray = true;
  const TableRenderer gray(Straight(640, 360), p, o);
  const std::vector<RenderBall> balls = {RenderBall::AtRest(1, PoolBallColour(1), {0.5, 0.5}),
                                         RenderBall::AtRest(8, PoolBallColour(8), {1.5, 0.7})};
  cv::Mat expected;
  cv::cvtColor(colour.Render(balls, 0.0), expected, cv::COLOR_BGR2GRAY);
  const cv::Mat frame = gray.Render(balls, 0.0);
  ASSERT_EQ(frame.type(), CV_8UC1);
  EXPECT_LE(cv::norm(frame, expected, cv::NORM_INF), 1.0);
}

// A light of another colour or strength scales each channel of everything it lights, balls,
// highlights and cloth alike: the frame is the white light's times the gain, to a grey level of
// rounding twice (the background's and the frame's: shadows darken the rounded background),
// wherever the white light's is not clipped.
TEST(TableRenderer, ALightOfAnotherColourScalesEveryChannel) {
  const physics::ModelParameters p = Pool();
  RenderOptions o;
  o.noise_sigma = 0;
  o.exposure_s = 0;
  const std::vector<RenderBall> balls = {RenderBall::AtRest(0, PoolBallColour(0), {0.5, 0.5}),
                                         RenderBall::AtRest(3, PoolBallColour(3), {1.5, 0.7})};
  const cv::Mat white = TableRenderer(Straight(640, 360), p, o).Render(balls, 0.0);
  o.light_colour = {0.55f, 0.8f, 1.0f};  // a tungsten bulb's
  const cv::Mat warm = TableRenderer(Straight(640, 360), p, o).Render(balls, 0.0);
  int compared = 0;
  for (int v = 0; v < white.rows; ++v) {
    for (int u = 0; u < white.cols; ++u) {
      for (int c = 0; c < 3; ++c) {
        const int w = white.at<cv::Vec3b>(v, u)[c];
        if (w == 255) continue;
        ++compared;
        ASSERT_NEAR(warm.at<cv::Vec3b>(v, u)[c], o.light_colour[c] * w, 1.5)
            << u << ", " << v << " channel " << c;
      }
    }
  }
  EXPECT_GT(compared, 0.99 * 3 * white.total());
  o.light_colour = {1.0f, -0.1f, 1.0f};
  EXPECT_THROW(TableRenderer(Straight(64, 36), p, o), std::invalid_argument);
}

TEST(TableRenderer, NoiseIsReproducibleFromTheSeedAndHasTheAskedSigma) {
  const physics::ModelParameters p = Pool();
  RenderOptions o;
  o.noise_sigma = 3.0;
  const camera::CameraModel camera = Straight(640, 360);
  const TableRenderer a(camera, p, o), b(camera, p, o);
  o.seed = 2;
  const TableRenderer other(camera, p, o);
  const std::vector<RenderBall> balls = {RenderBall::AtRest(3, PoolBallColour(3), {1.0, 0.6})};
  const cv::Mat frame = a.Render(balls, 0.25);
  const auto same = [](const cv::Mat& x, const cv::Mat& y) {
    return cv::norm(x, y, cv::NORM_INF) == 0;
  };
  EXPECT_TRUE(same(frame, a.Render(balls, 0.25)));
  EXPECT_TRUE(same(frame, b.Render(balls, 0.25)));
  EXPECT_FALSE(same(frame, other.Render(balls, 0.25)));
  EXPECT_FALSE(same(frame, a.Render(balls, 0.25 + 1.0 / 120)));

  // On the cloth (far from saturation) the noise is zero-mean with the asked sigma, and the noise
  // of two frames is uncorrelated.
  const cv::Rect cloth(100, 60, 200, 100);
  cv::Mat n1, n2;
  cv::subtract(a.Render({}, 1.0)(cloth), a.background()(cloth), n1, cv::noArray(), CV_64F);
  cv::subtract(a.Render({}, 2.0)(cloth), a.background()(cloth), n2, cv::noArray(), CV_64F);
  cv::Scalar mean, sigma;
  cv::meanStdDev(n1.reshape(1), mean, sigma);
  EXPECT_NEAR(mean[0], 0.0, 0.05);
  EXPECT_NEAR(sigma[0], 3.0, 0.1);
  EXPECT_LT(std::abs(n1.dot(n2)) / (n1.total() * 3 * 9.0), 0.02);
}

TEST(TableRenderer, MotionBlurSpreadsAMovingBallAlongItsPath) {
  const physics::ModelParameters p = Pool();
  const double r = p.ball.radius;
  const camera::CameraModel camera = Straight();
  RenderOptions o = Flat();
  o.exposure_s = 0.01;
  o.subframes = 32;
  const TableRenderer renderer(camera, p, o);
  // 6 m/s for 10 ms: a 60 mm streak, longer than the ball's diameter.
  const Eigen::Vector2d start(1.0, 0.5), velocity(6.0, 1.5);
  const RenderBall ball{0, kWhite, [&](double t) { return Eigen::Vector2d(start + t * velocity); }};
  const double t = 0.1;
  const cv::Mat coverage = Coverage(renderer.Render({ball}, t), renderer.background(), kWhite);
  const Blob blob = Measure(coverage);

  const auto at = [&](double time) {
    const Eigen::Vector2d xy = start + time * velocity;
    return camera.Project({xy.x(), xy.y(), r});
  };
  EXPECT_LT((blob.centroid - at(t)).norm(), 0.1);
  // Blur moves light around, it does not add any.
  const Blob still = Measure(Coverage(renderer.Render({RenderBall::AtRest(0, kWhite, start)}, t),
                                      renderer.background(), kWhite));
  EXPECT_NEAR(blob.area, still.area, 0.01 * still.area);
  // Every pixel along the centre's path is lit for at least the share of the exposure the ball
  // spends within a radius of it (at the ends: about r / streak length = 0.46).
  const Eigen::Vector2d from = at(t - 0.005), to = at(t + 0.005);
  const double length = (to - from).norm();
  ASSERT_GT(length, 2 * EquivalentRadius(still));
  for (double s = 0; s <= length; s += 0.5) {
    const Eigen::Vector2d q = from + (to - from) * s / length;
    EXPECT_GT(coverage.at<double>(static_cast<int>(std::lround(q.y())),
                                  static_cast<int>(std::lround(q.x()))),
              0.4)
        << s;
  }
  // And nothing is lit beyond the ends of the streak.
  const Eigen::Vector2d dir = (to - from) / length;
  for (const Eigen::Vector2d& q : {Eigen::Vector2d(to + dir * (EquivalentRadius(still) + 2)),
                                   Eigen::Vector2d(from - dir * (EquivalentRadius(still) + 2))}) {
    EXPECT_EQ(coverage.at<double>(static_cast<int>(std::lround(q.y())),
                                  static_cast<int>(std::lround(q.x()))),
              0.0);
  }
}

TEST(TableRenderer, NearerOfTwoTouchingBallsHidesTheOther) {
  // Seen from an angle, touching balls overlap in the image. The camera is above the table's
  // centre, so the ball nearer the centre is nearer the camera: it must stay whole.
  const physics::ModelParameters p = Pool();
  const double r = p.ball.radius;
  const TableRenderer renderer(Straight(), p, Flat());
  const RenderBall near = RenderBall::AtRest(0, kWhite, {0.1, 0.635});
  const RenderBall far = RenderBall::AtRest(1, cv::Vec3b(0, 0, 255), {0.1 - 2 * r, 0.635});
  const cv::Mat both = renderer.Render({far, near}, 0.0);
  const cv::Mat near_alone = renderer.Render({near}, 0.0);
  const cv::Mat far_alone = renderer.Render({far}, 0.0);
  const cv::Mat& table = renderer.background();
  int overlap = 0;
  for (int v = 0; v < table.rows; ++v) {
    for (int u = 0; u < table.cols; ++u) {
      if (near_alone.at<cv::Vec3b>(v, u) != kWhite) continue;  // not wholly the near ball
      EXPECT_EQ(both.at<cv::Vec3b>(v, u), kWhite) << u << ", " << v;
      overlap += far_alone.at<cv::Vec3b>(v, u) != table.at<cv::Vec3b>(v, u);
    }
  }
  EXPECT_GT(overlap, 20);  // the far ball alone does reach under the near one
}

TEST(TableRenderer, TheNearCushionHidesTheLowerPartOfABallAgainstIt) {
  // A camera beyond the near rail (2 m from the table's middle, 35 degrees up, no lens distortion)
  // sees a ball against the near cushion over the cushion's nose, 36 mm high: what it sees of the
  // ball is its silhouette on the far side of the nose's image, a straight line (the exact
  // polygons of the sphere's silhouette, clipped). An overhead camera sees the same ball whole.
  const physics::ModelParameters p = Pool();
  const double r = p.ball.radius;
  const Eigen::Vector3d middle(0.5 * p.table.length, 0.5 * p.table.width, 0.0);
  const double elevation = 35.0 * M_PI / 180.0;
  const camera::CameraModel side = camera::CameraModel::LookingAt(
      middle + 2.0 * Eigen::Vector3d(0, -std::cos(elevation), std::sin(elevation)), middle, 1280,
      720, 1.2);
  const RenderOptions flat = Flat();
  const TableRenderer renderer(side, p, flat);
  const Eigen::Vector2d nose_a = side.Project({0.5, 0.0, flat.cushion_height});
  const Eigen::Vector2d nose_b = side.Project({2.0, 0.0, flat.cushion_height});
  for (const double x : {1.0, 1.9}) {
    const Eigen::Vector3d centre(x, r, r);
    SCOPED_TRACE(testing::Message() << "ball at x = " << x);
    const Blob blob = Measure(Coverage(renderer.Render({RenderBall::AtRest(0, kWhite, {x, r})}, 0.0),
                                       renderer.background(), kWhite));
    const Blob whole = Silhouette(side, centre, r);
    const Blob seen = PolygonBlob(
        Clipped(SilhouettePolygon(side, centre, r), nose_a, nose_b, side.Project({x, 0.5, 0.0})));
    EXPECT_LT(seen.area, 0.9 * whole.area);  // the nose does hide a good part of it
    EXPECT_NEAR(EquivalentRadius(blob), EquivalentRadius(seen), 0.1);
    EXPECT_LT((blob.centroid - seen.centroid).norm(), 0.05);
  }
  const camera::CameraModel overhead = Straight();
  const TableRenderer from_above(overhead, p, flat);
  const Blob blob = Measure(Coverage(from_above.Render({RenderBall::AtRest(0, kWhite, {1.0, r})}, 0.0),
                                     from_above.background(), kWhite));
  const Blob truth = Silhouette(overhead, {1.0, r, r}, r);
  EXPECT_NEAR(EquivalentRadius(blob), EquivalentRadius(truth), 0.1);
  EXPECT_LT((blob.centroid - truth.centroid).norm(), 0.03);
}

// Not a timing assertion: the time per frame is printed for the record (sim/README.md).
TEST(TableRenderer, FrameTimeOfA1280x720TableWith16Balls) {
  const physics::ModelParameters p = Pool();
  const camera::CameraModel camera = Straight();
  const auto built = std::chrono::steady_clock::now();
  const TableRenderer renderer(camera, p);
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - built).count();
  std::vector<RenderBall> balls;
  for (int i = 0; i < 16; ++i) {
    const Eigen::Vector2d xy(0.2 + 0.15 * i, 0.25 + 0.05 * (i % 5) + 0.3 * (i % 3));
    if (i < 4) {  // four balls swinging at up to 1-4 m/s, the rest at rest
      const Eigen::Vector2d v(std::cos(i), std::sin(i));
      balls.push_back({i, PoolBallColour(i), [=](double t) {
                         return Eigen::Vector2d(xy + (i + 1.0) * 0.01 * v * std::sin(100 * t));
                       }});
    } else {
      balls.push_back(RenderBall::AtRest(i, PoolBallColour(i), xy));
    }
  }
  cv::Mat frame;
  const int frames = 60;
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) renderer.Render(balls, f / 120.0, &frame);
  const double per_frame_ms =
      1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
      frames;
  std::cerr << "1280x720, 16 balls (4 moving, 8 subframes), noise: " << per_frame_ms
            << " ms per frame; renderer setup " << setup_s << " s\n";
  EXPECT_EQ(frame.size(), cv::Size(1280, 720));
}

}  // namespace
}  // namespace billiard::render
