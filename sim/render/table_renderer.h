// Camera frames of the simulated table, so that the estimator can be tested against ground truth.
//
// Geometry is exact for the CameraModel (pinhole, lens distortion, pose): every pixel's ray is
// computed once per renderer, through the pixel's centre (OpenCV's convention: pixel (i, j)
// covers [i - 1/2, i + 1/2] x [j - 1/2, j + 1/2]). The table is a box model: the cloth at z = 0
// inside the playing surface, cushions of height `cushion_height` and width `cushion_width`
// around it (their top and their inner face, which a camera above the table sees as a thin band
// along the cloth's edge), the wooden rail outside them at the same height, and the floor beyond.
// That background is rendered once, 3x3 supersampled. A frame is a copy of it plus the balls:
// each ball is ray-traced as a sphere of radius r centred at (x, y, r), only inside the bounding
// box of its projection and of its shadow, with analytic anti-aliasing (the pixel's coverage
// from the ray's distance to the sphere). A camera beyond a rail sees that side's cushion hide
// what lies beyond its nose: the lower part of a ball against it (CoverAt, the nose's edge
// anti-aliased the same way); a camera above the playing surface sees every ball whole.
//
// What the estimator should know about the pictures:
//  - The centre of a ball's silhouette is not exactly Project((x, y, r)): a sphere off the optical
//    axis projects to an ellipse stretched away from the image centre, whose centre lies further
//    out by about f (r/D)^2 tan(theta) / cos^2(theta) (D the distance, theta the angle off the
//    axis): up to 0.09 px at the corners of a 1280x720 overhead view of a pool table without
//    distortion (0.05 px with k1 = -0.12, whose barrel squeezes the outer side).
//  - Shading moves the intensity centroid much more than that: the overhead light makes the top of
//    the ball brightest, and off-axis the top is seen displaced from the centre.
//  - The contact shadow is centred under the ball on the cloth, not at the ball's image.
//
// Shading: Lambertian under a directional light (ambient + diffuse, with ambient + diffuse = 1
// so a surface facing the light shows its colour), a specular highlight of the light's colour
// (Blinn-Phong), the light's colour and strength a gain per channel on all of it, radial
// vignetting (1 - vignetting rho^2, rho the distance from the image centre relative to the
// corner), and a soft contact shadow on the cloth around each ball.
//
// Motion blur: the frame at time t is the mean of `subframes` renderings at times spread evenly
// over [t - exposure/2, t + exposure/2] (midpoints of equal slices), in the boxes of moving balls
// only: balls that do not move during the exposure (and whose boxes overlap no moving ball's) are
// rendered once.
//
// Sensor noise: Gaussian, rounded to gray levels, added to every byte with saturation. It comes
// from one buffer drawn once from `seed`, read at an offset drawn from (seed, frame time in whole
// microseconds): the same renderer options and frame give the same bytes, and consecutive frames
// get independent-looking noise at the cost of a memory pass.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/camera/camera_model.h"
#include "sim/physics/parameters.h"
#include "sim/physics/trajectory.h"

namespace billiard::render {

struct RenderOptions {
  double exposure_s = 0.004;  // exposure time; 0 renders the instant t
  int subframes = 8;          // renderings averaged over the exposure (moving balls only)
  double noise_sigma = 2.0;   // standard deviation of the sensor noise [gray levels]; 0 for none
  std::uint64_t seed = 1;     // of the noise
  bool gray = false;          // 8UC1 (OpenCV's luma of the colour frame) instead of 8UC3 BGR

  // Colours (B, G, R) as they appear lit straight on, without vignetting.
  cv::Vec3b cloth{60, 110, 30};
  cv::Vec3b cushion{48, 88, 24};  // cushion cloth, a little darker than the bed
  cv::Vec3b rail{30, 60, 95};     // wood
  cv::Vec3b floor{40, 40, 40};
  double cushion_height = 0.036;  // nose height above the cloth [m] (pool: 63.5 % of a ball)
  double cushion_width = 0.05;    // [m]
  double rail_width = 0.12;       // [m]

  Eigen::Vector3d light_direction{0.0, 0.0, 1.0};  // towards the light, table frame
  double ambient = 0.35;                           // share of the light that reaches every surface
  double specular = 0.5;                           // highlight strength [fraction of white]
  double shininess = 60.0;                         // Blinn-Phong exponent
  double vignetting = 0.12;                        // darkening at the image corners
  double shadow = 0.45;  // darkening of the cloth at the contact, gone at 1.5 radii
  // The light's colour and strength as a gain per channel (B, G, R) on everything it lights, the
  // highlight included: {1, 1, 1} is the white light the colours above are given under; a
  // tungsten bulb's warm light is about {0.55, 0.8, 1} of a daylight lamp's, a dimmer one all
  // three lower. A camera's white balance set for another light scales the channels the same way.
  cv::Vec3f light_colour{1, 1, 1};
};

// One ball of a frame: its number (pool: 0 the cue ball, 1-15), colour (B, G, R) and where its
// centre is on the table at time t.
struct RenderBall {
  int id = 0;
  cv::Vec3b colour;
  std::function<Eigen::Vector2d(double t)> position;
  // A stripe (pool's 9-15): `colour` on a band around the ball, ivory caps either side of it
  // (where the surface's normal is more than kStripeHalfWidth along `axis`). The orientation is
  // fixed as the ball moves (the renderer does not roll it): by default the band lies along x.
  bool striped = false;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // unit, table frame
  // A pool ball's number: an ivory circle kSpotRadius (an angle at the ball's centre) around
  // both ends of `spot` (unit, table frame; on a stripe it should lie on the band), its figure a
  // dark disc kFigureRadius across in its middle (a figure's strokes cover about a quarter of its
  // circle). None when zero, as the cue ball.
  Eigen::Vector3d spot = Eigen::Vector3d::Zero();

  static RenderBall AtRest(int id, const cv::Vec3b& colour, const Eigen::Vector2d& xy);
  // Follows a simulated trajectory (held alive by the ball).
  static RenderBall Following(int id, const cv::Vec3b& colour,
                              std::shared_ptr<const physics::Trajectory> trajectory);
};

// The colours of the pool set (0: the cue ball, 1-8 the solids, 9-15 the stripes' colour,
// drawn with RenderBall::striped).
cv::Vec3b PoolBallColour(int id);
// Whether pool ball `id` is a stripe (9-15).
inline bool PoolBallStriped(int id) { return id >= 9 && id <= 15; }
// The stripe's band: |normal . y| below this is the colour, a band of 41 degrees of latitude
// (a regulation stripe's is wider, some 60): seen from above, its caps are then 45 % of the
// middle three quarters of the disc, which the estimator reads a ball's colours from
// (estimator/ball_identity.cc), where 60 degrees would leave 22 %, too little to tell a stripe.
inline constexpr double kStripeHalfWidth = 0.3;
// A number's circle, about 17 mm across on a 57 mm ball (asin(8.5 / 28.6)), and its figure.
inline constexpr double kSpotRadius = 0.30;
inline constexpr double kFigureRadius = 0.15;

class TableRenderer {
 public:
  // Precomputes the rays and the background. Throws std::invalid_argument on a camera without
  // pixels, a ball radius or table size that is not positive, subframes < 1, or a light's colour
  // that is negative or not finite.
  TableRenderer(const camera::CameraModel& camera, const physics::ModelParameters& params,
                const RenderOptions& options = {});

  // The frame whose exposure is centred at t: 8UC3 BGR, or 8UC1 with options.gray.
  cv::Mat Render(const std::vector<RenderBall>& balls, double t) const;
  // The same into `frame`, reusing its memory when it has the right size and type.
  void Render(const std::vector<RenderBall>& balls, double t, cv::Mat* frame) const;

  // The empty table without noise.
  const cv::Mat& background() const { return background_; }
  const camera::CameraModel& camera() const { return camera_; }
  const RenderOptions& options() const { return options_; }

 private:
  struct Region;
  void RenderRegion(const Region& region, cv::Mat* frame) const;
  static const Eigen::Vector3f& SurfaceColour(const Region& region, int k,
                                              const Eigen::Vector3d& normal,
                                              const Eigen::Vector3f& ivory,
                                              const Eigen::Vector3f& figure);
  // What the cushions and the rail hide along a ray `d`: what lies beyond `distance` along it
  // (where the ray comes down to the cushions' height), `share` of it (0 where the ray comes down
  // onto the playing surface, 1 onto a cushion, a pixel's ramp between). A camera beyond the rail
  // sees the near cushion hide the lower part of a ball against it.
  struct CushionCover {
    double distance = std::numeric_limits<double>::infinity();
    float share = 0;
  };
  CushionCover CoverAt(const Eigen::Vector3d& d, double pixel_angle) const;
  void AddNoise(double t, cv::Mat* frame) const;
  const Eigen::Vector3d& RayAt(int u, int v) const { return rays_[v * camera_.width + u]; }
  float Vignette(int u, int v) const;

  camera::CameraModel camera_;
  double radius_;
  physics::TableParameters table_;
  RenderOptions options_;
  Eigen::Vector3d centre_;             // the camera's, table frame
  std::vector<Eigen::Vector3d> rays_;  // unit, table frame, row-major by pixel
  float vignette_scale_;               // vignetting / (centre-to-corner distance [px])^2
  cv::Mat background_;
  std::vector<std::int8_t> noise_;  // rounded Gaussian noise, longer than a frame
};

}  // namespace billiard::render
